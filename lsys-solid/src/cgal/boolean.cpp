// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The union of many closed parts with CGAL 5.5's corefinement
// (PMP::corefine_and_compute_union) over Epeck. Measured on a 2-core machine
// of this kind (docs/design.md, "Union"): chained unions with inexact
// constructions self-intersect; a balanced pairing in Z-order is ten times
// faster than a sequential fold; pairs with disjoint boxes need no boolean
// (Manifold's BatchUnion does the same). CGAL's preconditions are on, as
// exceptions, in every CGAL translation unit (lsys-solid/CMakeLists.txt).
#include "kernel.hpp"

#include "lsolid/boolean.hpp"

#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/box_intersection_d.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>

#include "cgal/union/exact_union.hpp"
#include "conversion.hpp"
#include "golden.hpp"
#include "lsolid/errors.hpp"
#include "lsolid/rounding.hpp"
#include "settled_rounding.hpp"
#include "triangle_pair.hpp"

namespace lsolid {
namespace {

constexpr double kPerturbationMm = 1e-5;
// The direction of that shift: along no axis or diagonal, so that it moves
// off the coincidences that lattice-like models make: (1, φ', 1 − φ') with
// the golden section φ' = kGolden to three digits, 0.618 (the digits every
// union that needed a retry was built and checked with).
constexpr double kShiftGolden =
    static_cast<int>(kGolden * 1000.0 + 0.5) / 1000.0;
constexpr std::array<double, 3> kShift{1.0, kShiftGolden, 1.0 - kShiftGolden};
constexpr int kAttempts = 3;
// The exact engine's shift, at least this and less than twice as far: small
// enough to be far below what any output format keeps (a float's step at
// 100 mm is 6·10⁻⁶ mm), large enough to be a million steps of a double
// there, so the coincidence is gone for sure.
constexpr double kExactShiftMm = 1e-8;
// How far the exact engine grows an operand whose faces touch the other's,
// in units in the last place of its largest coordinate (at least this and
// less than twice as far): 1.5·10⁻¹¹ to 3·10⁻¹¹ mm at 100 mm, a thousand steps
// of a double, so the faces that touched overlap for sure, while the volume
// changes by less than 10⁻⁹ of a tube's (its surface times the distance).
constexpr double kGrowthUlps = 1024.0;
// A union where coplanar faces face the same way is grown only if there are
// no more pairs of them than one in this many of the smaller operand's
// faces (see merge).
constexpr double kFewAlikeShare = 100.0;
// A vertex is moved along a direction that leaves each of its faces at
// least this much (the cosine of about 84°), and the whole grown region
// along kShift by kGrowthShift of the distance: so every face moves
// outward, off the plane it touched, and no vertex stays on a plane of the
// other operand's (a tube's ring, moved outward, stays in the plane of the
// neighbour's end cap at that ring; the shift moves it off).
constexpr double kGrowthMinCosine = 0.1;
constexpr double kGrowthShift = 0.05;
// Rounds of putting back the corners of faces that a growth made meet.
constexpr int kGrowthRounds = 8;
constexpr double kMendVolumeSlack = 1e-6;

CGAL::Bbox_3 box_of(const Box& b) {
  constexpr double kMargin = 1e-6;  // touching parts must be unioned
  return {b.min.x - kMargin, b.min.y - kMargin, b.min.z - kMargin,
          b.max.x + kMargin, b.max.y + kMargin, b.max.z + kMargin};
}

// Some parts united. With the exact engine a group holds double
// coordinates (`plain`); with the corefinement, and after a corefinement
// whose new points could not be rounded, exact points (`exact`).
struct Group {
  TriangleMesh plain;
  std::optional<ExactMesh> exact;
  CGAL::Bbox_3 box;
  std::vector<std::size_t> parts;
  // Holds the steps a growth left where faces touched (grown_mesh): what
  // grows next had better be another operand.
  bool grown = false;

  std::size_t faces() const {
    return exact ? exact->number_of_faces() : plain.triangles.size();
  }
  ExactMesh& exact_mesh() {
    if (!exact) {
      exact = surface_mesh_or_throw<ExactMesh>(plain, "unite");
      plain = {};
    }
    return *exact;
  }
  void join(Group& other) {
    if (!exact && !other.exact) {
      append(plain, other.plain);
    } else {
      exact_mesh().join(other.exact_mesh());
    }
    box += other.box;
    parts.insert(parts.end(), other.parts.begin(), other.parts.end());
    grown = grown || other.grown;
  }
};

// Interleaves the bits of three 10-bit coordinates (a Morton code).
std::uint32_t morton(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  const auto spread = [](std::uint32_t v) {
    v = (v | (v << 16U)) & 0x030000FFU;
    v = (v | (v << 8U)) & 0x0300F00FU;
    v = (v | (v << 4U)) & 0x030C30C3U;
    v = (v | (v << 2U)) & 0x09249249U;
    return v;
  };
  return spread(x) | (spread(y) << 1U) | (spread(z) << 2U);
}

// Whether a mesh whose new points were just rounded is still free of
// degenerate and intersecting faces near them (`near_new`: the faces that
// touch a new point); only faces whose boxes meet those can have changed.
bool valid_near(const InexactMesh& rounded,
                const std::vector<InexactMesh::Face_index>& near_new) {
  using Face = InexactMesh::Face_index;
  for (const Face f : near_new)
    if (PMP::is_degenerate_triangle_face(f, rounded)) return false;
  using FaceBox = CGAL::Box_intersection_d::Box_with_info_d<double, 3, Face>;
  std::vector<FaceBox> changed_boxes;
  std::vector<FaceBox> all_boxes;
  for (const Face f : near_new)
    changed_boxes.emplace_back(PMP::face_bbox(f, rounded), f);
  for (const Face f : rounded.faces())
    all_boxes.emplace_back(PMP::face_bbox(f, rounded), f);
  std::set<Face> range(near_new.begin(), near_new.end());
  CGAL::box_intersection_d(changed_boxes.begin(), changed_boxes.end(),
                           all_boxes.begin(), all_boxes.end(),
                           [&](const FaceBox&, const FaceBox& other) {
                             range.insert(other.info());
                           });
  return !PMP::does_self_intersect(range, rounded);
}

// Whether the point's coordinates are not all doubles (a point the union
// constructed, whose approximation is an interval).
bool is_new_point(const Exact::Point_3& p) {
  const auto& a = CGAL::approx(p);
  return !a.x().is_point() || !a.y().is_point() || !a.z().is_point();
}

bool has_new_points(const ExactMesh& mesh) {
  const auto vertices = mesh.vertices();
  return std::any_of(vertices.begin(), vertices.end(),
                     [&](auto v) { return is_new_point(mesh.point(v)); });
}

// The vertices a union created are lazy exact points whose exact values
// (rationals) grow with every level of the reduction; most of the union's
// time went into GMP for them. Where rounding them to doubles provably keeps
// the mesh valid (no face near them becomes degenerate or intersecting,
// tested with exact predicates on the rounded coordinates), they are
// rounded, and the next union starts from doubles again. Where it would not,
// the exact points stay. Returns true if the points were rounded.
bool round_new_points(ExactMesh& mesh) {
  using Face = InexactMesh::Face_index;
  std::vector<bool> is_new(mesh.number_of_vertices(), false);
  bool any = false;
  for (const auto v : mesh.vertices()) {
    if (is_new_point(mesh.point(v))) {
      is_new[static_cast<std::size_t>(v)] = true;
      any = true;
    }
  }
  if (!any) return false;
  InexactMesh rounded;
  rounded.reserve(mesh.number_of_vertices(), mesh.number_of_edges(),
                  mesh.number_of_faces());
  for (const auto v : mesh.vertices()) {
    const Exact::Point_3& p = mesh.point(v);
    rounded.add_vertex(Inexact::Point_3(CGAL::to_double(p.x()),
                                        CGAL::to_double(p.y()),
                                        CGAL::to_double(p.z())));
  }
  std::vector<Face> near_new;
  for (const auto f : mesh.faces()) {
    std::array<InexactMesh::Vertex_index, 3> corners;
    std::size_t k = 0;
    bool touches_new = false;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      corners[k++] = InexactMesh::Vertex_index(static_cast<std::uint32_t>(v));
      touches_new = touches_new || is_new[static_cast<std::size_t>(v)];
    }
    const Face g = rounded.add_face(corners[0], corners[1], corners[2]);
    if (g == InexactMesh::null_face()) return false;
    if (touches_new) near_new.push_back(g);
  }
  if (!valid_near(rounded, near_new)) return false;
  for (const auto v : mesh.vertices()) {
    if (!is_new[static_cast<std::size_t>(v)]) continue;
    const Inexact::Point_3& p =
        rounded.point(InexactMesh::Vertex_index(static_cast<std::uint32_t>(v)));
    mesh.point(v) = Exact::Point_3(p.x(), p.y(), p.z());
  }
  return true;
}

// Where some new points had to stay exact, the whole union is rounded to
// doubles and mended as the final mesh is (round_and_repair: slivers
// collapsed or flipped, intersecting faces rebuilt), so that the next union
// starts from doubles and no rational grows across unions; dense models
// (ABOP fig. 1.24b) spent most of their time in GMP otherwise. Kept only
// if the result is a closed, self-intersection-free surface.
std::optional<TriangleMesh> mended(const TriangleMesh& rounded,
                                   const std::vector<char>& settled = {}) {
  Rounded repaired =
      round_and_repair(rounded,
                       {.precision = {.kind = Precision::Kind::Double},
                        .retry_keeping_slivers = false},
                       settled);
  TriangleMesh& out = repaired.mesh;
  const std::optional<InexactMesh> check = to_surface_mesh<InexactMesh>(out);
  // A clean repair was last tested as it is returned: no face pair meets.
  if (!check || check->number_of_faces() == 0 || !CGAL::is_closed(*check) ||
      !CGAL::is_valid_polygon_mesh(*check) ||
      (!repaired.clean && PMP::does_self_intersect(*check))) {
    return std::nullopt;
  }
  // Rebuilding intersecting faces can delete whole thin pieces (leaf plates
  // that met face on face lost four fifths of their volume here): a mend
  // that changes the volume more than rounding can is refused.
  const double before = signed_volume(rounded);
  if (std::fabs(signed_volume(out) - before) >
      kMendVolumeSlack * std::fabs(before)) {
    return std::nullopt;
  }
  return std::move(out);
}

// The faces of an exact union that no crossing cut (every corner an
// operand's vertex): they meet no other such face (the operands are free
// of self-intersections, and faces of the two that met would have been
// cut), and rounding the new points leaves them where they are.
std::vector<char> uncut_faces(const exact_union::PairUnion& u) {
  std::vector<char> out(u.mesh.triangles.size(), 0);
  for (std::uint32_t f = 0; f < out.size(); ++f) {
    out[f] = exact_union::has_new_corner(u, f) ? 0 : 1;
  }
  return out;
}

bool round_and_mend(ExactMesh& mesh) {
  const std::optional<TriangleMesh> out = mended(to_triangle_mesh(mesh));
  if (!out) return false;
  mesh = surface_mesh_or_throw<ExactMesh>(*out, "unite");
  return true;
}

// The mesh moved by `distance_mm` along kShift, in doubles.
TriangleMesh shifted_mesh(TriangleMesh mesh, double distance_mm) {
  const glm::dvec3 by(distance_mm * kShift[0], distance_mm * kShift[1],
                      distance_mm * kShift[2]);
  for (glm::dvec3& p : mesh.vertices) p += by;
  return mesh;
}

// The mesh grown by about `distance_mm` where its faces meet `near` (the
// other operand's box): each of their corners moved along a direction that
// leaves every face around it (kGrowthMinCosine), so that the faces move
// outward, off any face of the other operand they lay on, and all of them along
// kShift by kGrowthShift of the distance. The direction starts as the mean
// of the faces' unit normals weighted by their angle at the vertex (the
// pseudo-normal), then is turned towards the face it leaves least, a few
// times (a perceptron's steps), where a crease of a union makes the mean lean
// too far one way; a vertex for which that finds no direction (a saddle whose
// faces face every way) is only shifted: a face touching the other operand
// with such corners alone may still touch it (the union then says so again)
// or leave it by 10⁻¹³ mm, which the union's checks and rounding then see
// (kept in place instead, such corners left the touching Hilbert curve's
// largest union to the corefinement). Nothing if the grown mesh intersects
// itself: features closer than the distance, such as the steps an earlier
// growth left.
std::optional<TriangleMesh> grown_mesh(TriangleMesh mesh, double distance_mm,
                                       const CGAL::Bbox_3& near) {
  constexpr int kTurns = 16;
  const glm::dvec3 shift =
      distance_mm * kGrowthShift *
      glm::normalize(glm::dvec3(kShift[0], kShift[1], kShift[2]));
  const std::size_t nv = mesh.vertices.size();
  const std::vector<glm::dvec3> original = mesh.vertices;
  std::vector<char> moves(nv, 0);
  for (const auto& t : mesh.triangles) {
    CGAL::Bbox_3 box;
    for (const std::uint32_t v : t) {
      const glm::dvec3& p = mesh.vertices[v];
      box += CGAL::Bbox_3(p.x, p.y, p.z, p.x, p.y, p.z);
    }
    if (!CGAL::do_overlap(box, near)) continue;
    for (const std::uint32_t v : t) moves[v] = 1;
  }
  std::vector<glm::dvec3> unit_normal(mesh.triangles.size(), glm::dvec3(0.0));
  std::vector<glm::dvec3> direction(nv, glm::dvec3(0.0));
  std::vector<std::uint32_t> first(nv + 1, 0);  // faces around each vertex
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    if (!moves[t[0]] && !moves[t[1]] && !moves[t[2]]) continue;
    const glm::dvec3 n = glm::cross(mesh.vertices[t[1]] - mesh.vertices[t[0]],
                                    mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    const double length = glm::length(n);
    if (!(length > 0.0)) continue;  // too small for doubles: no constraint
    unit_normal[f] = n / length;
    for (int i = 0; i < 3; ++i) {
      const glm::dvec3& p = mesh.vertices[t[i]];
      const glm::dvec3 e0 = mesh.vertices[t[(i + 1) % 3]] - p;
      const glm::dvec3 e1 = mesh.vertices[t[(i + 2) % 3]] - p;
      const double angle =
          std::atan2(glm::length(glm::cross(e0, e1)), glm::dot(e0, e1));
      direction[t[i]] += angle * unit_normal[f];
      ++first[t[i] + 1];
    }
  }
  for (std::size_t v = 0; v < nv; ++v) first[v + 1] += first[v];
  std::vector<std::uint32_t> around(first[nv]);
  {
    std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
      if (unit_normal[f] == glm::dvec3(0.0)) continue;
      for (const std::uint32_t v : mesh.triangles[f])
        around[next[v]++] = static_cast<std::uint32_t>(f);
    }
  }
  for (std::size_t v = 0; v < nv; ++v) {
    if (!moves[v]) continue;
    glm::dvec3 d = direction[v];
    bool leaves_all = false;
    for (int turn = 0; turn <= kTurns && !leaves_all; ++turn) {
      const double length = glm::length(d);
      if (!(length > 0.0)) break;
      d /= length;
      double least = 2.0;
      glm::dvec3 worst(0.0);
      for (std::uint32_t k = first[v]; k < first[v + 1]; ++k) {
        const double c = glm::dot(d, unit_normal[around[k]]);
        if (c < least) {
          least = c;
          worst = unit_normal[around[k]];
        }
      }
      leaves_all = least >= kGrowthMinCosine;
      if (!leaves_all) d += (2.0 * kGrowthMinCosine - least) * worst;
    }
    mesh.vertices[v] += leaves_all ? distance_mm * d + shift : shift;
  }
  // Only faces with a moved corner can have come to meet another. Where
  // some did (the steps an earlier growth left, finer than this one), their
  // corners go back where they were, until none meet: at worst the mesh as
  // it was.
  for (int round = 0;; ++round) {
    std::vector<IndexedTriangle> triangles(mesh.triangles.size());
    std::vector<char> settled(mesh.triangles.size(), 1);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
      const auto& t = mesh.triangles[f];
      triangles[f].ids = t;
      for (int i = 0; i < 3; ++i) {
        triangles[f].points[i] = mesh.vertices[t[i]];
        if (moves[t[i]]) settled[f] = 0;
      }
    }
    const std::vector<std::pair<std::uint32_t, std::uint32_t>> meeting =
        intersecting_pairs(triangles, settled);
    if (meeting.empty()) return mesh;
    if (round == kGrowthRounds) return std::nullopt;
    for (const auto& [f, g] : meeting) {
      for (const std::uint32_t face : {f, g}) {
        for (const std::uint32_t v : mesh.triangles[face]) {
          if (!moves[v]) continue;
          moves[v] = 0;
          mesh.vertices[v] = original[v];
        }
      }
    }
  }
}

// kGrowthUlps units in the last place of the mesh's largest coordinate.
double growth_unit_mm(const TriangleMesh& mesh) {
  double largest = 0.0;
  for (const glm::dvec3& p : mesh.vertices) {
    largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  const double ulp =
      std::nextafter(largest, std::numeric_limits<double>::infinity()) -
      largest;
  return kGrowthUlps * ulp;
}

void translate(ExactMesh& mesh, const Exact::Vector_3& by) {
  for (const auto v : mesh.vertices()) mesh.point(v) = mesh.point(v) + by;
}

class Unioner {
 public:
  Unioner(std::vector<Part> parts, std::function<void(double)> progress,
          UnionEngine engine)
      : parts_(std::move(parts)),
        progress_(std::move(progress)),
        engine_(engine) {
    stats_.engine = engine;
  }

  UnionResult run(const std::function<void(double)>& expect) {
    if (parts_.empty())
      throw GeometryError("nothing to unite: there are no parts");
    std::vector<Group> groups = initial_groups();
    if (expect) {
      expect(static_cast<double>(stats_.contacts) * kUnionSecondsPerContact);
    }
    const Group all = reduce(std::move(groups), true);
    stats_.predicates = filters_.orient_2d + filters_.along_edge;
    stats_.filter_failures =
        filters_.orient_2d_exact + filters_.along_edge_exact;
    UnionResult result;
    result.stats = stats_;
    result.mesh = all.exact ? to_triangle_mesh(*all.exact) : all.plain;
    if (progress_) progress_(1.0);
    return result;
  }

 private:
  // Parts whose boxes meet go to different layers; each layer is the
  // concatenation of its parts, a valid operand since they are disjoint.
  // So a union takes in many parts at once, and the number of unions is
  // about the number of layers, not of parts (as Manifold's BatchBoolean
  // batches). Layers are filled greedily in Z-order of the parts' boxes.
  std::vector<Group> initial_groups() {
    std::vector<CGAL::Bbox_3> boxes;
    boxes.reserve(parts_.size());
    for (const Part& part : parts_) boxes.push_back(box_of(bounds(part.mesh)));
    const Box all = bounds(parts_);
    using PartBox = CGAL::Box_intersection_d::Box_with_info_d<
        double, 3, std::size_t, CGAL::Box_intersection_d::ID_EXPLICIT>;
    std::vector<PartBox> part_boxes;
    part_boxes.reserve(parts_.size());
    for (std::size_t i = 0; i < parts_.size(); ++i)
      part_boxes.emplace_back(boxes[i], i);
    std::vector<std::vector<std::size_t>> neighbours(parts_.size());
    CGAL::box_self_intersection_d(part_boxes.begin(), part_boxes.end(),
                                  [&](const PartBox& a, const PartBox& b) {
                                    neighbours[a.info()].push_back(b.info());
                                    neighbours[b.info()].push_back(a.info());
                                  });
    count_contacts(boxes, neighbours);
    const glm::dvec3 span = glm::max(all.size(), glm::dvec3(1e-9));
    std::vector<std::pair<std::uint32_t, std::size_t>> order;
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      const CGAL::Bbox_3& b = boxes[i];
      const glm::dvec3 centre((b.xmin() + b.xmax()) / 2,
                              (b.ymin() + b.ymax()) / 2,
                              (b.zmin() + b.zmax()) / 2);
      const glm::dvec3 unit = (centre - all.min) / span * 1023.0;
      order.emplace_back(morton(static_cast<std::uint32_t>(unit.x),
                                static_cast<std::uint32_t>(unit.y),
                                static_cast<std::uint32_t>(unit.z)),
                         i);
    }
    std::sort(order.begin(), order.end());
    std::vector<int> layer(parts_.size(), -1);
    std::vector<Group> groups;
    for (const auto& [code, i] : order) {
      (void)code;
      check_part(i);
      std::vector<bool> taken(groups.size(), false);
      for (const std::size_t n : neighbours[i]) {
        if (layer[n] >= 0) taken[static_cast<std::size_t>(layer[n])] = true;
      }
      const auto free = static_cast<std::size_t>(
          std::find(taken.begin(), taken.end(), false) - taken.begin());
      layer[i] = static_cast<int>(free);
      Group part = single(i, boxes[i]);
      if (free == groups.size()) {
        groups.push_back(std::move(part));
      } else {
        groups[free].join(part);
        ++stats_.concatenations;
      }
    }
    return groups;
  }

  // Counts, for each part, its triangles whose box meets the box of a
  // neighbour (once per neighbour): a cheap measure, before any boolean, of
  // how much corefinement work the union holds.
  void count_contacts(const std::vector<CGAL::Bbox_3>& boxes,
                      const std::vector<std::vector<std::size_t>>& neighbours) {
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      if (neighbours[i].empty()) continue;
      const TriangleMesh& mesh = parts_[i].mesh;
      for (const auto& t : mesh.triangles) {
        const glm::dvec3& a = mesh.vertices[t[0]];
        const glm::dvec3& b = mesh.vertices[t[1]];
        const glm::dvec3& c = mesh.vertices[t[2]];
        const glm::dvec3 lo = glm::min(glm::min(a, b), c);
        const glm::dvec3 hi = glm::max(glm::max(a, b), c);
        const CGAL::Bbox_3 triangle_box(lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
        for (const std::size_t j : neighbours[i]) {
          if (CGAL::do_overlap(triangle_box, boxes[j])) ++stats_.contacts;
        }
      }
    }
  }

  // Corefinement requires closed operands without self-intersections; a
  // part that is not is a bug of the part builder, reported by name.
  void check_part(std::size_t i) const {
    const std::optional<InexactMesh> mesh =
        to_surface_mesh<InexactMesh>(parts_[i].mesh);
    if (!mesh || mesh->number_of_faces() == 0 || !CGAL::is_closed(*mesh) ||
        PMP::does_self_intersect(*mesh)) {
      throw GeometryError("a part is not a valid closed solid: " +
                          parts_[i].label);
    }
  }

  // A part as a group of its own, in the engine's representation.
  Group single(std::size_t i, const CGAL::Bbox_3& box) const {
    Group g{{}, std::nullopt, box, {i}};
    if (engine_ == UnionEngine::Corefinement) {
      g.exact = surface_mesh_or_throw<ExactMesh>(parts_[i].mesh, "unite");
    } else {
      g.plain = parts_[i].mesh;
    }
    return g;
  }

  // The exact engine's union of two groups of double coordinates; nothing
  // if it met a degeneracy (`degenerate_`) or failed, with the reason in
  // last_failure_. Intermediate results (`round_points`) must stay valid
  // once rounded: else they are mended as the corefinement's are, or given
  // back.
  std::optional<TriangleMesh> exact_union(const Group& a, const Group& b,
                                          bool round_points) {
    exact_union::PairUnion u =
        exact_union::unite_pair(a.plain, b.plain, filters_);
    stats_.crossings += u.counters.crossings;
    stats_.cut_faces += u.counters.cut_faces;
    degenerate_ = u.degenerate;
    transversal_ = u.transversal;
    face_on_face_ = u.face_on_face;
    alike_pairs_ = u.alike_pairs;
    unrounded_ = false;
    if (!u.failure.empty()) {
      last_failure_ = u.failure;
      return std::nullopt;
    }
    if (!round_points) return std::move(u.mesh);
    std::optional<TriangleMesh> out = exact_union::rounding_kept_valid(u)
                                          ? std::move(u.mesh)
                                          : mended(u.mesh, uncut_faces(u));
    if (!out) {
      last_failure_ = "its new points could not be rounded to doubles";
      unrounded_ = true;
      return std::nullopt;
    }
    ++stats_.rounded;
    return out;
  }

  Group merge(Group a, Group b, bool round_points) {
    if (!CGAL::do_overlap(a.box, b.box)) {
      a.join(b);
      ++stats_.concatenations;
      return a;
    }
    if (engine_ == UnionEngine::ExactCrossings && !a.exact && !b.exact) {
      // A degeneracy where faces cross (an edge through an edge where
      // branches mirror each other) is moved off by a tiny shift of the
      // smaller operand along the corefinement's retry direction, 10⁻⁸ mm:
      // faces that cross go on crossing; solids that met only at that point
      // are parted or joined, as the corefinement's own shift does with
      // parts that touch at a point. New points that could not be rounded to
      // doubles are shifted, too: they then fall elsewhere (ABOP fig. 1.26's
      // leaf plates at n = 3 rounded at the second shift). Faces that touch
      // are made to overlap by a growth (below). Coplanar faces that face
      // the same way go to the corefinement, which handles them exactly, as
      // does a shift or growth that does not help; it costs minutes on a
      // large operand (ternary fig. 2.8b: one such union, 50 s of 61).
      Group& moved = b.faces() <= a.faces() ? b : a;
      std::optional<TriangleMesh> u = exact_union(a, b, round_points);
      const bool degenerate = degenerate_;
      const std::string failure = last_failure_;
      // Faces that touch face on (tubes side by side in a space-filling
      // curve as wide as its spacing, a leaf lying on a leaf) are made to
      // overlap: one operand grows by a thousand units in the last place
      // (grown_mesh), so that its faces that lay on the other's cross into
      // it, and the solids are joined there as the exact union of the faces
      // that touch joins them, within 3·10⁻¹¹ mm. Not where solids touch
      // only at an edge or a point from outside (a growth would join them
      // by a neck that thin; the corefinement's shift parts or joins them),
      // and not where many coplanar faces face the same way (cubes side by
      // side, their tops in one plane): a growth leaves a step that high
      // between them, a sliver along their whole outline, which rounding to
      // the output's floats could not mend on Lparser's Menger cube (it
      // rebuilt 23,802 faces and lost parts), where such pairs are 1.5 to
      // 62 in a hundred of the smaller operand's faces. A few (the caps of
      // tubes that end in one plane in the touching Hilbert curve, at most
      // 0.2 in a hundred) leave steps the rounding mends, and those unions
      // are grown (kFewAlikeShare). The operand grown is one without an
      // earlier growth's steps if one is, else the smaller; the other if
      // that one cannot grow.
      std::optional<Group> grown;
      if (!u && degenerate_ && !transversal_ && face_on_face_ &&
          kFewAlikeShare * double(alike_pairs_) <=
              double(std::min(a.faces(), b.faces()))) {
        Group* order[2] = {&moved, &moved == &b ? &a : &b};
        if (order[0]->grown && !order[1]->grown) std::swap(order[0], order[1]);
        const double golden_step = kGolden * static_cast<double>(growths_++);
        for (Group* candidate : order) {
          const Group& other = candidate == &a ? b : a;
          const double distance_mm =
              growth_unit_mm(candidate->plain) *
              (1.0 + golden_step - std::floor(golden_step));
          std::optional<TriangleMesh> g =
              grown_mesh(candidate->plain, distance_mm, other.box);
          if (!g) continue;
          grown = Group{std::move(*g), {}, {}, {}};
          u = exact_union(other, *grown, round_points);
          if (u) {
            ++stats_.grown;
            candidate->box += box_of(bounds(grown->plain));
          }
          break;
        }
      }
      // A shift would undo a growth, a thousand times smaller than it: a
      // grown union that fails goes to the corefinement.
      for (int attempt = 1;
           !u && !grown && (transversal_ || unrounded_) && attempt < kAttempts;
           ++attempt) {
        // Each shift of the build its own distance: a part shifted once,
        // met again by its twin shifted by as much, would coincide again
        // (two identical leaves of the blog's tree B did).
        const double golden_step = kGolden * static_cast<double>(shifts_++);
        const double distance_mm =
            kExactShiftMm * (1.0 + golden_step - std::floor(golden_step));
        const Group& fixed = &moved == &b ? a : b;
        const Group shifted{shifted_mesh(moved.plain, distance_mm), {}, {}, {}};
        u = exact_union(fixed, shifted, round_points);
        if (u) {
          ++stats_.retries;
          moved.box += box_of(bounds(shifted.plain));
        }
      }
      if (u) {
        ++stats_.booleans;
        ++stats_.exact_unions;
        a.grown = a.grown || b.grown || grown.has_value();
        a.plain = std::move(*u);
        a.box += b.box;
        a.parts.insert(a.parts.end(), b.parts.begin(), b.parts.end());
        return a;
      }
      // Counted by the first failure: a degeneracy that a shift did not
      // take away is still one.
      std::size_t& count =
          degenerate ? stats_.degenerate_unions : stats_.fallbacks;
      std::string& reason =
          degenerate ? stats_.degenerate_reason : stats_.fallback_reason;
      if (count++ == 0) {
        reason = "the union of " + describe(a) + " with " + describe(b) + ": " +
                 failure;
        if (failure != last_failure_) {
          reason += grown ? " (grown: " : " (shifted: ";
          reason += last_failure_;
          reason += ")";
        }
      }
    }
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
      ExactMesh first = a.exact_mesh();
      ExactMesh second = b.exact_mesh();
      if (attempt > 0) {
        // A tiny deterministic shift of one operand removes the coincidences
        // (shared vertices, partly shared edges) that corefinement refuses.
        const double d = kPerturbationMm * attempt;
        translate(second,
                  Exact::Vector_3(d * kShift[0], d * kShift[1], d * kShift[2]));
        ++stats_.retries;
      }
      ExactMesh out;
      bool ok = false;
      try {
        ok = PMP::corefine_and_compute_union(first, second, out);
      } catch (const std::exception& e) {
        last_failure_ = e.what();
        ok = false;
      }
      // The union reports success even where parts touch at a single point,
      // which leaves a pinched vertex that a halfedge mesh cannot hold (seen
      // with leaf plates meeting at a corner): retry those shifted, too.
      if (ok && !CGAL::is_valid_polygon_mesh(out)) {
        ok = false;
        last_failure_ = "the parts touch at a point";
      }
      if (!ok) continue;
      out = canonical_order(out);
      bool in_doubles = false;
      if (round_points) {
        if (round_new_points(out) || round_and_mend(out)) {
          ++stats_.rounded;
          in_doubles = true;
        } else {
          in_doubles = !has_new_points(out);
        }
      }
      ++stats_.booleans;
      a.box += b.box;
      a.parts.insert(a.parts.end(), b.parts.begin(), b.parts.end());
      a.grown = a.grown || b.grown;
      if (in_doubles && engine_ == UnionEngine::ExactCrossings) {
        // Back to the exact engine for the unions after this one: kept
        // exact, every later union that took in these parts went to the
        // corefinement too (blog tree A: one union of touching leaves
        // made 21 s of its 22 s of union).
        a.plain = to_triangle_mesh(out);
        a.exact.reset();
        return a;
      }
      a.exact = std::move(out);
      return a;
    }
    // A shift moves a whole operand, which may hold many parts; where that
    // does not help, the operand with more parts is united again in two
    // halves, each merged on its own, until the failure is down to two
    // parts that a shift of one of them cannot separate.
    if (a.parts.size() > 1 || b.parts.size() > 1) {
      ++stats_.splits;
      Group& split = b.parts.size() >= a.parts.size() ? b : a;
      Group& other = b.parts.size() >= a.parts.size() ? a : b;
      const auto middle = split.parts.begin() +
                          static_cast<std::ptrdiff_t>(split.parts.size() / 2);
      Group first =
          unite(std::vector<std::size_t>(split.parts.begin(), middle));
      Group second = unite(std::vector<std::size_t>(middle, split.parts.end()));
      Group merged = merge(std::move(other), std::move(first), round_points);
      return merge(std::move(merged), std::move(second), round_points);
    }
    throw GeometryError(
        "the union failed for " + describe(a) + " with " + describe(b) +
        (last_failure_.empty() ? "" : " (" + last_failure_ + ")"));
  }

  // The union of some parts, each its own operand.
  Group unite(const std::vector<std::size_t>& ids) {
    std::vector<Group> groups;
    for (const std::size_t i : ids)
      groups.push_back(single(i, box_of(bounds(parts_[i].mesh))));
    return reduce(std::move(groups), false);
  }

  // Unites the groups, the two smallest first, so that the large ones take
  // part in few unions: a union costs time in proportion to both operands'
  // sizes, not only to where they meet. For the final union (`is_final`)
  // progress is told, and the last union's new points are left to
  // round_and_repair, which rounds the whole mesh.
  Group reduce(std::vector<Group> groups, bool is_final) {
    const auto larger = [](const Group& a, const Group& b) {
      return a.faces() > b.faces();
    };
    std::make_heap(groups.begin(), groups.end(), larger);
    const bool tell = is_final && progress_;
    const double total = tell ? expected_work(groups) : 0.0;
    double done = 0.0;
    while (groups.size() > 1) {
      std::pop_heap(groups.begin(), groups.end(), larger);
      Group a = std::move(groups.back());
      groups.pop_back();
      std::pop_heap(groups.begin(), groups.end(), larger);
      Group b = std::move(groups.back());
      const bool last = is_final && groups.size() == 1;
      done += static_cast<double>(a.faces() + b.faces());
      groups.back() = merge(std::move(a), std::move(b), !last);
      if (tell && !last) progress_(std::min(done / total, 0.99));
      std::push_heap(groups.begin(), groups.end(), larger);
    }
    return std::move(groups.front());
  }

  // The work reduce() expects: each union costs about its operands' sizes,
  // and a union's result is about as large as both (the same merge order,
  // on sizes alone).
  static double expected_work(const std::vector<Group>& groups) {
    std::vector<double> sizes;
    for (const Group& g : groups)
      sizes.push_back(static_cast<double>(g.faces()));
    const auto more = std::greater<>();
    std::make_heap(sizes.begin(), sizes.end(), more);
    double total = 0.0;
    while (sizes.size() > 1) {
      std::pop_heap(sizes.begin(), sizes.end(), more);
      const double a = sizes.back();
      sizes.pop_back();
      std::pop_heap(sizes.begin(), sizes.end(), more);
      sizes.back() += a;
      total += sizes.back();
      std::push_heap(sizes.begin(), sizes.end(), more);
    }
    return total;
  }

  std::string describe(const Group& g) const {
    std::string out;
    const std::size_t shown = std::min<std::size_t>(g.parts.size(), 3);
    for (std::size_t i = 0; i < shown; ++i) {
      if (i > 0) out += ", ";
      out += parts_[g.parts[i]].label;
    }
    if (g.parts.size() > shown) {
      out += " and " + std::to_string(g.parts.size() - shown) + " more parts";
    }
    return out;
  }

  std::vector<Part> parts_;
  std::function<void(double)> progress_;
  UnionEngine engine_;
  UnionStats stats_;
  exact_union::FilterCounters filters_;
  std::string last_failure_;     // what CGAL said, if it threw
  bool degenerate_ = false;      // the exact engine's last failure
  bool transversal_ = false;     // and whether a shift removes it
  std::size_t alike_pairs_ = 0;  // or pairs of coplanar faces alike
  bool face_on_face_ = false;    // and whether any lie face on face
  bool unrounded_ = false;       // its new points could not be rounded
  std::size_t shifts_ = 0;       // the exact engine's shifts so far
  std::size_t growths_ = 0;      // and its operands grown
};

}  // namespace

const char* engine_name(UnionEngine engine) {
  return engine == UnionEngine::ExactCrossings ? "exact" : "corefine";
}

UnionResult union_parts(std::vector<Part> parts, const UnionOptions& options) {
  std::optional<tbb::global_control> limit;
  if (options.threads > 0) {
    limit.emplace(tbb::global_control::max_allowed_parallelism,
                  static_cast<std::size_t>(options.threads));
  }
  UnionResult result =
      Unioner(std::move(parts), options.progress, options.engine)
          .run(options.expect);
  result.stats.threads = static_cast<int>(std::min<std::size_t>(
      tbb::global_control::active_value(
          tbb::global_control::max_allowed_parallelism),
      static_cast<std::size_t>(tbb::this_task_arena::max_concurrency())));
  return result;
}

TriangleMesh subtract(const TriangleMesh& a, const TriangleMesh& b) {
  std::optional<ExactMesh> first = to_surface_mesh<ExactMesh>(a);
  std::optional<ExactMesh> second = to_surface_mesh<ExactMesh>(b);
  if (!first || !second || first->is_empty() || second->is_empty()) {
    throw GeometryError(
        "cannot subtract volumes that are not closed 2-manifolds");
  }
  ExactMesh out;
  bool ok = false;
  try {
    ok = PMP::corefine_and_compute_difference(*first, *second, out);
  } catch (const std::exception& e) {
    throw GeometryError(std::string("subtracting one volume from another "
                                    "failed: ") +
                        e.what());
  }
  if (!ok) {
    throw GeometryError(
        "subtracting one volume from another did not give a 2-manifold");
  }
  return to_triangle_mesh(canonical_order(out));
}

}  // namespace lsolid
