// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The front end of Lowclouds' L-system Explorer
// (docs/dialects/lowclouds.md): settings and variables as `name = value`
// lines, its preprocessor, mathjs expressions, its widths and what it
// refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>

#include "lsys/interpretation.hpp"
#include "support/core_helpers.hpp"

namespace lsys {
namespace {

using testing::located_error_of;

constexpr testing::Notation kLowclouds{Dialect::Lowclouds, "plant.ls"};

bool has_warning(const Grammar& g, std::string_view part) {
  return std::any_of(
      g.warnings.begin(), g.warnings.end(),
      [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

TEST(Lowclouds, IsDetectedByItsSettingsWhateverTheFileIsNamed) {
  EXPECT_EQ(detect_dialect("stemsize=0.2\naxiom: F\n", "tree.ls"),
            Dialect::Lowclouds);
  EXPECT_EQ(detect_dialect("stemsize: 1.5\ndlength: 13\naxiom: A\n", "t.ls"),
            Dialect::Lowclouds);
  EXPECT_EQ(detect_dialect("view = {auto: 'X'}\naxiom: F\n", "t.ls"),
            Dialect::Lowclouds);
  EXPECT_EQ(detect_dialect("n=1; delta=22.5\naxiom: F\nF->FF\n", "b.ls"),
            Dialect::Lowclouds);
  EXPECT_EQ(dialect_named("lowclouds"), Dialect::Lowclouds);
  EXPECT_EQ(dialect_name(Dialect::Lowclouds), "lowclouds");
  // lsolid's own files stay its own, and so do cpfg's, whose statement
  // blocks hold `a = 1; b = 2;` after the axiom.
  EXPECT_EQ(detect_dialect("n=2, delta=90\naxiom: F\nF -> FF\n", "t.ls"),
            Dialect::Ls);
  EXPECT_EQ(detect_dialect("Lsystem: 1\nAxiom: F\nStart: {\n a = 1; b = 2;\n}"
                           "\nendlsystem\n",
                           "plant.l"),
            Dialect::Cpfg);
}

TEST(Lowclouds, IncludesNoFileOutsideTheModelsFolder) {
  EXPECT_EQ(kLowclouds.error("delta=22.5\n#include \"/etc/passwd\"\n"
                             "axiom: F\n"),
            "2:1: #include \"/etc/passwd\": an absolute name; a model reads "
            "only files in its own folder (--include-dir allows another)");
  EXPECT_EQ(kLowclouds.error("delta=22.5\n#include \"../../../etc/passwd\"\n"
                             "axiom: F\n"),
            "2:1: #include \"../../../etc/passwd\": a name that leaves the "
            "folder ('..'); a model reads only files in its own folder "
            "(--include-dir allows another)");
}

TEST(Lowclouds, SetsAngleWidthAndStepFromItsVariables) {
  const Grammar g = kLowclouds.parse(
      "n=1; delta=22.5; stemsize=0.3\nstep = 2\naxiom: F\nF -> F+F\n");
  EXPECT_EQ(g.settings.derivation_length, 1);
  EXPECT_DOUBLE_EQ(g.settings.angle_deg, 22.5);
  EXPECT_DOUBLE_EQ(g.settings.initial_width, 0.3);
  EXPECT_DOUBLE_EQ(g.settings.step, 2.0);
  const Skeleton s = interpret(g);
  ASSERT_EQ(s.segments.size(), 2U);
  EXPECT_NEAR(glm::length(s.segments[0].p1 - s.segments[0].p0), 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.segments[0].start_diameter, 0.3);
}

TEST(Lowclouds, TakesItsDefaultsWhereTheFileSetsNone) {
  const Grammar g = kLowclouds.parse("axiom: F\nF -> FF\n");
  EXPECT_DOUBLE_EQ(g.settings.angle_deg, 90.0);
  EXPECT_DOUBLE_EQ(g.settings.initial_width, 0.1);
  EXPECT_EQ(g.settings.derivation_length, 1);
  EXPECT_TRUE(has_warning(g, "no derivation length"));
  EXPECT_EQ(g.settings.roll, RollConvention::Cpfg);
}

TEST(Lowclouds, DerivationLengthWinsOverTheVariableN) {
  // bracketed-c.ls: `n=1` sets a variable; `derivation length: 4` counts.
  EXPECT_EQ(
      kLowclouds.derived("n=1; delta=22.5; stemsize=0.1\nderivation length: 3\n"
                         "axiom: F\np0: F->FF\n"),
      "FFFFFFFF");
  EXPECT_EQ(kLowclouds.derived("n=6,delta=60\naxiom: F\nF->FF\n"),
            std::string(64, 'F'));
  EXPECT_EQ(kLowclouds.derived("stemsize: 1.5\ndlength: 2\naxiom: F\nF->FF\n"),
            "FFFF");
}

// turtle3d.js's goto (`@M` draws, `@m` moves) and setHeading, in its
// Babylon.js coordinates: Y up, the turtle home along +X with left +Z.
TEST(Lowclouds, MovesDrawsAndHeadsToPointsInItsCoordinates) {
  const Skeleton s =
      interpret(kLowclouds.parse("n=0\naxiom: @m(1,2,3)@M(1,2,5)@R(0,1,0)F\n"));
  ASSERT_EQ(s.segments.size(), 2U);
  EXPECT_EQ(s.segments[0].p0, glm::dvec3(-3.0, -2.0, 1.0));
  EXPECT_EQ(s.segments[0].p1, glm::dvec3(-5.0, -2.0, 1.0));
  EXPECT_EQ(s.segments[1].p1 - s.segments[1].p0, glm::dvec3(0.0, -1.0, 0.0));
}

TEST(Lowclouds, KeepsDoubleSlashesAsTwoRolls) {
  // hilbert3d.ls ends its productions with `//`, which C would take for a
  // comment.
  EXPECT_EQ(kLowclouds.derived("delta=90\nstemsize= 0.1\nderivation length: 1\n"
                               "axiom: A\nA -> F//F\n"),
            "F//F");
}

TEST(Lowclouds, VariablesAreConstantsThatExpressionsRead) {
  const Grammar g = kLowclouds.parse(
      "D=0\nR=2 /* rate */\nstemsize=1.5\ndelta = 45\nderivation length: 2\n"
      "axiom: A(0)\nP1: A(d) : d>0 -> A(d-1)\n"
      "P2: A(d) : d==0 -> F(1)[+(delta/3)A(D)]F(R)A(0)\n");
  EXPECT_EQ(to_string(derive(g), g.alphabet),
            "F(1)[+(15)F(1)[+(15)A(0)]F(2)A(0)]F(2)F(1)[+(15)A(0)]F(2)A(0)");
  EXPECT_EQ(g.constants.at("R"), 2.0);
  ParseOptions options;
  options.defines = {"R=3"};
  const Grammar redefined = kLowclouds.parse(
      "R=2\nderivation length: 1\naxiom: A\nA -> F(R)\n", options);
  EXPECT_EQ(to_string(derive(redefined), redefined.alphabet), "F(3)");
}

TEST(Lowclouds, AssignedVariablesAreGlobalsThatStartAtTheirValue) {
  // size_control_00.ls: a statement block after the test `*` moves a
  // variable on each time the production applies.
  const Grammar g = kLowclouds.parse(
      "zpos = 10\nderivation length: 1\naxiom: PPP\n"
      "P : * {zpos = zpos+3} -> Z(zpos)\n");
  ASSERT_EQ(g.globals.size(), 1U);
  EXPECT_EQ(g.globals[0], "zpos");
  EXPECT_EQ(g.constants.count("zpos"), 0U);
  EXPECT_EQ(to_string(derive(g), g.alphabet), "Z(13)Z(16)Z(19)");
}

TEST(Lowclouds, ReadsMathjsLogicAndRadians) {
  EXPECT_EQ(kLowclouds.derived("derivation length: 1\naxiom: A(1)A(5)A(9)\n"
                               "A(x) : x > 2 and not (x > 8) -> B\n"
                               "A(x) : x < 2 or x > 8 -> C(x mod 4)\n"),
            "C(1)BC(1)");
  EXPECT_EQ(
      kLowclouds.derived("derivation length: 1\naxiom: A\nA -> F(sin(pi/2))\n"),
      "F(1)");
  EXPECT_EQ(kLowclouds.derived("derivation length: 1\naxiom: A(2.5)\n"
                               "A(x) -> B(round(x), pow(2, 3))\n"),
            "B(3,8)");
  // A parameter named like an operator word is a parameter.
  EXPECT_EQ(kLowclouds.derived("derivation length: 1\naxiom: A(2)\n"
                               "A(order) : order > 1 -> B(order)\n"),
            "B(2)");
}

TEST(Lowclouds, RandomNumbersAreTheSameEveryRun) {
  const std::string text =
      "derivation length: 1\naxiom: AAA\nA -> F(random(2, 4))\n";
  const std::string first = kLowclouds.derived(text);
  EXPECT_EQ(first, kLowclouds.derived(text));
  const Grammar g = kLowclouds.parse(text);
  const ModuleString modules = derive(g);
  for (std::size_t i = 0; i < modules.size(); ++i) {
    ASSERT_EQ(modules.parameters(i).size(), 1U);
    EXPECT_GE(modules.parameters(i)[0], 2.0);
    EXPECT_LT(modules.parameters(i)[0], 4.0);
  }
  EXPECT_NE(kLowclouds
                .error("derivation length: 1\naxiom: A\n"
                       "A -> F(random(1, 2, 3))\n")
                .find("'random' takes at most 2 arguments"),
            std::string::npos);
  // A variable is set once, before deriving: never silently to 1.
  EXPECT_EQ(kLowclouds.error("x = random()\nstemsize=0.1\naxiom: F(x)\n"),
            "1:5: a constant's value must be a number or arithmetic over "
            "numbers and constants, not a random number");
}

TEST(Lowclouds, OnlyNumberedLabelsAreLabels) {
  // `P : * → …` rewrites the module P; `p2:` is a label.
  EXPECT_EQ(kLowclouds.derived("derivation length: 1\naxiom: PQ\nP : * -> X\n"
                               "p2: Q -> Y\n"),
            "XY");
}

TEST(Lowclouds, IndentedLinesContinueTheLineBefore) {
  // anabaena-2.ls and decomp-homomorphism.ls break a production before
  // its arrow.
  EXPECT_EQ(kLowclouds.derived("derivation length: 1\naxiom: A(2)\n"
                               "p1: A(t) : t > 1\n    -> B(t)\n"),
            "B(2)");
}

TEST(Lowclouds, BareHashAddsOneAndBareBangTakesATenthAway) {
  const Skeleton s = interpret(kLowclouds.parse(
      "stemsize=0.5\nderivation length: 1\naxiom: F#F!F!(0.25)F\n"));
  ASSERT_EQ(s.segments.size(), 4U);
  EXPECT_DOUBLE_EQ(s.segments[0].end_diameter, 0.5);
  EXPECT_DOUBLE_EQ(s.segments[1].end_diameter, 1.5);
  EXPECT_DOUBLE_EQ(s.segments[2].end_diameter, 1.4);
  EXPECT_DOUBLE_EQ(s.segments[3].end_diameter, 0.25);
}

TEST(Lowclouds, DrawsASphereOneAcrossUnlessTold) {
  const Skeleton s =
      interpret(kLowclouds.parse("derivation length: 1\naxiom: F@OF@O(0.5)\n"));
  ASSERT_EQ(s.spheres.size(), 2U);
  EXPECT_DOUBLE_EQ(s.spheres[0].diameter, 1.0);
  EXPECT_DOUBLE_EQ(s.spheres[0].center.z, 1.0);
  EXPECT_DOUBLE_EQ(s.spheres[1].diameter, 0.5);
  EXPECT_DOUBLE_EQ(s.spheres[1].center.z, 2.0);
  EXPECT_EQ(s.spheres[1].parent, 1);
}

TEST(Lowclouds, DrawsADiscOneAcrossUnlessToldInTheHeadingUpPlane) {
  // turtle3d.js: drawDisc(d = 1), turned so that its normal is left.
  const Skeleton s =
      interpret(kLowclouds.parse("derivation length: 1\naxiom: F@o@o(3)\n"));
  ASSERT_EQ(s.polygons.size(), 2U);
  const glm::dvec3 tip = s.segments[0].p1;
  // The turtle's first left is (-1, 0, 0).
  testing::expect_disc(s.polygons[0], tip, glm::dvec3(1, 0, 0), 1.0);
  testing::expect_disc(s.polygons[1], tip, glm::dvec3(1, 0, 0), 3.0);
}

TEST(Lowclouds, RefusesWhatItCannotBuildByName) {
  EXPECT_EQ(kLowclouds.error("derivation length: 1\naxiom: F@c(2)\n"),
            "2:9: '@c' (a circle) is not supported by lsolid");
  EXPECT_EQ(kLowclouds.error("derivation length: 1\naxiom: F@H F\n"),
            "2:9: '@H' (the turtle's home) is not supported by lsolid");
  EXPECT_EQ(kLowclouds.error("derivation length: 1\naxiom: A\nA -> {(0)F}\n"),
            "3:6: L-system Explorer's '{(n)' (a path or a spline) "
            "is not supported; write '{' for a polygon");
  EXPECT_EQ(kLowclouds.error("lsystem: 1\naxiom: A\nendlsystem\nlsystem: 2\n"
                             "axiom: B\nendlsystem\n"),
            "4:1: a second 'lsystem:': sub-L-systems are not "
            "supported");
  EXPECT_EQ(kLowclouds.error("colors = [1, 2]\naxiom: F\n"),
            "1:10: L-system Explorer's arrays, objects, strings and "
            "functions are not supported; a variable takes a number");
  // Found by the fuzzer: a piece without `=` among the settings.
  EXPECT_EQ(kLowclouds.error("n=1; delta=22.5; [4,4,-6]};\naxiom: F\n"),
            "1:18: expected 'name = value'");
  EXPECT_EQ(kLowclouds.error("axiom: F\nx = 2\n"),
            "2:1: a variable set after the axiom (L-system Explorer "
            "ignores it); set it before 'axiom:'");
}

TEST(Lowclouds, IgnoresTheView) {
  const Grammar g = kLowclouds.parse(
      "view = {position: [45,18,5], target: [4,4,-6]};\ndelta=90\n"
      "derivation length: 1\naxiom: F\n");
  EXPECT_EQ(g.constants.count("view"), 0U);
  EXPECT_DOUBLE_EQ(g.settings.angle_deg, 90.0);
}

}  // namespace
}  // namespace lsys
