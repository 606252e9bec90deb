// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/rounding.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "lsolid/boolean.hpp"
#include "lsolid/errors.hpp"
#include "lsolid/precision.hpp"
#include "lsolid/solid.hpp"
#include "support/core_helpers.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::box_mesh;
using testing::expect_printable;

TEST(Rounding, MendsSliversThatFloatsCannotHold) {
  // Boxes offset by 1e-7 mm: the union has faces 1e-7 apart, closer than
  // floats near 100 mm can tell.
  std::vector<Part> parts{
      {box_mesh({100, 100, 100}, {101, 101, 101}), "a"},
      {box_mesh({100.5, 100, 100 + 1e-7}, {101.5, 101, 101 + 1e-7}), "b"}};
  const TriangleMesh united = union_parts(std::move(parts)).mesh;
  const ValidationReport naive =
      validate(snapped(united, {.kind = Precision::Kind::Float}));
  EXPECT_FALSE(naive.is_printable());
  const auto [repaired, stats, clean, as_floats] =
      round_and_repair(united, {.precision = {.kind = Precision::Kind::Float}});
  expect_printable(repaired);
  EXPECT_TRUE(clean);
  EXPECT_FALSE(as_floats);
  EXPECT_GT(stats.slivers_removed, 0U);
  for (const glm::dvec3& p : repaired.vertices) {
    volatile float rounded = static_cast<float>(p.x);  // see vertex_key.hpp
    EXPECT_EQ(p.x, static_cast<double>(rounded)) << std::hexfloat << p.x;
  }
  EXPECT_NEAR(signed_volume(repaired), 1.5, 1e-4);
}

TEST(Rounding, RefusesAMeshThatIsNotA2Manifold) {
  TriangleMesh fan = box_mesh({0, 0, 0}, {1, 1, 1});
  fan.triangles.push_back(fan.triangles[0]);
  EXPECT_THROW((void)round_and_repair(fan), GeometryError);
}

TEST(Rounding, AddsUpWhatLaterRoundingsMended) {
  RoundingStats total{.passes = 3,
                      .slivers_removed = 2,
                      .faces_rebuilt = 1,
                      .repairs_refused = 0,
                      .volume_change_mm3 = -0.5,
                      .ways_tried = 2};
  accumulate(total, {.passes = 1,
                     .slivers_removed = 4,
                     .faces_rebuilt = 0,
                     .repairs_refused = 1,
                     .volume_change_mm3 = 0.25,
                     .ways_tried = 1});
  EXPECT_EQ(total.passes, 1);
  EXPECT_EQ(total.slivers_removed, 6U);
  EXPECT_EQ(total.faces_rebuilt, 1U);
  EXPECT_EQ(total.repairs_refused, 1U);
  EXPECT_DOUBLE_EQ(total.volume_change_mm3, -0.25);
  EXPECT_EQ(total.ways_tried, 3);
}

TEST(Rounding, LeavesACleanMeshAsItIs) {
  const auto [box, stats, clean, as_floats] =
      round_and_repair(box_mesh({0, 0, 0}, {1, 2, 3}),
                       {.precision = {.kind = Precision::Kind::Float}});
  EXPECT_TRUE(clean);
  EXPECT_FALSE(as_floats);
  EXPECT_EQ(box.triangles.size(), 12U);
  EXPECT_EQ(stats.passes, 1);
  EXPECT_EQ(stats.slivers_removed, 0U);
}

// Lparser's Menger cube at n = 4, 40 mm: round tubes overlapping face on
// face. Collapsing every sliver of its union made three times the pairs of
// intersecting faces it had, and rebuilding those lost parts of the model
// (the build stopped with "the union lost part of the model"); with
// slivers collapsed only where rebuilding made no progress, it comes out
// clean, its volume as it was. The first pass of each way tells which to
// carry on: the other is not tried. The union's own mends choose so too:
// of its 6 booleans (the corefinement's, where faces touch), 4 come back to
// doubles for the exact engine, where collapsing slivers brought 3 back.
TEST(Rounding, KeepsItsSliversWhenCollapsingThemMakesMoreFacesMeet) {
  const Solid solid = build_solid(
      lsys::testing::parse_file("tests/data/dialects/lparser/menger-cube.ls"),
      {.print = {.size_mm = 40.0}, .decimate = false});
  EXPECT_TRUE(solid.report.rounding.slivers_kept);
  EXPECT_EQ(solid.report.rounding.ways_tried, 1);
  EXPECT_EQ(solid.report.union_stats.booleans, 6U);
  EXPECT_EQ(solid.report.union_stats.rounded, 4U);
  EXPECT_LT(std::abs(solid.report.rounding.volume_change_mm3), 0.01);
  expect_printable(solid.mesh);
}

}  // namespace
}  // namespace lsolid
