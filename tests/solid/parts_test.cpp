// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/parts.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lsolid/boolean.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::expect_printable;

lsys::Segment segment(glm::dvec3 a, glm::dvec3 b, double diameter,
                      std::int32_t parent = -1) {
  return lsys::Segment{a, b, diameter, diameter, 0, parent};
}

// The area of a regular m-gon inscribed in a circle of radius r.
double polygon_area(int m, double r) {
  return 0.5 * m * r * r * std::sin(2 * std::numbers::pi / m);
}

TEST(Parts, ChoosesSidesFromTheChordTolerance) {
  EXPECT_EQ(tube_sides(0.4, 0.05), 7);  // sagitta of a heptagon < 0.05 mm
  EXPECT_EQ(tube_sides(5.0, 0.05), 23);
  EXPECT_EQ(tube_sides(0.01, 0.05), 6);
  const int m = tube_sides(2.0, 0.01);
  EXPECT_LE(2.0 * (1 - std::cos(std::numbers::pi / m)), 0.01);
  EXPECT_GT(2.0 * (1 - std::cos(std::numbers::pi / (m - 1))), 0.01);
}

TEST(Parts, MakesOneClosedTubePerSegmentChain) {
  lsys::Skeleton s;
  s.segments = {segment({0, 0, 0}, {0, 0, 10}, 2),
                segment({0, 0, 10}, {0, 0, 20}, 2, 0),
                segment({0, 0, 20}, {0, 10, 20}, 2, 1)};  // a 90° mitred bend
  const PartSet parts = build_parts(s, {.tolerance_mm = 0.05});
  ASSERT_EQ(parts.parts.size(), 1U);
  EXPECT_EQ(parts.tubes, 1U);
  EXPECT_EQ(parts.joints, 0U);
  expect_printable(parts.parts[0].mesh);
  // Mitred prisms keep the cross-section area times the axis length.
  const int m = tube_sides(1.0, 0.05);
  EXPECT_NEAR(signed_volume(parts.parts[0].mesh), polygon_area(m, 1.0) * 30.0,
              1e-9);
}

TEST(Parts, BreaksChainsAtTurnBacksAndJoinsThem) {
  lsys::Skeleton s;
  s.segments = {segment({0, 0, 0}, {0, 0, 10}, 2),
                segment({0, 0, 10}, {0, 0, 5}, 2, 0)};  // `|`: back down
  const PartSet parts = build_parts(s);
  EXPECT_EQ(parts.tubes, 2U);
  EXPECT_EQ(parts.joints, 1U);
  for (const Part& p : parts.parts) expect_printable(p.mesh);
}

TEST(Parts, JoinsABranchToItsParentWithTheHullOfTheirRings) {
  lsys::Skeleton s;
  s.segments = {segment({0, 0, 0}, {0, 0, 10}, 2),
                segment({0, 0, 10}, {7, 0, 17}, 1, 0),   // branch, 45°
                segment({0, 0, 10}, {0, 0, 20}, 2, 0)};  // main axis goes on
  const PartSet parts = build_parts(s, {.tolerance_mm = 0.05});
  EXPECT_EQ(parts.tubes, 3U);
  EXPECT_EQ(parts.junctions, 1U);
  EXPECT_EQ(parts.joints, 0U);
  // One closed part, no boolean needed: the tubes end in rings that are
  // faces of the junction's convex hull.
  ASSERT_EQ(parts.parts.size(), 1U);
  expect_printable(parts.parts[0].mesh);
  // The main axis whole, the branch outside it, and the hull's web in the
  // fork, which fills at most the branch's ring distance again.
  const double main_axis = polygon_area(tube_sides(1.0, 0.05), 1.0) * 20.0;
  const double branch =
      polygon_area(tube_sides(0.5, 0.05), 0.5) *
      (std::sqrt(98.0) - 1.0 / std::sin(std::numbers::pi / 4));
  const double v = signed_volume(parts.parts[0].mesh);
  EXPECT_GT(v, main_axis + 0.98 * branch);
  EXPECT_LT(v, main_axis + branch + 4.0);
}

TEST(Parts, LeavesAJunctionToTheUnionWhereRingsDoNotFit) {
  lsys::Skeleton s;
  s.segments = {segment({0, 0, 0}, {0, 0, 10}, 2),
                segment({0, 0, 10}, {0.5, 0, 10.5}, 1, 0),  // a short branch
                segment({0, 0, 10}, {0, 0, 20}, 2, 0)};
  const PartSet parts = build_parts(s);
  EXPECT_EQ(parts.tubes, 2U);
  EXPECT_EQ(parts.junctions, 0U);
  EXPECT_EQ(parts.joints, 1U);
  // The main axis stays one tube: the joint's sphere encloses the branch's cap.
  EXPECT_NE(parts.parts[0].label.find("segments 0-2"), std::string::npos);
  for (const Part& p : parts.parts) expect_printable(p.mesh);
}

TEST(Parts, GivesUpJunctionsWhoseBranchesRunIntoTheTree) {
  lsys::Skeleton s;
  // A branch that bends back across the trunk above its fork.
  s.segments = {segment({0, 0, 0}, {0, 0, 10}, 2),
                segment({0, 0, 10}, {0, 0, 30}, 2, 0),
                segment({0, 0, 10}, {6, 0, 16}, 1, 0),
                segment({6, 0, 16}, {-4, 0, 24}, 1, 2)};
  const PartSet parts = build_parts(s);
  EXPECT_EQ(parts.tubes, 2U);
  EXPECT_EQ(parts.junctions, 0U);
  EXPECT_EQ(parts.joints, 1U);
  // Each part is a valid operand for the union; the union is one shell.
  for (const Part& p : parts.parts) expect_printable(p.mesh);
  expect_printable(union_parts(parts.parts).mesh);
}

TEST(Parts, ThickensPolygonsIntoPlatesOfWallThickness) {
  lsys::Skeleton s;
  lsys::Polygon square;
  square.points = {{0, 0, 0}, {10, 0, 0}, {10, 0, 5}, {5, 0, 7}, {0, 0, 5}};
  s.polygons = {square};
  const PartSet parts = build_parts(s, {.wall_mm = 0.8});
  ASSERT_EQ(parts.plates, 1U);
  expect_printable(parts.parts[0].mesh);
  EXPECT_NEAR(signed_volume(parts.parts[0].mesh), (50.0 + 10.0) * 0.8, 1e-9);
  const Box b = bounds(parts.parts[0].mesh);
  EXPECT_NEAR(b.size().y, 0.8, 1e-12);
}

TEST(Parts, TriangulatesConcaveLeaves) {
  lsys::Skeleton s;
  lsys::Polygon arrow;  // a concave dart
  arrow.points = {{0, 0, 0}, {4, 0, 2}, {8, 0, 0}, {4, 0, 8}};
  s.polygons = {arrow};
  const PartSet parts = build_parts(s, {.wall_mm = 1.0});
  expect_printable(parts.parts[0].mesh);
  EXPECT_NEAR(signed_volume(parts.parts[0].mesh), 24.0, 1e-9);
}

TEST(Parts, SkipsPolygonsThatCrossThemselves) {
  lsys::Skeleton s;
  lsys::Polygon bowtie;
  bowtie.points = {
      {0, 0, 0}, {6, 0, 6}, {6, 0, 0}, {0, 0, 2}};  // unequal lobes
  s.polygons = {bowtie};
  const PartSet parts = build_parts(s);
  EXPECT_EQ(parts.skipped_polygons, 1U);
  EXPECT_TRUE(parts.parts.empty());
}

TEST(Parts, SkipsPolygonsWithoutArea) {
  lsys::Skeleton s;
  lsys::Polygon line;
  line.points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  s.polygons = {line};
  EXPECT_EQ(build_parts(s).skipped_polygons, 1U);
}

TEST(Parts, FusesALeafAtATipWithAJoint) {
  lsys::Skeleton s;
  s.segments = {segment({0, 0, 0}, {0, 0, 10}, 1)};
  lsys::Polygon leaf;
  leaf.points = {{0, 0, 10}, {3, 0, 12}, {0, 0, 15}, {-3, 0, 12}};
  leaf.parent = 0;
  s.polygons = {leaf};
  const PartSet parts = build_parts(s);
  EXPECT_EQ(parts.joints, 1U);
  EXPECT_EQ(parts.plates, 1U);
  expect_printable(union_parts(parts.parts).mesh);
}

TEST(Parts, LetsALeafCutThroughAStemThatGoesOn) {
  lsys::Skeleton s;
  s.segments = {segment({0, 0, 0}, {0, 0, 10}, 1),
                segment({0, 0, 10}, {0, 0, 20}, 1, 0)};
  lsys::Polygon leaf;
  leaf.points = {{0, 0, 10}, {3, 0, 12}, {0, 0, 15}, {-3, 0, 12}};
  leaf.parent = 0;
  s.polygons = {leaf};
  const PartSet parts = build_parts(s, {.wall_mm = 0.8});
  EXPECT_EQ(parts.joints, 0U);
  EXPECT_EQ(parts.plates, 1U);
  expect_printable(union_parts(parts.parts).mesh);
}

}  // namespace
}  // namespace lsolid
