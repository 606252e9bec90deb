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

#include <cmath>
#include <set>
#include <unordered_map>
#include <vector>

#include "conversion.hpp"
#include "vertex_key.hpp"

namespace lsolid {
namespace {

constexpr int kMaxPasses = 6;
constexpr double kShortEdgeMm = 1e-4;
constexpr double kCapCosine = -0.985;  // angles above ~170° are caps

void snap_to_float(InexactMesh& mesh) {
  for (const auto v : mesh.vertices()) {
    const InexactPoint& p = mesh.point(v);
    mesh.point(v) =
        InexactPoint(to_float(p.x()), to_float(p.y()), to_float(p.z()));
  }
}

std::size_t count_faces(const InexactMesh& mesh) {
  return mesh.number_of_faces();
}

}  // namespace

void accumulate(RoundingStats& total, const RoundingStats& later) {
  total.passes = later.passes;
  total.slivers_removed += later.slivers_removed;
  total.faces_rebuilt += later.faces_rebuilt;
  total.repairs_refused += later.repairs_refused;
  total.volume_change_mm3 += later.volume_change_mm3;
}

Rounded round_and_repair(const TriangleMesh& input,
                         const RoundingOptions& options) {
  const bool float_coordinates = options.float_coordinates;
  RoundingStats stats;
  InexactMesh mesh = surface_mesh_or_throw<InexactMesh>(input, "round");
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    stats.passes = pass + 1;
    if (float_coordinates) snap_to_float(mesh);
    const std::size_t before = count_faces(mesh);
    PMP::remove_degenerate_faces(mesh);
    PMP::experimental::remove_almost_degenerate_faces(
        faces(mesh), mesh, kCapCosine, 1.0, kShortEdgeMm,
        CGAL::parameters::flip_triangle_height_threshold(kShortEdgeMm));
    mesh.collect_garbage();
    // Collapses may move vertices off the float grid: round again, and
    // judge the result only as it will be written.
    if (float_coordinates) snap_to_float(mesh);
    stats.slivers_removed += before - std::min(before, count_faces(mesh));

    std::vector<std::pair<InexactMesh::Face_index, InexactMesh::Face_index>>
        pairs;
    PMP::self_intersections(mesh, std::back_inserter(pairs));
    bool has_degenerate = false;
    for (const auto f : mesh.faces()) {
      if (PMP::is_degenerate_triangle_face(f, mesh)) {
        has_degenerate = true;
        break;
      }
    }
    if (pairs.empty() && !has_degenerate) break;
    std::set<InexactMesh::Face_index> bad;
    for (const auto& [a, b] : pairs) {
      bad.insert(a);
      bad.insert(b);
    }
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
  if (float_coordinates) snap_to_float(mesh);  // what is checked is written
  TriangleMesh out = to_triangle_mesh(mesh);
  stats.volume_change_mm3 = signed_volume(out) - signed_volume(input);
  return Rounded{.mesh = std::move(out), .stats = stats};
}

}  // namespace lsolid
