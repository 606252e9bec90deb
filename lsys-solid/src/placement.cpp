// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/placement.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <numbers>
#include <optional>

#include "lsolid/parts.hpp"

namespace lsolid {
namespace {

// A model whose footprint is narrower than this share of its height tips
// over easily (a tree on its trunk, a planar figure on its edge).
constexpr double kTipping = 0.2;

// A closed cylinder with m sides around the vertical axis through `centre`
// (at z = 0), from z = 0 to `height`.
TriangleMesh disc(const glm::dvec2& centre, double radius, double height,
                  int m) {
  TriangleMesh mesh;
  for (const double z : {0.0, height}) {
    for (int i = 0; i < m; ++i) {
      const double a = 2.0 * std::numbers::pi * i / m;
      mesh.vertices.push_back({centre.x + radius * std::cos(a),
                               centre.y + radius * std::sin(a), z});
    }
  }
  const auto at = [m](int ring, int i) {
    return static_cast<std::uint32_t>(ring * m + (i + m) % m);
  };
  for (int i = 0; i < m; ++i) {
    mesh.triangles.push_back({at(0, i), at(0, i + 1), at(1, i + 1)});
    mesh.triangles.push_back({at(0, i), at(1, i + 1), at(1, i)});
  }
  for (int i = 1; i + 1 < m; ++i) {
    mesh.triangles.push_back({at(0, 0), at(0, i + 1), at(0, i)});
    mesh.triangles.push_back({at(1, 0), at(1, i), at(1, i + 1)});
  }
  return mesh;
}

void translate(std::vector<Part>& parts, const glm::dvec3& by) {
  for (Part& part : parts) {
    for (glm::dvec3& p : part.mesh.vertices) p += by;
  }
}

// The rotation taking the unit vector n to +Z: Rodrigues' formula about
// n × Z, or half a turn about X when n = -Z. A rotation keeps triangles
// outward.
glm::dvec3 turned_to_z(const glm::dvec3& n, const glm::dvec3& p) {
  const glm::dvec3 z(0.0, 0.0, 1.0);
  const double c = glm::dot(n, z);
  glm::dvec3 axis = glm::cross(n, z);
  const double s = glm::length(axis);
  if (s < 1e-12) return c > 0.0 ? p : glm::dvec3(p.x, -p.y, -p.z);
  axis /= s;
  return p * c + glm::cross(axis, p) * s + axis * glm::dot(axis, p) * (1.0 - c);
}

}  // namespace

std::optional<SkeletonPlane> skeleton_plane(const lsys::Skeleton& skeleton,
                                            double wall_mm) {
  // A ball stands out of any plane, and a sheet is curved (its thickened
  // plate is no footprint): a model with either is never flat.
  if (!skeleton.spheres.empty() || !skeleton.sheets.empty()) {
    return std::nullopt;
  }
  std::vector<glm::dvec3> points;
  double thinnest = 1e300;
  for (const lsys::Segment& s : skeleton.segments) {
    points.push_back(s.p0);
    points.push_back(s.p1);
    thinnest =
        std::min({thinnest, s.start_diameter / 2.0, s.end_diameter / 2.0});
  }
  for (const lsys::Polygon& polygon : skeleton.polygons) {
    points.insert(points.end(), polygon.points.begin(), polygon.points.end());
  }
  if (points.size() < 3) return std::nullopt;
  glm::dvec3 lo = points[0];
  glm::dvec3 hi = points[0];
  for (const glm::dvec3& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const double size = glm::length(hi - lo);
  if (size <= 0.0) return std::nullopt;
  // The normal from the farthest point from the first and the point
  // farthest from the line through both: a well-conditioned triangle.
  const glm::dvec3 a = points[0];
  glm::dvec3 b = a;
  for (const glm::dvec3& p : points) {
    if (glm::distance(p, a) > glm::distance(b, a)) b = p;
  }
  const glm::dvec3 ab = glm::normalize(b - a);
  glm::dvec3 normal(0.0);
  for (const glm::dvec3& p : points) {
    const glm::dvec3 n = glm::cross(ab, p - a);
    if (glm::length(n) > glm::length(normal)) normal = n;
  }
  if (glm::length(normal) <= 1e-6 * size) return std::nullopt;  // a line
  normal = glm::normalize(normal);
  for (const glm::dvec3& p : points) {
    if (std::fabs(glm::dot(p - a, normal)) > 1e-9 * size) return std::nullopt;
  }
  return SkeletonPlane{
      .normal = normal,
      .point = a,
      .thinnest_radius_mm =
          std::max(wall_mm / 2.0, skeleton.segments.empty() ? 0.0 : thinnest)};
}

glm::dvec3 on_bed(const Placement& placement, const glm::dvec3& p) {
  return turned_to_z(placement.plane_normal, p) + placement.moved_by_mm;
}

Placed place_on_bed(std::vector<Part> parts, const PlacementOptions& options) {
  const Base base = options.base;
  const double wall_mm = options.wall_mm;
  const std::optional<SkeletonPlane>& plane = options.plane;
  Placement placement;
  if (parts.empty()) return {.parts = std::move(parts), .placement = placement};
  if (base == Base::Auto && plane) {
    for (Part& part : parts) {
      for (glm::dvec3& p : part.mesh.vertices) {
        p = turned_to_z(plane->normal, p);
      }
    }
    const double plane_z = turned_to_z(plane->normal, plane->point).z;
    const Box box = bounds(parts);
    const glm::dvec3 move(-(box.min.x + box.max.x) / 2.0,
                          -(box.min.y + box.max.y) / 2.0, -box.min.z);
    translate(parts, move);
    placement.plane_normal = plane->normal;
    placement.moved_by_mm = move;
    placement.lies_flat = true;
    placement.cut_depth_mm = plane->thinnest_radius_mm / 2.0;
    placement.cut_z_mm =
        std::max(0.0, plane_z + move.z - placement.cut_depth_mm);
    placement.footprint_mm =
        std::min(box.max.x - box.min.x, box.max.y - box.min.y);
    return {.parts = std::move(parts), .placement = placement};
  }
  const Box box = bounds(parts);
  const glm::dvec3 move(-(box.min.x + box.max.x) / 2.0,
                        -(box.min.y + box.max.y) / 2.0, -box.min.z);
  placement.moved_by_mm = move;
  // What the model stands on: its vertices within a wall of the bottom.
  glm::dvec2 foot_min(0.0);
  glm::dvec2 foot_max(0.0);
  bool any = false;
  // The centre of mass of the parts, each weighted by its volume (overlaps
  // count twice; good enough to place a base).
  glm::dvec3 moment(0.0);
  double mass = 0.0;
  for (Part& part : parts) {
    for (glm::dvec3& p : part.mesh.vertices) {
      p += move;
      if (p.z <= wall_mm) {
        const glm::dvec2 q(p.x, p.y);
        foot_min = any ? glm::min(foot_min, q) : q;
        foot_max = any ? glm::max(foot_max, q) : q;
        any = true;
      }
    }
    for (const auto& t : part.mesh.triangles) {
      const glm::dvec3& a = part.mesh.vertices[t[0]];
      const glm::dvec3& b = part.mesh.vertices[t[1]];
      const glm::dvec3& c = part.mesh.vertices[t[2]];
      const double v = glm::dot(a, glm::cross(b, c)) / 6.0;
      moment += v * (a + b + c) / 4.0;
      mass += v;
    }
  }
  const glm::dvec2 foot = foot_max - foot_min;
  placement.footprint_mm = std::min(foot.x, foot.y);
  const double height = box.max.z - box.min.z;
  const double span = std::max(box.max.x - box.min.x, box.max.y - box.min.y);
  const bool wanted =
      base == Base::Disc ||
      (base == Base::Auto && placement.footprint_mm < kTipping * height);
  if (!wanted) return {.parts = std::move(parts), .placement = placement};
  const glm::dvec2 centre = (foot_min + foot_max) / 2.0;
  const glm::dvec2 balance =
      mass > 0.0 ? glm::dvec2(moment.x, moment.y) / mass : centre;
  const double radius =
      std::max({1.5 * glm::length(balance - centre) + 2.0 * wall_mm,
                0.25 * span, glm::length(foot) / 2.0 + 2.0 * wall_mm});
  const double thickness = std::max(2.0 * wall_mm, 1.2);
  // The foot sinks half-way into the disc, so that no face of the model
  // lies in the disc's bottom plane.
  const glm::dvec3 lift(0.0, 0.0, thickness / 2.0);
  translate(parts, lift);
  placement.moved_by_mm += lift;
  // Sides from the chord tolerance, as the tubes', but at least 32: a disc
  // is seen whole.
  const int m = std::max(32, tube_sides(radius, options.tolerance_mm));
  parts.push_back(Part{disc(centre, radius, thickness, m), "base disc"});
  // Centre the model with its base.
  const Box all = bounds(parts);
  const glm::dvec3 shift(-(all.min.x + all.max.x) / 2.0,
                         -(all.min.y + all.max.y) / 2.0, 0.0);
  translate(parts, shift);
  placement.moved_by_mm += shift;
  placement.has_base = true;
  placement.base_radius_mm = radius;
  placement.base_thickness_mm = thickness;
  return {.parts = std::move(parts), .placement = placement};
}

}  // namespace lsolid
