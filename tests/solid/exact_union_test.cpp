// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "cgal/union/exact_union.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <set>
#include <vector>

#include "lsolid/boolean.hpp"
#include "lsolid/parts.hpp"
#include "lsolid/validate.hpp"
#include "shells.hpp"
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
  const PairUnion u =
      unite_pair(box_mesh({0, 0, 0}, {2, 2, 2}),
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
  const TriangleMesh a =
      prism({-3, 0.01, 0.02}, {3, 0.03, -0.01}, 1.0, 12, 0.1);
  const TriangleMesh b =
      prism({0.02, -3, 0.01}, {-0.01, 3, 0.03}, 0.8, 10, 0.2);
  ASSERT_GT(signed_volume(a), 0.0);
  const PairUnion u = unite_pair(a, b, filters);
  ASSERT_TRUE(u.failure.empty()) << u.failure;
  expect_printable(u.mesh);
  EXPECT_GT(signed_volume(u.mesh), signed_volume(a));
  EXPECT_LT(signed_volume(u.mesh), signed_volume(a) + signed_volume(b));
}

// Random prisms in a 10 mm box, as the tubes of a tree meet: rings of 6 to
// 16 sides, radii 0.3 to 1.5 mm, turned at random.
std::vector<Part> random_tubes(unsigned seed, int count) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coordinate(0.0, 10.0);
  std::uniform_real_distribution<double> radius(0.3, 1.5);
  std::uniform_real_distribution<double> phase(0.0, 1.0);
  std::uniform_int_distribution<int> sides(6, 16);
  std::vector<Part> parts;
  for (int i = 0; i < count; ++i) {
    const glm::dvec3 a(coordinate(random), coordinate(random),
                       coordinate(random));
    glm::dvec3 b(coordinate(random), coordinate(random), coordinate(random));
    b = a + 0.5 * (b - a);
    std::string label = "tube ";
    label += std::to_string(i);
    parts.push_back(
        {prism(a, b, radius(random), sides(random), phase(random)), label});
  }
  return parts;
}

// The Euler characteristic of a closed triangle mesh, V − E + F.
long euler_characteristic(const TriangleMesh& m) {
  return static_cast<long>(m.vertices.size()) -
         static_cast<long>(m.triangles.size()) / 2;
}

TEST(ExactUnion, AgreesWithTheCorefinementOnRandomTubes) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const std::vector<Part> parts = random_tubes(seed, 40);
    const UnionResult exact =
        union_parts(parts, {.engine = UnionEngine::ExactCrossings});
    const UnionResult oracle =
        union_parts(parts, {.engine = UnionEngine::Corefinement});
    SCOPED_TRACE(seed);
    EXPECT_GT(exact.stats.exact_unions, 0U);
    EXPECT_EQ(exact.stats.fallbacks, 0U) << exact.stats.fallback_reason;
    EXPECT_EQ(exact.stats.degenerate_unions, 0U)
        << exact.stats.degenerate_reason;
    const double volume = signed_volume(oracle.mesh);
    EXPECT_NEAR(signed_volume(exact.mesh), volume, 1e-9 * volume);
    EXPECT_EQ(label_shells(exact.mesh).count, label_shells(oracle.mesh).count);
    EXPECT_EQ(euler_characteristic(exact.mesh),
              euler_characteristic(oracle.mesh));
    const ValidationReport check = validate(exact.mesh);
    EXPECT_EQ(check.boundary_edges, 0U);
    EXPECT_EQ(check.non_manifold_edges, 0U);
    EXPECT_EQ(check.non_manifold_vertices, 0U);
    EXPECT_EQ(check.genus, validate(oracle.mesh).genus);
  }
}

TEST(ExactUnion, CountsItsPredicatesAndDecidesMostInIntervals) {
  const UnionResult u = union_parts(random_tubes(7, 40));
  EXPECT_GT(u.stats.predicates, 1000U);
  EXPECT_LT(static_cast<double>(u.stats.filter_failures),
            0.1 * static_cast<double>(u.stats.predicates));
  EXPECT_GT(u.stats.crossings, 0U);
  EXPECT_GT(u.stats.cut_faces, 0U);
}

// Two cubes whose faces' diagonals cross exactly where the other's edges
// pass: a degeneracy where the faces cross each other's planes.
TEST(ExactUnion, SaysWhereFacesCrossAtACoincidence) {
  FilterCounters filters;
  const PairUnion u = unite_pair(box_mesh({0, 0, 0}, {2, 2, 2}),
                                 box_mesh({1, 1, 1}, {3, 3, 3}), filters);
  EXPECT_TRUE(u.degenerate);
  EXPECT_TRUE(u.transversal);
  EXPECT_EQ(u.failure, "an edge passes through an edge");
}

TEST(ExactUnion, ShiftsACoincidenceWhereFacesCrossAway) {
  std::vector<Part> parts{{box_mesh({0, 0, 0}, {2, 2, 2}), "a"},
                          {box_mesh({1, 1, 1}, {3, 3, 3}), "b"}};
  const UnionResult u = union_parts(std::move(parts));
  EXPECT_EQ(u.stats.degenerate_unions, 0U) << u.stats.degenerate_reason;
  EXPECT_EQ(u.stats.exact_unions, 1U);
  EXPECT_EQ(u.stats.retries, 1U);
  // One cube moved by 10⁻⁸ mm along (1, 0.618, 0.382): the overlap, a unit
  // cube, changes by about the sum of the shift's components.
  EXPECT_NEAR(std::abs(signed_volume(u.mesh) - 15.0), 2e-8, 1e-9);
  expect_printable(u.mesh);
}

TEST(ExactUnion, LeavesFacesThatTouchToTheCorefinementWhichUnitesThemExactly) {
  std::vector<Part> parts{{box_mesh({0, 0, 0}, {2, 2, 2}), "a"},
                          {box_mesh({2, 0.5, 0.5}, {3, 1.5, 1.5}), "b"}};
  const UnionResult u = union_parts(std::move(parts));
  EXPECT_EQ(u.stats.degenerate_unions, 1U);
  EXPECT_EQ(u.stats.exact_unions, 0U);
  EXPECT_EQ(u.stats.retries, 0U);
  EXPECT_NE(u.stats.degenerate_reason.find(" with "), std::string::npos)
      << u.stats.degenerate_reason;
  EXPECT_NE(u.stats.degenerate_reason.find(": faces touch"), std::string::npos)
      << u.stats.degenerate_reason;
  EXPECT_DOUBLE_EQ(signed_volume(u.mesh), 9.0);
  EXPECT_EQ(label_shells(u.mesh).count, 1U);
}

// The faces with no new corner are the operands' own faces, whole; every
// other face has a corner that is no vertex of either operand.
TEST(ExactUnion, TellsThePiecesOfCutFacesByTheirNewCorners) {
  const TriangleMesh a = prism({0, 0, 0}, {4, 0.3, 0.2}, 1.0, 12, 0.1);
  const TriangleMesh b = prism({2, -3, 0.1}, {2.2, 3, -0.3}, 0.7, 9, 0.4);
  FilterCounters filters;
  const PairUnion u = unite_pair(a, b, filters);
  ASSERT_TRUE(u.failure.empty()) << u.failure;
  std::set<std::array<double, 3>> operand_points;
  std::set<std::array<std::array<double, 3>, 3>> operand_faces;
  for (const TriangleMesh* m : {&a, &b}) {
    for (const glm::dvec3& p : m->vertices)
      operand_points.insert({p.x, p.y, p.z});
    for (const auto& t : m->triangles) {
      std::array<std::array<double, 3>, 3> corners;
      for (int i = 0; i < 3; ++i) {
        const glm::dvec3& p = m->vertices[t[i]];
        corners[i] = {p.x, p.y, p.z};
      }
      std::rotate(corners.begin(),
                  std::min_element(corners.begin(), corners.end()),
                  corners.end());
      operand_faces.insert(corners);
    }
  }
  std::size_t cut = 0;
  for (std::uint32_t f = 0; f < u.mesh.triangles.size(); ++f) {
    std::array<std::array<double, 3>, 3> corners;
    bool all_operand = true;
    for (int i = 0; i < 3; ++i) {
      const glm::dvec3& p = u.mesh.vertices[u.mesh.triangles[f][i]];
      corners[i] = {p.x, p.y, p.z};
      all_operand = all_operand && operand_points.contains(corners[i]);
    }
    std::rotate(corners.begin(),
                std::min_element(corners.begin(), corners.end()),
                corners.end());
    if (has_new_corner(u, f)) {
      ++cut;
      EXPECT_FALSE(all_operand) << f;
    } else {
      EXPECT_TRUE(operand_faces.contains(corners)) << f;
    }
  }
  EXPECT_GT(cut, 0U);
  EXPECT_LT(cut, u.mesh.triangles.size());
}

// Two boxes that touch face on are united first (the fewest faces), by the
// corefinement; the prism that crosses both is then united with their union
// by the exact engine again, as the union's points were all rounded.
TEST(ExactUnion, ReturnsToTheExactEngineAfterFacesThatTouch) {
  std::vector<Part> parts{
      {box_mesh({0, 0, 0}, {2, 2, 2}), "a"},
      {box_mesh({2, 0.5, 0.5}, {3, 1.5, 1.5}), "b"},
      {prism({1.3, -1, 1.1}, {2.7, 3, 1.2}, 0.3, 16, 0.1), "c"}};
  const UnionResult u = union_parts(parts);
  EXPECT_EQ(u.stats.degenerate_unions, 1U);
  EXPECT_EQ(u.stats.booleans, 2U);
  EXPECT_EQ(u.stats.exact_unions, 1U);
  const UnionResult oracle =
      union_parts(parts, {.engine = UnionEngine::Corefinement});
  const double volume = signed_volume(oracle.mesh);
  EXPECT_NEAR(signed_volume(u.mesh), volume, 1e-9 * volume);
  EXPECT_EQ(label_shells(u.mesh).count, 1U);
  expect_printable(u.mesh);
}

TEST(ExactUnion, RefusesFacesThatTouchAsADegeneracy) {
  FilterCounters filters;
  const PairUnion u =
      unite_pair(box_mesh({0, 0, 0}, {1, 1, 1}),
                 box_mesh({1, 0.2, 0.3}, {2, 0.7, 0.8}), filters);
  EXPECT_TRUE(u.degenerate);
  EXPECT_FALSE(u.transversal);
  EXPECT_FALSE(u.failure.empty());
}

}  // namespace
}  // namespace lsolid::exact_union
