// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/boolean.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "lsolid/errors.hpp"
#include "lsolid/parts.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::box_mesh;
using testing::expect_printable;

lsys::Segment segment(glm::dvec3 a, glm::dvec3 b, double d0, double d1,
                      std::int32_t parent = -1) {
  return lsys::Segment{a, b, d0, d1, 0, parent};
}

UnionResult unite(const lsys::Skeleton& s, double tolerance = 0.05) {
  return union_parts(build_parts(s, {.tolerance_mm = tolerance}).parts);
}

// True if p is inside the frustum (a circular cone segment) from a to b.
bool in_frustum(const glm::dvec3& p, const lsys::Segment& s) {
  const glm::dvec3 axis = s.p1 - s.p0;
  const double t = glm::dot(p - s.p0, axis) / glm::dot(axis, axis);
  if (t < 0.0 || t > 1.0) return false;
  const double r =
      (s.start_diameter + t * (s.end_diameter - s.start_diameter)) / 2;
  return glm::length(p - (s.p0 + t * axis)) <= r;
}

// The cubes' face diagonals cross the other's edges: the corefinement
// unites them as they are, the exact engine with one of them shifted by
// 10⁻⁸ mm (ExactUnion.ShiftsACoincidenceWhereFacesCrossAway).
TEST(Boolean, UnitesTwoBoxesToTheirExactVolume) {
  for (const UnionEngine engine :
       {UnionEngine::Corefinement, UnionEngine::ExactCrossings}) {
    std::vector<Part> parts{{box_mesh({0, 0, 0}, {2, 2, 2}), "a"},
                            {box_mesh({1, 1, 1}, {3, 3, 3}), "b"}};
    const UnionResult u = union_parts(std::move(parts), {.engine = engine});
    SCOPED_TRACE(engine_name(engine));
    expect_printable(u.mesh);
    if (engine == UnionEngine::Corefinement) {
      EXPECT_DOUBLE_EQ(signed_volume(u.mesh), 8.0 + 8.0 - 1.0);
    } else {
      EXPECT_NEAR(signed_volume(u.mesh), 8.0 + 8.0 - 1.0, 1e-7);
    }
    EXPECT_EQ(u.stats.booleans, 1U);
  }
}

TEST(Boolean, CountsItsContactsAndTellsItsExpectedTimeBeforeTheFirstBoolean) {
  // Each cube has three faces (six triangles, each as wide as its face) in
  // the other's box; the third cube meets neither.
  std::vector<Part> parts{{box_mesh({0, 0, 0}, {2, 2, 2}), "a"},
                          {box_mesh({1, 1, 1}, {3, 3, 3}), "b"},
                          {box_mesh({9, 9, 9}, {10, 10, 10}), "c"}};
  std::vector<std::string> told;
  double expected = -1.0;
  const UnionResult u =
      union_parts(std::move(parts),
                  {.progress = [&](double) { told.emplace_back("progress"); },
                   .expect =
                       [&](double seconds) {
                         told.emplace_back("expect");
                         expected = seconds;
                       }});
  EXPECT_EQ(u.stats.contacts, 12U);
  EXPECT_DOUBLE_EQ(expected, 12 * kUnionSecondsPerContact);
  ASSERT_FALSE(told.empty());
  EXPECT_EQ(told.front(), "expect");
  EXPECT_EQ(std::count(told.begin(), told.end(), "expect"), 1);
}

TEST(Boolean, JoinsPartsWithDisjointBoxesWithoutABoolean) {
  std::vector<Part> parts{{box_mesh({0, 0, 0}, {1, 1, 1}), "a"},
                          {box_mesh({5, 0, 0}, {6, 1, 1}), "b"}};
  const UnionResult u = union_parts(std::move(parts));
  EXPECT_EQ(u.stats.booleans, 0U);
  EXPECT_EQ(u.stats.concatenations, 1U);
  expect_printable(u.mesh, 2);
}

TEST(Boolean, UnitesPartsThatDoNotMeetEachOtherInOneBoolean) {
  // Four cubes on a bar: their boxes are disjoint, so they form one layer,
  // and one union takes them all in.
  std::vector<Part> parts{{box_mesh({0, 0, 0}, {10, 1, 1}), "bar"}};
  for (int i = 0; i < 4; ++i) {
    const double x = 0.5 + 2.5 * i;
    parts.push_back({box_mesh({x, -1, 0.5}, {x + 1, 2, 2}), "cube"});
  }
  const UnionResult u = union_parts(std::move(parts));
  expect_printable(u.mesh);
  EXPECT_EQ(u.stats.booleans, 1U);
  EXPECT_EQ(u.stats.concatenations, 3U);
  // Within the exact engine's shift where a cube's diagonal meets the bar's
  // edge.
  EXPECT_NEAR(signed_volume(u.mesh), 10.0 + 4 * (4.5 - 0.5), 1e-7);
}

TEST(Boolean, ReportsProgressUpToTheEnd) {
  std::vector<Part> parts;
  for (int i = 0; i < 6; ++i) {  // a chain of overlapping cubes
    parts.push_back({box_mesh({i * 0.5, 0, 0}, {i * 0.5 + 1, 1, 1}), "cube"});
  }
  std::vector<double> told;
  const UnionResult u =
      union_parts(std::move(parts),
                  {.progress = [&](double done) { told.push_back(done); }});
  ASSERT_FALSE(told.empty());
  EXPECT_TRUE(std::is_sorted(told.begin(), told.end()));
  EXPECT_GT(told.front(), 0.0);
  EXPECT_EQ(told.back(), 1.0);
  EXPECT_NEAR(signed_volume(u.mesh), 3.5, 1e-9);
}

TEST(Boolean, CrossingFrustaAgreeWithAnIndependentVolume) {
  lsys::Skeleton s;
  s.segments = {segment({-10, 0, 0}, {10, 0, 0}, 6, 4),
                segment({0, -10, -1}, {0, 10, 1}, 5, 5)};
  const UnionResult u = unite(s, 0.002);  // fine facets: close to circles
  expect_printable(u.mesh);
  // Independent estimate: count points of a fine grid inside either frustum.
  const Box box = bounds(u.mesh);
  constexpr int kSteps = 160;
  const glm::dvec3 step = box.size() / static_cast<double>(kSteps);
  std::size_t inside = 0;
  for (int i = 0; i < kSteps; ++i) {
    for (int j = 0; j < kSteps; ++j) {
      for (int k = 0; k < kSteps; ++k) {
        const glm::dvec3 p = box.min + (glm::dvec3(i, j, k) + 0.5) * step;
        if (in_frustum(p, s.segments[0]) || in_frustum(p, s.segments[1]))
          ++inside;
      }
    }
  }
  const double estimate =
      static_cast<double>(inside) * step.x * step.y * step.z;
  EXPECT_NEAR(signed_volume(u.mesh), estimate, 0.01 * estimate);
}

TEST(Boolean, SurvivesCoincidentCaps) {
  // Two chains whose end caps lie exactly on each other.
  lsys::Skeleton s;
  s.segments = {segment({0, 0, 0}, {0, 0, 10}, 2, 2),
                segment({0, 0, 10}, {0, 0, 20}, 2, 2)};
  expect_printable(unite(s).mesh);
}

TEST(Boolean, SurvivesParallelOverlappingSegments) {
  lsys::Skeleton s;
  s.segments = {segment({0, 0, 0}, {0, 0, 10}, 2, 2),
                segment({0, 0, 0}, {0, 0, 10}, 2, 2),
                segment({0.3, 0, 2}, {0.3, 0, 12}, 2, 2)};
  expect_printable(unite(s).mesh);
}

TEST(Boolean, SurvivesABranchThatDoublesBack) {
  lsys::Skeleton s;
  s.segments = {segment({0, 0, 0}, {0, 0, 10}, 2, 2),
                segment({0, 0, 10}, {0, 0, 3}, 1.5, 1.5, 0),  // `[|F]`
                segment({0, 0, 10}, {0, 0, 20}, 2, 2, 0)};
  const UnionResult u = unite(s);
  expect_printable(u.mesh);
}

TEST(Boolean, NamesAnInvalidPart) {
  TriangleMesh open = box_mesh({0, 0, 0}, {1, 1, 1});
  open.triangles.pop_back();
  std::vector<Part> parts{{box_mesh({0, 0, 0}, {2, 2, 2}), "a"},
                          {open, "the broken one"}};
  try {
    (void)union_parts(std::move(parts));
    FAIL() << "no error";
  } catch (const GeometryError& e) {
    EXPECT_STREQ(e.what(),
                 "a part is not a valid closed solid: the broken one");
  }
}

}  // namespace
}  // namespace lsolid
