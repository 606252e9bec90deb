// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "cgal/triangle_pair.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "cgal/exact_checks.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::box_mesh;

std::vector<IndexedTriangle> indexed(const TriangleMesh& mesh) {
  std::vector<IndexedTriangle> out;
  for (const auto& t : mesh.triangles) {
    out.push_back(IndexedTriangle{
        t, {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]}});
  }
  return out;
}

// Two boxes in one mesh, the second shifted by `by`.
TriangleMesh two_boxes(const glm::dvec3& by) {
  TriangleMesh mesh = box_mesh({0, 0, 0}, {2, 2, 2});
  append(mesh, box_mesh(by, by + glm::dvec3(2, 2, 2)));
  return mesh;
}

TEST(TrianglePair, FindsNoPairOnAClosedSurface) {
  EXPECT_TRUE(
      intersecting_pairs(indexed(box_mesh({0, 0, 0}, {1, 2, 3}))).empty());
}

TEST(TrianglePair, FindsThePairsOfOverlappingBoxesAsCgalDoes) {
  for (const glm::dvec3& by :
       {glm::dvec3(1, 1, 1), glm::dvec3(1, 0.5, 0.25),
        // Face on face: coplanar triangles that overlap meet.
        glm::dvec3(2, 0.5, 0.5), glm::dvec3(2, 0, 0)}) {
    const TriangleMesh mesh = two_boxes(by);
    const auto pairs = intersecting_pairs(indexed(mesh));
    EXPECT_FALSE(pairs.empty());
    EXPECT_EQ(pairs.size(),
              exact_checks(mesh, true, true).self_intersecting_pairs)
        << by.x << " " << by.y << " " << by.z;
    // The check builds a closed manifold's halfedge mesh from its faces as
    // they stand, anything else through CGAL's soup repair: the same pairs.
    EXPECT_EQ(exact_checks(mesh, true, false).self_intersecting_pairs,
              pairs.size());
    for (const auto& [f, g] : pairs) {
      // Each box is a closed surface: a pair takes one triangle of each.
      EXPECT_TRUE((f < 12u) != (g < 12u)) << f << " " << g;
    }
  }
  EXPECT_TRUE(intersecting_pairs(indexed(two_boxes({3, 0, 0}))).empty());
}

TEST(TrianglePair, TestsNoPairOfTwoSettledTrianglesAndEveryOther) {
  const TriangleMesh mesh = two_boxes({1, 0.5, 0.25});
  const std::vector<IndexedTriangle> triangles = indexed(mesh);
  const auto all = intersecting_pairs(triangles);
  ASSERT_FALSE(all.empty());
  // The first box's faces settled: every pair takes one face of each box,
  // so all are still found.
  std::vector<char> settled(triangles.size(), 0);
  for (std::size_t i = 0; i < 12; ++i) settled[i] = 1;
  EXPECT_EQ(intersecting_pairs(triangles, settled), all);
  // Both settled (as a pass of rounding would never leave them): none is.
  settled.assign(triangles.size(), 1);
  EXPECT_TRUE(intersecting_pairs(triangles, settled).empty());
}

TEST(TrianglePair, ReportsADegenerateTriangleAloneAndLeavesItOut) {
  TriangleMesh mesh = box_mesh({0, 0, 0}, {1, 1, 1});
  // Collinear corners across the box's bottom face.
  mesh.vertices.push_back({0.5, 0.5, 0});
  mesh.vertices.push_back({0.25, 0.25, 0});
  mesh.triangles.push_back({0, 9, 8});
  const auto pairs = intersecting_pairs(indexed(mesh));
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].first, 12u);
  EXPECT_EQ(pairs[0].second, 12u);
}

TEST(TrianglePair, TellsAFoldFromNeighboursAlongTheirEdge) {
  const glm::dvec3 a(0, 0, 0);
  const glm::dvec3 b(1, 0, 0);
  const IndexedTriangle first{{0, 1, 2}, {a, b, glm::dvec3(0, 1, 0)}};
  const IndexedTriangle flat{{1, 0, 3}, {b, a, glm::dvec3(0, -1, 0)}};
  const IndexedTriangle folded{{1, 0, 3}, {b, a, glm::dvec3(0.5, 1, 0)}};
  EXPECT_FALSE(triangles_intersect(first, flat));
  EXPECT_TRUE(triangles_intersect(first, folded));
  EXPECT_EQ(intersecting_pairs({first, folded}).size(), 1u);
}

TEST(TrianglePair, TellsTrianglesRoundOneCornerApartFromOverlapping) {
  const glm::dvec3 o(0.1, 0.2, 0.3);
  const auto at = [&](double x, double y, double z) {
    return o + glm::dvec3(x, y, z);
  };
  const IndexedTriangle first{{0, 1, 2}, {o, at(1, 0, 0), at(1, 1, 0)}};
  // Round the corner in one plane: the next but one of a fan, and one
  // overlapping the first.
  const IndexedTriangle beyond{{0, 3, 4}, {o, at(0, 1, 0), at(-1, 1, 0)}};
  const IndexedTriangle over{{0, 3, 4}, {o, at(1, 0.5, 0), at(0, 1, 0)}};
  // Out of the plane: below the first, then through it.
  const IndexedTriangle below{{0, 3, 4}, {o, at(0.5, 0.8, -1), at(0, 1, -1)}};
  const IndexedTriangle through{{0, 3, 4},
                                {o, at(0.9, 0.5, -1), at(0.9, 0.5, 1)}};
  // Seen from above, one lies over the other's sector; they only meet at
  // the corner since it rises away.
  const IndexedTriangle above{{0, 3, 4}, {o, at(1, 0.2, 1), at(1, 0.8, 1)}};
  EXPECT_FALSE(triangles_intersect(first, beyond));
  EXPECT_FALSE(triangles_intersect(beyond, first));
  EXPECT_TRUE(triangles_intersect(first, over));
  EXPECT_TRUE(triangles_intersect(over, first));
  EXPECT_FALSE(triangles_intersect(first, below));
  EXPECT_TRUE(triangles_intersect(first, through));
  EXPECT_TRUE(triangles_intersect(through, first));
  EXPECT_FALSE(triangles_intersect(first, above));
  EXPECT_FALSE(triangles_intersect(above, first));
}

TEST(TrianglePair, FindsThePairsOfAFoldedFanAsCgalDoes) {
  // A flat fan of 24 triangles round a centre, then the same fan with every
  // third rim point pushed across its neighbour: coplanar overlaps round
  // one corner that the projection alone must not clear.
  for (const bool folded : {false, true}) {
    TriangleMesh mesh;
    mesh.vertices.push_back({0.3, 0.7, 1.1});
    constexpr int kRim = 24;
    for (int i = 0; i < kRim; ++i) {
      double angle = 2.0 * std::numbers::pi * i / kRim;
      if (folded && i % 3 == 0) angle += 2.5 * 2.0 * std::numbers::pi / kRim;
      mesh.vertices.push_back(
          {0.3 + std::cos(angle), 0.7 + std::sin(angle), 1.1});
    }
    for (std::uint32_t i = 0; i < kRim; ++i) {
      mesh.triangles.push_back({0, 1 + i, 1 + (i + 1) % kRim});
    }
    const auto pairs = intersecting_pairs(indexed(mesh));
    EXPECT_EQ(pairs.size(),
              exact_checks(mesh, true, false).self_intersecting_pairs)
        << folded;
    EXPECT_EQ(pairs.empty(), !folded);
  }
}

// Two triangles apart (round % 3 == 0), two along an edge (the second
// running it the other way, as in a mesh), or an open fan of three round one
// vertex, whose first and last share only that vertex (two triangles alone
// would pinch it, which CGAL's conversion splits), on six points of `point`.
template <typename Point>
TriangleMesh random_pair_or_fan(int round, Point point) {
  TriangleMesh mesh;
  mesh.vertices = {point(), point(), point(), point(), point(), point()};
  switch (round % 3) {
    case 0:
      mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
      break;
    case 1:
      mesh.triangles = {{0, 1, 2}, {1, 0, 3}};
      break;
    default:
      mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
  }
  return mesh;
}

// The pairs of the mesh's triangles that proper_triangles_intersect finds
// meeting.
std::size_t meeting_pairs(const std::vector<IndexedTriangle>& t) {
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    for (std::size_t j = i + 1; j < t.size(); ++j) {
      pairs += proper_triangles_intersect(t[i], t[j]) ? 1 : 0;
    }
  }
  return pairs;
}

// Compares proper_triangles_intersect with CGAL's self-intersection test on
// 3,000 random pairs and fans of `point`, none degenerate, of which some
// but not most meet.
template <typename Point>
void expect_answers_as_cgal(Point point) {
  int compared = 0;
  int meeting = 0;
  for (int round = 0; round < 3000; ++round) {
    const TriangleMesh mesh = random_pair_or_fan(round, point);
    const std::vector<IndexedTriangle> t = indexed(mesh);
    if (std::any_of(t.begin(), t.end(), is_degenerate)) continue;
    ++compared;
    const std::size_t pairs = meeting_pairs(t);
    meeting += pairs > 0 ? 1 : 0;
    EXPECT_EQ(pairs, exact_checks(mesh, true, false).self_intersecting_pairs)
        << round;
  }
  EXPECT_GT(compared, 1000);
  EXPECT_GT(meeting, 100);
  EXPECT_LT(meeting, compared - 100);
}

TEST(TrianglePair, AnswersForProperTrianglesAsCgalDoes) {
  // Random triangles on a coarse lattice (so that many touch or lie in one
  // plane). None degenerate, the pairs that meet are those CGAL's
  // self-intersection test finds in a mesh of them.
  std::mt19937 random(7);
  std::uniform_int_distribution<int> coordinate(0, 3);
  const auto point = [&] {
    return glm::dvec3(coordinate(random), coordinate(random),
                      coordinate(random));
  };
  expect_answers_as_cgal(point);
}

TEST(TrianglePair, AnswersForNearlyCoplanarTrianglesAsCgalDoes) {
  // The test first tries to show a triangle's free corners strictly on one
  // side of the other's plane in double arithmetic, within an error bound.
  // Points of a lattice on a tilted plane near 40 mm, rounded to doubles and
  // each coordinate moved by up to one unit in the last place: corners
  // within a few ulps of each other's planes, where the arithmetic's sign
  // can be wrong and the bound must give way to the exact tests.
  std::mt19937 random(11);
  std::uniform_int_distribution<int> step(0, 3);
  std::uniform_int_distribution<int> ulps(-1, 1);
  const glm::dvec3 origin(40.0, 40.0, 40.0);
  const glm::dvec3 u(0.37, 0.61, -0.23);
  const glm::dvec3 v(-0.52, 0.19, 0.44);
  const auto nudged = [&](double x) {
    const int steps = ulps(random);
    return steps == 0 ? x : std::nextafter(x, steps > 0 ? 1e9 : -1e9);
  };
  const auto point = [&] {
    const glm::dvec3 p =
        origin + u * (step(random) / 3.0) + v * (step(random) / 3.0);
    return glm::dvec3(nudged(p.x), nudged(p.y), nudged(p.z));
  };
  expect_answers_as_cgal(point);
}

}  // namespace
}  // namespace lsolid
