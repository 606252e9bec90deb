// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/colors.hpp"

#include <gtest/gtest.h>

#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::box_mesh;

TEST(Colors, GivesBarkThenGreensAndGoesRound) {
  EXPECT_EQ(hex(palette_color(0)), "#7B4A2A");
  EXPECT_EQ(hex(palette_color(3)), "#8CC63F");
  EXPECT_EQ(palette_color(10), palette_color(0));
  EXPECT_EQ(palette_color(13), palette_color(3));
  EXPECT_EQ(palette_color(-2), palette_color(0));
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < i; ++j) {
      EXPECT_NE(palette_color(i), palette_color(j)) << i << " " << j;
    }
  }
}

TEST(Colors, TakesTheColoursGivenAndMergesIndicesOfOneColour) {
  const std::vector<Rgb> bark_and_leaf{
      {0x7B, 0x4A, 0x2A}, {0x7B, 0x4A, 0x2A}, {0x8C, 0xC6, 0x3F}};
  EXPECT_EQ(hex(palette_color(1, bark_and_leaf)), "#7B4A2A");
  EXPECT_EQ(hex(palette_color(2, bark_and_leaf)), "#8CC63F");
  EXPECT_EQ(hex(palette_color(7, bark_and_leaf)), "#8CC63F");  // the last
  EXPECT_EQ(material_index(0, bark_and_leaf), 0);
  EXPECT_EQ(material_index(1, bark_and_leaf), 0);
  EXPECT_EQ(material_index(2, bark_and_leaf), 2);
  EXPECT_EQ(material_index(9, bark_and_leaf), 2);
  // lsolid's own palette goes round every ten.
  EXPECT_EQ(material_index(4), 4);
  EXPECT_EQ(material_index(13), 3);
  EXPECT_EQ(material_index(-1), 0);
}

TEST(Colors, ColoursEachTriangleByTheNearestPart) {
  // A stem box of colour 0 and a leaf box of colour 3 beside it: the
  // "union" is both, each triangle on the surface of one of them.
  const Part stem{.mesh = box_mesh({0, 0, 0}, {1, 1, 4}), .label = "stem"};
  const Part leaf{
      .mesh = box_mesh({1, 0, 3}, {3, 1, 3.5}), .label = "leaf", .color = 3};
  TriangleMesh both = stem.mesh;
  append(both, leaf.mesh);
  const std::vector<int> colors = color_triangles(both, {stem, leaf});
  ASSERT_EQ(colors.size(), 24U);
  for (std::size_t t = 0; t < 12; ++t) EXPECT_EQ(colors[t], 0) << t;
  for (std::size_t t = 12; t < 24; ++t) EXPECT_EQ(colors[t], 3) << t;
}

TEST(Colors, GivesOneColouredModelItsColour) {
  const Part only{
      .mesh = box_mesh({0, 0, 0}, {1, 1, 1}), .label = "box", .color = 5};
  const std::vector<int> colors = color_triangles(only.mesh, {only});
  EXPECT_EQ(colors, std::vector<int>(12, 5));
}

}  // namespace
}  // namespace lsolid
