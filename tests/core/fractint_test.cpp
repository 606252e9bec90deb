// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The Fractint front end (docs/dialects/fractint.md).
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "support/core_helpers.hpp"

namespace lsys {
namespace {

using testing::expect_near;
using testing::located_error_of;

constexpr const char* kTwoSystems =
    "Koch1 { ; Adrian Mariano\n"
    "; from The Fractal Geometry of Nature by Mandelbrot\n"
    "  Angle 6\n"
    "  Axiom F--F--F\n"
    "  F=F+F--F+F\n"
    "  }\n"
    "\n"
    "Tree{\n"
    "  angle 8\n"
    "  axiom X\n"
    "  X=F[+X]F\n"
    "  X=[-X]\n"
    "  }\n";

Grammar fractint(std::string_view text, std::string system = {}) {
  return parse_grammar_text(text, {.system = std::move(system)}, "f.l");
}

Skeleton drawn(std::string_view body, int n = 0) {
  Grammar g = fractint("S {\n" + std::string(body) + "\n}\n");
  g.settings.derivation_length = n;
  return interpret(g);
}

TEST(Fractint, ReadsTheSystemItIsToldWithoutRegardToCase) {
  Grammar koch = fractint(kTwoSystems, "KOCH1");
  EXPECT_NEAR(koch.settings.angle_deg, 60.0, 1e-12);
  EXPECT_EQ(koch.settings.derivation_length, 2);  // Fractint's default order
  koch.settings.derivation_length = 1;
  EXPECT_EQ(interpret(koch).segments.size(), 12U);
  // Two rules of one symbol are joined: X=F[+X]F[-X].
  const Grammar tree = fractint(kTwoSystems, "tree");
  EXPECT_EQ(to_string(derive(tree, {.derivation_length = 1}), tree.alphabet),
            "f[+x]f[-x]");
}

// A stray `{` after a keyword (Rouse's `Angle 6 {`) is no system's start:
// the other systems read, and that one is refused at its line.
TEST(Fractint, ReadsTheOtherSystemsOfAFileWithAStrayBrace) {
  const std::string file =
      "Good {\n  Angle 4\n  Axiom F\n  F=F+F\n}\n"
      "Bad {\n  Angle 6 { ; a comment\n  Axiom F\n}\n";
  EXPECT_EQ(interpret(fractint(file, "Good")).segments.size(), 4U);
  EXPECT_EQ(located_error_of([&] { (void)fractint(file, "Bad"); }),
            "7:11: extra text: a Fractint rule or axiom is one word, without "
            "blanks");
}

TEST(Fractint, RefusesToChooseAmongSeveralAndNamesThem) {
  EXPECT_EQ(located_error_of([] { (void)fractint(kTwoSystems); }),
            "1:1: this file holds 2 systems; choose one with --system NAME: "
            "Koch1, Tree");
  EXPECT_EQ(located_error_of([] { (void)fractint(kTwoSystems, "Koch2"); }),
            "1:1: no system named 'Koch2' in this file; it holds Koch1, Tree");
}

TEST(Fractint, TurnsByAngleStepsAndByDegreesWrittenAfterTheSlash) {
  // angle 4: + is a quarter turn left; \90 turns 90 degrees left, /45 45
  // degrees right.
  const Skeleton steps = drawn("angle 4\naxiom F+F");
  ASSERT_EQ(steps.segments.size(), 2U);
  expect_near(steps.segments[1].p1, {-1, 0, 1});
  const Skeleton degrees = drawn("angle 4\naxiom D\\90D/45D");
  ASSERT_EQ(degrees.segments.size(), 3U);
  expect_near(degrees.segments[1].p1, {-1, 0, 1});
  expect_near(degrees.segments[2].p1,
              {-1 - std::sqrt(0.5), 0, 1 + std::sqrt(0.5)});
}

TEST(Fractint, TurnsTheLargestStepBelowAHalfTurnWithABarWhenTheAngleIsOdd) {
  // angle 5: | is 2 steps of 72 degrees to the right; ! does not change it.
  for (const char* axiom : {"F|F", "F!|F"}) {
    const Skeleton s = drawn(std::string("angle 5\naxiom ") + axiom);
    ASSERT_EQ(s.segments.size(), 2U);
    const double a = 144.0 * std::acos(-1.0) / 180.0;
    expect_near(s.segments[1].p1, {std::sin(a), 0, 1 + std::cos(a)});
  }
}

TEST(Fractint, SwapsPlusAndMinusWithABang) {
  const Skeleton s = drawn("angle 4\naxiom F!+F[!+F]+F");
  ASSERT_EQ(s.segments.size(), 4U);
  expect_near(s.segments[1].p1, {1, 0, 1});  // ! + turns right
  expect_near(s.segments[2].p1, {1, 0, 2});  // !! + turns left again...
  expect_near(s.segments[3].p1, {1, 0, 0});  // ...only inside [ ]
}

TEST(Fractint, ScalesTheStepAsFractintReadsItsNumbers) {
  // @Q4 is √4, @I2 is 1/2, @IQ4 is 1/√4; a bare @ makes the step 0.
  const Skeleton s = drawn("angle 4\naxiom @Q4F@I2F@iq4F");
  ASSERT_EQ(s.segments.size(), 3U);
  expect_near(s.segments[0].p1, {0, 0, 2});
  expect_near(s.segments[1].p1, {0, 0, 3});
  expect_near(s.segments[2].p1, {0, 0, 3.5});
}

TEST(Fractint, SetsAndShiftsTheColourWithNumbersAfterTheCommand) {
  const Skeleton s = drawn("angle 4\naxiom Fc3F<2F>9F");
  ASSERT_EQ(s.segments.size(), 4U);
  EXPECT_EQ(s.segments[0].color, 15);  // Fractint's default
  EXPECT_EQ(s.segments[1].color, 3);
  EXPECT_EQ(s.segments[2].color, 5);
  EXPECT_EQ(s.segments[3].color, 0);
}

TEST(Fractint, RefusesWhatFractintRefusesAtItsPlace) {
  EXPECT_EQ(located_error_of(
                [] { (void)fractint("S {\nangle 4\naxiom F\n+=F-\n}\n"); }),
            "4:1: '+' is a drawing command and cannot have a rule");
  EXPECT_EQ(
      located_error_of([] { (void)fractint("S {\nangle 60\naxiom F\n}\n"); }),
      "2:7: Fractint's angle is a number of steps from 3 to 50 (turns "
      "of 360/n degrees), here 60");
  EXPECT_EQ(
      located_error_of([] { (void)fractint("S {\nangle 4\naxiom F F\n}\n"); }),
      "3:9: extra text: a Fractint rule or axiom is one word, without "
      "blanks");
  // F turns with + and D with \: two headings in Fractint, one here.
  EXPECT_EQ(located_error_of(
                [] { (void)fractint("S {\nangle 4\naxiom F+D\\90F\n}\n"); }),
            "3:9: this system turns with '+', '-' or '|', which Fractint's "
            "'D' and 'M' do not follow (they keep a heading of their own); "
            "lsolid's turtle has one heading: not supported");
}

TEST(Fractint, ReadsRulesAsStrtokCutsThem) {
  // `f = f+f` and ` =f` (a rule for f that deletes it) are Fractint rules.
  const Grammar spaced = fractint("S {\n angle 4\n axiom f\n f = f+f\n}\n");
  EXPECT_EQ(
      to_string(derive(spaced, {.derivation_length = 1}), spaced.alphabet),
      "f+f");
  const Grammar deleted = fractint("S {\n angle 4\n axiom fg\n =f\n}\n");
  EXPECT_EQ(
      to_string(derive(deleted, {.derivation_length = 1}), deleted.alphabet),
      "g");
}

TEST(Fractint, EndsABlockAtItsFirstBraceAndRefusesOneLeftOpen) {
  const char* text =
      "comment { a one-line comment }\nKoch {\n angle 6\n axiom f\n}\n"
      "Dragon {\n angle 4\n axiom fx\n}\n";
  EXPECT_EQ(located_error_of([&] { (void)fractint(text); }),
            "2:1: this file holds 2 systems; choose one with --system NAME: "
            "Koch, Dragon");
  EXPECT_EQ(located_error_of([] {
              (void)fractint(
                  "Koch {\n angle 6\n axiom f\nDragon {\n"
                  " angle 4\n axiom fx\n}\n");
            }),
            "4:1: a system starts inside 'Koch {' (line 1), which has no "
            "closing '}' line");
  EXPECT_EQ(located_error_of([] { (void)fractint("Koch {\n angle 6\n"); }),
            "1:1: 'Koch {' has no closing '}' line");
}

TEST(Fractint, PlacesAColourSumOutOfRangeAtTheModuleThatAdds) {
  EXPECT_EQ(located_error_of([] {
              Grammar g =
                  fractint("S {\n angle 4\n axiom ff\n f=f<600000\n}\n");
              g.settings.derivation_length = 2;
              (void)interpret(g);
            }),
            "4:5: colour index 1200015 is out of range 0 to 1048576");
}

}  // namespace
}  // namespace lsys
