// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "cgal/orientation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/vec3.hpp>

namespace lsolid {
namespace {

TEST(Orientation, TellsTheSideOfAPlaneByTheRightHandRule) {
  const glm::dvec3 a(0.0, 0.0, 0.0);
  const glm::dvec3 b(1.0, 0.0, 0.0);
  const glm::dvec3 c(0.0, 1.0, 0.0);
  EXPECT_EQ(orientation_3(a, b, c, {0.3, 0.3, 1.0}), 1);
  EXPECT_EQ(orientation_3(a, b, c, {0.3, 0.3, -1e-300}), -1);
  EXPECT_EQ(orientation_3(a, b, c, {5.0, -7.0, 0.0}), 0);
}

// Kettner et al., "Classroom examples of robustness problems in geometric
// computations": a point one unit in the last place off the line through
// (12, 12) and (24, 24). In doubles the differences round it onto the line
// ((12 − 0.5 − 2⁻⁵³) is 11.5); the exact determinant is −12 · 2⁻⁵³.
TEST(Orientation, DecidesExactlyWhereDoublesCannot) {
  const double u = std::ldexp(1.0, -53);
  const glm::dvec3 a(0.5 + u, 0.5, 0.0);
  const glm::dvec3 b(12.0, 12.0, 0.0);
  const glm::dvec3 c(24.0, 24.0, 0.0);
  const double naive = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  ASSERT_EQ(naive, 0.0);
  EXPECT_EQ(projected_orientation(a, b, c, 2), -1);
  EXPECT_EQ(orientation_3(a, b, c, {0.0, 0.0, 1.0}), -1);
  EXPECT_EQ(projected_orientation({0.5, 0.5, 0.0}, b, c, 2), 0);
}

TEST(Orientation, ProjectsAlongEachAxisInCyclicOrder) {
  // A triangle turning counter-clockwise about (1, 1, 1): seen along each
  // axis, its normal's coordinate there is positive.
  const glm::dvec3 a(1.0, 0.0, 0.0);
  const glm::dvec3 b(0.0, 1.0, 0.0);
  const glm::dvec3 c(0.0, 0.0, 1.0);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_EQ(projected_orientation(a, b, c, axis), 1) << axis;
    EXPECT_EQ(projected_orientation(a, c, b, axis), -1) << axis;
  }
  // Seen along its own plane a triangle is a line.
  EXPECT_EQ(projected_orientation({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0},
                                  {0.0, 0.0, 1.0}, 2),
            0);
}

}  // namespace
}  // namespace lsolid
