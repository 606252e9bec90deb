// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Exact geometric checks with CGAL 5.5 and its filtered exact predicates
// (EPICK): coordinates are doubles, and every predicate is decided exactly.
// CGAL's preconditions stay on, as exceptions, in release builds too (see
// boolean.cpp): a check must report, not crash.
#include "kernel.hpp"

#include "exact_checks.hpp"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <optional>
#include <utility>
#include <vector>

#include "conversion.hpp"
#include "triangle_pair.hpp"

namespace lsolid {

ExactChecks exact_checks(const TriangleMesh& input, bool is_edge_manifold,
                         bool is_closed_manifold) {
  ExactChecks r;
  TriangleMesh mesh = input;
  remove_unused_vertices(mesh);  // a halfedge mesh has no isolated points
  std::vector<InexactPoint> points;
  points.reserve(mesh.vertices.size());
  for (const glm::dvec3& p : mesh.vertices) points.emplace_back(p.x, p.y, p.z);
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] ||
        CGAL::collinear(points[t[0]], points[t[1]], points[t[2]])) {
      ++r.degenerate_faces;
      continue;  // CGAL's mesh checks require non-degenerate faces
    }
    polygons.push_back({t[0], t[1], t[2]});
  }
  if (!is_edge_manifold || polygons.empty()) return r;
  try {
    // A closed manifold (validate's own counts: every edge two faces of
    // opposite directions, no pinched vertex) with every face kept is a
    // polygon mesh as it stands: to_surface_mesh adds its faces directly.
    // CGAL's test of the soup, which its conversion repeats as a
    // precondition, was a fifth of the check of the bush at n = 7.
    std::optional<InexactMesh> direct;
    if (is_closed_manifold && r.degenerate_faces == 0) {
      direct = to_surface_mesh<InexactMesh>(mesh);
    }
    InexactMesh sm;
    if (direct) {
      sm = std::move(*direct);
    } else {
      // Pinched vertices are split so that a halfedge mesh can hold the
      // faces; faces that met only there then count as intersecting, as
      // they touch.
      if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
        PMP::orient_polygon_soup(points, polygons);
      }
      PMP::polygon_soup_to_polygon_mesh(points, polygons, sm);
    }
    // What the halfedge mesh was built from goes before the searches.
    polygons = {};
    points = {};
    mesh = TriangleMesh{};
    // The pairs CGAL's PMP::self_intersections finds, searched on a grid
    // and tested on oneTBB's threads (triangle_pair.hpp): CGAL's search
    // runs on one thread and tests each pair's degeneracy again, and it
    // was the longest task of the decimation's last step on the bush at
    // n = 7, the serial check beside the measurement.
    r.self_intersecting_pairs =
        intersecting_pairs(indexed_triangles(sm)).size();
    r.self_intersections_checked = true;
    if (is_closed_manifold && r.degenerate_faces == 0 &&
        r.self_intersecting_pairs == 0) {
      // does_bound_a_volume checks that nested shells alternate in
      // orientation; is_outward_oriented that the outermost shell (the one
      // with the highest vertex) faces out.
      r.is_outward =
          PMP::does_bound_a_volume(sm) && PMP::is_outward_oriented(sm);
      r.orientation_checked = true;
    }
  } catch (const std::exception&) {
    // A precondition CGAL found unmet: the checks not done stay unchecked,
    // which makes the mesh not printable.
  }
  return r;
}

}  // namespace lsolid
