// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "cgal/triangle_pair.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "cgal/exact_checks.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::box_mesh;

std::vector<IndexedTriangle> indexed(const TriangleMesh& mesh) {
  std::vector<IndexedTriangle> out;
  for (const auto& t : mesh.triangles) {
    out.push_back(IndexedTriangle{
        t, {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]}});
  }
  return out;
}

// Two boxes in one mesh, the second shifted by `by`.
TriangleMesh two_boxes(const glm::dvec3& by) {
  TriangleMesh mesh = box_mesh({0, 0, 0}, {2, 2, 2});
  append(mesh, box_mesh(by, by + glm::dvec3(2, 2, 2)));
  return mesh;
}

TEST(TrianglePair, FindsNoPairOnAClosedSurface) {
  EXPECT_TRUE(
      intersecting_pairs(indexed(box_mesh({0, 0, 0}, {1, 2, 3}))).empty());
}

TEST(TrianglePair, FindsThePairsOfOverlappingBoxesAsCgalDoes) {
  for (const glm::dvec3& by :
       {glm::dvec3(1, 1, 1), glm::dvec3(1, 0.5, 0.25),
        // Face on face: coplanar triangles that overlap meet.
        glm::dvec3(2, 0.5, 0.5), glm::dvec3(2, 0, 0)}) {
    const TriangleMesh mesh = two_boxes(by);
    const auto pairs = intersecting_pairs(indexed(mesh));
    EXPECT_FALSE(pairs.empty());
    EXPECT_EQ(pairs.size(),
              exact_checks(mesh, true, true).self_intersecting_pairs)
        << by.x << " " << by.y << " " << by.z;
    // The check builds a closed manifold's halfedge mesh from its faces as
    // they stand, anything else through CGAL's soup repair: the same pairs.
    EXPECT_EQ(exact_checks(mesh, true, false).self_intersecting_pairs,
              pairs.size());
    for (const auto& [f, g] : pairs) {
      // Each box is a closed surface: a pair takes one triangle of each.
      EXPECT_TRUE((f < 12u) != (g < 12u)) << f << " " << g;
    }
  }
  EXPECT_TRUE(intersecting_pairs(indexed(two_boxes({3, 0, 0}))).empty());
}

TEST(TrianglePair, ReportsADegenerateTriangleAloneAndLeavesItOut) {
  TriangleMesh mesh = box_mesh({0, 0, 0}, {1, 1, 1});
  // Collinear corners across the box's bottom face.
  mesh.vertices.push_back({0.5, 0.5, 0});
  mesh.vertices.push_back({0.25, 0.25, 0});
  mesh.triangles.push_back({0, 9, 8});
  const auto pairs = intersecting_pairs(indexed(mesh));
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].first, 12u);
  EXPECT_EQ(pairs[0].second, 12u);
}

TEST(TrianglePair, TellsAFoldFromNeighboursAlongTheirEdge) {
  const glm::dvec3 a(0, 0, 0);
  const glm::dvec3 b(1, 0, 0);
  const IndexedTriangle first{{0, 1, 2}, {a, b, glm::dvec3(0, 1, 0)}};
  const IndexedTriangle flat{{1, 0, 3}, {b, a, glm::dvec3(0, -1, 0)}};
  const IndexedTriangle folded{{1, 0, 3}, {b, a, glm::dvec3(0.5, 1, 0)}};
  EXPECT_FALSE(triangles_intersect(first, flat));
  EXPECT_TRUE(triangles_intersect(first, folded));
  EXPECT_EQ(intersecting_pairs({first, folded}).size(), 1u);
}

}  // namespace
}  // namespace lsolid
