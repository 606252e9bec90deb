// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "cgal/settled_rounding.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "lsolid/boolean.hpp"
#include "lsolid/precision.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::box_mesh;

void expect_same(const Rounded& a, const Rounded& b) {
  EXPECT_EQ(a.mesh.vertices, b.mesh.vertices);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  EXPECT_EQ(a.clean, b.clean);
  EXPECT_EQ(a.stats.passes, b.stats.passes);
  EXPECT_EQ(a.stats.slivers_removed, b.stats.slivers_removed);
  EXPECT_EQ(a.stats.faces_rebuilt, b.stats.faces_rebuilt);
}

TEST(SettledRounding, StillTestsSettledFacesAgainstTheOthers) {
  // Two boxes through each other in one mesh: every intersecting pair has
  // a face of each. With the first box's faces settled (they meet no other
  // of them), those pairs are still found and rebuilt, as without.
  TriangleMesh mesh = box_mesh({0, 0, 0}, {2, 2, 2});
  const std::size_t first = mesh.triangles.size();
  append(mesh, box_mesh({1, 0.5, 0.5}, {3, 1.5, 1.5}));
  std::vector<char> settled(mesh.triangles.size(), 0);
  std::fill(settled.begin(), settled.begin() + first, 1);
  const RoundingOptions options{.precision = {.kind = Precision::Kind::Double}};
  const Rounded plain = round_and_repair(mesh, options);
  const Rounded known = round_and_repair(mesh, options, settled);
  EXPECT_GT(known.stats.faces_rebuilt, 0U);
  expect_same(known, plain);
}

TEST(SettledRounding, MendsAUnionWhoseUncutFacesAreSettledAsWithout) {
  // Boxes offset by 1e-7 mm, united: slivers that floats cannot hold. The
  // faces with only the boxes' own corners are the uncut ones.
  std::vector<Part> parts{
      {box_mesh({100, 100, 100}, {101, 101, 101}), "a"},
      {box_mesh({100.5, 100, 100 + 1e-7}, {101.5, 101, 101 + 1e-7}), "b"}};
  const TriangleMesh united = union_parts(std::move(parts)).mesh;
  const auto corner = [](const glm::dvec3& p) {
    const auto on = [](double x, double lo) {
      return x == lo || x == lo + 1.0;
    };
    return (on(p.x, 100) && on(p.y, 100) && on(p.z, 100)) ||
           (on(p.x, 100.5) && on(p.y, 100) && on(p.z, 100 + 1e-7));
  };
  std::vector<char> settled(united.triangles.size(), 0);
  std::size_t count = 0;
  for (std::size_t f = 0; f < settled.size(); ++f) {
    const auto& t = united.triangles[f];
    if (corner(united.vertices[t[0]]) && corner(united.vertices[t[1]]) &&
        corner(united.vertices[t[2]])) {
      settled[f] = 1;
      ++count;
    }
  }
  EXPECT_GT(count, 0U);
  const RoundingOptions options{.precision = {.kind = Precision::Kind::Float}};
  const Rounded known = round_and_repair(united, options, settled);
  testing::expect_printable(known.mesh);
  expect_same(known, round_and_repair(united, options));
}

}  // namespace
}  // namespace lsolid
