// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/mesh.hpp"

#include <gtest/gtest.h>

#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::box_mesh;

TEST(Mesh, MeasuresBoundsAndVolume) {
  const TriangleMesh box = box_mesh({0, 0, 0}, {1, 2, 3});
  EXPECT_DOUBLE_EQ(signed_volume(box), 6.0);
  EXPECT_EQ(bounds(box).max, glm::dvec3(1, 2, 3));
  EXPECT_TRUE(Box{}.empty());
}

TEST(Mesh, AppendsWithoutABoolean) {
  TriangleMesh both = box_mesh({0, 0, 0}, {1, 1, 1});
  append(both, box_mesh({5, 0, 0}, {6, 1, 1}));
  EXPECT_EQ(both.vertices.size(), 16U);
  EXPECT_EQ(both.triangles.size(), 24U);
  EXPECT_DOUBLE_EQ(signed_volume(both), 2.0);
}

// A box with a sealed cavity: the cavity is its own shell, facing inward.
TriangleMesh box_with_cavity() {
  return testing::box_with_cavity({0, 0, 0}, {4, 4, 4}, {1, 1, 1}, {2, 2, 2});
}

TEST(Mesh, FillsSealedCavitiesAndKeepsTheOuterSurface) {
  const CavitiesFilled filled = fill_cavities(box_with_cavity());
  EXPECT_EQ(filled.removed, 1U);
  EXPECT_EQ(filled.mesh.triangles.size(), 12U);
  EXPECT_EQ(filled.mesh.vertices.size(), 8U);
  EXPECT_DOUBLE_EQ(signed_volume(filled.mesh), 64.0);
}

TEST(Mesh, LeavesAMeshWithoutCavitiesAsItIs) {
  TriangleMesh two = box_mesh({0, 0, 0}, {1, 1, 1});
  append(two, box_mesh({5, 0, 0}, {6, 1, 1}));
  const CavitiesFilled filled = fill_cavities(two);
  EXPECT_EQ(filled.removed, 0U);
  EXPECT_EQ(filled.mesh.triangles, two.triangles);
}

}  // namespace
}  // namespace lsolid
