// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/placement.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <numbers>

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

}  // namespace

Placement place_on_bed(std::vector<Part>& parts, Base base, double wall_mm,
                       double tolerance_mm) {
  Placement placement;
  if (parts.empty()) return placement;
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
  if (!wanted) return placement;
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
  const int m = std::max(32, tube_sides(radius, tolerance_mm));
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
  return placement;
}

}  // namespace lsolid
