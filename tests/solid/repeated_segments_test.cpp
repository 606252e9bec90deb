// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/repeated_segments.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace lsolid {
namespace {

lsys::Segment segment(glm::dvec3 a, glm::dvec3 b, double d0, double d1,
                      std::int32_t parent = -1, int color = 0) {
  return lsys::Segment{a, b, d0, d1, color, parent};
}

TEST(RepeatedSegments,
     LeavesOutBranchesDrawnAgainAndHangsTheirChildrenOnTheKeptOne) {
  // F[F][F]F: the three branches from the first segment's end are one.
  lsys::Skeleton s;
  s.segments = {segment({0, 0, 0}, {0, 0, 1}, 0.2, 0.2),
                segment({0, 0, 1}, {0, 0, 2}, 0.2, 0.2, 0),
                segment({0, 0, 1}, {0, 0, 2}, 0.2, 0.2, 0),
                segment({0, 0, 1}, {0, 0, 2}, 0.2, 0.2, 0),
                // drawn on from the third copy
                segment({0, 0, 2}, {1, 0, 2}, 0.1, 0.1, 3)};
  s.polygons = {lsys::Polygon{{{0, 0, 2}, {1, 1, 2}, {0, 1, 2}}, 0, 2}};
  const WithoutRepeats w = without_repeated_segments(s);
  EXPECT_EQ(w.dropped, 2U);
  ASSERT_EQ(w.skeleton.segments.size(), 3U);
  EXPECT_EQ(w.skeleton.segments[1].parent, 0);
  EXPECT_EQ(w.skeleton.segments[2].parent, 1);
  EXPECT_EQ(w.skeleton.segments[2].p1, glm::dvec3(1, 0, 2));
  ASSERT_EQ(w.skeleton.polygons.size(), 1U);
  EXPECT_EQ(w.skeleton.polygons[0].parent, 1);
}

TEST(RepeatedSegments, KeepsTheWiderOfTwoWhereOneContainsTheOther) {
  lsys::Skeleton s;
  s.segments = {segment({0, 0, 0}, {0, 0, 1}, 0.2, 0.1),
                segment({0, 0, 0}, {0, 0, 1}, 0.3, 0.1)};
  const WithoutRepeats w = without_repeated_segments(s);
  EXPECT_EQ(w.dropped, 1U);
  ASSERT_EQ(w.skeleton.segments.size(), 1U);
  EXPECT_EQ(w.skeleton.segments[0].start_diameter, 0.3);
  EXPECT_EQ(w.skeleton.segments[0].end_diameter, 0.1);
}

TEST(RepeatedSegments, KeepsBothWhereNeitherContainsTheOtherOrTheyDiffer) {
  lsys::Skeleton s;
  s.segments = {
      segment({0, 0, 0}, {0, 0, 1}, 0.2, 0.1),
      segment({0, 0, 0}, {0, 0, 1}, 0.1, 0.2),         // tapers the other way
      segment({0, 0, 1}, {0, 0, 0}, 0.2, 0.1),         // drawn backwards
      segment({0, 0, 0}, {0, 0, 1}, 0.2, 0.1, -1, 1),  // another colour
      segment({0, 0, 0}, {0, 0, 1.001}, 0.2, 0.1)};    // ends elsewhere
  const WithoutRepeats w = without_repeated_segments(s);
  EXPECT_EQ(w.dropped, 0U);
  EXPECT_EQ(w.skeleton.segments.size(), 5U);
}

TEST(RepeatedSegments, MatchesEndsAFewUlpsApart) {
  // A turtle that comes back by other rotations lands a few ulps away.
  const glm::dvec3 end(0.3, 0.7, 1.1);
  const glm::dvec3 near_end(std::nextafter(0.3, 1.0), 0.7,
                            std::nextafter(1.1, 0.0));
  lsys::Skeleton s;
  s.segments = {segment({0, 0, 0}, end, 0.2, 0.2),
                segment({0, 0, 0}, near_end, 0.2, 0.2)};
  EXPECT_EQ(without_repeated_segments(s).dropped, 1U);
}

TEST(RepeatedSegments, LeavesASkeletonWithoutRepeatsAsItIs) {
  lsys::Skeleton s;
  s.segments = {segment({0, 0, 0}, {0, 0, 1}, 0.2, 0.2),
                segment({0, 0, 1}, {0, 1, 2}, 0.2, 0.1, 0)};
  const WithoutRepeats w = without_repeated_segments(s);
  EXPECT_EQ(w.dropped, 0U);
  ASSERT_EQ(w.skeleton.segments.size(), 2U);
  EXPECT_EQ(w.skeleton.segments[1].parent, 0);
  EXPECT_TRUE(
      without_repeated_segments(lsys::Skeleton{}).skeleton.segments.empty());
}

TEST(RepeatedSegments, LeavesOutBallsThatAnotherBallHolds) {
  // vlab's sympodial plant: the same bud twice, a few ulps apart; a small
  // ball inside a big one; and two that only overlap, which both stay.
  lsys::Skeleton s;
  const glm::dvec3 bud(-3.1976425923446485, 14.854651310439685, 98.8131838);
  const glm::dvec3 twin(-3.1976425923446468, 14.854651310439687, 98.8131838);
  s.spheres = {lsys::Sphere{bud, 0.8, 2, -1},
               lsys::Sphere{twin, 0.8, 3, -1},
               lsys::Sphere{{10, 0, 0}, 0.5, 0, -1},
               lsys::Sphere{{10.2, 0, 0}, 2.0, 1, -1},
               lsys::Sphere{{20, 0, 0}, 2.0, 0, -1},
               lsys::Sphere{{21, 0, 0}, 2.0, 0, -1}};
  const WithoutRepeats w = without_repeated_segments(s);
  EXPECT_EQ(w.dropped_spheres, 2U);
  ASSERT_EQ(w.skeleton.spheres.size(), 4U);
  EXPECT_EQ(w.skeleton.spheres[0].color, 2);       // the first of the twins
  EXPECT_EQ(w.skeleton.spheres[1].diameter, 2.0);  // the big one holds
  EXPECT_EQ(w.skeleton.spheres[2].center, glm::dvec3(20, 0, 0));
  EXPECT_EQ(w.skeleton.spheres[3].center, glm::dvec3(21, 0, 0));
}

}  // namespace
}  // namespace lsolid
