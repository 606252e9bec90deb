// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Point in solid by the parity of ray crossings (Jordan's theorem for a
// closed surface), with every decision an exact orientation on the input
// doubles. A ray that meets an edge or a vertex is not perturbed
// symbolically: the caller tries another axis, and CGAL's
// Side_of_triangle_mesh where all three meet one (it shoots random rays).
#include "cgal/union/ray_parity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>

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

namespace {

// What the ray from p along +axis does at face f.
enum class Meets { kMiss, kCrosses, kAmbiguous, kOnSurface };

// @pre p lies within f's box across the ray, and not beyond it along it.
Meets meets(const TriangleMesh& mesh, std::size_t f, const glm::dvec3& p,
            int axis) {
  using Point2 = Inexact::Point_2;
  using Point3 = Inexact::Point_3;
  // (u, v, axis) is right-handed, so that the orientation of a face's
  // projection has the sign of its normal's `axis` coordinate.
  const int u = (axis + 1) % 3;
  const int v = (axis + 2) % 3;
  const Point2 q(p[u], p[v]);
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
  if (positive && negative) return Meets::kMiss;
  // Through an edge or a vertex of it, or the face is edge-on.
  if (zero) return Meets::kAmbiguous;
  // Through its inside: the face's normal has the projection's sign along
  // the axis, and the crossing lies ahead of p where p is behind the face's
  // plane as the normal sees it.
  const CGAL::Orientation normal = positive ? CGAL::POSITIVE : CGAL::NEGATIVE;
  const CGAL::Orientation side =
      CGAL::orientation(Point3(a.x, a.y, a.z), Point3(b.x, b.y, b.z),
                        Point3(c.x, c.y, c.z), Point3(p.x, p.y, p.z));
  if (side == CGAL::COPLANAR) return Meets::kOnSurface;
  return side != normal ? Meets::kCrosses : Meets::kMiss;
}

// Whether p lies within the box of face f across the ray along +axis and
// not beyond it along the ray.
bool in_reach(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& p,
              int axis) {
  const int u = (axis + 1) % 3;
  const int v = (axis + 2) % 3;
  return p[u] >= lo[u] && p[u] <= hi[u] && p[v] >= lo[v] && p[v] <= hi[v] &&
         hi[axis] >= p[axis];
}

}  // namespace

std::optional<RaySide> side_by_ray(const RaySurface& surface,
                                   const glm::dvec3& p, int axis) {
  const TriangleMesh& mesh = *surface.mesh;
  bool inside = false;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (!in_reach(surface.box_min[f], surface.box_max[f], p, axis)) continue;
    switch (meets(mesh, f, p, axis)) {
      case Meets::kMiss:
        break;
      case Meets::kCrosses:
        inside = !inside;
        break;
      case Meets::kAmbiguous:
        return std::nullopt;
      case Meets::kOnSurface:
        return RaySide::kOnSurface;
    }
  }
  return inside ? RaySide::kInside : RaySide::kOutside;
}

std::vector<std::optional<RaySide>> sides_by_ray(
    const TriangleMesh& mesh, const std::vector<glm::dvec3>& points, int axis) {
  const int u = (axis + 1) % 3;
  const int v = (axis + 2) % 3;
  std::vector<std::optional<RaySide>> out(points.size(), RaySide::kOutside);
  if (points.empty() || mesh.triangles.empty()) return out;
  // The points in square cells over their shadow, about one a cell.
  double lo_u = points[0][u];
  double lo_v = points[0][v];
  double hi_u = lo_u;
  double hi_v = lo_v;
  for (const glm::dvec3& p : points) {
    lo_u = std::min(lo_u, p[u]);
    lo_v = std::min(lo_v, p[v]);
    hi_u = std::max(hi_u, p[u]);
    hi_v = std::max(hi_v, p[v]);
  }
  const double count = static_cast<double>(points.size());
  const double cell_mm =
      std::max({std::sqrt((hi_u - lo_u) * (hi_v - lo_v) / count),
                std::max(hi_u - lo_u, hi_v - lo_v) / count, 1e-300});
  // Monotone in the coordinate (a difference and a division, rounded), so
  // that a point within a face's box lies in one of the box's cells.
  const int cells_u = static_cast<int>(std::floor((hi_u - lo_u) / cell_mm)) + 1;
  const int cells_v = static_cast<int>(std::floor((hi_v - lo_v) / cell_mm)) + 1;
  // Clamped before the conversion: a face far larger than the points'
  // shadow reaches cells beyond the range of int.
  const auto cell = [&](double x, double origin, int cells) {
    return static_cast<int>(std::clamp(std::floor((x - origin) / cell_mm), 0.0,
                                       static_cast<double>(cells - 1)));
  };
  const std::size_t cells =
      static_cast<std::size_t>(cells_u) * static_cast<std::size_t>(cells_v);
  std::vector<std::uint32_t> first(cells + 1, 0);
  std::vector<std::size_t> cell_of(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    cell_of[i] = static_cast<std::size_t>(cell(points[i][u], lo_u, cells_u)) *
                     static_cast<std::size_t>(cells_v) +
                 static_cast<std::size_t>(cell(points[i][v], lo_v, cells_v));
    ++first[cell_of[i] + 1];
  }
  for (std::size_t k = 0; k < cells; ++k) first[k + 1] += first[k];
  std::vector<std::uint32_t> in_cell(points.size());
  std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
  for (std::size_t i = 0; i < points.size(); ++i) {
    in_cell[next[cell_of[i]]++] = static_cast<std::uint32_t>(i);
  }
  // Per point: crossings so far (parity), and whether its ray met an edge
  // or a vertex, or a face that holds it.
  std::vector<char> inside(points.size(), 0);
  std::vector<char> ambiguous(points.size(), 0);
  std::vector<char> on_surface(points.size(), 0);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    const glm::dvec3& a = mesh.vertices[t[0]];
    const glm::dvec3& b = mesh.vertices[t[1]];
    const glm::dvec3& c = mesh.vertices[t[2]];
    const glm::dvec3 lo = glm::min(glm::min(a, b), c);
    const glm::dvec3 hi = glm::max(glm::max(a, b), c);
    if (hi[u] < lo_u || lo[u] > hi_u || hi[v] < lo_v || lo[v] > hi_v) continue;
    const int u0 = cell(lo[u], lo_u, cells_u);
    const int u1 = cell(hi[u], lo_u, cells_u);
    const int v0 = cell(lo[v], lo_v, cells_v);
    const int v1 = cell(hi[v], lo_v, cells_v);
    for (int i = u0; i <= u1; ++i) {
      const std::size_t row =
          static_cast<std::size_t>(i) * static_cast<std::size_t>(cells_v);
      for (std::uint32_t e = first[row + static_cast<std::size_t>(v0)];
           e < first[row + static_cast<std::size_t>(v1) + 1]; ++e) {
        const std::uint32_t k = in_cell[e];
        const glm::dvec3& p = points[k];
        if (!in_reach(lo, hi, p, axis)) continue;
        switch (meets(mesh, f, p, axis)) {
          case Meets::kMiss:
            break;
          case Meets::kCrosses:
            inside[k] = inside[k] == 0 ? 1 : 0;
            break;
          case Meets::kAmbiguous:
            ambiguous[k] = 1;
            break;
          case Meets::kOnSurface:
            on_surface[k] = 1;
            break;
        }
      }
    }
  }
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (ambiguous[k] != 0) {
      out[k] = std::nullopt;
    } else if (on_surface[k] != 0) {
      out[k] = RaySide::kOnSurface;
    } else {
      out[k] = inside[k] != 0 ? RaySide::kInside : RaySide::kOutside;
    }
  }
  return out;
}

}  // namespace lsolid::exact_union
