// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "cgal/part_queries.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

#include "cgal/triangle_pair.hpp"
#include "lsolid/errors.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::box_mesh;

TEST(PartQueries, GivesTheHullOfTheCornersOutwardAndLeavesInnerPointsOut) {
  const std::vector<glm::dvec3> points{{0, 0, 0}, {2, 0, 0}, {0, 3, 0},
                                       {2, 3, 0}, {0, 0, 4}, {2, 0, 4},
                                       {0, 3, 4}, {2, 3, 4}, {1, 1, 1}};
  TriangleMesh hull;
  hull.vertices = points;
  for (const auto& t : convex_hull_triangles(points)) {
    hull.triangles.push_back(t);
    EXPECT_EQ(std::count(t.begin(), t.end(), 8U), 0);
  }
  EXPECT_EQ(hull.triangles.size(), 12U);
  EXPECT_DOUBLE_EQ(signed_volume(hull), 24.0);
}

// Every pair of triangles tested, one by one, against the search's answer:
// the same pairs, each (i, j) with i < j, in increasing order.
TEST(PartQueries, FindsEveryCrossingPairOfAPartInOrder) {
  TriangleMesh mesh = box_mesh({0, 0, 0}, {2, 2, 2});
  append(mesh, box_mesh({1.1, 0.7, 0.3}, {3.2, 1.6, 2.5}));
  std::vector<std::pair<std::uint32_t, std::uint32_t>> expected;
  for (std::uint32_t i = 0; i < mesh.triangles.size(); ++i) {
    for (std::uint32_t j = i + 1; j < mesh.triangles.size(); ++j) {
      const auto& a = mesh.triangles[i];
      const auto& b = mesh.triangles[j];
      const IndexedTriangle ta{
          a, {mesh.vertices[a[0]], mesh.vertices[a[1]], mesh.vertices[a[2]]}};
      const IndexedTriangle tb{
          b, {mesh.vertices[b[0]], mesh.vertices[b[1]], mesh.vertices[b[2]]}};
      if (triangles_intersect(ta, tb)) expected.emplace_back(i, j);
    }
  }
  EXPECT_FALSE(expected.empty());
  EXPECT_EQ(intersecting_triangle_pairs(mesh), expected);
  EXPECT_TRUE(
      intersecting_triangle_pairs(box_mesh({0, 0, 0}, {1, 1, 1})).empty());
}

TEST(PartQueries, RefusesTrianglesThatFormNoOrientedSurface) {
  TriangleMesh mesh = box_mesh({0, 0, 0}, {1, 1, 1});
  std::swap(mesh.triangles[0][1], mesh.triangles[0][2]);
  EXPECT_THROW((void)intersecting_triangle_pairs(mesh), GeometryError);
}

}  // namespace
}  // namespace lsolid
