// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// An independent check of the decimation's measured deviation, used by the
// tests. CGAL's bounded-error Hausdorff distance (after Tang et al. 2009)
// bounds the answer instead of sampling; it is slow where large coplanar
// faces coincide (14 s on a 3k-triangle figure with a flat underside), so
// the build measures by sampling (openmesh/decimate.cpp). Sequential_tag:
// the parallel version needs METIS.
#include "kernel.hpp"

#include "lsolid/distance.hpp"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Side_of_triangle_mesh.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "conversion.hpp"
#include "hausdorff.hpp"
#include "lsolid/errors.hpp"

namespace lsolid {
namespace {

// Through a polygon soup, as validate() does: adding the faces one by one
// fails on some valid meshes whose fans are completed out of order.
InexactMesh stitched(const TriangleMesh& mesh) {
  auto [points, polygons] = polygon_soup<InexactPoint>(mesh);
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    PMP::orient_polygon_soup(points, polygons);
  }
  InexactMesh out;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, out);
  if (out.number_of_faces() == 0) {
    throw GeometryError("cannot measure the distance to an empty mesh");
  }
  return out;
}

}  // namespace

double hausdorff_distance_mm(const TriangleMesh& a, const TriangleMesh& b,
                             double error_bound_mm) {
  const InexactMesh first = stitched(a);
  const InexactMesh second = stitched(b);
  return PMP::bounded_error_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(
      first, second, error_bound_mm);
}

double overlap_depth_mm(const TriangleMesh& a, const TriangleMesh& b) {
  const InexactMesh solid = stitched(b);
  using Primitive = CGAL::AABB_face_graph_triangle_primitive<InexactMesh>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Inexact, Primitive>>;
  Tree tree(faces(solid).first, faces(solid).second, solid);
  tree.accelerate_distance_queries();
  const CGAL::Side_of_triangle_mesh<InexactMesh, Inexact> side(tree);
  const Box box = bounds(b);
  double deepest = 0.0;
  const auto sample = [&](const glm::dvec3& p) {
    if (p.x < box.min.x || p.y < box.min.y || p.z < box.min.z ||
        p.x > box.max.x || p.y > box.max.y || p.z > box.max.z) {
      return;
    }
    const InexactPoint q(p.x, p.y, p.z);
    if (side(q) != CGAL::ON_BOUNDED_SIDE) return;
    deepest = std::max(deepest, std::sqrt(tree.squared_distance(q)));
  };
  for (const glm::dvec3& p : a.vertices) sample(p);
  for (const auto& t : a.triangles) {
    const glm::dvec3& p0 = a.vertices[t[0]];
    const glm::dvec3& p1 = a.vertices[t[1]];
    const glm::dvec3& p2 = a.vertices[t[2]];
    sample((p0 + p1 + p2) / 3.0);
    sample((p0 + p1) / 2.0);
    sample((p1 + p2) / 2.0);
    sample((p2 + p0) / 2.0);
  }
  return deepest;
}

}  // namespace lsolid
