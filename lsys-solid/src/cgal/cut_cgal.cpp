// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The flat underside of planar models, cut from each part before the union
// (see solid.cpp): clipping the united Sierpinski triangle, whose cut face
// crosses thousands of tubes, did not finish in minutes, as CGAL
// triangulates the plane's two large triangles around every crossing.
// Exact coordinates (EPECK): the new vertices lie exactly in the plane, and
// as z_mm is a double they keep it when rounded.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/clip.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <vector>

#include "conversion.hpp"
#include "lsolid/cut.hpp"
#include "lsolid/errors.hpp"

namespace lsolid {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

}  // namespace

TriangleMesh cut_below(const TriangleMesh& input, double z_mm) {
  std::vector<Kernel::Point_3> points;
  points.reserve(input.vertices.size());
  for (const glm::dvec3& p : input.vertices) points.emplace_back(p.x, p.y, p.z);
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(input.triangles.size());
  for (const auto& t : input.triangles) polygons.push_back({t[0], t[1], t[2]});
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    throw GeometryError("cannot cut a mesh that is not a 2-manifold");
  }
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  try {
    // clip keeps the negative side of the plane: -z + z_mm < 0, z > z_mm.
    const bool closed = PMP::clip(mesh, Kernel::Plane_3(0, 0, -1, z_mm),
                                  CGAL::parameters::clip_volume(true));
    if (!closed) throw GeometryError("CGAL could not close the cut");
    PMP::triangulate_faces(mesh);
  } catch (const std::exception& e) {
    throw GeometryError(std::string("cutting the underside failed: ") +
                        e.what());
  }
  mesh.collect_garbage();
  return to_triangle_mesh(mesh);
}

}  // namespace lsolid
