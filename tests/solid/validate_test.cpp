// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/validate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::box_mesh;

TEST(Validate, AcceptsAClosedOutwardBox) {
  const ValidationReport r = validate(box_mesh({0, 0, 0}, {1, 1, 1}));
  EXPECT_TRUE(r.is_printable());
  EXPECT_EQ(r.shells, 1U);
  EXPECT_EQ(r.genus, 0);
  EXPECT_DOUBLE_EQ(r.volume_mm3, 1.0);
  EXPECT_TRUE(r.problems().empty());
}

TEST(Validate, ListsPiecesLargestFirstAndTellsCavitiesApart) {
  TriangleMesh m = box_mesh({0, 0, 0}, {1, 1, 1});
  // A cavity inside the large box: a shell of negative volume.
  append(m, testing::box_with_cavity({5, 0, 0}, {7, 2, 2}, {5.5, 0.5, 0.5},
                                     {6, 1, 1}));
  const ValidationReport r = validate(m);
  EXPECT_TRUE(r.is_printable());
  EXPECT_EQ(r.shells, 3U);
  EXPECT_EQ(r.pieces(), 2U);
  ASSERT_EQ(r.shell_list.size(), 3U);
  EXPECT_NEAR(r.shell_list[0].volume_mm3, 8.0, 1e-12);
  EXPECT_NEAR(r.shell_list[1].volume_mm3, 1.0, 1e-12);
  EXPECT_NEAR(r.shell_list[2].volume_mm3, -0.125, 1e-12);
  EXPECT_EQ(r.shell_list[1].bounds.max, glm::dvec3(1, 1, 1));
  EXPECT_EQ(r.shell_list[0].triangles, 12U);
}

TEST(Validate, FindsHoles) {
  TriangleMesh m = box_mesh({0, 0, 0}, {1, 1, 1});
  m.triangles.pop_back();
  const ValidationReport r = validate(m);
  EXPECT_EQ(r.boundary_edges, 3U);
  EXPECT_FALSE(r.is_printable());
}

TEST(Validate, FindsAFlippedFace) {
  TriangleMesh m = box_mesh({0, 0, 0}, {1, 1, 1});
  std::swap(m.triangles[0][1], m.triangles[0][2]);
  EXPECT_EQ(validate(m).misoriented_edges, 3U);
}

TEST(Validate, FindsAnInsideOutMesh) {
  TriangleMesh m = box_mesh({0, 0, 0}, {1, 1, 1});
  for (auto& t : m.triangles) std::swap(t[1], t[2]);
  const ValidationReport r = validate(m);
  EXPECT_TRUE(r.orientation_checked);
  EXPECT_FALSE(r.is_outward);
  EXPECT_LT(r.volume_mm3, 0.0);
}

TEST(Validate, FindsSelfIntersectionsExactly) {
  TriangleMesh m = box_mesh({0, 0, 0}, {1, 1, 1});
  append(m, box_mesh({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}));
  const ValidationReport r = validate(m);
  EXPECT_TRUE(r.self_intersections_checked);
  EXPECT_GT(r.self_intersecting_pairs, 0U);
  EXPECT_EQ(r.shells, 2U);
  EXPECT_FALSE(r.is_printable());
}

TEST(Validate, FindsEdgesSharedByFourFaces) {
  // Two boxes meeting along one edge, with that edge's vertices shared.
  TriangleMesh m = box_mesh({0, 0, 0}, {1, 1, 1});
  TriangleMesh other = box_mesh({1, 1, 0}, {2, 2, 1});
  const auto offset = static_cast<std::uint32_t>(m.vertices.size());
  append(m, other);
  // Vertex (1,1,0) is 3 in the first box and 0 in the second; (1,1,1) is 7
  // and 4.
  for (auto& t : m.triangles) {
    for (auto& v : t) {
      if (v == offset + 0) v = 3;
      if (v == offset + 4) v = 7;
    }
  }
  const ValidationReport r = validate(m);
  EXPECT_EQ(r.non_manifold_edges, 1U);
  EXPECT_FALSE(r.self_intersections_checked);
  EXPECT_FALSE(r.is_printable());
}

TEST(Validate, FindsVerticesWhereShellsTouch) {
  TriangleMesh m = box_mesh({0, 0, 0}, {1, 1, 1});
  const auto offset = static_cast<std::uint32_t>(m.vertices.size());
  append(m, box_mesh({1, 1, 1}, {2, 2, 2}));
  for (auto& t : m.triangles) {
    for (auto& v : t) {
      if (v == offset) v = 7;  // (1,1,1) shared
    }
  }
  EXPECT_EQ(validate(m).non_manifold_vertices, 1U);
}

TEST(Validate, FindsDegenerateFaces) {
  TriangleMesh m = box_mesh({0, 0, 0}, {1, 1, 1});
  m.vertices.push_back({0.5, 0, 0});
  m.triangles.push_back({0, 1, 8});  // collinear corners
  EXPECT_EQ(validate(m).degenerate_faces, 1U);
}

TEST(Validate, CountsTheGenusOfATorus) {
  TriangleMesh torus;
  constexpr int kRing = 12;
  constexpr int kTube = 8;
  for (int i = 0; i < kRing; ++i) {
    for (int j = 0; j < kTube; ++j) {
      const double u = 2 * std::numbers::pi * i / kRing;
      const double v = 2 * std::numbers::pi * j / kTube;
      torus.vertices.push_back({(3 + std::cos(v)) * std::cos(u),
                                (3 + std::cos(v)) * std::sin(u), std::sin(v)});
    }
  }
  const auto at = [](int i, int j) {
    return static_cast<std::uint32_t>(((i + kRing) % kRing) * kTube +
                                      (j + kTube) % kTube);
  };
  for (int i = 0; i < kRing; ++i) {
    for (int j = 0; j < kTube; ++j) {
      torus.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      torus.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  const ValidationReport r = validate(torus);
  EXPECT_EQ(r.genus, 1);
  EXPECT_TRUE(r.is_printable());
}

}  // namespace
}  // namespace lsolid
