// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/interpretation.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <set>
#include <string>
#include <tuple>

#include "support/abop_systems.hpp"
#include "support/core_helpers.hpp"

namespace lsys {
namespace {

using testing::kHilbert;
using testing::kHonda;
using testing::parse;

Skeleton walk(const std::string& text, DerivationOptions options = {},
              InterpretOptions interpret_options = {}) {
  return interpret(parse(text), options, interpret_options);
}

std::array<long long, 3> lattice(const glm::dvec3& p) {
  return {std::llround(p.x), std::llround(p.y), std::llround(p.z)};
}

void expect_lattice_path(const Skeleton& s, std::size_t points, long long box) {
  std::set<std::array<long long, 3>> visited;
  for (std::size_t i = 0; i < s.segments.size(); ++i) {
    const Segment& seg = s.segments[i];
    for (const glm::dvec3& p : {seg.p0, seg.p1}) {
      const auto q = lattice(p);
      // Quarter turns are exact, so the points are exact integers.
      ASSERT_EQ(p, glm::dvec3(q[0], q[1], q[2]));
      for (long long c : q) {
        ASSERT_GE(c, 0);
        ASSERT_LE(c, box);
      }
      visited.insert(q);
    }
    EXPECT_EQ(glm::length(seg.p1 - seg.p0), 1.0);
    if (i > 0) {
      EXPECT_EQ(seg.p0, s.segments[i - 1].p1);
    }
  }
  EXPECT_EQ(visited.size(), points);
}

TEST(Interpretation, Hilbert2Draws63UnitSegmentsThrough64LatticePoints) {
  const Skeleton s = walk(kHilbert);
  ASSERT_EQ(s.segments.size(), 63U);
  expect_lattice_path(s, 64, 3);
}

TEST(Interpretation, Hilbert3Draws511SegmentsThrough512PointsOfA7Box) {
  const Skeleton s = walk(kHilbert, {.derivation_length = 3});
  ASSERT_EQ(s.segments.size(), 511U);
  expect_lattice_path(s, 512, 7);
}

TEST(Interpretation, Hilbert3IsAlsoACurveWithCpfgRolls) {
  const Skeleton s =
      walk(kHilbert, {.derivation_length = 3}, {.roll = RollConvention::Cpfg});
  ASSERT_EQ(s.segments.size(), 511U);
  std::set<std::array<long long, 3>> visited;
  for (const Segment& seg : s.segments) visited.insert(lattice(seg.p1));
  EXPECT_EQ(visited.size(), 511U);
}

TEST(Interpretation, HondaTreeHas1023SegmentsAndItsTrunk) {
  const Skeleton s = walk(kHonda);
  ASSERT_EQ(s.segments.size(), 1023U);
  // The trunk: the segments on the Z axis, lengths 0.9^k, widths 10·0.707^k.
  std::vector<const Segment*> trunk;
  for (const Segment& seg : s.segments) {
    if (std::hypot(seg.p0.x, seg.p0.y) < 1e-9 &&
        std::hypot(seg.p1.x, seg.p1.y) < 1e-9) {
      trunk.push_back(&seg);
    }
  }
  ASSERT_EQ(trunk.size(), 10U);
  double top = 0.0;
  for (std::size_t k = 0; k < trunk.size(); ++k) {
    const Segment& seg = *trunk[k];
    EXPECT_NEAR(seg.p1.z - seg.p0.z, std::pow(0.9, k), 1e-12);
    EXPECT_NEAR(seg.start_diameter, 10.0 * std::pow(0.707, k), 1e-9);
    EXPECT_EQ(seg.start_diameter, seg.end_diameter);
    top = std::max(top, seg.p1.z);
  }
  EXPECT_NEAR(top, (1.0 - std::pow(0.9, 10)) / 0.1, 1e-12);  // 6.513215599
  EXPECT_EQ(s.segments.front().start_diameter, 10.0);
}

TEST(Interpretation, HondaLateralBranchesAreRolledToTheVertical) {
  // After `$`, L is horizontal, so `+(a2)` keeps B's branches' headings at
  // the same height change as the parent axis.
  const Skeleton s = walk(kHonda, {.derivation_length = 3});
  for (const Segment& seg : s.segments) {
    EXPECT_GE(seg.p1.z, seg.p0.z - 1e-12) << "no branch points downward";
  }
}

TEST(Interpretation, PlusTurnsLeftSeenFromTheFront) {
  const Skeleton s = walk("\u03C9: F+F-F\n\u03B4=90");
  ASSERT_EQ(s.segments.size(), 3U);
  EXPECT_EQ(s.segments[1].p1, glm::dvec3(-1, 0, 1));
  EXPECT_EQ(s.segments[2].p1, glm::dvec3(-1, 0, 2));
}

TEST(Interpretation, PlanarFiguresLieInTheXzPlane) {
  const Skeleton s = walk("n=5, \u03B4=25.7\u00B0\nF\nF \u2192 F[+F]F[-F]F");
  ASSERT_EQ(s.segments.size(), 3125U);
  double height = 0.0;
  for (const Segment& seg : s.segments) {
    EXPECT_EQ(seg.p0.y, 0.0);
    EXPECT_EQ(seg.p1.y, 0.0);
    height = std::max(height, seg.p1.z);
  }
  EXPECT_NEAR(height, 243.0, 1e-9);  // the main axis: 3^5 unit segments
}

TEST(Interpretation, Abop124dLeansLeftAsItsTextDefines) {
  // X → F[+X]F[-X]+X: the apex turns by +δ each step, counter-clockwise.
  const Skeleton s =
      walk("n=7, \u03B4=20\u00B0\nX\nX \u2192 F[+X]F[-X]+X\nF \u2192 FF");
  ASSERT_EQ(s.segments.size(), 4118U);
  double sum_x = 0.0;
  for (const Segment& seg : s.segments) sum_x += seg.p1.x;
  EXPECT_LT(sum_x / 4118.0, -10.0);
}

TEST(Interpretation, AbopLeafIsAHexagon) {
  const Skeleton s = walk("\u03C9: ''{-f+f+f-|-f+f+f}\n\u03B4=22.5");
  ASSERT_EQ(s.polygons.size(), 1U);
  const Polygon& leaf = s.polygons[0];
  EXPECT_EQ(leaf.points.size(), 6U);  // the closing point equals the first
  EXPECT_EQ(leaf.color, 2);
  EXPECT_EQ(leaf.points.front(), glm::dvec3(0, 0, 0));
  for (const glm::dvec3& p : leaf.points) EXPECT_NEAR(p.y, 0.0, 1e-12);
  EXPECT_TRUE(s.segments.empty());
}

TEST(Interpretation, Seed000LeafFansFromItsBase) {
  const Skeleton s = walk(
      "\u03C9: {[++++G.][++GG.][+GGG.][GGGGG.][-GGG.][--GG.][-G.]}\n"
      "\u03B4=18");
  ASSERT_EQ(s.polygons.size(), 1U);
  EXPECT_EQ(s.polygons[0].points.size(), 8U);  // the base and seven tips
  EXPECT_EQ(s.segments.size(), 17U);           // G draws the veins
}

TEST(Interpretation, DropsDegeneratePolygons) {
  const Skeleton s = walk("\u03C9: {.f.}{}\n");
  EXPECT_TRUE(s.polygons.empty());
  EXPECT_EQ(s.degenerate_polygons, 2U);
}

TEST(Interpretation, DrawInsideAPolygonAddsAVertexWithoutASegment) {
  const Skeleton s = walk("\u03C9: F{+F-F-F}F\n\u03B4=90");
  EXPECT_EQ(s.segments.size(), 2U);
  ASSERT_EQ(s.polygons.size(), 1U);
  EXPECT_EQ(s.polygons[0].points.size(), 4U);
  EXPECT_EQ(s.polygons[0].parent, 0);
}

TEST(Interpretation, WidthIsSetByExclamationWithAParameter) {
  const Skeleton s = walk("\u03C9: !(3)F!(0.5)F\nwidth scale: 2");
  EXPECT_EQ(s.segments[0].start_diameter, 6.0);
  EXPECT_EQ(s.segments[1].start_diameter, 1.0);
}

TEST(Interpretation, BareExclamationFollowsTheFilesWidthRule) {
  EXPECT_DOUBLE_EQ(walk("\u03C9: F!F\nwidth: 2").segments[1].start_diameter,
                   2.0 * 0.707);
  EXPECT_DOUBLE_EQ(walk("\u03C9: F!F\nwidth: 2\nwidth factor: 0.5")
                       .segments[1]
                       .start_diameter,
                   1.0);
  EXPECT_DOUBLE_EQ(walk("\u03C9: F!F!!F\nwidth: 2\nwidth increment: 0.5")
                       .segments[2]
                       .start_diameter,
                   0.5);
  EXPECT_EQ(walk("\u03C9: F!!!!F\nwidth: 1\nwidth increment: 0.5")
                .segments[1]
                .start_diameter,
            0.0);
}

TEST(Interpretation, TapersWithASecondDrawParameter) {
  const Skeleton s = walk("\u03C9: !(4)F(2,1)F");
  EXPECT_EQ(s.segments[0].start_diameter, 4.0);
  EXPECT_EQ(s.segments[0].end_diameter, 1.0);
  EXPECT_EQ(s.segments[1].start_diameter, 1.0);
  EXPECT_EQ(s.segments[0].p1, glm::dvec3(0, 0, 2));
}

TEST(Interpretation, ThinsBranchesByTheGenerationThatMadeThem) {
  // Seed 001's trees: radius 0.02, reduced by 0.0015 per generation.
  const Skeleton s = walk(
      "aliases: f=F\nIterations: 3\nBranch radius: 0.02\n"
      "Branch radius reduction: 0.0015\nInitial value : ffA\n"
      "Production rules : A = fA\n");
  ASSERT_EQ(s.segments.size(), 5U);
  const std::array<double, 5> expected{0.04, 0.04, 0.037, 0.034, 0.031};
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_NEAR(s.segments[i].start_diameter, expected[i], 1e-15);
  }
}

TEST(Interpretation, StepsColours) {
  const Skeleton s = walk("\u03C9: F'F';F,F;(7)F\ncolor: 1");
  const std::array<int, 5> expected{1, 2, 4, 3, 7};
  for (std::size_t i = 0; i < 5; ++i)
    EXPECT_EQ(s.segments[i].color, expected[i]);
}

TEST(Interpretation, RestoresTheWholeStateAfterABranch) {
  const Skeleton s = walk("\u03C9: F[+!(5)'F]F\n\u03B4=90");
  ASSERT_EQ(s.segments.size(), 3U);
  EXPECT_EQ(s.segments[2].p0, glm::dvec3(0, 0, 1));
  EXPECT_EQ(s.segments[2].p1, glm::dvec3(0, 0, 2));
  EXPECT_EQ(s.segments[2].start_diameter, 0.1);  // the default width
  EXPECT_EQ(s.segments[2].color, 0);
}

TEST(Interpretation, LinksEachSegmentToTheOneItContinues) {
  const Skeleton s = walk("\u03C9: F[+F]F f F G g G\n\u03B4=90");
  ASSERT_EQ(s.segments.size(), 6U);
  EXPECT_EQ(s.segments[0].parent, -1);
  EXPECT_EQ(s.segments[1].parent, 0);  // a branch names its base
  EXPECT_EQ(s.segments[2].parent, 0);
  EXPECT_EQ(s.segments[3].parent, -1);  // f moved without drawing
  EXPECT_EQ(s.segments[4].parent, 3);
  EXPECT_EQ(s.segments[5].parent, -1);
}

TEST(Interpretation, CpfgRollConventionMirrorsRolls) {
  const char* text = "\u03C9: /(90)&(90)F";
  const Skeleton lpfg = walk(text);
  const Skeleton cpfg = walk(text, {}, {.roll = RollConvention::Cpfg});
  EXPECT_EQ(lpfg.segments[0].p1, glm::dvec3(-1, 0, 0));
  EXPECT_EQ(cpfg.segments[0].p1, glm::dvec3(1, 0, 0));
  EXPECT_EQ(walk(std::string(text) + "\nroll: cpfg").segments[0].p1,
            glm::dvec3(1, 0, 0));
}

TEST(Interpretation, BendsTowardTheTropismAfterEachSegment) {
  const Skeleton s =
      walk("\u03C9: +(90)FFFF\ntropism: 0, 0, -1\nelasticity: 0.2\n");
  ASSERT_EQ(s.segments.size(), 4U);
  EXPECT_EQ(s.segments[0].p1, glm::dvec3(-1, 0, 0));
  double previous_dz = 0.0;
  for (std::size_t i = 1; i < 4; ++i) {
    const double dz = s.segments[i].p1.z - s.segments[i].p0.z;
    EXPECT_LT(dz, previous_dz);  // bending further down each time
    previous_dz = dz;
  }
  EXPECT_NEAR(s.segments[1].p1.z - s.segments[1].p0.z, -std::sin(0.2), 1e-12);
  const Skeleton modules = walk("\u03C9: +(90)@Tp(0,0,-1)@Ts(0.2)FF\n");
  EXPECT_NEAR(modules.segments[1].p1.z, -std::sin(0.2), 1e-12);
}

TEST(Interpretation, AppliesTheHomomorphismUpToTheMaximumDepth) {
  const char* text = "\u03C9: A\nhomomorphism:\nA \u2192 BFB\nB \u2192 F(2)\n";
  EXPECT_EQ(walk(text).segments.size(), 1U);
  const Skeleton deeper = walk(std::string(text) + "maximum depth: 2\n");
  ASSERT_EQ(deeper.segments.size(), 3U);
  EXPECT_EQ(deeper.segments[2].p1, glm::dvec3(0, 0, 5));
}

TEST(Interpretation, RefusesAHomomorphismThatExplodes) {
  const Grammar g = parse(
      "n=0\n\u03C9: A\nhomomorphism:\nmaximum depth: 1000\nA \u2192 AA\n");
  EXPECT_THROW((void)interpret(g), ParseError);
}

TEST(Interpretation, CountsUnclosedAndUnmatchedPolygons) {
  const Skeleton s = walk("\u03C9: }{f+f+f\n\u03B4=90");
  EXPECT_EQ(s.unclosed_polygons, 1U);
  EXPECT_EQ(s.unmatched_polygon_ends, 1U);
  EXPECT_TRUE(s.polygons.empty());
}

TEST(Interpretation, AliasesGiveModulesTurtleMeanings) {
  const Skeleton s = walk("aliases: f=F v=& >=/\nangle: 90\n\u03C9: f>vf\n");
  ASSERT_EQ(s.segments.size(), 2U);
  EXPECT_EQ(s.segments[1].p1, glm::dvec3(-1, 0, 1));
}

TEST(Interpretation, CutBranchesAreNotDrawn) {
  EXPECT_EQ(walk("\u03C9: F[F%FF]F\n").segments.size(), 3U);
}

// `line:column: message` of interpreting `.ls` text, or "no error".
std::string walk_error(const std::string& text) {
  return testing::located_error_of([&] { (void)walk(text); });
}

TEST(Interpretation, RefusesAColourIndexOutOfRangeAtItsModule) {
  // Both were converted to int undefined (UBSan: float-cast-overflow),
  // giving colour -2147483648.
  EXPECT_EQ(walk_error("\u03C9: F'(1e300)F\n"),
            "1:5: colour index 1e+300 is out of range 0 to 1048576");
  EXPECT_EQ(walk_error("\u03C9: F;(2147483648)F\n"),
            "1:5: colour index 2147483648 is out of range 0 to 1048576");
  EXPECT_EQ(walk_error("\u03C9: F,(-1)F\n"),
            "1:5: colour index -1 is out of range 0 to 1048576");
  // A computed index is placed at the module that computes it.
  EXPECT_EQ(walk_error("n=1\n\u03C9: A(3e9)\nA(x) \u2192 F;(x)F\n"),
            "3:9: colour index 3e+09 is out of range 0 to 1048576");
  EXPECT_EQ(walk_error("colour: 1048576\n\u03C9: F'F\n"),
            "2:5: colour index 1048577 is out of range 0 to 1048576");
}

TEST(Interpretation, TruncatesAColourIndexWithinRange) {
  const Skeleton s = walk("\u03C9: ;(2.5)F;(1048576)F\n");
  ASSERT_EQ(s.segments.size(), 2U);
  EXPECT_EQ(s.segments[0].color, 2);
  EXPECT_EQ(s.segments[1].color, 1 << 20);
}

TEST(Interpretation, RefusesATurtleThatLeavesTheFiniteNumbers) {
  EXPECT_EQ(walk_error("\u03C9: F(1e308)F(1e308)\n"),
            "1:4: the turtle's position overflows: it is no longer a finite "
            "number");
  EXPECT_EQ(walk_error("width scale: 1e10\n\u03C9: !(1e300)F\n"),
            "2:4: the turtle's width overflows: it is no longer a finite "
            "number");
}

// The error for building `.ls` text that draws nothing.
std::string nothing_drawn(const std::string& text) {
  const Grammar g = parse(text);
  const Skeleton s = interpret(g);
  EXPECT_TRUE(s.segments.empty() && s.polygons.empty());
  return testing::located_error_of([&] { throw nothing_drawn_error(g, s); });
}

TEST(Interpretation, DrawsNoSegmentForAStepThatMovesTheTurtleNowhere) {
  // Found by ls_fuzzer: at 1e308 a step of 1e38 is lost to rounding, and a
  // segment from a point to itself broke the skeleton's invariant.
  const Skeleton s = walk("axiom: F(1e20)F(1e-10)F(1e-12)\n");
  ASSERT_EQ(s.segments.size(), 1U);
  EXPECT_EQ(s.zero_length_segments, 2U);
  for (const Segment& seg : s.segments) EXPECT_NE(seg.p0, seg.p1);
  // Nor one of some ulps near the origin (a tube without a direction).
  const Skeleton ulps = walk("axiom: FF(1e-17)F(2e-12)F\n");
  EXPECT_EQ(ulps.segments.size(), 3U);
  EXPECT_EQ(ulps.zero_length_segments, 1U);
}

TEST(Interpretation, PlacesWhatMakesAnEmptyDrawingWhereItCanBeKnown) {
  EXPECT_EQ(walk("\u03C9: FF(0)F(0)\nstep: 0\n").zero_length_segments, 3U);
  EXPECT_EQ(nothing_drawn("n=2\nstep: 0\n\u03C9: F\nF \u2192 FF\n"),
            "2:7: nothing to build: the step is 0, so F without a length "
            "draws a segment of length 0");
  EXPECT_EQ(nothing_drawn("n=1\n\u03C9: A\nA \u2192 +F(0)\n"),
            "3:6: nothing to build: every segment has length 0");
  EXPECT_EQ(nothing_drawn("\u03C9: A+B\n"),
            "1:4: nothing to build: the L-system draws no segment and no "
            "polygon; modules without a turtle meaning draw nothing (map "
            "them with an alias block, e.g. 'aliases: Fl=F Fr=F')");
  EXPECT_EQ(nothing_drawn("\u03C9: A{f}\n"),
            "1:5: nothing to build: every polygon has fewer than 3 distinct "
            "points");
}

}  // namespace
}  // namespace lsys
