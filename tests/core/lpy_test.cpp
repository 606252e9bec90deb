// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The L-Py front end (docs/dialects/lpy.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "support/core_helpers.hpp"

namespace lsys {
namespace {

using testing::expect_near;
using testing::located_error_of;

constexpr testing::Notation kLpy{Dialect::Lpy, "plant.lpy"};

Skeleton drawn(std::string_view axiom) {
  return interpret(
      kLpy.parse("Axiom: " + std::string(axiom) +
                 "\nderivation length: 0\nproduction:\nendlsystem\n"));
}

constexpr const char* kApex =
    "from math import *\n"
    "dl = 0.5  # shrink\n"
    "h = (dl*8) ** 0.5\n"
    "module Apex(x)\n"
    "\n"
    "Axiom: F(h)Apex(1)\n"
    "derivation length: 2\n"
    "production:\n"
    "Apex(x) --> F(x*dl)Apex(x*dl)\n"
    "interpretation:\n"
    "Apex(x) --> G\n"
    "endlsystem\n"
    "###### INITIALISATION ######\n"
    "__authors__ = 'someone'\n"
    "def __initialiseContext__(context):\n"
    "\tpass\n";

TEST(Lpy, ReadsConstantsModulesAndRuleSections) {
  const Grammar g = kLpy.parse(kApex);
  EXPECT_EQ(g.settings.derivation_length, 2);
  EXPECT_EQ(to_string(derive(g), g.alphabet), "F(2)F(0.5)F(0.25) Apex(0.25)");
  // G is not a turtle module in L-Py: the homomorphism's G draws nothing.
  const Skeleton s = interpret(g);
  ASSERT_EQ(s.segments.size(), 3U);
  expect_near(s.segments[2].p1, {0, 0, 2.75});
  // --define replaces a constant, as extern() parameters are replaced.
  const Grammar defined = kLpy.parse(kApex, {.defines = {"dl=0.25"}});
  EXPECT_EQ(to_string(derive(defined), defined.alphabet),
            "F(1.4142135623730951)F(0.25)F(0.0625) Apex(0.0625)");
}

TEST(Lpy, IsDetectedByItsAxiomAndProductionLines) {
  EXPECT_EQ(detect_dialect(kApex), Dialect::Lpy);
}

TEST(Lpy, TakesWidthsAsRadiiAndWidensWithUnderscore) {
  // L-Py's width is 0.1 (a radius); _(2) and !(3) set it, _ and ! add and
  // subtract the increment of 1.
  const Skeleton s = drawn("F_(2)F!(3)F_F!F");
  ASSERT_EQ(s.segments.size(), 5U);
  EXPECT_DOUBLE_EQ(s.segments[0].start_diameter, 0.2);
  EXPECT_DOUBLE_EQ(s.segments[1].start_diameter, 4.0);
  EXPECT_DOUBLE_EQ(s.segments[2].start_diameter, 6.0);
  EXPECT_DOUBLE_EQ(s.segments[3].start_diameter, 8.0);
  EXPECT_DOUBLE_EQ(s.segments[4].start_diameter, 6.0);
}

TEST(Lpy, TurnsBySixtyDegreesUnlessPythonSetsTheAngle) {
  const Skeleton sixty = drawn("F+F");
  const double r = std::acos(-1.0) / 3.0;
  expect_near(sixty.segments[1].p1, {-std::sin(r), 0, 1 + std::cos(r)});
  const Skeleton ninety = interpret(
      kLpy.parse("execContext().turtle.setAngleIncrement(90)\nAxiom: F+F\n"
                 "derivation length: 0\nproduction:\nendlsystem\n"));
  expect_near(ninety.segments[1].p1, {-1, 0, 1});
}

TEST(Lpy, DrawsAModuleAliasAsItsTarget) {
  const Grammar g = kLpy.parse(
      "module A = F\nAxiom: A(1)\nderivation length: 5\nproduction:\n"
      "A(x) --> A(x+1)\nendlsystem\n");
  const Skeleton s = interpret(g);
  ASSERT_EQ(s.segments.size(), 1U);
  expect_near(s.segments[0].p1, {0, 0, 6});
}

TEST(Lpy, LeavesOutRulesOfGroupsOnlyPythonCanSelect) {
  const Grammar g = kLpy.parse(
      "Axiom: A\nderivation length: 1\nproduction:\nA --> F\ngroup 1:\n"
      "A --> FF\nendgroup\nendlsystem\n");
  EXPECT_EQ(to_string(derive(g), g.alphabet), "F");
  ASSERT_EQ(g.warnings.size(), 1U);
  EXPECT_EQ(g.warnings[0],
            "rules of 'group 1:' are left out: they apply only when Python "
            "code selects their group");
}

TEST(Lpy, RefusesPythonItWouldHaveToRunAtItsLine) {
  const std::string tail =
      ": this is Python code, and lsolid does not run Python; it reads the "
      "declarative part of L-Py (docs/dialects/lpy.md)";
  // An import is read; what the file uses of a module other than math and
  // random is refused where it is used, naming the module.
  EXPECT_EQ(
      located_error_of([] {
        (void)kLpy.parse("import numpy\nAxiom: F\nproduction:\nendlsystem\n");
      }),
      "no error");
  EXPECT_EQ(located_error_of([] {
              (void)kLpy.parse(
                  "from copy import deepcopy\nimport numpy.random as "
                  "nr\nk = nr.uniform(0, 1)\nAxiom: F\nproduction:\n");
            }),
            "3:5: 'nr' comes from Python's module numpy.random, which lsolid "
            "does not run; it reads math and random (docs/dialects/lpy.md)");
  // A hook that reads the string L-Py passes it is refused; one that only
  // prints it is read.
  EXPECT_EQ(located_error_of([] {
              (void)kLpy.parse(
                  "def EndEach(lstring):\n  x = len(lstring)\nAxiom: F\n"
                  "production:\n");
            }),
            "1:1: 'def EndEach(lstring):', a hook that reads the string L-Py "
            "passes it" +
                tail);
  EXPECT_EQ(located_error_of([] {
              (void)kLpy.parse(
                  "def EndEach(lstring):\n  print(lstring)\nAxiom: F\n"
                  "production:\n");
            }),
            "no error");
  EXPECT_EQ(located_error_of([] {
              (void)kLpy.parse("def f(x):\n  y = x\n  return y\nAxiom: A\n");
            }),
            "1:1: 'def f(x):'" + tail);
}

// What L-Py's tutorials write around their rules: functions of returns
// chosen by if/elif/else (after a docstring), lists of numbers, asserts
// and prints at the top level, values in predecessors, predecessors of
// several modules, and Python's randint.
// What L-Py's users write besides: tuples of numbers, `random.seed` in a
// hook or body (lsolid draws from its own generator), one name with
// several parameter counts, `choice` and `randrange`.
TEST(Lpy, ReadsTuplesSeedsVaryingParameterCountsAndChoices) {
  const Grammar g = kLpy.parse(
      "import random\nwidth = (0.01, 0.5)\ndef Start():\n  random.seed(3)\n"
      "Axiom: S S(2)\nderivation length: 1\nproduction:\n"
      "S --> T(width[1])\nS(x) :\n  random.seed(1)\n"
      "  produce T(choice([-1, 1]), randrange(3), randrange(5, 7))\n"
      "endlsystem\n");
  const ModuleString m = derive(g);
  ASSERT_EQ(m.size(), 2U);
  EXPECT_EQ(m.parameters(0)[0], 0.5);
  const auto p = m.parameters(1);
  ASSERT_EQ(p.size(), 3U);
  EXPECT_TRUE(p[0] == -1.0 || p[0] == 1.0) << p[0];
  EXPECT_TRUE(p[1] == 0.0 || p[1] == 1.0 || p[1] == 2.0) << p[1];
  EXPECT_TRUE(p[2] == 5.0 || p[2] == 6.0) << p[2];
}

TEST(Lpy, ReadsFunctionsOfReturnsListsAssertsAndValuesInPredecessors) {
  const Grammar g = kLpy.parse(
      "k = 2\nprint(k)\nassert 0 < k < 3, 'k'\ncolor = [1, 3, 2]\n"
      "def size(t):\n  \"\"\" the size \"\"\"\n  if t < k: return t * 10\n"
      "  elif t == k:\n    return -1\n  else:\n    return 100\n"
      "def half(x):  # a comment\n  if x > 1:\n    return x / 2\n  return x\n"
      "Axiom: D(0) A(1) A(2) A(3) F(1)+F(2)\nderivation length: 1\n"
      "production:\nD(0) --> E(color[-1], color[1])\nD(x) --> D(x+1)\n"
      "A(t) --> B(size(t), half(t))\nF(x)+F(y) --> G(x+y)\nendlsystem\n");
  EXPECT_EQ(to_string(derive(g), g.alphabet),
            "E(2,3)B(10,1)B(-1,1)B(100,1.5)G(3)");
  EXPECT_EQ(
      to_string(derive(kLpy.parse("Axiom: D(1)\nderivation length: 1\n"
                                  "production:\nD(0) --> E\nendlsystem\n")),
                g.alphabet),
      "D(1)");
  EXPECT_EQ(located_error_of([] {
              (void)kLpy.parse("k = 4\nassert k < 3\nAxiom: F\nproduction:\n");
            }),
            "2:8: this assertion fails: k < 3");
  EXPECT_EQ(located_error_of([] {
              (void)derive(
                  kLpy.parse("c = [1, 2]\nAxiom: A(2)\nderivation length: 1\n"
                             "production:\nA(i) --> B(c[i])\n"));
            }),
            "5:14: subscript 2 is out of range: this dimension of the array "
            "has 2 elements, 0 to 1");
  const Grammar r = kLpy.parse(
      "from random import randint\nAxiom: A\nderivation length: 1\n"
      "production:\nA --> B(randint(1, 3))B(randint(1, 3))B(randint(1, 3))"
      "B(randint(1, 3))B(randint(1, 3))B(randint(1, 3))\nendlsystem\n");
  const ModuleString drawn = derive(r);
  ASSERT_EQ(drawn.size(), 6U);
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    const double v = drawn.parameters(i)[0];
    EXPECT_TRUE(v == 1.0 || v == 2.0 || v == 3.0) << v;
  }
}

// An L-Py rule whose body is Python: each `produce` is a production whose
// statements are the body and whose condition is that this produce ran.
TEST(Lpy, RunsRuleBodiesOfAssignmentsConditionsAndProduce) {
  const auto derived = [](std::string_view rules, int n) {
    const Grammar g =
        kLpy.parse("Axiom: A(0)\nderivation length: " + std::to_string(n) +
                   "\nproduction:\n" + std::string(rules) + "endlsystem\n");
    return to_string(derive(g), g.alphabet);
  };
  EXPECT_EQ(derived("A(x) :\n  if x < 2:\n    produce F A(x+1)\n"
                    "  else:\n    produce B(x)\n",
                    4),
            "FFB(2)");
  // One-line bodies, elif, locals, augmented assignment, and Python's
  // operators; the successor reads the locals.
  EXPECT_EQ(
      derived("A(x) :\n  y = x * 2\n  y += 1\n"
              "  if y % 2 == 0: produce X\n"
              "  elif not (y > 3 and x != 0): produce B(y, 7 // 2, -7 % 3)"
              "\n  else: produce C\n",
              1),
      "B(1,3,2)");
  // What follows a produce does not run; a body that produces nothing
  // leaves the module to the next rule.
  EXPECT_EQ(derived("A(x) :\n  if x == 0:\n    produce B\n  produce C\n", 1),
            "B");
  EXPECT_EQ(derived("A(x) :\n  if x == 1:\n    produce B\n"
                    "A(x) --> D(x if x > 0 else 5)\n",
                    1),
            "D(5)");
  EXPECT_EQ(derived("A(x) :\n  pass\n", 2), "A(0)");
  // Python chains comparisons and binds `not` below them.
  EXPECT_EQ(derived("A(x) :\n  produce B(0 < x < 3, -1 < x < 1, "
                    "not x == 1, not 2 > 1 > 0)\n",
                    1),
            "B(0,1,1,0)");
  EXPECT_EQ(located_error_of([] {
              (void)kLpy.parse(
                  "Axiom: A(1)\nproduction:\nA(x) :\n"
                  "  produce B(x ^ 2)\nendlsystem\n");
            }),
            "4:15: Python's '^' (a bitwise exclusive or) is not supported; "
            "'**' is the power");
}

// L-Py's hooks run as cpfg's Start: and its kin; what they assign is
// global, and rule bodies read and change it.
TEST(Lpy, RunsTheHooksStartAndStartEachWithGlobalVariables) {
  const Grammar g = kLpy.parse(
      "def Start():\n  global m\n  print('Start')\n  m = 10\n"
      "def StartEach():\n  global m\n  m += 1\n"
      "Axiom: A\nderivation length: 3\nproduction:\n"
      "A :\n  global m\n  produce B(m) A\nendlsystem\n");
  EXPECT_EQ(to_string(derive(g), g.alphabet), "B(11)B(12)B(13)A");
  // Without `global`, a rule's assignment makes a local, as in Python.
  const Grammar local = kLpy.parse(
      "def Start():\n  global m\n  m = 10\n"
      "Axiom: AD\nderivation length: 1\nproduction:\n"
      "A :\n  m = 5\n  produce B(m)\nD :\n  produce C(m)\nendlsystem\n");
  EXPECT_EQ(to_string(derive(local), local.alphabet), "B(5)C(10)");
  EXPECT_EQ(located_error_of([] {
              (void)kLpy.parse("def Start():\n  produce A\nAxiom: A\n");
            }),
            "2:3: 'produce' outside a rule");
}

// PlantGL's turtle starts heading +Z with left (0, −1, 0) and up
// (1, 0, 0): queries answer in its coordinates.
TEST(Lpy, AnswersQueriesInPlantGLsCoordinates) {
  const Grammar g = kLpy.parse(
      "Axiom: F+(90)F?P(0,0,0)?H(0,0,0)?L(0,0,0)?U(0,0,0)\n"
      "derivation length: 1\nproduction:\nendlsystem\n");
  EXPECT_EQ(to_string(derive(g), g.alphabet),
            "F+(90)F ?P(0,-1,1) ?H(0,-1,0) ?L(0,0,-1) ?U(1,0,0)");
}

// A function of one `return` is compiled where it is called, with its
// parameters bound to the arguments; it sees constants, not the rule's
// names. Modules imported under another name are read through it.
TEST(Lpy, CompilesFunctionsOfOneReturnWhereTheyAreCalled) {
  const Grammar g = kLpy.parse(
      "import math as m\nk = 3\ndef alpha(x):\n  return 30 - k*x  # deg\n"
      "def twice(a, b): return alpha(a) * 2 + b\n"
      "Axiom: A(2)\nderivation length: 1\nproduction:\n"
      "A(x) :\n  y = 100\n  produce B(alpha(x), twice(1, x), m.floor(2.5))\n"
      "endlsystem\n");
  EXPECT_EQ(to_string(derive(g), g.alphabet), "B(24,56,2)");
  EXPECT_EQ(located_error_of([] {
              (void)kLpy.parse("def f(x):\n  y = x\n  return y\nAxiom: A\n");
            }),
            "1:1: 'def f(x):': this is Python code, and lsolid does not run "
            "Python; it reads the declarative part of L-Py "
            "(docs/dialects/lpy.md)");
  EXPECT_EQ(located_error_of([] {
              (void)derive(
                  kLpy.parse("def f(x): return y\nAxiom: A(1)\n"
                             "production:\nA(y) --> B(f(y))\n"));
            }),
            "1:18: undefined name 'y'");
}

// The body runs once per module, as in L-Py: a production that a run did
// not select undoes that run's draws, so the next production draws the same
// numbers and every module is rewritten by exactly one of them.
TEST(Lpy, RunsARandomBodyOncePerModule) {
  const Grammar g = kLpy.parse("Axiom: " + std::string(64, 'A') +
                               "\nderivation length: 1\nproduction:\n"
                               "A :\n  if random() < 0.5: produce B\n"
                               "  else: produce C\nendlsystem\n");
  const std::string s = to_string(derive(g), g.alphabet);
  EXPECT_EQ(s.size(), 64U);
  EXPECT_EQ(std::count(s.begin(), s.end(), 'A'), 0);
  EXPECT_GT(std::count(s.begin(), s.end(), 'B'), 16);
  EXPECT_GT(std::count(s.begin(), s.end(), 'C'), 16);
}

// A body that produces nothing has still drawn its numbers, as in L-Py: the
// next rule (`A --> A`) leaves the module, and the next step draws anew. It
// once undid them, so the guard drew the same rejected number for ever
// (one B in 1,000 steps where L-Py gives about 500).
TEST(Lpy, KeepsTheDrawsOfABodyThatProducesNothing) {
  const Grammar g = kLpy.parse(
      "from random import *\nAxiom: A\nderivation length: 1000\n"
      "production:\nA:\n    if random() < 0.5:\n        produce BA\n"
      "A --> A\nendlsystem\n");
  const std::string s = to_string(derive(g), g.alphabet);
  // One draw a step: a B for each below one half.
  const auto draws = testing::drand48_sequence(1000);
  const auto expected = std::count_if(draws.begin(), draws.end(),
                                      [](double u) { return u < 0.5; });
  EXPECT_EQ(std::count(s.begin(), s.end(), 'B'), expected);
  EXPECT_NEAR(static_cast<double>(expected), 500.0, 50.0);
  // Several produce statements: the body still draws once a step, whichever
  // branch runs or none.
  const Grammar two = kLpy.parse(
      "Axiom: A\nderivation length: 1000\nproduction:\nA:\n"
      "    x = random()\n    if x < 0.3:\n        produce BA\n"
      "    elif x < 0.6:\n        produce CA\nA --> A\nendlsystem\n");
  const std::string t = to_string(derive(two), two.alphabet);
  EXPECT_EQ(std::count(t.begin(), t.end(), 'B'),
            std::count_if(draws.begin(), draws.end(),
                          [](double u) { return u < 0.3; }));
  EXPECT_EQ(std::count(t.begin(), t.end(), 'C'),
            std::count_if(draws.begin(), draws.end(),
                          [](double u) { return u >= 0.3 && u < 0.6; }));
}

TEST(Lpy, RefusesPythonARuleBodyCannotRunAtItsPlace) {
  const auto error = [](std::string_view body) {
    return located_error_of([&] {
      (void)kLpy.parse("Axiom: A\nproduction:\nA :\n" + std::string(body) +
                       "endlsystem\n");
    });
  };
  const std::string tail =
      " is not supported: lsolid runs assignments, if/elif/else, for … in "
      "range(…), while, break, continue, pass, global, print, produce and "
      "nproduce (docs/dialects/lpy.md)";
  EXPECT_EQ(error("  for m in modules:\n    nproduce F\n"),
            "4:12: lsolid runs 'for' loops over range(…) only");
  EXPECT_EQ(error("  return 1\n"), "4:3: Python's 'return'" + tail);
  // Refused even where no produce follows.
  EXPECT_EQ(error("  x = 1\n  yield x\n"), "5:3: Python's 'yield'" + tail);
  EXPECT_EQ(error("  break\n  produce F\n"), "4:3: 'break' outside a loop");
  EXPECT_EQ(error("  if 1:\n  produce F\n"),
            "4:8: expected an indented block after ':'");
  EXPECT_EQ(error("  x = 1\n    produce F\n"), "5:5: unexpected indentation");
  EXPECT_EQ(error("  for i in range(1, 5, 0):\n    nproduce F\n"),
            "4:24: range's step cannot be 0");
}

// L-Py's nproduce: the body builds its successor piece by piece, in loops
// and branches, and a branch one piece opens another may close.
TEST(Lpy, BuildsASuccessorAsTheBodyRunsWithNproduceAndLoops) {
  const auto derived = [](std::string_view axiom, std::string_view rules) {
    const Grammar g = kLpy.parse("Axiom: " + std::string(axiom) +
                                 "\nderivation length: 1\nproduction:\n" +
                                 std::string(rules) + "endlsystem\n");
    return to_string(derive(g), g.alphabet);
  };
  EXPECT_EQ(derived("A(4)",
                    "A(n) :\n  for i in range(n):\n    nproduce F(i)\n"
                    "    if i % 2 == 0:\n      nproduce [ +(30)\n"
                    "      nproduce F(1) ]\n"),
            "F(0)[+(30)F(1)]F(1)F(2)[+(30)F(1)]F(3)");
  // while, continue, break; range with a start and a negative step; the
  // body may change the loop's name without changing the count.
  EXPECT_EQ(derived("B",
                    "B :\n  i = 0\n  while True:\n    i += 1\n"
                    "    if i == 2: continue\n    if i > 4: break\n"
                    "    nproduce X(i)\n"
                    "  for j in range(5, 0, -2):\n    nproduce Y(j)\n"
                    "    j = 100\n"),
            "X(1)X(3)X(4)Y(5)Y(3)Y(1)");
  // produce appends its own modules and ends the body.
  EXPECT_EQ(derived("C", "C :\n  nproduce F\n  produce G(1)\n  nproduce H\n"),
            "FG(1)");
  // A body that produces nothing leaves the module to the next rule, and
  // `produce` alone erases it.
  EXPECT_EQ(derived("DE",
                    "D :\n  for i in range(0):\n    nproduce F\n"
                    "E :\n  nproduce F\n  produce\n"),
            "DF");
  EXPECT_EQ(
      located_error_of([&] { (void)derived("A", "A :\n  nproduce [ F\n"); }),
      "4:1: this body produced a '[' that it did not close");
}

// `Axiom:` above a Python body: the body produces the axiom (L-Py's
// tutorial of Fibonacci numbers passed along a row of modules).
TEST(Lpy, RunsAnAxiomWrittenAsPython) {
  const Grammar g = kLpy.parse(
      "nbValues = 5\nAxiom: \n  nproduce -(90)\n"
      "  for i in range(nbValues):\n    nproduce I(1)\n\n"
      "derivation length: 3\nproduction:\n"
      "I(j)I(k) < I(i) --> I(k+j)\nendlsystem\n");
  EXPECT_EQ(to_string(derive(g), g.alphabet), "-(90)I(1)I(1)I(2)I(3)I(5)");
  EXPECT_EQ(located_error_of([] {
              (void)kLpy.parse("Axiom:\n  x = 1\nproduction:\nendlsystem\n");
            }),
            "1:1: an axiom built by Python statements without 'nproduce' or "
            "'produce': this is Python code, and lsolid does not run Python; "
            "it reads the declarative part of L-Py (docs/dialects/lpy.md)");
}

TEST(Lpy, KnowsTheStepNumberAndPythonsIntRoundAndFloat) {
  const Grammar g = kLpy.parse(
      "Axiom: A\nderivation length: int(3.9)\nproduction:\n"
      "A :\n  produce B(getIterationNb(), int(-2.7), round(2.5), "
      "round(3.5), float(2)) A\nendlsystem\n");
  EXPECT_EQ(to_string(derive(g), g.alphabet),
            "B(0,-2,2,4,2)B(1,-2,2,4,2)B(2,-2,2,4,2)A");
}

// PlantGL's turtle reads the parameters it knows: `-(90, t)` turns by 90.
TEST(Lpy, IgnoresTurtleParametersPlantGLDoesNotRead) {
  const Skeleton s = drawn("F-(90, 7)f(1, 2)F(1)");
  ASSERT_EQ(s.segments.size(), 2U);
  // `-` turns right, to (1, 0, 0) from PlantGL's first heading and left.
  expect_near(s.segments[1].p0, {1, 0, 1});
  expect_near(s.segments[1].p1, {2, 0, 1});
}

// PlantGL's predefined leaf `~l`: a flat hexagon one long along the
// heading and half as wide, scaled by its parameter.
// PlantGL's moveTo, lineTo and setHead, in its coordinates: Z up, its
// first left (0, -1, 0), lsolid's (-1, 0, 0).
TEST(Lpy, MovesDrawsAndHeadsToWhatPlantGLsCoordinatesName) {
  const Skeleton s = drawn(
      "MoveTo(1, 2, 3) LineTo(1, 2, 5, 0.3) F SetHead(1,0,0, 0,0,1) F "
      "@M(0,0,0) @R(0,1,0) F");
  ASSERT_EQ(s.segments.size(), 4U);
  EXPECT_EQ(s.segments[0].p0, glm::dvec3(2.0, -1.0, 3.0));
  EXPECT_EQ(s.segments[0].p1, glm::dvec3(2.0, -1.0, 5.0));
  EXPECT_DOUBLE_EQ(s.segments[0].end_diameter, 0.6);        // radius 0.3
  EXPECT_EQ(s.segments[1].p1, glm::dvec3(2.0, -1.0, 6.0));  // frame kept
  EXPECT_NEAR(glm::distance(s.segments[2].p1 - s.segments[2].p0,
                            glm::dvec3(0.0, -1.0, 0.0)),
              0.0, 1e-12);
  EXPECT_EQ(s.segments[3].p0, glm::dvec3(0.0));
  EXPECT_NEAR(glm::distance(s.segments[3].p1, glm::dvec3(1.0, 0.0, 0.0)), 0.0,
              1e-12);
}

TEST(Lpy, DrawsPlantGLsPredefinedLeaf) {
  const Skeleton s = drawn("F(1)+(90)~l(2, 5)");
  ASSERT_EQ(s.sheets.size(), 1U);
  const Sheet& leaf = s.sheets[0];
  ASSERT_EQ(leaf.points.size(), 7U);
  EXPECT_EQ(leaf.triangles.size(), 6U);
  // Heading (-1, 0, 0) after the turn, left (0, 0, -1).
  expect_near(leaf.points[1], {0, 0, 1});
  expect_near(leaf.points[4], {-2, 0, 1});
  expect_near(leaf.points[2], {-2.0 / 3.0, 0, 0.5});
  expect_near(leaf.points[5], {-4.0 / 3.0, 0, 1.5});
}

// A label draws nothing in a solid: left out, its Python string unread,
// with a warning.
TEST(Lpy, LeavesOutLabelsWithAWarning) {
  const Grammar g = kLpy.parse(
      "Axiom: F@L(\"a (b)\")F Label(str(3))\nderivation length: 0\n"
      "production:\nendlsystem\n");
  EXPECT_EQ(interpret(g).segments.size(), 2U);
  ASSERT_EQ(g.warnings.size(), 2U);
  EXPECT_EQ(g.warnings[0],
            "'@L' (a label) is left out: it draws nothing in a solid");
}

// The editor's scalars are constants, as L-Py sets them in the context;
// the file's own assignment of the same name stays.
TEST(Lpy, ReadsTheEditorsScalarsAsConstants) {
  const Grammar g = kLpy.parse(
      "n = 2\nAxiom: F(size)\nderivation length: n\nproduction:\n"
      "endlsystem\n###### INITIALISATION ######\n"
      "def __initialiseContext__(context):\n"
      "\tscalars = [('V', 'Category'), ('size', 'Float', 1.5, 0, 10, 2), "
      "('n', 'Integer', 7, 0, 9), ('old', 4, 1, 20), ('on', 'Bool', True)]\n");
  EXPECT_DOUBLE_EQ(g.constants.at("size"), 1.5);
  EXPECT_DOUBLE_EQ(g.constants.at("old"), 4.0);
  EXPECT_DOUBLE_EQ(g.constants.at("on"), 1.0);
  EXPECT_EQ(g.settings.derivation_length, 2);
  EXPECT_EQ(g.constants.count("V"), 0U);
}

TEST(Lpy, DrawsSpheresByTheirRadius) {
  const Skeleton s = drawn("F@O(0.5)Sphere(2)");
  ASSERT_EQ(s.spheres.size(), 2U);
  EXPECT_DOUBLE_EQ(s.spheres[0].diameter, 1.0);
  EXPECT_DOUBLE_EQ(s.spheres[1].diameter, 4.0);
}

TEST(Lpy, DrawsCirclesByTheirRadiusAcrossTheHeading) {
  // PlantGL's turtle: a disc across the heading, of the width without a
  // radius.
  const Skeleton s = drawn("F@o(0.5)+(90)Circle");
  ASSERT_EQ(s.polygons.size(), 2U);
  const glm::dvec3 tip = s.segments[0].p1;
  testing::expect_disc(s.polygons[0], tip, glm::dvec3(0, 0, 1), 1.0);
  // Turned by 90°, the heading is the first left, (-1, 0, 0).
  testing::expect_disc(s.polygons[1], tip, glm::dvec3(1, 0, 0),
                       s.segments[0].end_diameter);
}

TEST(Lpy, RefusesModulesItCannotBuildByTheirWholeName) {
  EXPECT_EQ(located_error_of([] { (void)drawn("F@B(0.5)"); }),
            "1:9: '@B' (a box) is not supported by lsolid");
  EXPECT_EQ(located_error_of([] { (void)drawn("F~x(2)"); }),
            "1:9: '~' (a predefined surface other than ~l, PlantGL's leaf) is "
            "not supported by lsolid");
  // @Gc and @Ge are whole modules, never @, G and c.
  const Skeleton s = drawn("@GcF(2)+(30)F@Ge");
  EXPECT_EQ(s.segments.size(), 2U);
}

TEST(Lpy, TakesAnglesInRadiansInExpressionsAsPythonsMathDoes) {
  const Skeleton s = drawn("F(sin(pi/2))F(2*atan(1))");
  ASSERT_EQ(s.segments.size(), 2U);
  expect_near(s.segments[0].p1, {0, 0, 1});
  expect_near(s.segments[1].p1, {0, 0, 1 + std::acos(-1.0) / 2});
}

TEST(Lpy, TakesTheTurtlesSettingsFromTheEditorsBlock) {
  const Skeleton s = interpret(
      kLpy.parse("Axiom: F+F\nderivation length: 0\nproduction:\nendlsystem\n"
                 "###### INITIALISATION ######\n"
                 "def __initialiseContext__(context):\n"
                 "\tcontext.turtle.setAngleIncrement(90)\n"));
  ASSERT_EQ(s.segments.size(), 2U);
  expect_near(s.segments[1].p1, {-1, 0, 1});
}

TEST(Lpy, ReadsRangeEnumerationsAndLambdasAsConstantsAndFunctions) {
  const Grammar g = kLpy.parse(
      "Forward, Backward, Growth = range(3)\n"
      "width = lambda order, k : 10. / (order + 1) + k\n"
      "Axiom: A(Growth)\nderivation length: 1\nproduction:\n"
      "A(x) --> F(width(x, Backward))\nendlsystem\n");
  EXPECT_EQ(to_string(derive(g), g.alphabet), "F(4.333333333333334)");
  EXPECT_EQ(
      located_error_of([] { (void)kLpy.parse("A, B = range(3)\nAxiom: F\n"); }),
      "1:8: range(3) gives 3 values to 2 names");
}

// Python's call syntax: `F()` is F without parameters, in the axiom, a
// successor and a predecessor alike (a published L-Py file writes it).
TEST(Lpy, ReadsModulesCalledWithEmptyParenthesesAsWithoutParameters) {
  const Skeleton s = drawn("F()F(2)f()F( )");
  ASSERT_EQ(s.segments.size(), 3U);
  const auto length = [&](std::size_t i) {
    return glm::distance(s.segments[i].p0, s.segments[i].p1);
  };
  EXPECT_DOUBLE_EQ(length(0), 1.0);
  EXPECT_DOUBLE_EQ(length(1), 2.0);
  EXPECT_DOUBLE_EQ(length(2), 1.0);
  // f() moves a step without drawing.
  EXPECT_DOUBLE_EQ(glm::distance(s.segments[1].p1, s.segments[2].p0), 1.0);
  const Skeleton doubled =
      interpret(kLpy.parse("Axiom: F()\nderivation length: 3\nproduction:\n"
                           "F() --> F()F()\nendlsystem\n"));
  EXPECT_EQ(doubled.segments.size(), 8U);
}

}  // namespace
}  // namespace lsys
