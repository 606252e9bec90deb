// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "box_pairs.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace lsolid {
namespace {

using Pairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

bool meet(const Box& a, const Box& b) {
  for (int k = 0; k < 3; ++k) {
    if (a.min[k] > b.max[k] || b.min[k] > a.max[k]) return false;
  }
  return true;
}

Box box(glm::dvec3 lo, glm::dvec3 hi) { return Box{.min = lo, .max = hi}; }

// Boxes of a surface's triangles, most small, some of no size, a few long
// (a tube's side) or wide (a leaf) and a few over thousands of cells, on
// a lattice of 1/8 so that many touch exactly.
std::vector<Box> random_boxes(std::size_t count, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> cell(0, 64);
  std::uniform_int_distribution<int> small(0, 6);
  std::uniform_int_distribution<int> kind(0, 99);
  std::vector<Box> out;
  for (std::size_t i = 0; i < count; ++i) {
    const glm::dvec3 lo(cell(random) / 8.0, cell(random) / 8.0,
                        cell(random) / 8.0);
    glm::dvec3 size(small(random) / 8.0, small(random) / 8.0,
                    small(random) / 8.0);
    const int k = kind(random);
    if (k < 5) size = glm::dvec3(0.0);
    if (k >= 95) size.x = 6.0;
    if (k == 98) size = glm::dvec3(8.0, 8.0, 0.25);
    // Over thousands of cells (about two median boxes wide).
    if (k == 99) size = glm::dvec3(30.0, 30.0, 30.0);
    out.push_back(box(lo, lo + size));
  }
  return out;
}

TEST(BoxPairs, FindsEveryPairOfMeetingBoxesOnceInOrder) {
  for (const unsigned seed : {1U, 2U, 3U}) {
    const std::vector<Box> boxes = random_boxes(1500, seed);
    Pairs expected;
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
      for (std::uint32_t j = i + 1; j < boxes.size(); ++j) {
        if (meet(boxes[i], boxes[j])) expected.emplace_back(i, j);
      }
    }
    ASSERT_GT(expected.size(), 1000U);
    EXPECT_EQ(meeting_box_pairs(
                  boxes, [](std::uint32_t, std::uint32_t) { return true; }),
              expected)
        << seed;
  }
}

TEST(BoxPairs, KeepsOnlyThePairsItIsToldTo) {
  const std::vector<Box> boxes = random_boxes(600, 4);
  Pairs expected;
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    for (std::uint32_t j = i + 1; j < boxes.size(); ++j) {
      if (meet(boxes[i], boxes[j]) && (i + j) % 3 == 0) {
        expected.emplace_back(i, j);
      }
    }
  }
  EXPECT_EQ(meeting_box_pairs(boxes,
                              [](std::uint32_t i, std::uint32_t j) {
                                return (i + j) % 3 == 0;
                              }),
            expected);
}

TEST(BoxPairs, FindsEveryPairAcrossTwoSetsOnceInOrder) {
  const std::vector<Box> first = random_boxes(900, 5);
  const std::vector<Box> second = random_boxes(700, 6);
  Pairs expected;
  for (std::uint32_t i = 0; i < first.size(); ++i) {
    for (std::uint32_t j = 0; j < second.size(); ++j) {
      if (meet(first[i], second[j])) expected.emplace_back(i, j);
    }
  }
  ASSERT_GT(expected.size(), 500U);
  const auto all = [](std::uint32_t, std::uint32_t) { return true; };
  EXPECT_EQ(meeting_box_pairs(first, second, all), expected);
  EXPECT_TRUE(meeting_box_pairs(first, {}, all).empty());
}

TEST(BoxPairs, CountsBoxesThatOnlyTouchAsMeeting) {
  // Face to face, edge to edge, corner to corner, and one apart by a
  // hair.
  const std::vector<Box> boxes = {
      box({0, 0, 0}, {1, 1, 1}), box({1, 0, 0}, {2, 1, 1}),
      box({1, 1, 0}, {2, 2, 1}), box({1, 1, 1}, {2, 2, 2}),
      box({0, 0, 1.0000001}, {1, 1, 2})};
  const Pairs pairs = meeting_box_pairs(
      boxes, [](std::uint32_t, std::uint32_t) { return true; });
  const Pairs expected = {{0, 1}, {0, 2}, {0, 3}, {1, 2},
                          {1, 3}, {2, 3}, {3, 4}};
  EXPECT_EQ(pairs, expected);
}

TEST(BoxPairs, FindsTinyBoxesFarFromTheOrigin) {
  // Slivers a few nanometres wide 500 mm out: cells as fine as the boxes,
  // counted from the origin, would be 10¹⁴ cells out (the rounding of a
  // leaf's overlapping polygons met this).
  const glm::dvec3 far(500.0, -500.0, 250.0);
  const std::vector<Box> boxes = {box(far, far + 2e-9),
                                  box(far + 1e-9, far + 3e-9),
                                  box(far + 4e-9, far + 5e-9)};
  const auto all = [](std::uint32_t, std::uint32_t) { return true; };
  EXPECT_EQ(meeting_box_pairs(boxes, all), (Pairs{{0, 1}}));
  EXPECT_EQ(meeting_box_pairs({boxes[0]}, {boxes[1], boxes[2]}, all),
            (Pairs{{0, 0}}));
}

TEST(BoxPairs, FindsNothingAmongFewerThanTwoBoxes) {
  const auto all = [](std::uint32_t, std::uint32_t) { return true; };
  EXPECT_TRUE(meeting_box_pairs({}, all).empty());
  EXPECT_TRUE(meeting_box_pairs({box({0, 0, 0}, {1, 1, 1})}, all).empty());
}

}  // namespace
}  // namespace lsolid
