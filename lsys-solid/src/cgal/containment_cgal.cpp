// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The union's invariant: every part lies inside the result. A union that
// rounding or repair has emptied in places (seen: leaf plates that met face
// on face vanished, and the model was still "printable") leaves points
// that were deep inside a part outside the result. The points are found by
// ray casting inside each part; the test is CGAL's Side_of_triangle_mesh,
// exact predicates on the result's coordinates (EPICK).
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>

#include "conversion.hpp"
#include "lsolid/containment.hpp"
#include "lsolid/errors.hpp"

namespace lsolid {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

constexpr std::size_t kFacesPerWitness = 64;

glm::dvec3 to_glm(const Point& p) { return {p.x(), p.y(), p.z()}; }

void add_witnesses(const Part& part, std::size_t index,
                   std::vector<Witness>& out) {
  const Mesh mesh = to_surface_mesh<Mesh>(part.mesh);
  if (mesh.number_of_faces() == 0) return;
  Tree tree(faces(mesh).first, faces(mesh).second, mesh);
  tree.accelerate_distance_queries();
  std::size_t k = 0;
  for (const Mesh::Face_index f : mesh.faces()) {
    if (k++ % kFacesPerWitness != 0) continue;
    const auto h = mesh.halfedge(f);
    const Point& a = mesh.point(mesh.source(h));
    const Point& b = mesh.point(mesh.target(h));
    const Point& c = mesh.point(mesh.target(mesh.next(h)));
    const Kernel::Vector_3 normal = CGAL::cross_product(b - a, c - a);
    if (normal.squared_length() == 0.0) continue;
    const Point centre = CGAL::centroid(a, b, c);
    const Kernel::Ray_3 inward(centre, -normal);
    const auto hit = tree.first_intersection(
        inward, [f](const Mesh::Face_index g) { return g == f; });
    if (!hit) continue;
    const Point* exit = boost::get<Point>(&hit->first);
    if (exit == nullptr) continue;  // along a face: no clear inside
    const Point middle = CGAL::midpoint(centre, *exit);
    const double depth = std::sqrt(tree.squared_distance(middle));
    if (depth <= 0.0) continue;
    out.push_back(
        Witness{.part = index, .point = to_glm(middle), .depth_mm = depth});
  }
}

}  // namespace

std::vector<Witness> witnesses(const std::vector<Part>& parts) {
  std::vector<Witness> out;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    add_witnesses(parts[i], i, out);
  }
  return out;
}

std::vector<Witness> witnesses_outside(const TriangleMesh& mesh,
                                       const std::vector<Witness>& witnesses,
                                       double min_depth_mm) {
  std::vector<Witness> outside;
  if (witnesses.empty()) return outside;
  const Mesh solid = to_surface_mesh<Mesh>(mesh);
  if (solid.number_of_faces() == 0) {
    if (mesh.triangles.empty()) {
      for (const Witness& w : witnesses) {
        if (w.depth_mm >= min_depth_mm) outside.push_back(w);
      }
      return outside;
    }
    throw GeometryError(
        "cannot test points against a mesh that is not a 2-manifold");
  }
  Tree tree(faces(solid).first, faces(solid).second, solid);
  const CGAL::Side_of_triangle_mesh<Mesh, Kernel> side(tree);
  for (const Witness& w : witnesses) {
    if (w.depth_mm < min_depth_mm) continue;
    if (side(Point(w.point.x, w.point.y, w.point.z)) != CGAL::ON_BOUNDED_SIDE) {
      outside.push_back(w);
    }
  }
  return outside;
}

}  // namespace lsolid
