// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/overhang.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::box_mesh;

TEST(Overhang, IgnoresWhatLiesOnTheBed) {
  const OverhangReport r = overhang(box_mesh({0, 0, 0}, {10, 10, 10}));
  EXPECT_EQ(r.area_mm2, 0.0);
  EXPECT_FALSE(r.needs_supports);
}

TEST(Overhang, CountsTheUndersideOfWhatHangsInTheAir) {
  TriangleMesh m = box_mesh({0, 0, 0}, {1, 1, 1});
  append(m, box_mesh({-1, -1, 5}, {2, 1, 6}));  // a 3 × 2 mm ceiling
  const OverhangReport r = overhang(m);
  EXPECT_DOUBLE_EQ(r.area_mm2, 6.0);
  EXPECT_TRUE(r.needs_supports);  // more than kSupportArea
  TriangleMesh small = box_mesh({0, 0, 0}, {1, 1, 1});
  append(small, box_mesh({0, 0, 5}, {2, 2, 6}));
  EXPECT_DOUBLE_EQ(overhang(small).area_mm2, 4.0);
  EXPECT_FALSE(overhang(small).needs_supports);
}

TEST(Overhang, FlagsTheTrianglesOfACeilingOnly) {
  TriangleMesh m = box_mesh({0, 0, 0}, {1, 1, 1});
  append(m, box_mesh({-1, -1, 5}, {2, 1, 6}));
  const std::vector<bool> steep = overhang(m).triangles;
  ASSERT_EQ(steep.size(), m.triangles.size());
  std::size_t flagged = 0;
  for (std::size_t i = 0; i < steep.size(); ++i) {
    if (!steep[i]) continue;
    ++flagged;
    // Only the upper box's floor, at z = 5, faces down in the air.
    for (const std::uint32_t v : m.triangles[i]) {
      EXPECT_EQ(m.vertices[v].z, 5.0);
    }
  }
  EXPECT_EQ(flagged, 2U);
}

TEST(Overhang, CountsFacesSteeperThanTheLimitOnly) {
  // Two downward faces of 1 mm² above the bed: one 30° below the
  // horizontal (a gentle slope), one 60° below it.
  TriangleMesh m;
  const auto face = [&](double normal_below_deg, double z) {
    const double a = normal_below_deg * std::numbers::pi / 180.0;
    // A unit square whose normal is (cos a, 0, -sin a).
    const glm::dvec3 u(0, 1, 0);
    const glm::dvec3 v(std::sin(a), 0, std::cos(a));
    const glm::dvec3 o(0, 0, z);
    const auto i = static_cast<std::uint32_t>(m.vertices.size());
    m.vertices.insert(m.vertices.end(), {o, o + u, o + u + v, o + v});
    m.triangles.push_back({i, i + 1, i + 2});
    m.triangles.push_back({i, i + 2, i + 3});
  };
  m.vertices.push_back({0, 0, 0});  // the bed
  m.triangles.push_back({0, 0, 0});
  face(30.0, 5.0);
  EXPECT_NEAR(overhang(m).area_mm2, 0.0, 1e-12);
  face(60.0, 10.0);
  EXPECT_NEAR(overhang(m).area_mm2, 1.0, 1e-12);
  EXPECT_NEAR(overhang(m, 20.0).area_mm2, 2.0, 1e-12);
}

}  // namespace
}  // namespace lsolid
