// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/footprint.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <set>
#include <utility>

#include "lsolid/errors.hpp"
#include "lsolid/parts.hpp"
#include "lsolid/validate.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using Polygon = std::vector<glm::dvec2>;

Polygon square(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Polygon reversed(Polygon p) {
  std::reverse(p.begin(), p.end());
  return p;
}

double ring_area(const Polygon& ring) { return area(Footprint{{ring}}); }

TEST(Footprint, ABranchIsAsWideAsItsTubeAcrossTheCornersAndEndsSquare) {
  const Polygon quad = branch_outline({0.0, 0.0}, 0.4, {10.0, 0.0}, 0.8, 0.05);
  ASSERT_EQ(quad.size(), 4U);
  const double w0 = tube_corner_radius(0.4, 0.05);
  const double w1 = tube_corner_radius(0.8, 0.05);
  EXPECT_GT(w0, 0.4);
  EXPECT_EQ(quad[0], glm::dvec2(0.0, -w0));
  EXPECT_EQ(quad[1], glm::dvec2(10.0, -w1));
  EXPECT_EQ(quad[2], glm::dvec2(10.0, w1));
  EXPECT_EQ(quad[3], glm::dvec2(0.0, w0));
  EXPECT_NEAR(ring_area(quad), 10.0 * (w0 + w1), 1e-12);  // counter-clockwise
  EXPECT_TRUE(branch_outline({1.0, 2.0}, 0.4, {1.0, 2.0}, 0.4, 0.05).empty());
}

TEST(Footprint, ANodeIsAPolygonWhoseSidesTouchItsCircle) {
  const glm::dvec2 c(3.0, -2.0);
  const Polygon node = node_outline(c, 1.5, 0.05);
  ASSERT_EQ(node.size(), static_cast<std::size_t>(tube_sides(1.5, 0.05)));
  EXPECT_GT(ring_area(node), 0.0);
  for (std::size_t i = 0; i < node.size(); ++i) {
    const glm::dvec2& a = node[i];
    const glm::dvec2& b = node[(i + 1) % node.size()];
    EXPECT_NEAR(glm::distance(a, c), tube_corner_radius(1.5, 0.05), 1e-12);
    EXPECT_NEAR(glm::distance((a + b) / 2.0, c), 1.5, 1e-12);
  }
}

TEST(Footprint, TellsSimplePolygonsFromOnesThatCrossThemselves) {
  EXPECT_TRUE(is_simple_polygon(square(0, 0, 1, 1)));
  EXPECT_TRUE(is_simple_polygon(reversed(square(0, 0, 1, 1))));
  EXPECT_FALSE(is_simple_polygon({{0, 0}, {1, 1}, {1, 0}, {0, 1}}));  // bow tie
  EXPECT_FALSE(is_simple_polygon({{0, 0}, {1, 0}, {2, 0}}));          // no area
  // A figure eight touching itself at (1, 1).
  EXPECT_FALSE(
      is_simple_polygon({{0, 0}, {1, 1}, {2, 0}, {2, 2}, {1, 1}, {0, 2}}));
}

TEST(Footprint, UnitesOverlappingOutlinesOfEitherOrientationIntoOneRing) {
  // A clockwise square under a counter-clockwise one: by winding number
  // alone the overlap would cancel out.
  const Footprint f =
      footprint_union({reversed(square(0, 0, 2, 2)), square(1, 1, 3, 3)});
  ASSERT_EQ(f.rings.size(), 1U);
  EXPECT_EQ(area(f), 7.0);
  EXPECT_EQ(f.rings[0].size(), 8U);
}

TEST(Footprint, KeepsTheHoleThatBranchesAroundALoopEnclose) {
  const Footprint f =
      footprint_union({square(0, 0, 10, 1), square(9, 0, 10, 10),
                       square(0, 9, 10, 10), square(0, 0, 1, 10)});
  ASSERT_EQ(f.rings.size(), 2U);
  EXPECT_EQ(ring_area(f.rings[0]), 100.0);  // the outer ring first
  EXPECT_EQ(ring_area(f.rings[1]), -64.0);  // the hole, clockwise
  EXPECT_EQ(area(f), 36.0);
}

TEST(Footprint, SubtractsTheOutlinesBelow) {
  const Footprint f =
      footprint_union({square(0, 0, 4, 1)}, {square(1, -1, 2, 2)});
  ASSERT_EQ(f.rings.size(), 2U);
  EXPECT_EQ(area(f), 3.0);
}

TEST(Footprint, GrowsOutlinesThatTouchAtAPointUntilTheyOverlap) {
  const Footprint f = footprint_union({square(0, 0, 1, 1), square(1, 1, 2, 2)});
  std::set<std::pair<double, double>> points;
  for (const Polygon& ring : f.rings) {
    for (const glm::dvec2& p : ring) {
      EXPECT_TRUE(points.emplace(p.x, p.y).second) << p.x << ", " << p.y;
    }
  }
  EXPECT_EQ(f.rings.size(), 1U);
  // Grown by two grid steps of 2^-20 mm all round.
  EXPECT_GT(area(f), 2.0);
  EXPECT_NEAR(area(f), 2.0, 8 * 2 * std::ldexp(1.0, -20) + 1e-9);
}

TEST(Footprint, PutsEveryPointOnTheGrid) {
  const Footprint f = footprint_union({square(0.1, 0.2, 1.3, 1.7)});
  for (const glm::dvec2& p : f.rings.at(0)) {
    EXPECT_EQ(p.x * 1048576.0, std::round(p.x * 1048576.0));
    EXPECT_EQ(p.y * 1048576.0, std::round(p.y * 1048576.0));
  }
}

TEST(Footprint, ExtrudesIntoAClosedSolidOfItsAreaTimesItsHeight) {
  const Footprint f =
      footprint_union({square(0, 0, 10, 1), square(9, 0, 10, 10),
                       square(0, 9, 10, 10), square(0, 0, 1, 10)});
  const TriangleMesh solid = extrude(f, 2.5);
  testing::expect_printable(solid, 1);
  const ValidationReport r = validate(solid);
  EXPECT_EQ(r.genus, 1);
  EXPECT_EQ(r.volume_mm3, 36.0 * 2.5);
  EXPECT_EQ(r.bounds.min, glm::dvec3(0.0, 0.0, 0.0));
  EXPECT_EQ(r.bounds.max, glm::dvec3(10.0, 10.0, 2.5));
}

TEST(Footprint, RefusesToWallRingsThatCross) {
  const Footprint crossing{{square(0, 0, 2, 2), square(1, 1, 3, 3)}};
  EXPECT_THROW((void)extrude(crossing, 1.0), GeometryError);
  const Footprint touching{{square(0, 0, 1, 1), square(1, 1, 2, 2)}};
  EXPECT_THROW((void)extrude(touching, 1.0), GeometryError);
}

}  // namespace
}  // namespace lsolid
