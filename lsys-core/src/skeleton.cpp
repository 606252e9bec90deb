// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/skeleton.hpp"

namespace lsys {

Bounds bounds(const Skeleton& skeleton) {
  Bounds box;
  const auto grow = [&](const glm::dvec3& p) { box.add(p); };
  for (const Segment& s : skeleton.segments) {
    grow(s.p0);
    grow(s.p1);
  }
  for (const Polygon& polygon : skeleton.polygons) {
    for (const glm::dvec3& p : polygon.points) grow(p);
  }
  for (const Sphere& ball : skeleton.spheres) {
    grow(ball.center - glm::dvec3(ball.diameter / 2.0));
    grow(ball.center + glm::dvec3(ball.diameter / 2.0));
  }
  for (const Sheet& sheet : skeleton.sheets) {
    for (const glm::dvec3& p : sheet.points) grow(p);
  }
  return box;
}

}  // namespace lsys
