// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "shells.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <vector>

#include "lsolid/precision.hpp"
#include "support/mesh_checks.hpp"
#include "union_find.hpp"

namespace lsolid {
namespace {

using testing::box_mesh;

// The shells by their definition, pair by pair: two triangles are joined
// when a side of one, as an unordered pair of vertex indices (a vertex to
// itself included), is a side of the other.
ShellLabels shells_by_pairs(const TriangleMesh& mesh) {
  const auto sides = [&](std::size_t f) {
    std::set<std::uint64_t> out;
    const auto& t = mesh.triangles[f];
    for (std::size_t k = 0; k < 3; ++k)
      out.insert(edge_key(t[k], t[(k + 1) % 3]));
    return out;
  };
  const std::size_t n = mesh.triangles.size();
  UnionFind sets(n);
  for (std::uint32_t f = 0; f < n; ++f) {
    const std::set<std::uint64_t> mine = sides(f);
    for (std::uint32_t g = f + 1; g < n; ++g) {
      for (const std::uint64_t side : sides(g)) {
        if (mine.contains(side)) sets.join(f, g);
      }
    }
  }
  ShellLabels out;
  std::vector<std::uint32_t> label(n, ~0U);
  for (std::uint32_t f = 0; f < n; ++f) {
    std::uint32_t& l = label[sets.find(f)];
    if (l == ~0U) l = static_cast<std::uint32_t>(out.count++);
    out.of_triangle.push_back(l);
  }
  return out;
}

// The mesh with equal points made one vertex (snapped merges them).
TriangleMesh welded(const TriangleMesh& mesh) {
  return snapped(mesh, Precision{.kind = Precision::Kind::Double});
}

TEST(Shells, NumbersShellsInTheOrderOfTheirFirstTriangles) {
  TriangleMesh mesh = box_mesh({0, 0, 0}, {1, 1, 1});
  append(mesh, box_mesh({3, 0, 0}, {4, 1, 1}));
  // The first box's triangles again at the end: they join it.
  for (std::size_t f = 0; f < 2; ++f)
    mesh.triangles.push_back(mesh.triangles[f]);
  const ShellLabels shells = label_shells(mesh);
  EXPECT_EQ(shells.count, 2U);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    EXPECT_EQ(shells.of_triangle[f], f < 12 || f >= 24 ? 0U : 1U) << f;
  }
}

TEST(Shells, KeepsBoxesThatShareAVertexApartAndJoinsThoseThatShareAnEdge) {
  // Boxes meeting at the corner (1, 1, 1), welded there.
  TriangleMesh corner = box_mesh({0, 0, 0}, {1, 1, 1});
  TriangleMesh other = box_mesh({1, 1, 1}, {2, 2, 2});
  append(corner, other);
  corner = welded(corner);
  ASSERT_EQ(corner.vertices.size(), 15U);
  EXPECT_EQ(label_shells(corner).count, 2U);
  // Boxes meeting along the edge x = 1, y = 1, welded there.
  TriangleMesh edge = box_mesh({0, 0, 0}, {1, 1, 1});
  append(edge, box_mesh({1, 1, 0}, {2, 2, 1}));
  edge = welded(edge);
  ASSERT_EQ(edge.vertices.size(), 14U);
  EXPECT_EQ(label_shells(edge).count, 1U);
}

TEST(Shells, AgreesWithTheDefinitionOnRandomTrianglesWithRepeatedCorners) {
  std::mt19937 random(11);
  for (int round = 0; round < 200; ++round) {
    TriangleMesh mesh;
    const auto vertices = static_cast<std::uint32_t>(4 + round % 9);
    for (std::uint32_t v = 0; v < vertices; ++v)
      mesh.vertices.emplace_back(v, 0, 0);
    std::uniform_int_distribution<std::uint32_t> corner(0, vertices - 1);
    const int triangles = 1 + round % 7;
    for (int f = 0; f < triangles; ++f) {
      // A corner repeated now and then: a side from a vertex to itself.
      const std::uint32_t a = corner(random);
      const std::uint32_t b = corner(random);
      const std::uint32_t c = random() % 4 == 0 ? b : corner(random);
      mesh.triangles.push_back({a, b, c});
    }
    const ShellLabels fast = label_shells(mesh);
    const ShellLabels slow = shells_by_pairs(mesh);
    EXPECT_EQ(fast.count, slow.count) << round;
    EXPECT_EQ(fast.of_triangle, slow.of_triangle) << round;
  }
}

TEST(Shells, SumsEachShellsVolumeAndTellsACavityByItsSign) {
  const TriangleMesh mesh =
      testing::box_with_cavity({0, 0, 0}, {4, 4, 4}, {1, 1, 1}, {2, 2, 2});
  const ShellLabels shells = label_shells(mesh);
  ASSERT_EQ(shells.count, 2U);
  const std::vector<double> volumes = shell_volumes(mesh, shells);
  EXPECT_DOUBLE_EQ(volumes[0], 64.0);
  EXPECT_DOUBLE_EQ(volumes[1], -1.0);
}

TEST(Shells, ListsTheTrianglesRoundEachVertexInTriangleOrder) {
  TriangleMesh mesh = box_mesh({0, 0, 0}, {1, 1, 1});
  // A degenerate triangle with vertex 0 twice: listed twice round it.
  mesh.triangles.push_back({0, 0, 7});
  const VertexStars stars = vertex_stars(mesh);
  ASSERT_EQ(stars.first.size(), 9U);
  EXPECT_EQ(stars.triangles.size(), 3 * mesh.triangles.size());
  for (std::uint32_t v = 0; v < 8; ++v) {
    std::vector<std::uint32_t> expected;
    for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f) {
      for (const std::uint32_t w : mesh.triangles[f]) {
        if (w == v) expected.push_back(f);
      }
    }
    EXPECT_EQ(std::vector<std::uint32_t>(
                  stars.triangles.begin() + stars.first[v],
                  stars.triangles.begin() + stars.first[v + 1]),
              expected)
        << v;
  }
  // Three of the box's triangles, and the degenerate one twice.
  EXPECT_EQ(stars.first[1] - stars.first[0], 5U);
}

}  // namespace
}  // namespace lsolid
