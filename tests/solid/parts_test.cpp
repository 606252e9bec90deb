// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/parts.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <numbers>
#include <sstream>
#include <string>

#include "lsolid/boolean.hpp"
#include "lsolid/errors.hpp"
#include "lsolid/rounding.hpp"
#include "lsolid/validate.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::expect_printable;

lsys::Segment segment(glm::dvec3 a, glm::dvec3 b, double diameter,
                      std::int32_t parent = -1) {
  return lsys::Segment{a, b, diameter, diameter, 0, parent};
}

// The area of a regular m-gon whose sides touch a circle of radius r.
double polygon_area(int m, double r) {
  return m * r * r * std::tan(std::numbers::pi / m);
}

TEST(Parts, ChoosesSidesWhoseCornersStayWithinTheTolerance) {
  EXPECT_EQ(tube_sides(0.4, 0.05), 7);  // corners 0.044 mm out
  EXPECT_EQ(tube_sides(5.0, 0.05), 23);
  EXPECT_EQ(tube_sides(0.01, 0.05), 6);
  const int m = tube_sides(2.0, 0.01);
  EXPECT_LE(2.0 / std::cos(std::numbers::pi / m) - 2.0, 0.01);
  EXPECT_GT(2.0 / std::cos(std::numbers::pi / (m - 1)) - 2.0, 0.01);
  EXPECT_NEAR(tube_corner_radius(2.0, 0.01),
              2.0 / std::cos(std::numbers::pi / m), 1e-15);
}

TEST(Parts, TubesAreNeverThinnerThanTheirWidthSoTouchingTubesFuse) {
  lsys::Skeleton s;
  // Two parallel tubes of diameter 1 whose circles touch along a line.
  s.segments = {segment({0, 0, 0}, {0, 0, 10}, 1),
                segment({1, 0, 0}, {1, 0, 10}, 1)};
  const PartSet parts = build_parts(s, {.tolerance_mm = 0.05});
  ASSERT_EQ(parts.parts.size(), 2U);
  for (const Part& p : parts.parts) {
    const Box b = bounds(p.mesh);
    EXPECT_GE(b.size().x, 1.0 - 1e-12);
    EXPECT_GE(b.size().y, 1.0 - 1e-12);
  }
  expect_printable(union_parts(parts.parts).mesh, 1);
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

// A branch that bends back across the trunk above its fork.
lsys::Skeleton branch_back_across_the_trunk() {
  lsys::Skeleton s;
  s.segments = {segment({0, 0, 0}, {0, 0, 10}, 2),
                segment({0, 0, 10}, {0, 0, 30}, 2, 0),
                segment({0, 0, 10}, {6, 0, 16}, 1, 0),
                segment({6, 0, 16}, {-4, 0, 24}, 1, 2)};
  return s;
}

TEST(Parts, GivesUpJunctionsWhoseBranchesRunIntoTheTree) {
  const PartSet parts = build_parts(branch_back_across_the_trunk());
  EXPECT_EQ(parts.tubes, 2U);
  EXPECT_EQ(parts.junctions, 0U);
  EXPECT_EQ(parts.joints, 1U);
  // Each part is a valid operand for the union; the union is one shell.
  for (const Part& p : parts.parts) expect_printable(p.mesh);
  expect_printable(union_parts(parts.parts).mesh);
}

TEST(Parts, KeepsJunctionsThatCutTheirPartWhenOnlyMeasuring) {
  const lsys::Skeleton s = branch_back_across_the_trunk();
  const PartSet checked = build_parts(s);
  const PartSet measured = build_parts(s, {.check_self_intersections = false});
  // Unchecked, the hull junction stays, and with it the part that cuts
  // itself (the size loop's first pass only measures such parts).
  EXPECT_EQ(checked.junctions, 0U);
  EXPECT_EQ(measured.junctions, 1U);
  EXPECT_EQ(measured.joints, 0U);
  // Its box differs from the checked parts' only round the fork, where a
  // joint sphere (radius 1.14 mm) stands for the hull: by a tenth of a
  // millimetre, which the size loop's next pass, checked, measures again.
  const Box a = bounds(checked.parts);
  const Box b = bounds(measured.parts);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(a.min[k], b.min[k], 0.1) << k;
    EXPECT_NEAR(a.max[k], b.max[k], 0.1) << k;
  }
}

TEST(Parts, MeasuringAloneChangesNothingWhereNoPartCutsItself) {
  lsys::Skeleton s;
  s.segments = {segment({0, 0, 0}, {0, 0, 10}, 2),
                segment({0, 0, 10}, {7, 0, 17}, 1, 0),
                segment({0, 0, 10}, {0, 0, 20}, 2, 0)};
  const PartSet checked = build_parts(s, {.tolerance_mm = 0.05});
  const PartSet measured =
      build_parts(s, {.tolerance_mm = 0.05, .check_self_intersections = false});
  ASSERT_EQ(checked.parts.size(), measured.parts.size());
  for (std::size_t i = 0; i < checked.parts.size(); ++i) {
    EXPECT_EQ(checked.parts[i].mesh.vertices, measured.parts[i].mesh.vertices);
    EXPECT_EQ(checked.parts[i].mesh.triangles,
              measured.parts[i].mesh.triangles);
  }
}

TEST(Parts, ThickensPolygonsIntoPlatesThickerThanTheThinnestTube) {
  lsys::Skeleton s;
  lsys::Polygon square;
  square.points = {{0, 0, 0}, {10, 0, 0}, {10, 0, 5}, {5, 0, 7}, {0, 0, 5}};
  s.polygons = {square};
  const PartSet parts = build_parts(s, {.wall_mm = 0.8, .tolerance_mm = 0.05});
  ASSERT_EQ(parts.plates, 1U);
  expect_printable(parts.parts[0].mesh);
  const double t = plate_thickness_mm(0.8, 0.05);
  EXPECT_NEAR(t, 2 * 1.05 * tube_corner_radius(0.4, 0.05), 1e-15);
  EXPECT_GT(t, 0.8);
  EXPECT_NEAR(signed_volume(parts.parts[0].mesh), (50.0 + 10.0) * t, 1e-9);
  const Box b = bounds(parts.parts[0].mesh);
  EXPECT_NEAR(b.size().y, t, 1e-12);
}

TEST(Parts, TriangulatesConcaveLeaves) {
  lsys::Skeleton s;
  lsys::Polygon arrow;  // a concave dart
  arrow.points = {{0, 0, 0}, {4, 0, 2}, {8, 0, 0}, {4, 0, 8}};
  s.polygons = {arrow};
  const PartSet parts = build_parts(s, {.wall_mm = 1.0});
  expect_printable(parts.parts[0].mesh);
  EXPECT_NEAR(signed_volume(parts.parts[0].mesh),
              24.0 * plate_thickness_mm(1.0, 0.05), 1e-9);
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

lsys::Polygon polygon(std::vector<glm::dvec3> points, int color = 0) {
  lsys::Polygon p;
  p.points = std::move(points);
  p.color = color;
  return p;
}

// The joints among the parts, by their labels.
std::vector<const Part*> joints_of(const PartSet& parts) {
  std::vector<const Part*> out;
  for (const Part& part : parts.parts) {
    if (part.label.starts_with("joint at")) out.push_back(&part);
  }
  return out;
}

// Five petals of ABOP fig. 1.26's flower, `{ &&&& -f+f | -f+f }` turned
// by 72° each, from the corner at `apex`, of colour 1.
std::vector<lsys::Polygon> petals(const glm::dvec3& apex) {
  std::vector<lsys::Polygon> out;
  for (int k = 0; k < 5; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 5.0;
    const glm::dvec3 out_dir(std::cos(a), std::sin(a), 0.0);
    const glm::dvec3 side(-std::sin(a), std::cos(a), 0.0);
    const glm::dvec3 up(0.0, 0.0, 1.0);
    out.push_back(polygon({apex, apex + 2.0 * out_dir + 0.6 * side + up,
                           apex + 4.0 * out_dir + 2.0 * up,
                           apex + 2.0 * out_dir - 0.6 * side + up},
                          1));
  }
  return out;
}

TEST(Parts, JoinsPlatesThatStartFromOneCornerInDifferentPlanes) {
  lsys::Skeleton s;
  const glm::dvec3 apex(1.0, 2.0, 3.0);
  s.polygons = petals(apex);
  const PartSet parts = build_parts(s, {.wall_mm = 0.8});
  EXPECT_EQ(parts.plates, 5U);
  const std::vector<const Part*> joints = joints_of(parts);
  ASSERT_EQ(joints.size(), 1U);
  EXPECT_EQ(parts.joints, 1U);
  EXPECT_EQ(joints[0]->color, 1);
  // About the corner, and enclosing each plate's edge there, half a
  // plate's thickness to either side of it.
  double nearest = 1e9;
  double farthest = 0.0;
  for (const glm::dvec3& p : joints[0]->mesh.vertices) {
    nearest = std::min(nearest, glm::distance(p, apex));
    farthest = std::max(farthest, glm::distance(p, apex));
  }
  EXPECT_GT(nearest, 1.1 * plate_thickness_mm(0.8, 0.05) / 2.0);
  EXPECT_LT(farthest, 0.8);
  expect_printable(union_parts(parts.parts).mesh);
}

TEST(Parts, GivesTheCornerJointTheColourOfItsPlates) {
  // The stem of colour 0 ends where the petals start: its tip joint is
  // the petals' corner joint, of their colour, so that their own volume
  // (--multi-material) has it.
  lsys::Skeleton s;
  const glm::dvec3 apex(0.0, 0.0, 10.0);
  s.segments = {segment({0, 0, 0}, apex, 1)};
  s.polygons = petals(apex);
  for (lsys::Polygon& p : s.polygons) p.parent = 0;
  const PartSet parts = build_parts(s, {.wall_mm = 0.8});
  const std::vector<const Part*> joints = joints_of(parts);
  ASSERT_EQ(joints.size(), 1U);
  EXPECT_EQ(joints[0]->color, 1);
}

TEST(Parts, NeedsNoCornerJointWherePlatesShareAPlaneOrNoCorner) {
  lsys::Skeleton s;
  // Two triangles in one plane that share a corner only, and one that
  // starts on another's side, not at its corner.
  s.polygons = {polygon({{0, 0, 0}, {4, 0, 0}, {4, 3, 0}}),
                polygon({{0, 0, 0}, {-4, 0, 0}, {-4, -3, 0}}),
                polygon({{2, 0, 0}, {2, 0, 4}, {2, 3, 4}})};
  const PartSet parts = build_parts(s, {.wall_mm = 0.8});
  EXPECT_TRUE(joints_of(parts).empty());
}

// The polygons of tests/data/parts/fig-1.26-flowers.txt.
std::vector<lsys::Polygon> fig_1_26_flowers() {
  std::ifstream in(std::filesystem::path(LSOLID_SOURCE_DIR) / "tests" / "data" /
                   "parts" / "fig-1.26-flowers.txt");
  std::vector<lsys::Polygon> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    lsys::Polygon p;
    words >> p.color;
    glm::dvec3 q;
    while (words >> q.x >> q.y >> q.z) p.points.push_back(q);
    out.push_back(std::move(p));
  }
  return out;
}

TEST(Parts, CornerJointsKeepPetalsWithoutTheirStemPrintable) {
  lsys::Skeleton s;
  s.polygons = fig_1_26_flowers();
  ASSERT_EQ(s.polygons.size(), 15U);
  PartSet parts = build_parts(s, {.wall_mm = 0.8});
  // Moved as the build moved them onto the bed.
  const glm::dvec3 moved(-12.580917021827213, -4.158017665613464, 0.8);
  for (Part& part : parts.parts) {
    for (glm::dvec3& p : part.mesh.vertices) p += moved;
  }
  EXPECT_EQ(parts.plates, 15U);
  // The corners of both flowers and of two leaves from one node.
  EXPECT_EQ(joints_of(parts).size(), 3U);
  const Rounded rounded =
      round_for(union_parts(parts.parts).mesh, MeshFormat::ThreeMf);
  EXPECT_TRUE(rounded.clean);
  const ValidationReport check = validate(rounded.mesh);
  EXPECT_TRUE(check.is_printable())
      << fmt::format("{}", fmt::join(check.problems(), "; "));
}

TEST(Parts, UnitesAFanOfCoplanarTrianglesIntoOnePlate) {
  // ABOP fig. 5.5's way of drawing a leaf: triangles sharing the base and
  // an edge with the next one, here a half disc of radius 5 in y = 0.
  lsys::Skeleton s;
  constexpr int kBlades = 8;
  const auto rim = [](int k) {
    const double a = std::numbers::pi * k / kBlades;
    return glm::dvec3(5 * std::cos(a), 0, 5 * std::sin(a));
  };
  double area = 0.0;
  for (int k = 0; k < kBlades; ++k) {
    s.polygons.push_back(polygon({{0, 0, 0}, rim(k), rim(k + 1)}));
    area += 0.5 * 25 * std::sin(std::numbers::pi / kBlades);
  }
  const PartSet parts = build_parts(s, {.wall_mm = 0.8});
  ASSERT_EQ(parts.plates, 1U);
  ASSERT_EQ(parts.parts.size(), 1U);
  EXPECT_NE(parts.parts[0].label.find("polygons 0, 1 and 6 more"),
            std::string::npos)
      << parts.parts[0].label;
  expect_printable(parts.parts[0].mesh);
  // The outline's points move onto a grid of 2^-20 mm: at most half a cell
  // along its 25 mm, through the plate's thickness.
  EXPECT_NEAR(signed_volume(parts.parts[0].mesh),
              area * plate_thickness_mm(0.8, 0.05), 1e-5);
}

TEST(Parts, TakesALeafDrawnTwiceAFewUlpsApartAsOnePlate) {
  // Leaves 12 and 28 of the blog's tree A at n = 6, in millimetres: the
  // same hexagon drawn twice, two coordinates apart by an ulp. United
  // exactly, they made a plate that cut itself and the union refused.
  lsys::Skeleton s;
  s.polygons = {
      polygon({{-33.934294610295574, 0, 51.49246862589401},
               {-36.12924707365708, -2.354959764329187, 52.56106799859591},
               {-38.276448411446964, -4.953370368335126, 52.18245846973024},
               {-39.97354653363441, -7.308330132664312, 50.42758556851389},
               {-37.778594070272895, -4.953370368335126, 49.358986195811994},
               {-35.63139273248302, -2.3549597643291875, 49.73759572467767}}),
      polygon({{-33.934294610295574, 0, 51.492468625894006},
               {-36.12924707365708, -2.354959764329187, 52.5610679985959},
               {-38.276448411446964, -4.953370368335126, 52.182458469730236},
               {-39.97354653363441, -7.308330132664312, 50.427585568513884},
               {-37.778594070272895, -4.953370368335126, 49.358986195811994},
               {-35.63139273248302, -2.3549597643291875, 49.73759572467766}})};
  const PartSet parts = build_parts(s, {.wall_mm = 0.8});
  ASSERT_EQ(parts.plates, 1U);
  ASSERT_EQ(parts.parts.size(), 1U);
  expect_printable(parts.parts[0].mesh);
}

TEST(Parts, UnitesOverlappingCoplanarPolygonsAndKeepsApartTheRest) {
  lsys::Skeleton s;
  // Two squares overlapping by a quarter, a third far away in their
  // plane, and a fourth overlapping the first but in another plane.
  s.polygons = {polygon({{0, 0, 0}, {4, 0, 0}, {4, 0, 4}, {0, 0, 4}}),
                polygon({{2, 0, 2}, {6, 0, 2}, {6, 0, 6}, {2, 0, 6}}),
                polygon({{20, 0, 0}, {24, 0, 0}, {24, 0, 4}, {20, 0, 4}}),
                polygon({{1, -2, 1}, {1, 2, 1}, {1, 2, 3}, {1, -2, 3}})};
  const PartSet parts = build_parts(s, {.wall_mm = 0.5});
  ASSERT_EQ(parts.plates, 3U);
  std::vector<double> volumes;
  for (const Part& p : parts.parts) {
    expect_printable(p.mesh);
    volumes.push_back(signed_volume(p.mesh));
  }
  std::sort(volumes.begin(), volumes.end());
  const double t = plate_thickness_mm(0.5, 0.05);
  EXPECT_NEAR(volumes[0], 8 * t, 1e-9);         // the crossing one
  EXPECT_NEAR(volumes[1], 16 * t, 1e-9);        // the far one
  EXPECT_NEAR(volumes[2], (32 - 4) * t, 1e-9);  // the two united
}

TEST(Parts, UnitesCoplanarPolygonsAroundAHole) {
  lsys::Skeleton s;
  // Four bars framing a 2 x 2 hole, each overlapping the next at a corner.
  s.polygons = {polygon({{0, 0, 0}, {6, 0, 0}, {6, 0, 2}, {0, 0, 2}}),
                polygon({{4, 0, 0}, {6, 0, 0}, {6, 0, 6}, {4, 0, 6}}),
                polygon({{0, 0, 4}, {6, 0, 4}, {6, 0, 6}, {0, 0, 6}}),
                polygon({{0, 0, 0}, {2, 0, 0}, {2, 0, 6}, {0, 0, 6}})};
  const PartSet parts = build_parts(s, {.wall_mm = 1.0});
  ASSERT_EQ(parts.plates, 1U);
  expect_printable(parts.parts[0].mesh);
  const ValidationReport r = validate(parts.parts[0].mesh);
  EXPECT_EQ(r.genus, 1);
  EXPECT_NEAR(r.volume_mm3, (36.0 - 4.0) * plate_thickness_mm(1.0, 0.05), 1e-9);
}

TEST(Parts, KeepsCoplanarPolygonsOfTwoColoursApartWhenSplittingColours) {
  lsys::Skeleton s;
  s.polygons = {polygon({{0, 0, 0}, {4, 0, 0}, {4, 0, 4}, {0, 0, 4}}, 1),
                polygon({{2, 0, 2}, {6, 0, 2}, {6, 0, 6}, {2, 0, 6}}, 2)};
  EXPECT_EQ(build_parts(s, {.split_colors = true}).plates, 2U);
  EXPECT_EQ(build_parts(s, {.split_colors = false}).plates, 1U);
}

TEST(Parts, LeavesCoplanarPolygonsApartWhenTheFootprintWillUniteThem) {
  lsys::Skeleton s;
  s.polygons = {polygon({{0, 0, 0}, {4, 0, 0}, {4, 0, 4}, {0, 0, 4}}, 1),
                polygon({{2, 0, 2}, {6, 0, 2}, {6, 0, 6}, {2, 0, 6}}, 1)};
  const PartSet apart = build_parts(s, {.unite_coplanar_polygons = false});
  EXPECT_EQ(apart.plates, 2U);
  for (const Part& p : apart.parts) expect_printable(p.mesh);
}

// A sheet on a grid of `columns` × `rows` cells, point (i, j) at
// at(i / columns, j / rows).
template <typename At>
lsys::Sheet grid_sheet(int columns, int rows, const At& at) {
  lsys::Sheet sheet;
  for (int j = 0; j <= rows; ++j) {
    for (int i = 0; i <= columns; ++i) {
      sheet.points.push_back(
          at(static_cast<double>(i) / columns, static_cast<double>(j) / rows));
    }
  }
  const auto index = [&](int i, int j) {
    return static_cast<std::uint32_t>(j * (columns + 1) + i);
  };
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      sheet.triangles.push_back(
          {index(i, j), index(i + 1, j), index(i, j + 1)});
      sheet.triangles.push_back(
          {index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  }
  return sheet;
}

TEST(Parts, ThickensAFlatSheetIntoAPlateOfThePlatesThickness) {
  lsys::Skeleton s;
  s.sheets = {grid_sheet(4, 4, [](double u, double v) {
    return glm::dvec3(10.0 * u, 10.0 * v, 3.0);
  })};
  const PartSet set = build_parts(s, {.wall_mm = 0.8});
  ASSERT_EQ(set.parts.size(), 1U);
  EXPECT_EQ(set.sheets, 1U);
  EXPECT_EQ(set.hulled_sheets, 0U);
  expect_printable(set.parts[0].mesh);
  EXPECT_NEAR(signed_volume(set.parts[0].mesh),
              100.0 * plate_thickness_mm(0.8, 0.05), 1e-9);
  const Box box = bounds(set.parts);
  EXPECT_NEAR(box.max.z - box.min.z, plate_thickness_mm(0.8, 0.05), 1e-12);
}

TEST(Parts, ThickensACurvedSheetAlongItsNormals) {
  // Half a cylinder of radius 10 mm, 10 mm long: as thick all round.
  lsys::Skeleton s;
  s.sheets = {grid_sheet(16, 4, [](double u, double v) {
    const double a = std::numbers::pi * u;
    return glm::dvec3(10.0 * std::cos(a), 10.0 * v, 10.0 * std::sin(a));
  })};
  const PartSet set = build_parts(s, {.wall_mm = 0.8});
  ASSERT_EQ(set.parts.size(), 1U);
  expect_printable(set.parts[0].mesh);
  const double chords = 16 * 2.0 * 10.0 * std::sin(std::numbers::pi / 32);
  EXPECT_NEAR(signed_volume(set.parts[0].mesh),
              10.0 * chords * plate_thickness_mm(0.8, 0.05),
              0.01 * 10.0 * chords * plate_thickness_mm(0.8, 0.05));
}

// A sheet folded into a V of 10° along the y axis, `width` mm each wing.
lsys::Sheet folded_sheet(double width) {
  return grid_sheet(8, 2, [&](double u, double v) {
    const double r = width * std::abs(2.0 * u - 1.0);
    const double side = u < 0.5 ? -1.0 : 1.0;
    const double half = 5.0 * std::numbers::pi / 180.0;
    return glm::dvec3(side * r * std::sin(half), width * v, r * std::cos(half));
  });
}

TEST(Parts, MakesASmallSheetFoldedTooSharplyItsThickenedHull) {
  lsys::Skeleton s;
  s.sheets = {folded_sheet(2.0)};
  const PartSet set = build_parts(s, {.wall_mm = 0.8});
  ASSERT_EQ(set.parts.size(), 1U);
  EXPECT_EQ(set.hulled_sheets, 1U);
  expect_printable(set.parts[0].mesh);
  // The hull holds every point of the sheet, half the thickness clear.
  const Box box = bounds(set.parts);
  EXPECT_NEAR(box.max.y - box.min.y, 2.0 + plate_thickness_mm(0.8, 0.05),
              1e-12);
}

TEST(Parts, ThinsASheetOnlyWhereAnEdgeCurlsTighterThanItsThickness) {
  // A strip 20 mm long whose last mm turns back in a half circle of radius
  // 0.3 mm: no plate 0.93 mm thick follows the curl, none along one normal.
  lsys::Skeleton s;
  s.sheets = {grid_sheet(200, 2, [](double u, double v) {
    const double along = 20.0 * u;
    if (along <= 19.0) return glm::dvec3(along, 5.0 * v, 0.0);
    const double a = (along - 19.0) / 0.3;
    return glm::dvec3(19.0 + 0.3 * std::sin(a), 5.0 * v,
                      0.3 * (1.0 - std::cos(a)));
  })};
  const PartSet set = build_parts(s, {.wall_mm = 0.8});
  ASSERT_EQ(set.parts.size(), 1U);
  EXPECT_EQ(set.thinned_sheets, 1U);
  EXPECT_EQ(set.hulled_sheets, 0U);
  expect_printable(set.parts[0].mesh);
  const double thickness = plate_thickness_mm(0.8, 0.05);
  EXPECT_LT(set.thinnest_sheet_mm, thickness / 2.0);
  // The flat of the strip keeps its full thickness: its volume is at
  // least that of 18 mm of it.
  EXPECT_GT(signed_volume(set.parts[0].mesh), 18.0 * 5.0 * thickness);
}

TEST(Parts, RefusesALargeSheetFoldedTooSharplyToThicken) {
  lsys::Skeleton s;
  s.sheets = {folded_sheet(20.0)};
  try {
    (void)build_parts(s, {.wall_mm = 0.8});
    FAIL() << "a sheet folded this sharply cannot be thickened";
  } catch (const GeometryError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "surface 0 at (-1.743, 0.000, 19.924) mm, 20.0 mm across, "
                  "bends too sharply to thicken to 0.93 mm"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace lsolid
