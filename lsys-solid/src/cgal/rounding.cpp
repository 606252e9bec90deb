// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Repairs what rounding an exact union does to it, with CGAL 5.5's repair
// functions (PMP::remove_degenerate_faces, the experimental
// remove_almost_degenerate_faces and remove_self_intersections). Predicates
// are exact (EPICK) on the rounded coordinates themselves.
#include "kernel.hpp"

#include "lsolid/rounding.hpp"

#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_self_intersections.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <unordered_map>
#include <vector>

#include "conversion.hpp"
#include "settled_rounding.hpp"
#include "triangle_pair.hpp"
#include "vertex_key.hpp"

namespace lsolid {
namespace {

constexpr int kMaxPasses = 6;
constexpr double kShortEdgeMm = 1e-4;
constexpr double kCapCosine = -0.985;  // angles above ~170° are caps
// Faces that meet after the first pass with slivers collapsed, beyond which
// the way that keeps slivers makes its first pass too and the way that left
// fewer goes on first. Rebuilding a few pairs costs less than that pass
// (blog tree B: 3 pairs among 1.7 million faces), rebuilding thousands far
// more (Lparser's Menger cube at n = 4: 2,456 pairs, 15 s).
constexpr std::size_t kComparePairs = 100;

void snap(InexactMesh& mesh, const Precision& precision) {
  if (precision.kind == Precision::Kind::Double) return;
  for (const auto v : mesh.vertices()) {
    const InexactPoint& p = mesh.point(v);
    mesh.point(v) = InexactPoint(precision.snap(p.x()), precision.snap(p.y()),
                                 precision.snap(p.z()));
  }
}

std::size_t count_faces(const InexactMesh& mesh) {
  return mesh.number_of_faces();
}

TriangleKey corner_key(const IndexedTriangle& t) {
  return triangle_key(t.points[0], t.points[1], t.points[2]);
}

// The points two or more vertices share, sorted: a face with a corner
// there is not taken as known from one pass to the next. Elsewhere a face
// is its corners, and two faces share a point exactly where they share a
// vertex. (Snapped to floats, vertices a hair apart come together.)
std::vector<std::array<double, 3>> shared_points(const InexactMesh& mesh) {
  std::vector<std::array<double, 3>> points;
  points.reserve(mesh.number_of_vertices());
  for (const auto v : mesh.vertices()) {
    const InexactPoint& p = mesh.point(v);
    points.push_back({p.x(), p.y(), p.z()});
  }
  tbb::parallel_sort(points.begin(), points.end());
  std::vector<std::array<double, 3>> shared;
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (points[i] == points[i - 1] &&
        (shared.empty() || shared.back() != points[i])) {
      shared.push_back(points[i]);
    }
  }
  return shared;
}

// Whether a corner of `t` is one of the `shared` points.
bool at_shared_point(const IndexedTriangle& t,
                     const std::vector<std::array<double, 3>>& shared) {
  return std::any_of(
      t.points.begin(), t.points.end(), [&](const glm::dvec3& p) {
        return std::binary_search(shared.begin(), shared.end(),
                                  std::array<double, 3>{p.x, p.y, p.z});
      });
}

}  // namespace

void accumulate(RoundingStats& total, const RoundingStats& later) {
  total.passes = later.passes;
  total.slivers_removed += later.slivers_removed;
  total.faces_rebuilt += later.faces_rebuilt;
  total.repairs_refused += later.repairs_refused;
  total.volume_change_mm3 += later.volume_change_mm3;
  total.slivers_kept = total.slivers_kept || later.slivers_kept;
  total.ways_tried += later.ways_tried;
}

Rounded round_and_repair(const TriangleMesh& input,
                         const RoundingOptions& options) {
  return round_and_repair(input, options, std::vector<char>{});
}

namespace {

// One way of rounding and repairing, pass by pass: slivers collapsed and
// caps flipped everywhere (`collapse_slivers`), or only where rebuilding
// made no progress. Each pass rounds, removes what is degenerate, finds
// the faces that meet (search) and rebuilds them (rebuild); round_and_repair
// compares two attempts by the pairs their first search found.
class Attempt {
 public:
  Attempt(const TriangleMesh& input, const RoundingOptions& options,
          const std::vector<char>& settled_faces, bool collapse_slivers)
      : input_(input),
        precision_(options.precision),
        collapse_slivers_(collapse_slivers),
        // On a coarse grid (OpenSCAD's 10⁻³ mm) an edge or a cap a few
        // steps small is as good as degenerate: what is collapsed or flipped
        // grows with the step.
        short_mm_(std::max(kShortEdgeMm, 3.0 * options.precision.step_mm)),
        mesh_(surface_mesh_or_throw<InexactMesh>(input, "round")) {
    for (std::size_t i = 0; i < settled_faces.size(); ++i) {
      if (settled_faces[i] == 0) continue;
      const auto& t = input.triangles[i];
      settled_.push_back(triangle_key(
          input.vertices[t[0]], input.vertices[t[1]], input.vertices[t[2]]));
    }
    tbb::parallel_sort(settled_.begin(), settled_.end());
  }

  // The pairs of faces the last search found meeting (0 when clean; the
  // most there can be when CGAL refused a repair).
  [[nodiscard]] std::size_t pairs() const {
    return refused_ ? std::numeric_limits<std::size_t>::max() : pairs_.size();
  }

  // The first half of a pass: rounds, removes degenerate faces and slivers,
  // and finds the faces that meet; stops where CGAL refuses a repair (then
  // pairs() is the most there can be).
  void search() {
    stats_.passes = ++passes_;
    snap(mesh_, precision_);
    const std::size_t before = count_faces(mesh_);
    try {
      PMP::remove_degenerate_faces(mesh_);
      if (collapse_slivers_) {
        PMP::experimental::remove_almost_degenerate_faces(
            faces(mesh_), mesh_, kCapCosine, 1.0, short_mm_,
            CGAL::parameters::flip_triangle_height_threshold(short_mm_));
      } else if (!knot_.empty()) {
        std::vector<InexactMesh::Face_index> near;
        for (const auto f : mesh_.faces()) {
          for (const auto v :
               CGAL::vertices_around_face(mesh_.halfedge(f), mesh_)) {
            const InexactPoint& p = mesh_.point(v);
            if (std::binary_search(knot_.begin(), knot_.end(),
                                   std::array{p.x(), p.y(), p.z()})) {
              near.push_back(f);
              break;
            }
          }
        }
        PMP::experimental::remove_almost_degenerate_faces(
            near, mesh_, kCapCosine, 1.0, short_mm_,
            CGAL::parameters::flip_triangle_height_threshold(short_mm_));
      }
    } catch (const CGAL::Failure_exception&) {
      // CGAL 5.5 stops on a precondition where a collapse left a face that
      // is no longer a triangle; the mesh is then beyond these repairs.
      ++stats_.repairs_refused;
      refused_ = true;
      return;
    }
    mesh_.collect_garbage();
    // Collapses may move vertices off the grid: round again, and
    // judge the result only as it will be written.
    snap(mesh_, precision_);
    stats_.slivers_removed += before - std::min(before, count_faces(mesh_));

    // A face as it was when the last pass found it meeting no other is
    // not tested again against another such face: the second pass over
    // blog tree B's union (1.7 million faces, 7 rebuilt by the first) took
    // as long as the first.
    triangles_ = indexed_triangles(mesh_);
    std::vector<char> known(triangles_.size(), 0);
    shared_at_.reset();
    if (!settled_.empty()) {
      const std::vector<std::array<double, 3>>& points = shared();
      tbb::parallel_for(std::size_t{0}, triangles_.size(), [&](std::size_t i) {
        known[i] = std::binary_search(settled_.begin(), settled_.end(),
                                      corner_key(triangles_[i])) &&
                           !at_shared_point(triangles_[i], points)
                       ? 1
                       : 0;
      });
    }
    pairs_ = intersecting_pairs(triangles_, known);
    // Every degenerate face is among the pairs (paired with itself), so no
    // pair means no degenerate face either.
    clean_ = pairs_.empty();
  }

  // The second half of a pass: rebuilds the faces the search found.
  // @pre search() found pairs.
  void rebuild() {
    std::set<InexactMesh::Face_index> bad;
    for (const auto& [a, b] : pairs_) {
      bad.insert(InexactMesh::Face_index(a));
      bad.insert(InexactMesh::Face_index(b));
    }
    // Without collapses, a rebuild that left as many pairs as before
    // leaves a knot that rebuilding alone does not untie (Lparser's Menger
    // cube at n = 4: 9 pairs, pass after pass): the region rebuilt grows by
    // a ring of faces for each pass that made no progress, and the next
    // pass collapses the slivers among its corners.
    stalled_ =
        !collapse_slivers_ && pairs_.size() >= last_pairs_ ? stalled_ + 1 : 0;
    last_pairs_ = pairs_.size();
    const auto for_each_corner = [&](const auto& body) {
      for (const InexactMesh::Face_index f : bad) {
        for (const auto v :
             CGAL::vertices_around_face(mesh_.halfedge(f), mesh_))
          body(v);
      }
    };
    for (int ring = 0; ring < stalled_; ++ring) {
      std::set<InexactMesh::Face_index> grown = bad;
      for_each_corner([&](InexactMesh::Vertex_index v) {
        for (const auto g : CGAL::faces_around_target(mesh_.halfedge(v), mesh_))
          if (g != InexactMesh::null_face()) grown.insert(g);
      });
      bad = std::move(grown);
    }
    knot_.clear();
    if (stalled_ > 0) {
      for_each_corner([&](InexactMesh::Vertex_index v) {
        const InexactPoint& p = mesh_.point(v);
        knot_.push_back({p.x(), p.y(), p.z()});
      });
      std::sort(knot_.begin(), knot_.end());
    }
    settled_.clear();
    const std::vector<std::array<double, 3>>& points = shared();
    for (std::uint32_t i = 0; i < triangles_.size(); ++i) {
      if (!bad.contains(InexactMesh::Face_index(i)) &&
          !at_shared_point(triangles_[i], points)) {
        settled_.push_back(corner_key(triangles_[i]));
      }
    }
    tbb::parallel_sort(settled_.begin(), settled_.end());
    stats_.faces_rebuilt += bad.size();
    // CGAL refuses (a precondition, as an exception) to rebuild around a
    // face that rounding made degenerate; it is then rebuilt in place, and
    // the next pass collapses that face first.
    InexactMesh before_repair = mesh_;
    try {
      PMP::experimental::remove_self_intersections(
          bad, mesh_, CGAL::parameters::preserve_genus(false));
    } catch (const CGAL::Failure_exception&) {
      mesh_ = std::move(before_repair);
      ++stats_.repairs_refused;
    }
    mesh_.collect_garbage();
  }

  // The passes after the first search, until the mesh is clean, CGAL
  // refuses or the passes run out; then the result as it will be written.
  [[nodiscard]] Rounded finish() {
    while (!clean_ && !refused_) {
      rebuild();
      if (passes_ >= kMaxPasses) break;
      search();
    }
    snap(mesh_, precision_);  // what is checked is written
    TriangleMesh out = to_triangle_mesh(mesh_);
    stats_.volume_change_mm3 = signed_volume(out) - signed_volume(input_);
    stats_.slivers_kept = !collapse_slivers_;
    stats_.ways_tried = 1;
    return Rounded{.mesh = std::move(out), .stats = stats_, .clean = clean_};
  }

 private:
  // Found only when a pass needs them: most builds take one pass.
  const std::vector<std::array<double, 3>>& shared() {
    if (!shared_at_) shared_at_ = shared_points(mesh_);
    return *shared_at_;
  }

  const TriangleMesh& input_;
  Precision precision_;
  bool collapse_slivers_;
  double short_mm_;
  InexactMesh mesh_;
  RoundingStats stats_;
  int passes_ = 0;
  bool clean_ = false;
  bool refused_ = false;
  // The faces the last pass found meeting no other, but those at points
  // two vertices shared, sorted; before the first, those the caller knows.
  std::vector<TriangleKey> settled_;
  // The last search's faces and the pairs of them that meet.
  std::vector<IndexedTriangle> triangles_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs_;
  std::optional<std::vector<std::array<double, 3>>> shared_at_;
  // Pairs left by the last pass, and how many passes in a row left no
  // fewer.
  std::size_t last_pairs_ = std::numeric_limits<std::size_t>::max();
  int stalled_ = 0;
  // Without collapses: the corners of the faces a stalled pass could not
  // mend, whose slivers the next pass collapses.
  std::vector<std::array<double, 3>> knot_;
};

}  // namespace

Rounded round_and_repair(const TriangleMesh& input,
                         const RoundingOptions& options,
                         const std::vector<char>& settled_faces) {
  Attempt collapsing(input, options, settled_faces, true);
  collapsing.search();
  // CGAL's collapses and flips test nothing around them: in a dense union
  // (Lparser's Menger cube at n = 4, round tubes overlapping face on face)
  // collapsing 3,668 slivers made 2,456 intersecting pairs out of 195, and
  // rebuilding those took 15 s, moved the surface by millimetres and lost
  // parts of the model. Rounded with slivers collapsed only where
  // rebuilding alone made no progress, it comes out clean in 0.5 s. So
  // where many faces meet after collapses, the way whose first pass leaves
  // fewer goes first; the other only if that one does not come out clean.
  std::optional<Attempt> keeping;
  bool keep_first = false;
  if (collapsing.pairs() > kComparePairs) {
    keeping.emplace(input, options, settled_faces, false);
    keeping->search();
    keep_first = keeping->pairs() < collapsing.pairs();
  }
  // The union's own mends choose so too (the cube's unions where faces
  // touch: 4 of 6 back to doubles for the exact engine instead of 3, its
  // union 10.5 -> 7.2 s), but go no further: a shift or the corefinement
  // follows them, and carrying on the other way changed and slowed blog
  // tree B's union.
  Rounded first = keep_first ? keeping->finish() : collapsing.finish();
  if (first.clean || !options.retry_keeping_slivers) return first;
  if (!keeping) {
    keeping.emplace(input, options, settled_faces, false);
    keeping->search();
  }
  Rounded second = keep_first ? collapsing.finish() : keeping->finish();
  // Neither clean: the result with slivers collapsed, as it was before
  // the other way was tried.
  const bool second_kept = second.clean || keep_first;
  Rounded kept = std::move(second_kept ? second : first);
  kept.stats.ways_tried = 2;
  return kept;
}

}  // namespace lsolid
