// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/placement.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/common.hpp>

#include "lsolid/boolean.hpp"
#include "lsolid/parts.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::box_mesh;
using testing::expect_printable;

TEST(Placement, CentresTheModelAndPutsItsLowestPointAtZeroWithoutABase) {
  std::vector<Part> parts{{box_mesh({10, 20, 5}, {30, 40, 25}), "cube"}};
  const Placed placed = place_on_bed(
      parts, {.base = Base::Auto, .wall_mm = 0.8, .tolerance_mm = 0.05});
  parts = placed.parts;
  const Placement& p = placed.placement;
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
  const Placed placed = place_on_bed(
      parts, {.base = Base::Auto, .wall_mm = 0.8, .tolerance_mm = 0.05});
  parts = placed.parts;
  const Placement& p = placed.placement;
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
  EXPECT_TRUE(
      place_on_bed(cube,
                   {.base = Base::Disc, .wall_mm = 0.8, .tolerance_mm = 0.05})
          .placement.has_base);
  std::vector<Part> stick{{box_mesh({0, 0, 0}, {1, 1, 50}), "stick"}};
  const Placed standing = place_on_bed(
      stick, {.base = Base::None, .wall_mm = 0.8, .tolerance_mm = 0.05});
  EXPECT_FALSE(standing.placement.has_base);
  stick = standing.parts;
  EXPECT_EQ(stick.size(), 1U);
  EXPECT_EQ(bounds(stick[0].mesh).min.z, 0.0);
}

lsys::Skeleton skeleton_of(const std::vector<glm::dvec3>& path,
                           double diameter) {
  lsys::Skeleton s;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    s.segments.push_back({.p0 = path[i],
                          .p1 = path[i + 1],
                          .start_diameter = diameter,
                          .end_diameter = diameter});
  }
  return s;
}

TEST(Placement, FindsThePlaneOfAPlanarSkeletonOnly) {
  // An L in the plane x = 2: its normal is ±X.
  const auto plane =
      skeleton_plane(skeleton_of({{2, 0, 0}, {2, 0, 5}, {2, 3, 5}}, 1.0), 0.8);
  ASSERT_TRUE(plane.has_value());
  EXPECT_NEAR(std::fabs(plane->normal.x), 1.0, 1e-12);
  EXPECT_NEAR(plane->point.x, 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(plane->thinnest_radius_mm, 0.5);
  // Thinner than the wall: the tubes are made a wall thick.
  EXPECT_DOUBLE_EQ(
      skeleton_plane(skeleton_of({{0, 0, 0}, {0, 0, 5}, {0, 3, 5}}, 0.2), 0.8)
          ->thinnest_radius_mm,
      0.4);
  // A straight line spans no plane, and a corner out of it is 3D.
  EXPECT_FALSE(skeleton_plane(skeleton_of({{0, 0, 0}, {0, 0, 5}}, 1.0), 0.8));
  EXPECT_FALSE(skeleton_plane(
      skeleton_of({{0, 0, 0}, {0, 0, 5}, {0, 3, 5}, {1, 3, 5}}, 1.0), 0.8));
}

TEST(Placement, LaysAPlanarModelFlatWithACutBelowItsPlane) {
  // A vertical 10 × 10 × 1 plate standing in the plane y = 0.
  std::vector<Part> parts{{box_mesh({0, -0.5, 0}, {10, 0.5, 10}), "plate"}};
  const SkeletonPlane plane{
      .normal = {0, 1, 0}, .point = {0, 0, 0}, .thinnest_radius_mm = 0.5};
  const Placed placed = place_on_bed(parts, {.base = Base::Auto,
                                             .wall_mm = 0.8,
                                             .tolerance_mm = 0.05,
                                             .plane = plane});
  parts = placed.parts;
  const Placement& p = placed.placement;
  EXPECT_TRUE(p.lies_flat);
  EXPECT_FALSE(p.has_base);
  const Box box = bounds(parts);
  EXPECT_NEAR(box.min.z, 0.0, 1e-12);
  EXPECT_NEAR(box.max.z, 1.0, 1e-12);  // lying: 1 mm tall
  EXPECT_NEAR(box.size().x, 10.0, 1e-12);
  EXPECT_NEAR(box.size().y, 10.0, 1e-12);
  EXPECT_DOUBLE_EQ(p.cut_depth_mm, 0.25);
  EXPECT_NEAR(p.cut_z_mm, 0.25, 1e-12);  // the plane is at z = 0.5
  // With an explicit base it stands, as before.
  std::vector<Part> standing{{box_mesh({0, -0.5, 0}, {10, 0.5, 10}), "plate"}};
  EXPECT_FALSE(place_on_bed(standing, {.base = Base::None,
                                       .wall_mm = 0.8,
                                       .tolerance_mm = 0.05,
                                       .plane = plane})
                   .placement.lies_flat);
}

}  // namespace
}  // namespace lsolid
