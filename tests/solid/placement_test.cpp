// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/placement.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/common.hpp>

#include "lsolid/boolean.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::box_mesh;
using testing::expect_printable;

TEST(Placement, CentresTheModelAndPutsItsLowestPointAtZeroWithoutABase) {
  std::vector<Part> parts{{box_mesh({10, 20, 5}, {30, 40, 25}), "cube"}};
  const Placement p = place_on_bed(parts, Base::Auto, 0.8, 0.05);
  EXPECT_FALSE(p.has_base);  // a cube stands on its whole face
  EXPECT_EQ(parts.size(), 1U);
  const Box b = bounds(parts);
  EXPECT_EQ(b.min.z, 0.0);
  EXPECT_EQ(b.min.x, -10.0);
  EXPECT_EQ(b.max.y, 10.0);
  EXPECT_EQ(p.moved_by_mm, glm::dvec3(-20, -30, -5));
  EXPECT_DOUBLE_EQ(p.footprint_mm, 20.0);
}

TEST(Placement, StandsATallThinModelOnADisc) {
  // A stick 1 mm wide and 50 mm tall, with an arm that moves its centre of
  // mass off the foot.
  std::vector<Part> parts{{box_mesh({0, 0, 0}, {1, 1, 50}), "stick"},
                          {box_mesh({0, 0, 40}, {20, 1, 41}), "arm"}};
  const Placement p = place_on_bed(parts, Base::Auto, 0.8, 0.05);
  ASSERT_TRUE(p.has_base);
  ASSERT_EQ(parts.size(), 3U);
  EXPECT_EQ(parts.back().label, "base disc");
  EXPECT_DOUBLE_EQ(p.base_thickness_mm, 1.6);
  EXPECT_DOUBLE_EQ(p.footprint_mm, 1.0);
  const Box disc = bounds(parts.back().mesh);
  EXPECT_EQ(disc.min.z, 0.0);
  EXPECT_DOUBLE_EQ(disc.max.z, 1.6);
  // The foot sinks half-way into the disc.
  EXPECT_DOUBLE_EQ(bounds(parts[0].mesh).min.z, 0.8);
  // The centre of mass (of the volumes: stick 50, arm 20, at x = 0.5 and
  // 10 before centring) lies inside the disc, with room to spare.
  // The disc is centred under the foot (the stick), and the whole, disc
  // included, on the origin.
  const Box stick = bounds(parts[0].mesh);
  const double foot_x = (stick.min.x + stick.max.x) / 2.0;
  const double balance_x = foot_x + (50 * 0.5 + 20 * 10.0) / 70.0 - 0.5;
  const double radius = (disc.max.x - disc.min.x) / 2.0;
  EXPECT_NEAR((disc.min.x + disc.max.x) / 2.0, foot_x, 1e-9);
  EXPECT_GT(radius, 1.4 * std::fabs(balance_x - foot_x));
  const Box all = bounds(parts);
  EXPECT_NEAR(all.min.x, -all.max.x, 1e-9);
  EXPECT_NEAR(all.min.y, -all.max.y, 1e-9);
  expect_printable(parts.back().mesh);
  expect_printable(union_parts(parts).mesh);
}

TEST(Placement, AddsADiscOnlyWhenAskedOrNeeded) {
  std::vector<Part> cube{{box_mesh({0, 0, 0}, {10, 10, 10}), "cube"}};
  EXPECT_TRUE(place_on_bed(cube, Base::Disc, 0.8, 0.05).has_base);
  std::vector<Part> stick{{box_mesh({0, 0, 0}, {1, 1, 50}), "stick"}};
  EXPECT_FALSE(place_on_bed(stick, Base::None, 0.8, 0.05).has_base);
  EXPECT_EQ(stick.size(), 1U);
  EXPECT_EQ(bounds(stick[0].mesh).min.z, 0.0);
}

}  // namespace
}  // namespace lsolid
