// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "union/exact_union.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <vector>

#include "lsolid/parts.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid::exact_union {
namespace {

using lsolid::testing::box_mesh;
using lsolid::testing::expect_printable;

TriangleMesh joined(const TriangleMesh& a, const TriangleMesh& b) {
  TriangleMesh out = a;
  append(out, b);
  return out;
}

// A closed prism of `sides` around the segment from a to b, its ring turned
// by `phase` radians.
TriangleMesh prism(const glm::dvec3& a, const glm::dvec3& b, double radius,
                   int sides, double phase) {
  const glm::dvec3 axis = glm::normalize(b - a);
  const glm::dvec3 helper =
      std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(axis, helper));
  const glm::dvec3 v = glm::cross(axis, u);
  TriangleMesh m;
  for (const glm::dvec3& c : {a, b}) {
    for (int i = 0; i < sides; ++i) {
      const double t = phase + 2 * std::numbers::pi * i / sides;
      m.vertices.push_back(c + radius * (std::cos(t) * u + std::sin(t) * v));
    }
  }
  m.vertices.push_back(a);
  m.vertices.push_back(b);
  const auto n = static_cast<std::uint32_t>(sides);
  const std::uint32_t ca = 2 * n;
  const std::uint32_t cb = 2 * n + 1;
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    m.triangles.push_back({i, j, n + i});
    m.triangles.push_back({j, n + j, n + i});
    m.triangles.push_back({ca, j, i});
    m.triangles.push_back({cb, n + i, n + j});
  }
  return m;
}

TEST(ExactUnion, UnitesTwoBoxesInGeneralPositionToTheirVolume) {
  FilterCounters filters;
  const PairUnion u = unite_pair(box_mesh({0, 0, 0}, {2, 2, 2}),
                                 box_mesh({1.1, 1.2, 1.3}, {3, 3.5, 4}), filters);
  ASSERT_TRUE(u.failure.empty()) << u.failure;
  expect_printable(u.mesh);
  EXPECT_NEAR(signed_volume(u.mesh), 8.0 + 1.9 * 2.3 * 2.7 - 0.9 * 0.8 * 0.7,
              1e-12);
  EXPECT_GT(u.counters.crossings, 0U);
}

TEST(ExactUnion, KeepsAPartThatNoFaceCrossesOutsideAndDropsOneInside) {
  FilterCounters filters;
  const TriangleMesh big = box_mesh({0, 0, 0}, {4, 4, 4});
  const TriangleMesh inner = box_mesh({1, 1.1, 1.2}, {2, 2.1, 2.2});
  const TriangleMesh beside = box_mesh({5, 1, 1}, {6, 2, 2});
  const PairUnion u = unite_pair(big, joined(inner, beside), filters);
  ASSERT_TRUE(u.failure.empty()) << u.failure;
  expect_printable(u.mesh, 2);
  EXPECT_NEAR(signed_volume(u.mesh), 64.0 + 1.0, 1e-12);
}

TEST(ExactUnion, UnitesCrossingPrismsAsTheirVolumeSays) {
  FilterCounters filters;
  const TriangleMesh a = prism({-3, 0.01, 0.02}, {3, 0.03, -0.01}, 1.0, 12, 0.1);
  const TriangleMesh b = prism({0.02, -3, 0.01}, {-0.01, 3, 0.03}, 0.8, 10, 0.2);
  ASSERT_GT(signed_volume(a), 0.0);
  const PairUnion u = unite_pair(a, b, filters);
  ASSERT_TRUE(u.failure.empty()) << u.failure;
  expect_printable(u.mesh);
  EXPECT_GT(signed_volume(u.mesh), signed_volume(a));
  EXPECT_LT(signed_volume(u.mesh), signed_volume(a) + signed_volume(b));
}

TEST(ExactUnion, RefusesFacesThatTouchAsADegeneracy) {
  FilterCounters filters;
  const PairUnion u = unite_pair(box_mesh({0, 0, 0}, {1, 1, 1}),
                                 box_mesh({1, 0.2, 0.3}, {2, 0.7, 0.8}), filters);
  EXPECT_TRUE(u.degenerate);
  EXPECT_FALSE(u.failure.empty());
}

}  // namespace
}  // namespace lsolid::exact_union
