// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "kernel.hpp"

#include "cgal/orientation.hpp"

namespace lsolid {
namespace {

Inexact::Point_3 point(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

Inexact::Point_2 projected(const glm::dvec3& p, int axis) {
  return {p[(axis + 1) % 3], p[(axis + 2) % 3]};
}

}  // namespace

int orientation_3(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                  const glm::dvec3& d) {
  return static_cast<int>(
      CGAL::orientation(point(a), point(b), point(c), point(d)));
}

int projected_orientation(const glm::dvec3& a, const glm::dvec3& b,
                          const glm::dvec3& c, int axis) {
  return static_cast<int>(CGAL::orientation(
      projected(a, axis), projected(b, axis), projected(c, axis)));
}

}  // namespace lsolid
