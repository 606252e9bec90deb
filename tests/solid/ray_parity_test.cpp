// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "cgal/union/ray_parity.hpp"

#include <gtest/gtest.h>

#include <random>

#include "support/mesh_checks.hpp"

namespace lsolid::exact_union {
namespace {

using lsolid::testing::box_mesh;

// A box with a box-shaped hole inside (the inner surface turned inward):
// points in the wall are inside, points in the hole outside.
TriangleMesh hollow_box() {
  return lsolid::testing::box_with_cavity({0, 0, 0}, {4, 4, 4}, {1, 1, 1},
                                          {3, 3, 3});
}

std::optional<RaySide> first_decided(const RaySurface& surface,
                                     const glm::dvec3& p) {
  for (int axis = 0; axis < 3; ++axis) {
    if (const auto side = side_by_ray(surface, p, axis)) return side;
  }
  return std::nullopt;
}

TEST(RayParity, TellsTheWallFromTheHoleAndTheOutside) {
  const TriangleMesh mesh = hollow_box();
  const RaySurface surface = ray_surface(mesh);
  EXPECT_EQ(first_decided(surface, {0.5, 0.7, 0.3}), RaySide::kInside);
  EXPECT_EQ(first_decided(surface, {3.6, 2.1, 1.3}), RaySide::kInside);
  EXPECT_EQ(first_decided(surface, {2.1, 1.7, 2.3}), RaySide::kOutside);
  EXPECT_EQ(first_decided(surface, {-0.5, 1.7, 2.3}), RaySide::kOutside);
  EXPECT_EQ(first_decided(surface, {5.5, 1.7, 2.3}), RaySide::kOutside);
}

TEST(RayParity, AgreesWithTheBoxesOnRandomPoints) {
  const TriangleMesh mesh = hollow_box();
  const RaySurface surface = ray_surface(mesh);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-1.0, 5.0);
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 p(coordinate(random), coordinate(random),
                       coordinate(random));
    const auto within = [&](double lo, double hi) {
      return p.x > lo && p.x < hi && p.y > lo && p.y < hi && p.z > lo &&
             p.z < hi;
    };
    const RaySide expected =
        within(0, 4) && !within(1, 3) ? RaySide::kInside : RaySide::kOutside;
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_EQ(side_by_ray(surface, p, axis), expected) << i << " " << axis;
    }
  }
}

TEST(RayParity, GivesNoAnswerForARayThroughAnEdgeAndFindsPointsOnTheSurface) {
  const TriangleMesh mesh = box_mesh({0, 0, 0}, {4, 4, 4});
  const RaySurface surface = ray_surface(mesh);
  // box_mesh cuts the face x = 0 along y + z = 4: a ray along x through
  // (y, z) = (1, 3) meets that edge, one in the plane y = 0 runs in a face;
  // a ray along y from the first point decides.
  EXPECT_FALSE(side_by_ray(surface, {-1, 1, 3}, 0).has_value());
  EXPECT_FALSE(side_by_ray(surface, {-1, 0, 2}, 0).has_value());
  EXPECT_EQ(side_by_ray(surface, {-1, 1, 3}, 1), RaySide::kOutside);
  EXPECT_EQ(side_by_ray(surface, {1.2, 1, 2.5}, 1), RaySide::kInside);
  // On the top face and on the side x = 4, off their diagonals.
  EXPECT_EQ(first_decided(surface, {1.3, 2.9, 4}), RaySide::kOnSurface);
  EXPECT_EQ(first_decided(surface, {4, 1.7, 2.6}), RaySide::kOnSurface);
}

TEST(RayParity, AnswersManyPointsAtOnceAsOneByOne) {
  // The hollow box and a long thin box beside it: faces of very different
  // sizes, and points beyond the surface's shadow.
  TriangleMesh mesh = hollow_box();
  append(mesh, box_mesh({-3, 5, 1.5}, {7, 5.5, 2.5}));
  const RaySurface surface = ray_surface(mesh);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(-4.0, 8.0);
  std::vector<glm::dvec3> points;
  for (int i = 0; i < 3000; ++i) {
    points.emplace_back(coordinate(random), coordinate(random),
                        coordinate(random));
  }
  for (int axis = 0; axis < 3; ++axis) {
    const std::vector<std::optional<RaySide>> sides =
        sides_by_ray(mesh, points, axis);
    ASSERT_EQ(sides.size(), points.size());
    int inside = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      EXPECT_EQ(sides[i], side_by_ray(surface, points[i], axis))
          << i << " " << axis;
      inside += sides[i] == RaySide::kInside ? 1 : 0;
    }
    // The solid holds 56 + 10 of the sampled cube's 1,728 units.
    EXPECT_NEAR(inside, 3000 * 66.0 / 1728.0, 40) << axis;
  }
}

TEST(RayParity, AnswersManyPointsThroughEdgesAndOnTheSurfaceAsOneByOne) {
  const TriangleMesh mesh = box_mesh({0, 0, 0}, {4, 4, 4});
  const std::vector<glm::dvec3> points{
      {-1, 1, 3}, {-1, 0, 2}, {1.2, 1, 2.5}, {4, 1.7, 2.6}, {1, 5, 1}};
  const std::vector<std::optional<RaySide>> along_x =
      sides_by_ray(mesh, points, 0);
  EXPECT_FALSE(along_x[0].has_value());
  EXPECT_FALSE(along_x[1].has_value());
  EXPECT_EQ(along_x[2], RaySide::kInside);
  EXPECT_EQ(along_x[3], RaySide::kOnSurface);
  EXPECT_EQ(along_x[4], RaySide::kOutside);
  const std::vector<std::optional<RaySide>> along_y =
      sides_by_ray(mesh, points, 1);
  EXPECT_EQ(along_y[0], RaySide::kOutside);
  EXPECT_EQ(along_y[2], RaySide::kInside);
  // Along the side x = 4 that holds the point: no answer, as one by one.
  EXPECT_FALSE(along_y[3].has_value());
  EXPECT_FALSE(side_by_ray(ray_surface(mesh), points[3], 1).has_value());
  EXPECT_TRUE(sides_by_ray(mesh, {}, 2).empty());
}

}  // namespace
}  // namespace lsolid::exact_union
