// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The flat underside of planar models printed with the round profile, cut
// from the united model after the union (solid.cpp): cutting each part
// before the union made that union three times as slow, as the parts'
// coplanar caps met face on face.
// Exact coordinates (EPECK): the new vertices lie exactly in the plane, and
// as z_mm is a double they keep it when rounded.
//
// The cutter is a tetrahedron standing on one large triangle in the plane,
// not clip()'s plane overload: that one meshes the plane as a rectangle
// whose diagonal runs through the model's centre, at 45 degrees. Along the
// Koch island's mitred corners, on that diagonal, it made two vertices a
// rounding error apart, which collapsed to one when rounded to doubles;
// and clipping the united Sierpinski triangle with it did not finish in
// minutes, as CGAL triangulated the plane's two large triangles around
// every crossing tube.
#include "kernel.hpp"

#include "lsolid/cut.hpp"

#include <CGAL/Polygon_mesh_processing/clip.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <array>
#include <cmath>
#include <glm/glm.hpp>
#include <numbers>
#include <vector>

#include "conversion.hpp"

namespace lsolid {
namespace {

// A tetrahedron holding everything of `mesh` above z_mm, with its base in
// that plane and its other faces far outside the mesh. The base is
// equilateral with an inradius of 10 reaches (the mesh's largest distance
// from its centre) and the apex 10 reaches up: at any height h of the mesh
// above z_mm the cross-section's inradius is 10 reaches (1 - h/(10 reach))
// >= 9 reaches, so no side face touches the mesh.
ExactMesh cutter_above(const TriangleMesh& mesh, double z_mm) {
  glm::dvec3 lo(1e300);
  glm::dvec3 hi(-1e300);
  for (const glm::dvec3& p : mesh.vertices) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::dvec3 centre = (lo + hi) / 2.0;
  const double reach =
      std::max(glm::length(hi - lo), std::fabs(z_mm - centre.z)) + 1.0;
  const double r = 20.0 * reach;  // circumradius: twice the inradius
  ExactMesh cutter;
  std::array<ExactMesh::Vertex_index, 3> base;
  for (int i = 0; i < 3; ++i) {
    const double a = 2.0 * std::numbers::pi * i / 3.0;
    base[i] = cutter.add_vertex(ExactPoint(centre.x + r * std::cos(a),
                                           centre.y + r * std::sin(a), z_mm));
  }
  const ExactMesh::Vertex_index apex =
      cutter.add_vertex(ExactPoint(centre.x, centre.y, z_mm + 10.0 * reach));
  // Outward: the base faces down, seen from below clockwise.
  cutter.add_face(base[0], base[2], base[1]);
  cutter.add_face(base[0], base[1], apex);
  cutter.add_face(base[1], base[2], apex);
  cutter.add_face(base[2], base[0], apex);
  return cutter;
}

}  // namespace

std::optional<TriangleMesh> cut_below(const TriangleMesh& input, double z_mm) {
  // CGAL's preconditions throw (lsys-solid/CMakeLists.txt); a cut they
  // refuse, anywhere from reading the mesh to ordering the result, is a
  // cut that cannot be made.
  try {
    const auto soup = polygon_soup<ExactPoint>(input);
    if (!PMP::is_polygon_soup_a_polygon_mesh(soup.polygons)) {
      return std::nullopt;
    }
    ExactMesh mesh;
    PMP::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
    ExactMesh cutter = cutter_above(input, z_mm);
    if (!PMP::clip(mesh, cutter, CGAL::parameters::clip_volume(true))) {
      return std::nullopt;
    }
    PMP::triangulate_faces(mesh);
    mesh.collect_garbage();
    return to_triangle_mesh(canonical_order(mesh));
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace lsolid
