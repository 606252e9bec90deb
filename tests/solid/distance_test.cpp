// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/distance.hpp"

#include <gtest/gtest.h>

#include "cgal/hausdorff.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::box_mesh;

TEST(Distance, MeasuresTheHausdorffDistanceOfTwoBoxes) {
  const TriangleMesh a = box_mesh({0, 0, 0}, {1, 1, 1});
  const TriangleMesh b = box_mesh({0, 0, 0}, {1, 1, 1.25});
  EXPECT_NEAR(hausdorff_distance_mm(a, b, 1e-4), 0.25, 1e-3);
  EXPECT_NEAR(hausdorff_distance_mm(a, a, 1e-4), 0.0, 1e-3);
}

TEST(Distance, FindsNoOverlapWhereSolidsOnlyTouch) {
  const TriangleMesh a = box_mesh({0, 0, 0}, {1, 1, 1});
  const TriangleMesh b = box_mesh({1, 0, 0}, {2, 1, 1});
  EXPECT_EQ(overlap_depth_mm(a, b), 0.0);
  EXPECT_EQ(overlap_depth_mm(b, a), 0.0);
}

TEST(Distance, MeasuresHowDeepOneSolidReachesIntoAnother) {
  const TriangleMesh outer = box_mesh({0, 0, 0}, {1, 1, 1});
  const TriangleMesh inner = box_mesh({0.4, 0.4, 0.4}, {0.6, 0.6, 0.6});
  EXPECT_NEAR(overlap_depth_mm(inner, outer), 0.4, 1e-9);
  // The outer's surface lies nowhere inside the inner one.
  EXPECT_EQ(overlap_depth_mm(outer, inner), 0.0);
  // Two boxes overlapping by 0.5 mm along x: the face centres of one at
  // x = 1 are a third of a millimetre from the other's sides.
  const TriangleMesh shifted = box_mesh({0.5, 0, 0}, {1.5, 1, 1});
  EXPECT_GT(overlap_depth_mm(outer, shifted), 0.3);
}

}  // namespace
}  // namespace lsolid
