// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// An independent check of the decimation's measured deviation, used by the
// tests. CGAL's bounded-error Hausdorff distance (after Tang et al. 2009)
// bounds the answer instead of sampling; it is slow where large coplanar
// faces coincide (14 s on a 3k-triangle figure with a flat underside), so
// the build measures by sampling (decimate_openmesh.cpp). Sequential_tag:
// the parallel version needs METIS.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <vector>

#include "lsolid/distance.hpp"
#include "lsolid/errors.hpp"

namespace lsolid {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

// Through a polygon soup, as validate() does: adding the faces one by one
// fails on some valid meshes whose fans are completed out of order.
Mesh stitched(const TriangleMesh& mesh) {
  std::vector<Kernel::Point_3> points;
  points.reserve(mesh.vertices.size());
  for (const glm::dvec3& p : mesh.vertices) points.emplace_back(p.x, p.y, p.z);
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) polygons.push_back({t[0], t[1], t[2]});
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    PMP::orient_polygon_soup(points, polygons);
  }
  Mesh out;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, out);
  if (out.number_of_faces() == 0) {
    throw GeometryError("cannot measure the distance to an empty mesh");
  }
  return out;
}

}  // namespace

double hausdorff_distance_mm(const TriangleMesh& a, const TriangleMesh& b,
                             double error_bound_mm) {
  const Mesh first = stitched(a);
  const Mesh second = stitched(b);
  return PMP::bounded_error_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(
      first, second, error_bound_mm);
}

}  // namespace lsolid
