// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The 45° rule of FDM printing: a layer may overhang the one below by about
// its own height, so faces whose normal points down more steeply than 45°
// below the horizontal need support (the default of PrusaSlicer's and
// Cura's support generators).
#include "lsolid/overhang.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace lsolid {

OverhangReport overhang(const TriangleMesh& mesh, double limit_deg) {
  OverhangReport report;
  report.triangles.assign(mesh.triangles.size(), false);
  if (mesh.triangles.empty()) return report;
  const double bed = bounds(mesh).min.z;
  constexpr double kOnBed = 1e-3;
  const double steep = std::sin(limit_deg * std::numbers::pi / 180.0);
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    const glm::dvec3& a = mesh.vertices[t[0]];
    const glm::dvec3& b = mesh.vertices[t[1]];
    const glm::dvec3& c = mesh.vertices[t[2]];
    if (std::max({a.z, b.z, c.z}) <= bed + kOnBed) continue;
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double twice_area = glm::length(n);
    if (twice_area == 0.0 || -n.z / twice_area <= steep) continue;
    report.triangles[i] = true;
    report.area_mm2 += twice_area / 2.0;
  }
  report.needs_supports = report.area_mm2 > kSupportArea;
  return report;
}

}  // namespace lsolid
