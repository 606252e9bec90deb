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
}

Rounded round_and_repair(const TriangleMesh& input,
                         const RoundingOptions& options) {
  return round_and_repair(input, options, {});
}

namespace {

// The passes of round_and_repair; slivers are collapsed and caps flipped
// only if `collapse_slivers`.
Rounded round_in_passes(const TriangleMesh& input,
                        const RoundingOptions& options,
                        const std::vector<char>& settled_faces,
                        bool collapse_slivers) {
  const Precision& precision = options.precision;
  // On a coarse grid (OpenSCAD's 10⁻³ mm) an edge or a cap a few steps
  // small is as good as degenerate: what is collapsed or flipped grows with
  // the step.
  const double short_mm = std::max(kShortEdgeMm, 3.0 * precision.step_mm);
  RoundingStats stats;
  InexactMesh mesh = surface_mesh_or_throw<InexactMesh>(input, "round");
  bool clean = false;
  // The faces the last pass found meeting no other, but those at points
  // two vertices shared, sorted; before the first, those the caller knows.
  std::vector<TriangleKey> settled;
  for (std::size_t i = 0; i < settled_faces.size(); ++i) {
    if (settled_faces[i] == 0) continue;
    const auto& t = input.triangles[i];
    settled.push_back(triangle_key(input.vertices[t[0]], input.vertices[t[1]],
                                   input.vertices[t[2]]));
  }
  tbb::parallel_sort(settled.begin(), settled.end());
  // Pairs left by the last pass, and how many passes in a row left no
  // fewer.
  std::size_t last_pairs = std::numeric_limits<std::size_t>::max();
  int stalled = 0;
  // Without collapses: the corners of the faces a stalled pass could not
  // mend, whose slivers the next pass collapses.
  std::vector<std::array<double, 3>> knot;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    stats.passes = pass + 1;
    snap(mesh, precision);
    const std::size_t before = count_faces(mesh);
    try {
      PMP::remove_degenerate_faces(mesh);
      if (collapse_slivers) {
        PMP::experimental::remove_almost_degenerate_faces(
            faces(mesh), mesh, kCapCosine, 1.0, short_mm,
            CGAL::parameters::flip_triangle_height_threshold(short_mm));
      } else if (!knot.empty()) {
        std::vector<InexactMesh::Face_index> near;
        for (const auto f : mesh.faces()) {
          for (const auto v :
               CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
            const InexactPoint& p = mesh.point(v);
            if (std::binary_search(knot.begin(), knot.end(),
                                   std::array{p.x(), p.y(), p.z()})) {
              near.push_back(f);
              break;
            }
          }
        }
        PMP::experimental::remove_almost_degenerate_faces(
            near, mesh, kCapCosine, 1.0, short_mm,
            CGAL::parameters::flip_triangle_height_threshold(short_mm));
      }
    } catch (const CGAL::Failure_exception&) {
      // CGAL 5.5 stops on a precondition where a collapse left a face that
      // is no longer a triangle; the mesh is then beyond these repairs.
      ++stats.repairs_refused;
      break;
    }
    mesh.collect_garbage();
    // Collapses may move vertices off the grid: round again, and
    // judge the result only as it will be written.
    snap(mesh, precision);
    stats.slivers_removed += before - std::min(before, count_faces(mesh));

    // A face as it was when the last pass found it meeting no other is
    // not tested again against another such face: the second pass over
    // blog tree B's union (1.7 million faces, 7 rebuilt by the first) took
    // as long as the first.
    const std::vector<IndexedTriangle> triangles = indexed_triangles(mesh);
    std::vector<char> known(triangles.size(), 0);
    // Found only when a pass needs them: most builds take one pass.
    std::optional<std::vector<std::array<double, 3>>> shared_at;
    const auto shared = [&]() -> const std::vector<std::array<double, 3>>& {
      if (!shared_at) shared_at = shared_points(mesh);
      return *shared_at;
    };
    if (!settled.empty()) {
      const std::vector<std::array<double, 3>>& points = shared();
      tbb::parallel_for(std::size_t{0}, triangles.size(), [&](std::size_t i) {
        known[i] = std::binary_search(settled.begin(), settled.end(),
                                      corner_key(triangles[i])) &&
                           !at_shared_point(triangles[i], points)
                       ? 1
                       : 0;
      });
    }
    const std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs =
        intersecting_pairs(triangles, known);
    // Every degenerate face is among the pairs (paired with itself), so no
    // pair means no degenerate face either.
    if (pairs.empty()) {
      clean = true;
      break;
    }
    std::set<InexactMesh::Face_index> bad;
    for (const auto& [a, b] : pairs) {
      bad.insert(InexactMesh::Face_index(a));
      bad.insert(InexactMesh::Face_index(b));
    }
    // Without collapses, a rebuild that left as many pairs as before
    // leaves a knot that rebuilding alone does not untie (Lparser's Menger
    // cube at n = 4: 9 pairs, pass after pass): the region rebuilt grows by
    // a ring of faces for each pass that made no progress, and the next
    // pass collapses the slivers among its corners.
    stalled = !collapse_slivers && pairs.size() >= last_pairs ? stalled + 1 : 0;
    last_pairs = pairs.size();
    const auto for_each_corner = [&](const auto& body) {
      for (const InexactMesh::Face_index f : bad) {
        for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
          body(v);
      }
    };
    for (int ring = 0; ring < stalled; ++ring) {
      std::set<InexactMesh::Face_index> grown = bad;
      for_each_corner([&](InexactMesh::Vertex_index v) {
        for (const auto g : CGAL::faces_around_target(mesh.halfedge(v), mesh))
          if (g != InexactMesh::null_face()) grown.insert(g);
      });
      bad = std::move(grown);
    }
    knot.clear();
    if (stalled > 0) {
      for_each_corner([&](InexactMesh::Vertex_index v) {
        const InexactPoint& p = mesh.point(v);
        knot.push_back({p.x(), p.y(), p.z()});
      });
      std::sort(knot.begin(), knot.end());
    }
    settled.clear();
    const std::vector<std::array<double, 3>>& points = shared();
    for (std::uint32_t i = 0; i < triangles.size(); ++i) {
      if (!bad.contains(InexactMesh::Face_index(i)) &&
          !at_shared_point(triangles[i], points)) {
        settled.push_back(corner_key(triangles[i]));
      }
    }
    tbb::parallel_sort(settled.begin(), settled.end());
    stats.faces_rebuilt += bad.size();
    if (!bad.empty()) {
      // CGAL refuses (a precondition, as an exception) to rebuild around a
      // face that rounding made degenerate; it is then rebuilt in place, and
      // the next pass collapses that face first.
      InexactMesh before_repair = mesh;
      try {
        PMP::experimental::remove_self_intersections(
            bad, mesh, CGAL::parameters::preserve_genus(false));
      } catch (const CGAL::Failure_exception&) {
        mesh = std::move(before_repair);
        ++stats.repairs_refused;
      }
      mesh.collect_garbage();
    }
  }
  snap(mesh, precision);  // what is checked is written
  TriangleMesh out = to_triangle_mesh(mesh);
  stats.volume_change_mm3 = signed_volume(out) - signed_volume(input);
  return Rounded{.mesh = std::move(out), .stats = stats, .clean = clean};
}

}  // namespace

Rounded round_and_repair(const TriangleMesh& input,
                         const RoundingOptions& options,
                         const std::vector<char>& settled_faces) {
  Rounded first = round_in_passes(input, options, settled_faces, true);
  if (first.clean || !options.retry_keeping_slivers) return first;
  // CGAL's collapses and flips test nothing around them: in a dense union
  // (Lparser's Menger cube at n = 4, round tubes overlapping face on face)
  // collapsing 3,668 slivers made 2,425 intersecting pairs out of 677, and
  // rebuilding those moved the surface by millimetres and lost parts of
  // the model. Rounded again from the start with slivers collapsed only
  // where rebuilding alone made no progress, it comes out clean.
  Rounded second = round_in_passes(input, options, settled_faces, false);
  if (!second.clean) return first;
  second.stats.slivers_kept = true;
  return second;
}

}  // namespace lsolid
