// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/containment.hpp"

#include <gtest/gtest.h>

#include <glm/vector_relational.hpp>

#include "lsolid/boolean.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::box_mesh;

std::vector<Part> two_boxes() {
  std::vector<Part> parts;
  parts.push_back(Part{box_mesh({0, 0, 0}, {10, 10, 2}), "slab"});
  parts.push_back(Part{box_mesh({8, 8, 1}, {12, 12, 9}), "post"});
  return parts;
}

TEST(Containment, FindsPointsDeepInsideEveryPart) {
  const std::vector<Part> parts = two_boxes();
  const std::vector<Witness> found = witnesses(parts);
  std::vector<int> per_part(parts.size(), 0);
  for (const Witness& w : found) {
    ASSERT_LT(w.part, parts.size());
    ++per_part[w.part];
    const Box b = bounds(parts[w.part].mesh);
    const glm::dvec3 p = w.point;
    const double depth =
        std::min({p.x - b.min.x, b.max.x - p.x, p.y - b.min.y, b.max.y - p.y,
                  p.z - b.min.z, b.max.z - p.z});
    EXPECT_GT(depth, 0.0);
    EXPECT_NEAR(w.depth_mm, depth, 1e-9);
  }
  EXPECT_GE(per_part[0], 1);
  EXPECT_GE(per_part[1], 1);
}

TEST(Containment, SkipsASliverWhoseNormalIsTooShortToAimARay) {
  // A tetrahedron 100 mm up whose first face (the one sampled) is a sliver:
  // its normal, 1e-15 long, vanished beside the centre's z and made a
  // degenerate ray that CGAL refused (the blog's trees at full size).
  TriangleMesh sliver;
  sliver.vertices = {
      {0, 0, 100}, {1, 0, 100}, {0.5, 1e-15, 100}, {0.5, 0.5, 101}};
  sliver.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  std::vector<Part> parts;
  parts.push_back(Part{sliver, "sliver"});
  parts.push_back(Part{box_mesh({0, 0, 0}, {10, 10, 2}), "slab"});
  std::vector<Witness> found;
  ASSERT_NO_THROW(found = witnesses(parts));
  for (const Witness& w : found) {
    const Box b = bounds(parts[w.part].mesh);
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(w.point, b.min)));
    EXPECT_TRUE(glm::all(glm::lessThanEqual(w.point, b.max)));
  }
}

TEST(Containment, ShootsNoRayAtAFaceWithoutArea) {
  // A 6 x 6 x 3 prism whose top holds a zero-area face along its diagonal,
  // right above the first bottom face's centre: the ray from there meets
  // it, and CGAL refuses a degenerate triangle (blog tree A at full size).
  TriangleMesh prism;
  prism.vertices = {{0, 0, 0}, {6, 0, 0}, {6, 6, 0}, {0, 6, 0}, {0, 0, 3},
                    {6, 0, 3}, {6, 6, 3}, {0, 6, 3}, {4, 2, 3}};
  prism.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 7}, {5, 6, 8}, {8, 6, 7},
                     {5, 8, 7}, {0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5},
                     {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  std::vector<Part> parts;
  parts.push_back(Part{prism, "prism"});
  std::vector<Witness> found;
  ASSERT_NO_THROW(found = witnesses(parts));
  ASSERT_EQ(found.size(), 1U);
  EXPECT_EQ(found[0].point, glm::dvec3(4, 2, 1.5));
  EXPECT_DOUBLE_EQ(found[0].depth_mm, 1.5);
  std::vector<Witness> outside{found[0]};
  ASSERT_NO_THROW(outside = witnesses_outside(prism, found, 0.0));
  EXPECT_TRUE(outside.empty());
}

TEST(Containment, NamesThePartsAUnionLeftOut) {
  const std::vector<Part> parts = two_boxes();
  const std::vector<Witness> found = witnesses(parts);
  const TriangleMesh united = union_parts(parts).mesh;
  EXPECT_TRUE(witnesses_outside(united, found, 1e-3).empty());
  // A "union" that lost the post keeps only the slab.
  const std::vector<Witness> lost =
      witnesses_outside(parts[0].mesh, found, 1e-3);
  ASSERT_FALSE(lost.empty());
  for (const Witness& w : lost) EXPECT_EQ(w.part, 1U);
  // Points that may have moved out with the surface are not asked for.
  EXPECT_TRUE(witnesses_outside(parts[0].mesh, found, 100.0).empty());
}

TEST(Containment, FindsLooseFragmentsThatNoPartAccountsFor) {
  std::vector<Part> parts = two_boxes();
  parts.push_back(Part{box_mesh({30, 0, 0}, {32, 2, 2}), "far block"});
  const std::vector<Witness> found = witnesses(parts);
  TriangleMesh result = union_parts(parts).mesh;
  // Two real pieces: nothing unaccounted for.
  EXPECT_TRUE(unaccounted_pieces(result, found, 1e-3).empty());
  // A sliver that a faulty repair might leave floating beside them.
  append(result, box_mesh({0, 20, 0}, {0.5, 20.2, 0.1}));
  const std::vector<Shell> loose = unaccounted_pieces(result, found, 1e-3);
  ASSERT_EQ(loose.size(), 1U);
  EXPECT_NEAR(loose[0].volume_mm3, 0.5 * 0.2 * 0.1, 1e-12);
  EXPECT_EQ(loose[0].bounds.min.y, 20.0);
}

TEST(Containment, AnEmptyResultLosesEveryPart) {
  const std::vector<Part> parts = two_boxes();
  const std::vector<Witness> found = witnesses(parts);
  EXPECT_EQ(witnesses_outside(TriangleMesh{}, found, 0.0).size(), found.size());
}

}  // namespace
}  // namespace lsolid
