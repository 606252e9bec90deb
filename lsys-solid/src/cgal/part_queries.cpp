// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The two CGAL queries of the part builder: the convex hull that joins the
// tube rings at a branch point (as B-Mesh, Ji et al. 2010, and SQM, Bærentzen
// et al. 2012, build their junctions), and the exact self-intersection test
// that decides whether pieces stitched at their rings may stay one operand of
// the union. Both use exact predicates on the doubles given (EPICK).
// Preconditions stay on, as exceptions (see boolean.cpp).
#include "kernel.hpp"

#include "part_queries.hpp"

#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <map>

#include "conversion.hpp"
#include "lsolid/errors.hpp"

namespace lsolid {
std::vector<std::array<std::uint32_t, 3>> convex_hull_triangles(
    const std::vector<glm::dvec3>& points) {
  std::vector<InexactPoint> input;
  input.reserve(points.size());
  // The hull copies the coordinates exactly; they lead back to the indices.
  std::map<std::array<double, 3>, std::uint32_t> index;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const glm::dvec3& p = points[i];
    input.emplace_back(p.x, p.y, p.z);
    index.emplace(std::array<double, 3>{p.x, p.y, p.z},
                  static_cast<std::uint32_t>(i));
  }
  InexactMesh hull;
  CGAL::convex_hull_3(input.begin(), input.end(), hull);
  std::vector<std::array<std::uint32_t, 3>> out;
  if (hull.number_of_faces() < 4) return out;
  for (const auto f : hull.faces()) {
    std::array<std::uint32_t, 3> t{};
    std::size_t k = 0;
    for (const auto v : CGAL::vertices_around_face(hull.halfedge(f), hull)) {
      if (k == 3) return {};  // convex_hull_3 triangulates; never a polygon
      const InexactPoint& p = hull.point(v);
      t[k++] = index.at({p.x(), p.y(), p.z()});
    }
    // Each triangle from its least corner, keeping its orientation.
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.push_back(t);
  }
  // In a canonical order: convex_hull_3 lists faces in an order that
  // follows the addresses its allocations get, so a change elsewhere in
  // the program (a vector allocated earlier) reordered a junction's
  // triangles and changed the model's bytes.
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>>
intersecting_triangle_pairs(const TriangleMesh& mesh) {
  const std::optional<InexactMesh> surface = to_surface_mesh<InexactMesh>(mesh);
  if (!surface || surface->number_of_faces() != mesh.triangles.size()) {
    throw GeometryError("stitched parts do not form an oriented surface");
  }
  // The surface's own vertices tell shared corners apart, as they did for
  // CGAL's self_intersections; its faces are the triangles in order. The
  // pairs come in one order whatever the threads, which the part builder's
  // choice of the junction to give up depends on.
  return intersecting_pairs(indexed_triangles(*surface));
}

}  // namespace lsolid
