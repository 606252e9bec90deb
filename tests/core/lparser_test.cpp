// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The Lparser front end (docs/dialects/lparser.md).
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "support/core_helpers.hpp"

namespace lsys {
namespace {

using testing::expect_near;
using testing::located_error_of;

constexpr testing::Notation kLparser{Dialect::Lparser, "tree.ls"};

TEST(Lparser, ReadsTheThreeNumbersTheAxiomAndTheRulesUpToTheAt) {
  const Grammar g = kLparser.parse(
      "# --- L-System Parser/Mutator --- Lj Lapre ---\n"
      "2          # recursion\n"
      "90         # angle\n"
      "10         # thickness\n"
      "#\n"
      "F          # axiom\n"
      "F=F+F      # a rule, and a comment\n"
      "F=FF\n"
      "@\n"
      "this is not read\n");
  EXPECT_EQ(g.settings.derivation_length, 2);
  EXPECT_EQ(g.settings.angle_deg, 90.0);
  EXPECT_EQ(to_string(derive(g), g.alphabet), "F+F+F+F");  // first rule wins
  const Skeleton s = interpret(g);
  ASSERT_EQ(s.segments.size(), 4U);
  // F is 100 units, up (+Z); + turns toward the turtle's left.
  expect_near(s.segments[0].p1, {0, 0, 100});
  expect_near(s.segments[1].p1, {-100, 0, 100});
  EXPECT_DOUBLE_EQ(s.segments[0].start_diameter, 10.0);
  EXPECT_EQ(s.segments[0].color, 2);
}

TEST(Lparser, ReadsLparser5sKeywordFormAndIsDetectedByIt) {
  const std::string text =
      "# Lparser example file\r\n\r\nrecursion 2\r\nangle 90\r\n"
      "thickness 10\r\nshape 1\r\nswitch_yz 1\r\n\r\n"
      "axiom cF\r\n\r\nrule F = F+F\r\nrule F = FF\r\n@\r\nnot read\r\n";
  EXPECT_EQ(detect_dialect(text, "tree.ls"), Dialect::Lparser);
  const Grammar g = kLparser.parse(text);
  EXPECT_EQ(g.settings.derivation_length, 2);
  EXPECT_EQ(g.settings.angle_deg, 90.0);
  EXPECT_EQ(to_string(derive(g), g.alphabet), "cF+F+F+F");
  ASSERT_EQ(g.warnings.size(), 2U);
  EXPECT_EQ(g.warnings[0],
            "Lparser's 'shape' (how it writes its output) "
            "is left out");
  const Skeleton s = interpret(g);
  ASSERT_EQ(s.segments.size(), 4U);
  EXPECT_DOUBLE_EQ(s.segments[0].start_diameter, 10.0);
  EXPECT_EQ(located_error_of([] {
              (void)kLparser.parse("recursion 2\naxiom F\nrules F = FF\n");
            }),
            "3:1: unknown Lparser keyword 'rules': expected recursion, "
            "angle, thickness, axiom or rule");
  EXPECT_EQ(located_error_of([] {
              (void)kLparser.parse("recursion 2\naxiom F\nrule FF = F\n");
            }),
            "3:6: expected a rule such as 'rule F = FF' (one character, "
            "'=', the successor)");
}

TEST(Lparser, MakesEachSegmentAsThickAsAShareOfItsOwnLength) {
  const Skeleton s = interpret(kLparser.parse("0\n90\n10\nF'FZF(50)!F?F\n@\n"));
  ASSERT_EQ(s.segments.size(), 6U);
  EXPECT_DOUBLE_EQ(s.segments[0].start_diameter, 10.0);   // 10% of 100
  EXPECT_DOUBLE_EQ(s.segments[1].start_diameter, 9.0);    // ' : 90 long
  EXPECT_DOUBLE_EQ(s.segments[2].start_diameter, 4.5);    // Z: half a step
  EXPECT_DOUBLE_EQ(s.segments[3].start_diameter, 5.0);    // F(50)
  EXPECT_NEAR(s.segments[4].start_diameter, 6.3, 1e-12);  // ! : 7% of 90
  EXPECT_NEAR(s.segments[5].start_diameter, 9.0, 1e-12);  // ? undoes it
  expect_near(s.segments[2].p1, {0, 0, 100 + 90 + 45});
}

TEST(Lparser, LeavesAParameterBehindTheSuccessorOfItsModule) {
  // f(200) with f=z is z(200); F(30) with F='(1.25)F'(.8) drops the 30, as
  // the successor's last module has a parameter of its own.
  const char* text = "1\n90\n10\nf(200)F(30)F\nf=z\nF='(1.25)F'(.8)\n@\n";
  EXPECT_EQ(kLparser.derived(text), "z(200)'(1.25)F'(0.8)'(1.25)F'(0.8)");
  const Skeleton s = interpret(kLparser.parse(text));
  ASSERT_EQ(s.segments.size(), 2U);
  expect_near(s.segments[0].p0, {0, 0, 200});
  expect_near(s.segments[0].p1, {0, 0, 325});
  expect_near(s.segments[1].p1, {0, 0, 450});  // 125 × 0.8 × 1.25 again
}

TEST(Lparser, SwapsTurnsAfterADollarAsItsFrameTurnsRightHanded) {
  // After +(90) the heading is horizontal; `$` rolls up to the sky. In
  // Lparser's frame `+` then turns the way lsolid's `-` does.
  const Skeleton swapped =
      interpret(kLparser.parse("0\n90\n10\n+(90)$+(90)F\n@\n"));
  ASSERT_EQ(swapped.segments.size(), 1U);
  expect_near(swapped.segments[0].p1, {0, 100, 0});
  const Skeleton plain =
      interpret(kLparser.parse("0\n90\n10\n+(90)+(90)F\n@\n"));
  expect_near(plain.segments[0].p1, {0, 0, -100});
  // Straight up, `$` does nothing, and turns are not swapped.
  const Skeleton up = interpret(kLparser.parse("0\n90\n10\n$+(90)F\n@\n"));
  expect_near(up.segments[0].p1, {-100, 0, 0});
}

TEST(Lparser, PitchesTowardTheGroundWithTAfterADollar) {
  // Heading horizontal, upright: t(0.5) pitches down by 0.5 rad.
  const Skeleton s = interpret(kLparser.parse("0\n90\n10\n+(90)$t(.5)F\n@\n"));
  ASSERT_EQ(s.segments.size(), 1U);
  expect_near(s.segments[0].p1,
              {-100 * std::cos(0.5), 0, -100 * std::sin(0.5)});
}

TEST(Lparser, RollsAHalfTurnWithPercentAndNeverCutsWithIt) {
  const Grammar g = kLparser.parse("1\n90\n10\nA\nA=F%[+F]F\n@\n");
  const Skeleton s = interpret(g);
  ASSERT_EQ(s.segments.size(), 3U);
  expect_near(s.segments[1].p1, {100, 0, 100});  // left is now +X
}

TEST(Lparser, RefusesWhatItCannotReadAtItsPlace) {
  EXPECT_EQ(
      located_error_of([] { (void)kLparser.parse("2.5\n90\n10\nF\n@\n"); }),
      "1:1: a fractional recursion depth (Lparser's growing mode) is "
      "not supported: give a whole number");
  EXPECT_EQ(
      located_error_of([] { (void)kLparser.parse("2\n90\n10\nF\nF+F\n@\n"); }),
      "5:1: expected a rule such as 'F=FF' (one character, '=', the "
      "successor, no blanks) or '@' to end the file");
  EXPECT_EQ(
      located_error_of([] { (void)kLparser.parse("2\nninety\n10\nF\n@\n"); }),
      "2:1: expected the angle, a number on a line of its own");
}

TEST(Lparser, LetsAnyModuleCarryAParameterOrNone) {
  // A(2)B with A=AB, B=A: the (2) stays behind A's successor, AB(2).
  EXPECT_EQ(kLparser.derived("2\n22\n10\nA(2)B\nA=AB\nB=A\n@\n"), "ABA(2)AB");
}

}  // namespace
}  // namespace lsys
