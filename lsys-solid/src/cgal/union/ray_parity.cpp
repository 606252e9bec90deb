// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Point in solid by the parity of ray crossings (Jordan's theorem for a
// closed surface), with every decision an exact orientation on the input
// doubles. A ray that meets an edge or a vertex is not perturbed
// symbolically: the caller tries another axis, and CGAL's
// Side_of_triangle_mesh where all three meet one (it shoots random rays).
#include "cgal/union/ray_parity.hpp"

#include "cgal/kernel.hpp"

namespace lsolid::exact_union {

RaySurface ray_surface(const TriangleMesh& mesh) {
  RaySurface out{&mesh, {}, {}};
  out.box_min.reserve(mesh.triangles.size());
  out.box_max.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    const glm::dvec3& a = mesh.vertices[t[0]];
    const glm::dvec3& b = mesh.vertices[t[1]];
    const glm::dvec3& c = mesh.vertices[t[2]];
    out.box_min.push_back(glm::min(glm::min(a, b), c));
    out.box_max.push_back(glm::max(glm::max(a, b), c));
  }
  return out;
}

std::optional<RaySide> side_by_ray(const RaySurface& surface,
                                   const glm::dvec3& p, int axis) {
  using Point2 = Inexact::Point_2;
  using Point3 = Inexact::Point_3;
  const TriangleMesh& mesh = *surface.mesh;
  // (u, v, axis) is right-handed, so that the orientation of a face's
  // projection has the sign of its normal's `axis` coordinate.
  const int u = (axis + 1) % 3;
  const int v = (axis + 2) % 3;
  const Point2 q(p[u], p[v]);
  const Point3 p3(p.x, p.y, p.z);
  bool inside = false;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const glm::dvec3& lo = surface.box_min[f];
    const glm::dvec3& hi = surface.box_max[f];
    // Beyond the box across the ray, or wholly behind its start: not met.
    if (p[u] < lo[u] || p[u] > hi[u] || p[v] < lo[v] || p[v] > hi[v] ||
        hi[axis] < p[axis]) {
      continue;
    }
    const auto& t = mesh.triangles[f];
    const glm::dvec3& a = mesh.vertices[t[0]];
    const glm::dvec3& b = mesh.vertices[t[1]];
    const glm::dvec3& c = mesh.vertices[t[2]];
    const Point2 a2(a[u], a[v]);
    const Point2 b2(b[u], b[v]);
    const Point2 c2(c[u], c[v]);
    const CGAL::Orientation o[3] = {CGAL::orientation(a2, b2, q),
                                    CGAL::orientation(b2, c2, q),
                                    CGAL::orientation(c2, a2, q)};
    bool positive = false;
    bool negative = false;
    bool zero = false;
    for (const CGAL::Orientation s : o) {
      positive = positive || s == CGAL::POSITIVE;
      negative = negative || s == CGAL::NEGATIVE;
      zero = zero || s == CGAL::COLLINEAR;
    }
    // The ray's line passes beside the face's projection.
    if (positive && negative) continue;
    // Through an edge or a vertex of it, or the face is edge-on.
    if (zero) return std::nullopt;
    // Through its inside: the face's normal has the projection's sign along
    // the axis, and the crossing lies ahead of p where p is behind the
    // face's plane as the normal sees it.
    const CGAL::Orientation normal = positive ? CGAL::POSITIVE : CGAL::NEGATIVE;
    const CGAL::Orientation side =
        CGAL::orientation(Point3(a.x, a.y, a.z), Point3(b.x, b.y, b.z),
                          Point3(c.x, c.y, c.z), p3);
    if (side == CGAL::COPLANAR) return RaySide::kOnSurface;
    if (side != normal) inside = !inside;
  }
  return inside ? RaySide::kInside : RaySide::kOutside;
}

}  // namespace lsolid::exact_union
