// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Decimation with OpenMesh 9 (Debian's libopenmesh-dev): a plane quadric
// (Garland and Heckbert, "Surface simplification using quadric error
// metrics", SIGGRAPH 1997; plane_quadric.hpp) sets the order, OpenMesh's
// normal-flip and aspect-ratio modules veto, and ModIntersectionGuardT
// vetoes collapses that would make the mesh cut itself. OpenMesh's DecimaterT
// asks every module about every candidate each time a neighbourhood changes;
// the guard is far dearer than the others, so this driver asks it only for the
// collapse it is about to make, and on a refusal requeues the vertex with its
// next-best halfedge.
#include "lsolid/decimate.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/BaseDecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModAspectRatioT.hh>
#include <OpenMesh/Tools/Decimater/ModEdgeLengthT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <boost/container_hash/hash.hpp>
#include <cmath>
#include <cstdint>
#include <exception>
#include <functional>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <memory>
#include <numeric>
#include <queue>
#include <tuple>
#include <unordered_set>
#include <vector>

#include "cgal/orientation.hpp"
#include "intersection_guard.hpp"
#include "lsolid/errors.hpp"
#include "plane_quadric.hpp"
#include "surface_distance.hpp"
#include "vertex_key.hpp"

namespace lsolid {
namespace {

constexpr int kAttempts = 3;       // decimations, to keep within tolerance
constexpr double kRetreat = 0.85;  // of the aim that overshot, scaled
// Where the deviation is measured: every vertex and a grid this fine,
// at most this many steps along a triangle's side.
constexpr double kSampleSpacingMm = 0.1;
constexpr int kSampleSteps = 16;

using Corners = std::array<glm::dvec3, 3>;

// The steps a side of the grid a triangle is sampled on: about
// kSampleSpacingMm apart, at least `fewest` and at most kSampleSteps.
int sample_steps(const Corners& corner, double fewest) {
  const double longest = std::max({glm::distance(corner[0], corner[1]),
                                   glm::distance(corner[1], corner[2]),
                                   glm::distance(corner[2], corner[0])});
  return static_cast<int>(std::clamp(std::ceil(longest / kSampleSpacingMm),
                                     fewest, double(kSampleSteps)));
}

// The barycentric grid of `steps` a side over a triangle, on which it is
// sampled: grid coordinates (u, v) are steps along the first and second
// side from the first corner.
struct Lattice {
  Corners corner;
  int steps = 2;

  [[nodiscard]] glm::dvec3 at(double u, double v) const {
    return corner[0] + (corner[1] - corner[0]) * (u / steps) +
           (corner[2] - corner[0]) * (v / steps);
  }
  [[nodiscard]] glm::dvec3 at(const glm::dvec2& uv) const {
    return at(uv.x, uv.y);
  }

  // Calls visit(g) with the grid coordinates g of the grid points in
  // sub-triangle abc (grid coordinates, edges included), the triangle's
  // corners only if `with_corners`, while it returns true; false if one
  // returned false. A point on an edge two sub-triangles share is visited
  // by both, which changes no answer.
  template <typename Visit>
  bool visit_grid(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, bool with_corners,
                  Visit visit) const {
    const glm::dvec2 lo = glm::min(glm::min(a, b), c);
    const glm::dvec2 hi = glm::max(glm::max(a, b), c);
    const auto side = [](glm::dvec2 p, glm::dvec2 q, glm::dvec2 r) {
      return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
    };
    const double area = side(a, b, c);
    constexpr double kSlack = 1e-9;  // grid units; the corners are dyadic
    for (int i = static_cast<int>(std::ceil(lo.x - kSlack));
         i <= static_cast<int>(std::floor(hi.x + kSlack)); ++i) {
      for (int j = static_cast<int>(std::ceil(lo.y - kSlack));
           j <= static_cast<int>(std::floor(hi.y + kSlack)); ++j) {
        if (i < 0 || j < 0 || i + j > steps) continue;
        const bool corner_point = i == steps || j == steps || i + j == 0;
        if (corner_point && !with_corners) continue;
        const glm::dvec2 p(i, j);
        if (side(a, b, p) * area < -kSlack || side(b, c, p) * area < -kSlack ||
            side(c, a, p) * area < -kSlack) {
          continue;
        }
        if (!visit(p)) return false;
      }
    }
    return true;
  }

  // visit_grid, with the points themselves.
  template <typename Visit>
  bool visit_points(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, bool with_corners,
                    Visit visit) const {
    return visit_grid(a, b, c, with_corners,
                      [&](const glm::dvec2& g) { return visit(at(g)); });
  }
};

using Uv = std::array<glm::dvec2, 3>;

// The four quarters of sub-triangle abc (grid coordinates), split at the
// midpoints of its sides.
std::array<Uv, 4> quarters(const Uv& t) {
  const glm::dvec2 ab = (t[0] + t[1]) / 2.0;
  const glm::dvec2 bc = (t[1] + t[2]) / 2.0;
  const glm::dvec2 ca = (t[2] + t[0]) / 2.0;
  return {Uv{t[0], ab, ca}, Uv{ab, t[1], bc}, Uv{ca, bc, t[2]}, Uv{bc, ca, ab}};
}

// A sub-triangle of a lattice with `side_steps` steps a side that is
// sampled point by point rather than proven at once: a few points are
// sampled faster than proven.
constexpr double kFewestProvenSteps = 2.0;

// Calls visit(p) at the points of the triangle's barycentric grid of `steps`
// a side, its corners only if `with_corners`, while visit returns true;
// returns false as soon as one returns false. Points of a part of the
// triangle that covered(a, b, c) vouches for are skipped: covered may return
// true only if visit would return true at every point of triangle abc.
// Proving a sub-triangle at once (SurfaceDistance::covers, by convexity of
// the distance to a triangle) instead of sampling it leaves the answer
// unchanged and visits only the points near creases, where a triangle
// crosses from one face of the other surface to the next: on 36 branches
// meeting at one node, sampling every point was 40% of the whole build.
template <typename Covered, typename Visit>
bool visit_samples(const Corners& corner, int steps, bool with_corners,
                   Covered covered, Visit visit) {
  const Lattice lattice{corner, steps};
  const auto holds = [&](const auto& self, const Uv& t,
                         double side_steps) -> bool {
    if (side_steps <= kFewestProvenSteps) {
      return lattice.visit_points(t[0], t[1], t[2], with_corners, visit);
    }
    if (covered(lattice.at(t[0]), lattice.at(t[1]), lattice.at(t[2]))) {
      return true;
    }
    for (const Uv& quarter : quarters(t)) {
      if (!self(self, quarter, side_steps / 2.0)) return false;
    }
    return true;
  };
  return holds(
      holds,
      Uv{glm::dvec2(0.0, 0.0), glm::dvec2(steps, 0.0), glm::dvec2(0.0, steps)},
      double(steps));
}

// Faces whose unit normals' dot product is below this are not taken for
// coplanar without an exact test (GuardedDecimater::stays_in_plane).
constexpr double kFlatCosine = 1.0 - 1e-9;

struct Traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using Mesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;
using CollapseInfo = OpenMesh::Decimater::CollapseInfoT<Mesh>;

// A piece of the input that a face of the current mesh holds: a
// sub-triangle of input triangle `index`'s lattice, in grid coordinates
// (exact in floats: halves of at most 16 steps, three times), `side_steps`
// a side; a grid point (side 0, at uv[0]); or input vertex `index` (side
// -1). `bound_mm`: how far from the face that holds it the piece lies at
// most (its corners' farthest, by convexity), rounded up to a float.
struct InputPiece {
  std::uint32_t index = 0;
  float side_steps = 0.0F;
  std::array<glm::vec2, 3> uv{};
  float bound_mm = 0.0F;
};

// The steps a side of each input triangle's grid (sample_steps, at least 2).
std::vector<std::uint8_t> input_steps(const TriangleMesh& input) {
  std::vector<std::uint8_t> steps;
  steps.reserve(input.triangles.size());
  for (const auto& t : input.triangles) {
    steps.push_back(static_cast<std::uint8_t>(sample_steps(
        {input.vertices[t[0]], input.vertices[t[1]], input.vertices[t[2]]},
        2.0)));
  }
  return steps;
}

// Each face holding its input triangle whole: face f is input triangle
// `input_face[f]`.
std::vector<std::vector<InputPiece>> whole_pieces(
    const std::vector<std::uint8_t>& steps,
    const std::vector<std::uint32_t>& input_face) {
  std::vector<std::vector<InputPiece>> pieces;
  pieces.reserve(input_face.size());
  for (const std::uint32_t index : input_face) {
    const float n = steps[index];
    pieces.push_back({InputPiece{
        index, n, {glm::vec2(0, 0), glm::vec2(n, 0), glm::vec2(0, n)}, 0.0F}});
  }
  return pieces;
}

// The input that the result must stay near, in pieces, each held by a face
// of the current mesh that lies within the distance of it: the input triangles,
// each at first whole, and every vertex a collapse removes (as OpenMesh's
// ModHausdorffT keeps them). A collapse is refused unless every piece held by
// the faces it removes or moves lies within the distance of a triangle that
// replaces them: wholly, shown by convexity (one triangle within it of a
// piece's three corners), or else in quarters, down to the grid points that
// sampled_distance measures (sample_steps, with at least 2 steps a side),
// each on its own. So every point the measurement takes from the input
// lies within the distance of the result when decimation ends. Tested
// against the surface it replaced only, each collapse stayed within the
// tolerance of the last one while the input drifted further through a
// series of them: the touching Hilbert curve at n = 4 ended 0.06 mm from
// its input for 0.05 mm, and decimation ran three times.
class InputPieces {
 public:
  // Face f of `mesh` holds `pieces[f]`; vertex v is input vertex
  // `input_vertex[v]`. `input` and `steps` (input_steps) are kept by
  // reference.
  InputPieces(Mesh& mesh, const TriangleMesh& input,
              const std::vector<std::uint8_t>& steps,
              const std::vector<std::uint32_t>& input_vertex,
              std::vector<std::vector<InputPiece>> pieces)
      : mesh_(mesh), input_(input), steps_(steps) {
    mesh_.add_property(pieces_);
    // Garbage collection between runs renumbers the vertices; a removed
    // vertex is named by its index in `input`, which this property keeps.
    mesh_.add_property(input_vertex_);
    for (const auto v : mesh_.vertices()) {
      mesh_.property(input_vertex_, v) =
          input_vertex[static_cast<std::size_t>(v.idx())];
    }
    for (const auto f : mesh_.faces()) {
      mesh_.property(pieces_, f) =
          std::move(pieces[static_cast<std::size_t>(f.idx())]);
    }
  }
  ~InputPieces() {
    mesh_.remove_property(pieces_);
    mesh_.remove_property(input_vertex_);
  }
  InputPieces(const InputPieces&) = delete;
  InputPieces& operator=(const InputPieces&) = delete;

  // The pieces face f holds.
  [[nodiscard]] const std::vector<InputPiece>& pieces_of(
      Mesh::FaceHandle f) const {
    return mesh_.property(pieces_, f);
  }

  // The input vertex that vertex v is.
  [[nodiscard]] std::uint32_t input_vertex(Mesh::VertexHandle v) const {
    return mesh_.property(input_vertex_, v);
  }

  // Per input triangle, how far from the mesh its samples lie at most, by
  // the bounds its pieces and its removed corners keep: every grid point
  // of a triangle lies in one of its pieces but its corners, and a corner
  // is a vertex of the mesh, or a piece of its own once removed.
  [[nodiscard]] std::vector<float> farthest() const {
    std::vector<float> vertex(input_.vertices.size(), 0.0F);
    std::vector<float> triangle(input_.triangles.size(), 0.0F);
    for (const auto f : mesh_.faces()) {
      if (mesh_.status(f).deleted()) continue;
      for (const Piece& piece : mesh_.property(pieces_, f)) {
        float& at = piece.side_steps < 0.0F ? vertex[piece.index]
                                            : triangle[piece.index];
        at = std::max(at, piece.bound_mm);
      }
    }
    for (std::size_t t = 0; t < triangle.size(); ++t) {
      for (const std::uint32_t v : input_.triangles[t])
        triangle[t] = std::max(triangle[t], vertex[v]);
    }
    return triangle;
  }

  // Whether the pieces held by the faces round ci.v0, and v0 itself, lie
  // within `distance_mm` of the triangles that replace them (`fresh`);
  // remembers where each goes, for hand_over.
  bool hold(const CollapseInfo& ci, const std::vector<Corners>& fresh,
            double distance_mm) {
    const double squared = distance_mm * distance_mm;
    pending_.clear();
    star_.clear();
    // The squared distance of the points from the triangle that last
    // covered them, for the piece's bound.
    double worst = 0.0;
    const auto near = [&](const Corners& t, const glm::dvec3& p) {
      const glm::dvec3 d = closest_point_on_triangle(p, t[0], t[1], t[2]) - p;
      const double d2 = glm::dot(d, d);
      worst = std::max(worst, d2);
      return d2 <= squared;
    };
    // A fresh triangle within the distance of all of `points`, if any: any
    // will do. The one asked first is the one that replaces the face whose
    // pieces are placed (a piece mostly stays near its face when one corner
    // moves), or else the last that answered: asked from the first each
    // time, Lparser's Menger cube at n = 4 took 13.5 s to decimate against
    // 11.2 s, its flat faces holding hundreds of pieces each.
    std::size_t hint = 0;
    const auto covering = [&](std::initializer_list<glm::dvec3> points) {
      const auto covers = [&](std::size_t i) {
        worst = 0.0;
        return std::all_of(
            points.begin(), points.end(),
            [&](const glm::dvec3& p) { return near(fresh[i], p); });
      };
      if (hint < fresh.size() && covers(hint)) return hint;
      for (std::size_t i = 0; i < fresh.size(); ++i) {
        if (i != hint && covers(i)) {
          hint = i;
          return i;
        }
      }
      return fresh.size();
    };
    const auto keep = [&](Piece piece, std::size_t i) {
      if (i == fresh.size()) return false;
      piece.bound_mm =
          std::nextafter(static_cast<float>(std::sqrt(worst)), HUGE_VALF);
      pending_.emplace_back(piece, i);
      return true;
    };
    const auto place = [&](const auto& self, const Piece& piece) -> bool {
      if (piece.side_steps < 0.0F) {  // a removed vertex
        return keep(piece, covering({input_.vertices[piece.index]}));
      }
      const Lattice lattice = lattice_of(piece.index);
      const auto at = [&](const glm::vec2& uv) {
        return lattice.at(double(uv.x), double(uv.y));
      };
      if (piece.side_steps == 0.0F)
        return keep(piece, covering({at(piece.uv[0])}));
      const std::size_t i =
          covering({at(piece.uv[0]), at(piece.uv[1]), at(piece.uv[2])});
      if (i < fresh.size()) return keep(piece, i);
      const Uv uv{glm::dvec2(piece.uv[0]), glm::dvec2(piece.uv[1]),
                  glm::dvec2(piece.uv[2])};
      if (piece.side_steps <= kFewestProvenSteps) {
        // Each grid point on its own, as a piece of no size.
        const auto point = [&](const glm::dvec2& p) {
          return self(self,
                      Piece{piece.index, 0.0F, {glm::vec2(p), {}, {}}, 0.0F});
        };
        return lattice.visit_grid(uv[0], uv[1], uv[2], false, point);
      }
      for (const Uv& quarter : quarters(uv)) {
        if (!self(self, Piece{piece.index,
                              piece.side_steps / 2.0F,
                              {glm::vec2(quarter[0]), glm::vec2(quarter[1]),
                               glm::vec2(quarter[2])},
                              0.0F})) {
          return false;
        }
      }
      return true;
    };
    if (!place(place,
               Piece{mesh_.property(input_vertex_, ci.v0), -1.0F, {}, 0.0F})) {
      return false;
    }
    std::size_t own = 0;
    for (const auto f : mesh_.vf_range(ci.v0)) {
      star_.push_back(f);
      if (f != ci.fl && f != ci.fr) hint = own++;
      for (const Piece& piece : mesh_.property(pieces_, f)) {
        if (!place(place, piece)) return false;
      }
    }
    return true;
  }

  // Hands the pieces that hold() placed to the faces that replaced theirs.
  // @pre hold() returned true for the collapse just made, with the fresh
  // triangles of these faces, in this order.
  void hand_over(const std::vector<Mesh::FaceHandle>& fresh_faces) {
    for (const auto f : star_) mesh_.property(pieces_, f).clear();
    for (const auto& [piece, i] : pending_) {
      mesh_.property(pieces_, fresh_faces[i]).push_back(piece);
    }
  }

 private:
  using Piece = InputPiece;

  [[nodiscard]] Corners corners_of(std::uint32_t triangle) const {
    const auto& t = input_.triangles[triangle];
    return {input_.vertices[t[0]], input_.vertices[t[1]],
            input_.vertices[t[2]]};
  }

  [[nodiscard]] Lattice lattice_of(std::uint32_t triangle) const {
    return {corners_of(triangle), steps_[triangle]};
  }

  Mesh& mesh_;
  const TriangleMesh& input_;
  const std::vector<std::uint8_t>& steps_;  // per input triangle: its grid
  OpenMesh::FPropHandleT<std::vector<Piece>> pieces_;
  OpenMesh::VPropHandleT<std::uint32_t> input_vertex_;
  std::vector<std::pair<Piece, std::size_t>> pending_;
  std::vector<Mesh::FaceHandle> star_;
};

class GuardedDecimater : public OpenMesh::Decimater::BaseDecimaterT<Mesh> {
 public:
  explicit GuardedDecimater(Mesh& mesh)
      : BaseDecimaterT<Mesh>(mesh), mesh_(mesh) {
    mesh_.add_property(refused_);
    mesh_.add_property(version_);
  }
  ~GuardedDecimater() {
    mesh_.remove_property(refused_);
    mesh_.remove_property(version_);
  }
  GuardedDecimater(const GuardedDecimater&) = delete;
  GuardedDecimater& operator=(const GuardedDecimater&) = delete;

  // The module whose priority ranks the collapses (OpenMesh's one
  // non-binary module); the others only veto.
  void rank_by(OpenMesh::Decimater::ModBaseT<Mesh>& priority) {
    priority_ = &priority;
  }

  // Collapses until no legal collapse is left or at most `faces` remain.
  // Returns the number of collapses.
  // The vetoes are asked only here, for the collapse about to be made;
  // each may be null. The input pieces and the input surface must stay
  // within `tolerance_mm` of the new triangles.
  std::size_t decimate_to_faces(std::size_t faces, InputPieces* samples,
                                SurfaceDistance* input, double tolerance_mm,
                                ModIntersectionGuardT<Mesh>* guard,
                                const std::function<void(std::size_t)>& tell) {
    queue_ = {};
    for (const auto v : mesh_.vertices()) {
      mesh_.property(version_, v) = 0;
      for (const auto h : mesh_.voh_range(v))
        mesh_.property(refused_, h) = false;
    }
    for (const auto v : mesh_.vertices()) enqueue(v);
    std::size_t face_count = mesh_.n_faces();
    std::size_t collapses = 0;
    std::vector<Mesh::VertexHandle> support;
    while (!queue_.empty() && face_count > faces) {
      const auto [priority, index, version, target] = queue_.top();
      queue_.pop();
      const Mesh::VertexHandle v(index);
      if (mesh_.status(v).deleted() || mesh_.property(version_, v) != version) {
        continue;
      }
      CollapseInfo ci(mesh_, Mesh::HalfedgeHandle(target));
      if (!is_collapse_legal(ci)) {
        enqueue(v);
        continue;
      }
      // A collapse that leaves the surface where it was (stays_in_plane)
      // can neither stray from the input nor make faces meet that did not.
      const auto refused = [&] {
        take_new_triangles(ci);
        if (samples != nullptr && !samples->hold(ci, new_, tolerance_mm))
          return true;
        if ((input != nullptr || guard != nullptr) && stays_in_plane(ci))
          return false;
        return (input != nullptr && strays(*input, tolerance_mm)) ||
               (guard != nullptr && guard->would_intersect(ci));
      };
      if (refused()) {
        mesh_.property(refused_, ci.v0v1) = true;
        enqueue(v);
        continue;
      }
      support.assign(mesh_.vv_begin(ci.v0), mesh_.vv_end(ci.v0));
      preprocess_collapse(ci);
      mesh_.collapse(ci.v0v1);
      face_count -= (ci.fl.is_valid() ? 1 : 0) + (ci.fr.is_valid() ? 1 : 0);
      for (const auto f : mesh_.vf_range(ci.v1)) {
        mesh_.set_normal(f, mesh_.calc_face_normal(f));
      }
      postprocess_collapse(ci);
      if (samples != nullptr) samples->hand_over(new_faces_);
      if (guard != nullptr) guard->postprocess_collapse(ci);
      ++collapses;
      for (const auto w : support) {
        for (const auto h : mesh_.voh_range(w))
          mesh_.property(refused_, h) = false;
        enqueue(w);
      }
      if (tell && collapses % 4096 == 0) tell(collapses);
    }
    return collapses;
  }

 private:
  // The corners of face f, with v0 moved to p1 if `moved`.
  Corners corners(const CollapseInfo& ci, Mesh::FaceHandle f, bool moved) {
    Corners corner{};
    std::size_t k = 0;
    for (const auto v : mesh_.fv_range(f)) {
      const Mesh::Point& p = moved && v == ci.v0 ? ci.p1 : mesh_.point(v);
      corner[k++] = {p[0], p[1], p[2]};
    }
    return corner;
  }

  // The triangles the collapse leaves where v0's were, into new_, and their
  // faces, into new_faces_.
  void take_new_triangles(const CollapseInfo& ci) {
    new_.clear();
    new_faces_.clear();
    for (const auto f : mesh_.vf_range(ci.v0)) {
      if (f != ci.fl && f != ci.fr) {
        new_.push_back(corners(ci, f, true));
        new_faces_.push_back(f);
      }
    }
  }

  // Whether the collapse leaves the surface where it was: v0 and its ring in
  // one plane (exactly), and every triangle round v0 and every one that
  // replaces them turning the same way in it. Both are fans over v0's link,
  // and over any point of the plane a fan has as many triangles, counted
  // with their turn, as the link winds round the point; with every turn the
  // same, the new triangles cover exactly the points the old ones covered,
  // which lay as near the input as strays() asked (Menger cubes and
  // space-filling curves of boxes: flat faces in pieces, strays() half of
  // their decimation). Nor can a new triangle meet a face outside the fan
  // that no old one met: the old ones met such a face only at the link's
  // vertices and edges (the mesh has no intersecting faces), and a new
  // triangle touches the link only at its own corners and sides (turning
  // the same way, the new triangles sweep round v1 in strictly increasing
  // angles, so no side from v1 passes through a link vertex); the
  // intersection guard is not asked. A nearly flat star (normals apart in
  // doubles) is not asked exactly.
  // @pre take_new_triangles was called for the collapse.
  bool stays_in_plane(const CollapseInfo& ci) {
    // Only a closed fan covers the region its link bounds (a half's
    // boundary vertices are locked, so this holds there too; checked,
    // not assumed).
    if (mesh_.is_boundary(ci.v0)) return false;
    const Mesh::Normal n = mesh_.normal(*mesh_.vf_begin(ci.v0));
    for (const auto f : mesh_.vf_range(ci.v0)) {
      if (OpenMesh::dot(mesh_.normal(f), n) < kFlatCosine) return false;
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k) {
      if (std::fabs(n[k]) > std::fabs(n[axis])) axis = k;
    }
    const auto turn = [&](const Corners& t) {
      return projected_orientation(t[0], t[1], t[2], axis);
    };
    const Corners first = corners(ci, *mesh_.vf_begin(ci.v0), false);
    const int side = turn(first);
    if (side == 0) return false;
    for (const auto v : mesh_.vv_range(ci.v0)) {
      const Mesh::Point& q = mesh_.point(v);
      if (orientation_3(first[0], first[1], first[2], {q[0], q[1], q[2]}) != 0)
        return false;
    }
    for (const auto f : mesh_.vf_range(ci.v0)) {
      if (turn(corners(ci, f, false)) != side) return false;
    }
    return std::all_of(new_.begin(), new_.end(),
                       [&](const Corners& t) { return turn(t) == side; });
  }

  // True when a point sampled on a new triangle lies farther than the
  // tolerance from the input surface. The input pieces bound how far the
  // input lies from the result, not the other way: a long new triangle can
  // bridge a crease (0.10 mm for 0.05 mm on the bush before this test). The
  // grid is the one sampled_distance measures the result on (at least 2 steps a
  // side), so that every point it measures on a triangle of the result was
  // tested when the triangle was made. With a grid four tolerances apart (at
  // most 8 steps), a 1.3 mm triangle of the bush at n = 7 bulged 0.071 mm from
  // the input between samples, and the whole decimation ran again aiming
  // lower.
  // @pre take_new_triangles was called for the collapse.
  bool strays(SurfaceDistance& input, double tolerance_mm) {
    const auto covered = [&](const glm::dvec3& a, const glm::dvec3& b,
                             const glm::dvec3& c) {
      return input.covers(a, b, c, tolerance_mm) ||
             input.covers_in_two(a, b, c, tolerance_mm);
    };
    const auto near = [&](const glm::dvec3& p) {
      return input.within(p, tolerance_mm);
    };
    return !std::all_of(new_.begin(), new_.end(), [&](const Corners& t) {
      return visit_samples(t, sample_steps(t, 2.0), false, covered, near);
    });
  }

  // Queues the vertex's best collapse that is legal, within the modules'
  // bounds and not refused by the guard since its neighbourhood changed.
  // The priority module alone ranks the candidates; the binary modules and
  // the topological test (OpenMesh's is_collapse_ok, which walks both
  // one-rings) are asked in that order only until one passes, which is
  // mostly the first: asked of every halfedge, they were a third of the
  // decimation of the bush at n = 7. The choice is the same: the legal
  // candidate of least priority, the first of equals round the vertex.
  void enqueue(Mesh::VertexHandle v) {
    const std::uint32_t version = ++mesh_.property(version_, v);
    candidates_.clear();
    for (const auto h : mesh_.voh_range(v)) {
      if (mesh_.property(refused_, h)) continue;
      const float priority =
          priority_->collapse_priority(CollapseInfo(mesh_, h));
      if (priority >= 0.0F) candidates_.emplace_back(priority, h);
    }
    while (!candidates_.empty()) {
      const auto best = std::min_element(
          candidates_.begin(), candidates_.end(),
          [](const auto& a, const auto& b) { return a.first < b.first; });
      const CollapseInfo ci(mesh_, best->second);
      if (is_collapse_legal(ci) && collapse_priority(ci) >= 0.0F) {
        queue_.emplace(best->first, v.idx(), version, best->second.idx());
        return;
      }
      candidates_.erase(best);
    }
  }

  using Entry = std::tuple<float, int, std::uint32_t, int>;
  Mesh& mesh_;
  OpenMesh::HPropHandleT<bool> refused_;
  OpenMesh::VPropHandleT<std::uint32_t> version_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue_;
  OpenMesh::Decimater::ModBaseT<Mesh>* priority_ = nullptr;
  std::vector<std::pair<float, Mesh::HalfedgeHandle>> candidates_;
  std::vector<Corners> new_;  // the collapse being tested, v0 moved to p1
  std::vector<Mesh::FaceHandle> new_faces_;  // their faces
};

Mesh to_openmesh(const TriangleMesh& in) {
  Mesh mesh;
  std::vector<Mesh::VertexHandle> vertices;
  vertices.reserve(in.vertices.size());
  for (const glm::dvec3& p : in.vertices) {
    vertices.push_back(mesh.add_vertex(Mesh::Point(p.x, p.y, p.z)));
  }
  for (const auto& t : in.triangles) {
    if (!mesh.add_face(vertices[t[0]], vertices[t[1]], vertices[t[2]])
             .is_valid()) {
      throw GeometryError("cannot decimate: the mesh is not a 2-manifold");
    }
  }
  return mesh;
}

TriangleMesh from_openmesh(Mesh& mesh) {
  mesh.garbage_collection();
  TriangleMesh out;
  out.vertices.reserve(mesh.n_vertices());
  for (const auto v : mesh.vertices()) {
    const Mesh::Point& p = mesh.point(v);
    out.vertices.emplace_back(p[0], p[1], p[2]);
  }
  out.triangles.reserve(mesh.n_faces());
  for (const auto f : mesh.faces()) {
    std::array<std::uint32_t, 3> t{};
    int k = 0;
    for (const auto v : mesh.fv_range(f)) {
      t[k++] = static_cast<std::uint32_t>(v.idx());
    }
    out.triangles.push_back(t);
  }
  remove_unused_vertices(out);
  return out;
}

// One decimation run. With `bounded` false the quadric error is unbounded,
// to reach a triangle cap.
std::size_t run(Mesh& mesh, SurfaceDistance& input_surface,
                InputPieces& samples, const DecimateOptions& options,
                double aim, bool bounded, std::size_t faces,
                ModIntersectionGuardT<Mesh>* guard,
                const std::function<void(std::size_t)>& tell) {
  using namespace OpenMesh::Decimater;
  GuardedDecimater decimater(mesh);
  ModPlaneQuadricT<Mesh>::Handle quadric;
  ModNormalFlippingT<Mesh>::Handle normal_flipping;
  ModAspectRatioT<Mesh>::Handle aspect_ratio;
  decimater.add(quadric);
  decimater.add(normal_flipping);
  decimater.add(aspect_ratio);
  // The vetoes test at sample points, so they aim a little inside the
  // tolerance; the measured Hausdorff distance is what the report states.
  const double aim_mm = aim * options.tolerance_mm;
  if (bounded) decimater.module(quadric).set_max_error(aim_mm * aim_mm);
  decimater.module(normal_flipping)
      .set_max_normal_deviation(options.max_normal_deviation_deg);
  decimater.module(aspect_ratio)
      .set_aspect_ratio(static_cast<float>(options.max_aspect_ratio));
  if (!decimater.initialize()) {
    throw GeometryError("cannot set up OpenMesh's decimater");
  }
  decimater.rank_by(decimater.module(quadric));
  if (!bounded) {
    // The samples still follow their faces, refusing nothing.
    return decimater.decimate_to_faces(faces, &samples, nullptr,
                                       std::numeric_limits<double>::infinity(),
                                       guard, tell);
  }
  // The quadric bounds the kept vertex's distance to planes, not how far
  // the input lies from the new triangles (the samples) or they from it
  // (the input surface).
  return decimater.decimate_to_faces(faces, &samples, &input_surface, aim_mm,
                                     guard, tell);
}

// Collapses the edges shorter than `options.min_edge_mm`, shortest first,
// within the same vetoes: CuraEngine merges vertices closer than 0.03 mm and
// then reports overlapping faces, and the union leaves edges of 10⁻⁴ mm
// where parts meet at a shallow angle.
std::size_t collapse_short_edges(Mesh& mesh, SurfaceDistance& input_surface,
                                 InputPieces& samples,
                                 const DecimateOptions& options,
                                 ModIntersectionGuardT<Mesh>* guard) {
  using namespace OpenMesh::Decimater;
  GuardedDecimater decimater(mesh);
  ModEdgeLengthT<Mesh>::Handle edge_length;
  ModNormalFlippingT<Mesh>::Handle normal_flipping;
  decimater.add(edge_length);
  decimater.add(normal_flipping);
  decimater.module(edge_length).set_binary(false);
  // A collapse of a shorter edge than the tolerance moves the surface
  // less than the tolerance.
  decimater.module(edge_length)
      .set_edge_length(std::min(options.min_edge_mm, options.tolerance_mm));
  // Only a fold (a normal turned by 90° or more) is refused here: moving a
  // vertex by less than the edge turns only triangles about that small by
  // much, and the 45° of the main run left 42 edges under 0.03 mm, the
  // shortest 0.6 µm, on ABOP fig. 1.26's plant at n = 5 (30, the shortest
  // 6 µm, with this). The intersection guard and the measured deviation
  // still hold every collapse.
  decimater.module(normal_flipping).set_max_normal_deviation(85.0);
  if (!decimater.initialize()) {
    throw GeometryError("cannot set up OpenMesh's decimater");
  }
  decimater.rank_by(decimater.module(edge_length));
  return decimater.decimate_to_faces(0, &samples, &input_surface,
                                     options.tolerance_mm, guard, {});
}

std::size_t count_short_edges(const TriangleMesh& mesh, double length_mm) {
  std::size_t count = 0;
  for (const auto& t : mesh.triangles) {
    for (std::size_t k = 0; k < 3; ++k) {
      // Each edge once: from its smaller vertex index.
      if (t[k] < t[(k + 1) % 3] &&
          glm::distance(mesh.vertices[t[k]], mesh.vertices[t[(k + 1) % 3]]) <
              length_mm) {
        ++count;
      }
    }
  }
  return count;
}

// A triangle by its corners (triangle_key): collapses move no vertex, so a
// triangle the decimation left alone has the same key in the input and the
// output.
TriangleKey key_of(const TriangleMesh& mesh,
                   const std::array<std::uint32_t, 3>& t) {
  return triangle_key(mesh.vertices[t[0]], mesh.vertices[t[1]],
                      mesh.vertices[t[2]]);
}

using TriangleSet = std::unordered_set<TriangleKey, boost::hash<TriangleKey>>;

TriangleSet triangle_set(const TriangleMesh& mesh) {
  TriangleSet set;
  set.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) set.insert(key_of(mesh, t));
  return set;
}

// The largest distance from points of `from` to `to`, sampled at every
// vertex and on a barycentric grid over every triangle about kSampleSpacingMm
// apart (at most 16 steps a side); capped at `limit_mm`. Triangle i is
// left out where skip(i): one that `to` has too lies at distance 0 (on the
// bush at n = 6 that is most of the measuring time saved), or one whose
// samples are known to lie nearer than another measurement. The triangles are
// measured in fixed chunks on oneTBB's threads (each thread with its own
// query state on `to`'s index), and the largest of the chunks' largest
// distances is the answer: a sample is only skipped when proven no farther
// than a distance its chunk measured, so the answer is the same whatever
// the threads (one thread measured the bush's output for 1.5 s).
template <typename Skip>
double sampled_distance(const TriangleMesh& from, const SurfaceDistance& to,
                        double limit_mm, const Skip& skip) {
  constexpr std::size_t kChunk = 4096;
  const std::size_t chunks = (from.triangles.size() + kChunk - 1) / kChunk;
  std::vector<double> worst_of(chunks, 0.0);
  tbb::enumerable_thread_specific<std::unique_ptr<SurfaceDistance>> queriers;
  tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t chunk) {
    std::unique_ptr<SurfaceDistance>& querier = queriers.local();
    if (!querier) querier = std::make_unique<SurfaceDistance>(to.sharing());
    SurfaceDistance& near = *querier;
    // What a chunk proves must not depend on the chunks its thread ran
    // before it (covers_in_two tries the triangles that answered last).
    near.forget_answers();
    double worst = 0.0;
    // Only a point farther than the worst so far can change it: a part of
    // a triangle within that of one triangle of `to` is skipped, and most
    // points find a triangle that near at the first try.
    const auto covered = [&](const glm::dvec3& a, const glm::dvec3& b,
                             const glm::dvec3& c) {
      return worst > 0.0 && (near.covers(a, b, c, worst) ||
                             near.covers_in_two(a, b, c, worst));
    };
    const auto measure = [&](const glm::dvec3& p) {
      if (!near.within(p, worst)) {
        worst = std::max(worst, near.distance(p, limit_mm));
      }
      return true;
    };
    const std::size_t end =
        std::min(from.triangles.size(), (chunk + 1) * kChunk);
    for (std::size_t i = chunk * kChunk; i < end; ++i) {
      const auto& t = from.triangles[i];
      if (skip(i)) continue;
      const Corners corner{from.vertices[t[0]], from.vertices[t[1]],
                           from.vertices[t[2]]};
      visit_samples(corner, sample_steps(corner, 1.0), true, covered, measure);
    }
    worst_of[chunk] = worst;
  });
  return worst_of.empty() ? 0.0
                          : *std::max_element(worst_of.begin(), worst_of.end());
}

// Holds the status flags and normals the decimaters use. The decimaters
// request and release the status flags themselves; holding them here keeps
// the deleted marks alive for garbage_collection.
void prepare(Mesh& mesh) {
  mesh.request_vertex_status();
  mesh.request_edge_status();
  mesh.request_face_status();
  mesh.request_face_normals();
  mesh.update_face_normals();
}

std::vector<std::uint32_t> identity(std::size_t count) {
  std::vector<std::uint32_t> out(count);
  std::iota(out.begin(), out.end(), 0U);
  return out;
}

// The guard to pass to the runs: `guard`, indexed, or none if the options
// let collapses intersect.
ModIntersectionGuardT<Mesh>* guarding(ModIntersectionGuardT<Mesh>& guard,
                                      const DecimateOptions& options) {
  if (!options.refuse_intersections) return nullptr;
  guard.initialize();
  return &guard;
}

// One side of a mesh cut in two for decimation on two threads: the
// triangles wholly on that side and those that cross the cut, which both
// halves hold and neither changes (their corners are locked).
struct Half {
  TriangleMesh mesh;
  std::vector<std::uint32_t> input_vertex;  // per vertex of `mesh`
  std::vector<std::uint32_t> input_face;    // per triangle of `mesh`
  std::vector<char> on_cut;                 // per triangle: crosses the cut
  std::vector<char> locked;                 // per vertex: a corner of one
};

// Cuts `input` across its longest side at the median vertex. A collapse
// whose removed vertex is not locked changes only triangles wholly on its
// side, and their new corners stay on that side: strictly below the cut or
// at or above it. So the new triangles of one half cannot meet a triangle of
// the other (a plane parts them), and each half's intersection guard needs
// only its own triangles and those on the cut.
std::array<Half, 2> split_in_halves(const TriangleMesh& input) {
  const Box box = bounds(input);
  const glm::dvec3 size = box.size();
  const int axis =
      size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
  std::vector<double> along;
  along.reserve(input.vertices.size());
  for (const glm::dvec3& p : input.vertices) along.push_back(p[axis]);
  const auto middle =
      along.begin() + static_cast<std::ptrdiff_t>(along.size() / 2);
  std::nth_element(along.begin(), middle, along.end());
  const double cut = *middle;
  const auto side = [&](std::uint32_t v) {
    return input.vertices[v][axis] < cut ? 0 : 1;
  };
  constexpr int kOnCut = 2;
  std::vector<int> kind(input.triangles.size());
  std::vector<char> locked(input.vertices.size(), 0);
  for (std::size_t i = 0; i < input.triangles.size(); ++i) {
    const auto& t = input.triangles[i];
    const int s = side(t[0]);
    if (side(t[1]) == s && side(t[2]) == s) {
      kind[i] = s;
    } else {
      kind[i] = kOnCut;
      for (const std::uint32_t v : t) locked[v] = 1;
    }
  }
  std::array<Half, 2> halves;
  for (int h = 0; h < 2; ++h) {
    Half& half = halves[static_cast<std::size_t>(h)];
    std::vector<std::uint32_t> local(input.vertices.size(),
                                     std::numeric_limits<std::uint32_t>::max());
    for (std::size_t i = 0; i < input.triangles.size(); ++i) {
      if (kind[i] != h && kind[i] != kOnCut) continue;
      std::array<std::uint32_t, 3> t{};
      for (std::size_t c = 0; c < 3; ++c) {
        const std::uint32_t v = input.triangles[i][c];
        if (local[v] == std::numeric_limits<std::uint32_t>::max()) {
          local[v] = static_cast<std::uint32_t>(half.mesh.vertices.size());
          half.mesh.vertices.push_back(input.vertices[v]);
          half.input_vertex.push_back(v);
          half.locked.push_back(locked[v]);
        }
        t[c] = local[v];
      }
      half.mesh.triangles.push_back(t);
      half.input_face.push_back(static_cast<std::uint32_t>(i));
      half.on_cut.push_back(kind[i] == kOnCut ? 1 : 0);
    }
  }
  return halves;
}

// What decimation left of a half: its triangles by input vertex, the input
// pieces each holds, and which cross the cut.
struct DecimatedHalf {
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::vector<InputPiece>> pieces;
  std::vector<char> on_cut;
  std::size_t collapses = 0;
  std::size_t refused = 0;
};

DecimatedHalf decimate_half(const Half& half, const TriangleMesh& input,
                            const SurfaceDistance& input_index,
                            const std::vector<std::uint8_t>& steps,
                            const DecimateOptions& options, double aim,
                            const std::function<void(std::size_t)>& tell) {
  Mesh mesh = to_openmesh(half.mesh);
  prepare(mesh);
  for (const auto v : mesh.vertices()) {
    if (half.locked[static_cast<std::size_t>(v.idx())] != 0) {
      mesh.status(v).set_locked(true);
    }
  }
  InputPieces samples(mesh, input, steps, half.input_vertex,
                      whole_pieces(steps, half.input_face));
  ModIntersectionGuardT<Mesh> guard(mesh);
  ModIntersectionGuardT<Mesh>* const guarded = guarding(guard, options);
  // The input's index is shared; each thread keeps its own query state.
  SurfaceDistance input_surface = input_index.sharing();
  DecimatedHalf out;
  out.collapses =
      run(mesh, input_surface, samples, options, aim, true, 0, guarded, tell);
  out.refused = guard.refused();
  for (const auto f : mesh.faces()) {
    if (mesh.status(f).deleted()) continue;
    std::array<std::uint32_t, 3> t{};
    std::size_t k = 0;
    for (const auto v : mesh.fv_range(f)) t[k++] = samples.input_vertex(v);
    out.triangles.push_back(t);
    out.pieces.push_back(samples.pieces_of(f));
    // A triangle on the cut keeps its face and its corners.
    out.on_cut.push_back(half.on_cut[static_cast<std::size_t>(f.idx())]);
  }
  return out;
}

// The mesh to go on from: the input, or the two halves decimated on their
// own and put together, with the input pieces each face holds and the input
// vertex each vertex is.
struct Start {
  TriangleMesh mesh;
  std::vector<std::uint32_t> input_vertex;
  std::vector<std::vector<InputPiece>> pieces;
  std::size_t collapses = 0;
  std::size_t refused = 0;
};

Start decimate_halves(const TriangleMesh& input,
                      const SurfaceDistance& input_surface,
                      const std::vector<std::uint8_t>& steps,
                      const DecimateOptions& options, double aim,
                      const std::function<void(std::size_t)>& tell) {
  const std::array<Half, 2> halves = split_in_halves(input);
  std::array<DecimatedHalf, 2> done;
  // Only the first half tells the progress (the callback need not be
  // thread-safe); it adds what the second has done so far. A callback that
  // throws (the viewer cancelling a build) stops the second half too, at
  // its next report, rather than after its last collapse; the first
  // exception is the one rethrown.
  std::atomic<std::size_t> second{0};
  std::atomic<bool> stopped{false};
  struct Stopped {};
  tbb::parallel_invoke(
      [&] {
        done[0] = decimate_half(halves[0], input, input_surface, steps, options,
                                aim, [&](std::size_t collapses) {
                                  if (!tell) return;
                                  try {
                                    tell(collapses + second.load());
                                  } catch (...) {
                                    stopped = true;
                                    throw;
                                  }
                                });
      },
      [&] {
        done[1] = decimate_half(halves[1], input, input_surface, steps, options,
                                aim, [&](std::size_t collapses) {
                                  if (stopped) throw Stopped{};
                                  second.store(collapses);
                                });
      });
  // The triangles of the first half, then those of the second but the ones
  // on the cut, which the first already has; the vertices in input order.
  Start start;
  std::vector<std::uint32_t> local(input.vertices.size(),
                                   std::numeric_limits<std::uint32_t>::max());
  for (std::size_t h = 0; h < 2; ++h) {
    for (std::size_t i = 0; i < done[h].triangles.size(); ++i) {
      if (h == 1 && done[h].on_cut[i] != 0) continue;
      for (const std::uint32_t v : done[h].triangles[i]) local[v] = 0;
    }
  }
  for (std::uint32_t v = 0; v < local.size(); ++v) {
    if (local[v] == std::numeric_limits<std::uint32_t>::max()) continue;
    local[v] = static_cast<std::uint32_t>(start.mesh.vertices.size());
    start.mesh.vertices.push_back(input.vertices[v]);
    start.input_vertex.push_back(v);
  }
  for (std::size_t h = 0; h < 2; ++h) {
    for (std::size_t i = 0; i < done[h].triangles.size(); ++i) {
      if (h == 1 && done[h].on_cut[i] != 0) continue;
      const auto& t = done[h].triangles[i];
      start.mesh.triangles.push_back({local[t[0]], local[t[1]], local[t[2]]});
      start.pieces.push_back(std::move(done[h].pieces[i]));
    }
    start.collapses += done[h].collapses;
    start.refused += done[h].refused;
  }
  return start;
}

// One decimation whose vetoes aim at `aim` times the tolerance.
// Runs options.alongside on `result`, if set; its exception, if it throws
// one, goes to `thrown` for decimate to rethrow as it stands (not taken for
// a mesh that cannot be decimated).
void run_alongside(const DecimateOptions& options, const TriangleMesh& result,
                   std::exception_ptr& thrown) {
  if (!options.alongside) return;
  try {
    options.alongside(result);
  } catch (...) {
    thrown = std::current_exception();
  }
}

Decimated decimate_once(const TriangleMesh& input,
                        const DecimateOptions& options, double aim,
                        std::exception_ptr& alongside_thrown) {
  Decimated out;
  DecimateStats& stats = out.stats;
  stats.triangles_before = input.triangles.size();
  // Halfedge collapses remove two triangles each; about as many collapses
  // as a third of the triangles is what a tube model allows at 0.05 mm.
  const double expected = std::max(1.0, 0.35 * double(input.triangles.size()));
  std::size_t done = 0;
  const std::function<void(std::size_t)> tell = [&](std::size_t collapses) {
    if (options.progress) {
      options.progress(std::min(1.0, double(done + collapses) / expected));
    }
  };
  const std::vector<std::uint8_t> steps = input_steps(input);
  // A large mesh is decimated in two halves at once, then as a whole for
  // what is left; a cap on the triangles is reached on the whole mesh.
  const bool halved = !options.max_triangles &&
                      input.triangles.size() >= options.halve_from_triangles;
  SurfaceDistance input_surface(input, options.tolerance_mm);
  Start start;
  if (halved) {
    start = decimate_halves(input, input_surface, steps, options, aim, tell);
  }
  const TriangleMesh& from = halved ? start.mesh : input;
  Mesh mesh = to_openmesh(from);
  prepare(mesh);
  InputPieces samples(
      mesh, input, steps,
      halved ? start.input_vertex : identity(input.vertices.size()),
      halved ? std::move(start.pieces)
             : whole_pieces(steps, identity(input.triangles.size())));
  ModIntersectionGuardT<Mesh> guard(mesh);
  ModIntersectionGuardT<Mesh>* const guarded = guarding(guard, options);
  done = start.collapses;
  done += run(mesh, input_surface, samples, options, aim, true,
              options.max_triangles.value_or(0), guarded, tell);
  std::size_t faces = input.triangles.size() - 2 * done;
  if (options.max_triangles && faces > *options.max_triangles) {
    // OpenMesh's modules initialise over every face, deleted ones too.
    mesh.garbage_collection();
    if (guarded != nullptr) guard.initialize();
    done += run(mesh, input_surface, samples, options, aim, false,
                *options.max_triangles, guarded, tell);
    faces = input.triangles.size() - 2 * done;
    stats.reached_max_triangles = faces <= *options.max_triangles;
    stats.beyond_tolerance_for_cap = true;
  }
  if (options.min_edge_mm > 0.0) {
    mesh.garbage_collection();
    if (guarded != nullptr) guard.initialize();
    done +=
        collapse_short_edges(mesh, input_surface, samples, options, guarded);
  }
  stats.collapses = done;
  stats.refused_intersections = start.refused + guard.refused();
  const std::vector<float> farthest =
      options.measure_deviation ? samples.farthest() : std::vector<float>{};
  out.mesh = from_openmesh(mesh);
  stats.short_edges_left = count_short_edges(out.mesh, options.min_edge_mm);
  stats.triangles_after = out.mesh.triangles.size();
  if (options.measure_deviation && !out.mesh.triangles.empty()) {
    // Both ways: the input from the output and the output from the input.
    // No point lies farther than the diagonal of both meshes' box, so the
    // search is never cut short of the true distance.
    Box box = bounds(input);
    const Box other = bounds(out.mesh);
    box.min = glm::min(box.min, other.min);
    box.max = glm::max(box.max, other.max);
    const double limit_mm = 2.0 * glm::length(box.size()) + 1.0;
    // The output from the input first, beside the caller's check of the
    // result, as tasks on oneTBB's threads. Then the input from the output,
    // only where it could exceed that: the pieces bound how far each input
    // triangle's samples lie from the face that holds them, and a triangle
    // whose bound is below the distance already measured cannot change the
    // maximum, so the answer is the one measuring every triangle gives (the
    // bush at n = 7: 0.9 s of measuring, most of it on triangles whose
    // samples lie well within). The margin covers the rounding of a
    // distance computed from a face's corners in another order.
    TriangleSet kept_in_output;
    double output_from_input = 0.0;
    tbb::parallel_invoke(
        [&] { kept_in_output = triangle_set(out.mesh); },
        [&] {
          const TriangleSet kept_from_input = triangle_set(input);
          output_from_input = sampled_distance(
              out.mesh, input_surface, limit_mm, [&](std::size_t i) {
                return kept_from_input.contains(
                    key_of(out.mesh, out.mesh.triangles[i]));
              });
        },
        [&] { run_alongside(options, out.mesh, alongside_thrown); });
    constexpr double kMargin = 1.0 - 1e-9;
    const double known_mm = output_from_input * kMargin;
    SurfaceDistance output_surface(out.mesh, options.tolerance_mm);
    const double input_from_output =
        sampled_distance(input, output_surface, limit_mm, [&](std::size_t i) {
          return double(farthest[i]) < known_mm ||
                 kept_in_output.contains(key_of(input, input.triangles[i]));
        });
    stats.max_deviation_mm = std::max(input_from_output, output_from_input);
  } else {
    run_alongside(options, out.mesh, alongside_thrown);
  }
  return out;
}

}  // namespace

Decimated decimate(const TriangleMesh& input, const DecimateOptions& options) {
  if (!(options.tolerance_mm > 0.0)) {
    throw GeometryError("the decimation tolerance must be positive");
  }
  // The vetoes test at sample points, and the surface can stray a little
  // past them between samples: where the deviation measured afterwards
  // exceeds the tolerance, decimation starts again from the input, aiming
  // lower in proportion (ABOP fig. 1.24e: 0.054 mm for 0.05 mm at the
  // first aim).
  double aim = options.aim;
  Decimated out;
  for (int attempt = 1;; ++attempt) {
    // A mesh OpenMesh cannot take (GeometryError), or an exact test that
    // CGAL refuses (its preconditions throw logic errors), leaves the mesh
    // as it was: the build then checks and writes it undecimated. Anything
    // else, such as a progress callback's own exception or the caller's
    // check's (`alongside`), goes on.
    std::exception_ptr alongside_thrown;
    try {
      out = decimate_once(input, options, aim, alongside_thrown);
    } catch (const GeometryError& e) {
      return Decimated{.mesh = input, .refused = e.what()};
    } catch (const std::logic_error& e) {
      return Decimated{.mesh = input, .refused = e.what()};
    }
    if (alongside_thrown) std::rethrow_exception(alongside_thrown);
    out.stats.attempts = attempt;
    out.stats.tolerance_mm = options.tolerance_mm;
    const double deviation = out.stats.max_deviation_mm;
    out.stats.within_tolerance = deviation <= options.tolerance_mm;
    if (out.stats.within_tolerance || !options.measure_deviation ||
        out.stats.beyond_tolerance_for_cap || attempt >= kAttempts) {
      break;
    }
    aim *= kRetreat * options.tolerance_mm / deviation;
  }
  if (options.progress) options.progress(1.0);
  return out;
}

}  // namespace lsolid
