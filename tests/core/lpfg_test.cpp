// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The lpfg front end (docs/dialects/lpfg.md): statements that end in `;`,
// C++ rule bodies that `produce` their successors, lpfg's named modules,
// and what it refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <string>

#include "lsys/dialect.hpp"
#include "lsys/interpretation.hpp"
#include "support/core_helpers.hpp"

namespace lsys {
namespace {

using testing::located_error_of;

constexpr testing::Notation kLpfg{Dialect::Lpfg, "lsystem.l"};

constexpr std::string_view kHead =
    "#include <lpfgall.h>\n#include <math.h>\n#define ANGLE 45\n";

TEST(Lpfg, IsDetectedByItsHeader) {
  EXPECT_EQ(detect_dialect("#include <lpfgall.h>\nAxiom: A;\n", "a.l"),
            Dialect::Lpfg);
  EXPECT_EQ(dialect_named("lpfg"), Dialect::Lpfg);
}

// vlab's LPFG/Introduction/compound-param, as lpfg writes it: each body
// produces its successor, lpfg's names are modules, `SB()` takes nothing.
TEST(Lpfg, ReadsRulesWhoseBodiesProduceTheirSuccessors) {
  const std::string text =
      std::string(kHead) +
      "derivation length: 2;\nmodule A(float);\nmodule I(float);\n"
      "Axiom: SetWidth(3) A(1.0);\n"
      "A(v) :\n{\n  produce I(1)\n    SB() Right(ANGLE) A(v) EB()\n"
      "    SB() Left(ANGLE) A(v) EB() I(1) A(v);\n}\n"
      "I(x) : { produce I(2*x); }\n"
      "interpretation:\nA(v) : { produce IncColor() F(v); }\n"
      "I(x) : { produce F(x); }\n";
  EXPECT_EQ(kLpfg.derived(text),
            "SetWidth(3) I(2) SB Right(45) I(1) SB Right(45) A(1) EB SB "
            "Left(45) A(1) EB I(1)A(1) EB SB Left(45) I(1) SB Right(45) A(1) "
            "EB SB Left(45) A(1) EB I(1)A(1) EB I(2)I(1) SB Right(45) A(1) EB "
            "SB Left(45) A(1) EB I(1)A(1)");
  EXPECT_EQ(interpret(kLpfg.parse(text)).segments.size(), 17U);
}

// A body runs as C++: declarations, if/else, for, +=, ++, casts, float
// literals; `produce` ends it, and a body that produces nothing leaves the
// module to the next rule.
TEST(Lpfg, RunsTheBodysStatementsInOrder) {
  EXPECT_EQ(
      kLpfg.derived(std::string(kHead) +
                    "derivation length: 1;\nmodule A(int);\nmodule B(float, "
                    "float);\nAxiom: A(3) A(7);\n"
                    "A(n) : {\n  float sum = 0.5f, k;\n  int i;\n"
                    "  for (i = 0; i < n; i++) { sum += i; }\n"
                    "  k = (int)(sum / 2);\n  if (n > 5) produce B(sum, k);\n"
                    "  nproduce B(0, 0);\n}\n"
                    "A(n) : { produce B(-1, n); }\n"),
      "B(-1,3)B(21.5,10)");
}

TEST(Lpfg, KeepsGlobalsAndRunsStartBlocks) {
  EXPECT_EQ(kLpfg.derived(std::string(kHead) +
                          "int count;\nconst float step = 2;\n"
                          "derivation length: 3;\nmodule A(float);\n"
                          "Start: { count = 10; }\n"
                          "StartEach: { count += 1; }\n"
                          "Axiom: A(0);\n"
                          "A(x) : produce A(count * step);\n"),
            "A(26)");
}

// lpfg gives decomposition and interpretation each their depth.
TEST(Lpfg, KeepsTheInterpretationsOwnMaximumDepth) {
  const Grammar g = kLpfg.parse(
      "#include <lpfgall.h>\nderivation length: 0;\nmodule A(int);\n"
      "Axiom: A(0);\ndecomposition:\nmaximum depth: 1;\n"
      "interpretation:\nmaximum depth: 3;\n"
      "A(n) : { produce F(1) A(n+1); }\n");
  EXPECT_EQ(g.settings.maximum_depth, 1);
  EXPECT_EQ(g.settings.homomorphism_depth, 3);
  EXPECT_EQ(interpret(g).segments.size(), 3U);
}

TEST(Lpfg, ReadsFunctionsOfOneReturnAndTheirCalls) {
  EXPECT_EQ(kLpfg.derived(std::string(kHead) +
                          "float half(float x) { return x / 2; }\n"
                          "derivation length: 1;\nmodule A(float);\n"
                          "Axiom: A(8);\nA(x) : { produce A(half(x) + "
                          "pow(2, 3) + sin(M_PI / 2)); }\n"),
            "A(13)");
  EXPECT_EQ(located_error_of([] {
              (void)kLpfg.parse(
                  "#include <lpfgall.h>\nfloat f(float x) { float y "
                  "= x; return y; }\nAxiom: F(1);\n");
            }),
            "2:1: 'float f(float x)': a C++ function; lsolid reads "
            "functions of one 'return' only (docs/dialects/lpfg.md)");
}

// lpfg's turtle is cpfg's: the heading starts up, Left and Right turn,
// Sphere and Circle take radii.
// As in lpfg, a body that does not produce has drawn its numbers: the next
// rule leaves the module, and the next step draws anew (it once drew the
// same rejected number for ever).
TEST(Lpfg, KeepsTheDrawsOfABodyThatProducesNothing) {
  const Grammar g = kLpfg.parse(
      "#include <lpfgall.h>\nderivation length: 1000;\nmodule A();\n"
      "module B();\nAxiom: A();\n"
      "A(): { if (ran(1) < 0.5) produce B() A(); }\n"
      "A(): { produce A(); }\n");
  const std::string s = to_string(derive(g), g.alphabet);
  const auto draws = testing::drand48_sequence(1000);
  const auto expected = std::count_if(draws.begin(), draws.end(),
                                      [](double u) { return u < 0.5; });
  EXPECT_EQ(std::count(s.begin(), s.end(), 'B'), expected);
  EXPECT_NEAR(static_cast<double>(expected), 500.0, 50.0);
}

TEST(Lpfg, DrawsWithLpfgsNamedModules) {
  const Skeleton s = interpret(kLpfg.parse(
      "#include <lpfgall.h>\nAxiom: F(1) Left(90) F(2) SB() Right(90) F(1) "
      "EB() Sphere(0.5) Label(\"tip\");\n"));
  ASSERT_EQ(s.segments.size(), 3U);
  EXPECT_NEAR(glm::distance(s.segments[0].p1, glm::dvec3(0, 0, 1)), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(s.segments[1].p1 - s.segments[1].p0), 2.0, 1e-12);
  EXPECT_NEAR(glm::dot(s.segments[1].p1 - s.segments[1].p0,
                       s.segments[2].p1 - s.segments[2].p0),
              0.0, 1e-12);
  ASSERT_EQ(s.spheres.size(), 1U);
  EXPECT_DOUBLE_EQ(s.spheres[0].diameter, 1.0);
}

TEST(Lpfg, RefusesWhatItCannotReadAtItsPlace) {
  EXPECT_EQ(located_error_of([] {
              (void)kLpfg.parse(
                  "#include <lpfgall.h>\nmodule A(int);\nAxiom: A(1);\n"
                  "A(n) : { switch (n) { case 1: produce A(2); } }\n");
            }),
            "4:10: C++'s 'switch' is not supported: lsolid reads "
            "declarations, assignments, if, for, while, do, produce and "
            "nproduce (docs/dialects/lpfg.md)");
  EXPECT_EQ(located_error_of([] {
              (void)kLpfg.parse("#include <lpfgall.h>\nAxiom: F(1) Foo(2);\n");
            }),
            "2:13: 'Foo' is not a module: declare it with 'module Foo(…);'");
  EXPECT_EQ(
      located_error_of([] {
        (void)kLpfg.parse("#include <lpfgall.h>\nAxiom: Surface(0, 1);\n");
      }),
      "2:8: 'Surface' (a predefined surface) is not supported by "
      "lsolid");
  EXPECT_EQ(located_error_of([] {
              (void)kLpfg.parse(
                  "#include <lpfgall.h>\nstruct D { float x; };\n"
                  "Axiom: F(1);\n");
            }),
            "2:1: 'struct D': a C++ type; lsolid reads modules of numbers "
            "only (docs/dialects/lpfg.md)");
  EXPECT_EQ(located_error_of([] {
              (void)kLpfg.parse(
                  "#include <lpfgall.h>\n#include <time.h>\n"
                  "FILE* fp;\nAxiom: F(1);\n");
            }),
            "3:1: 'FILE* fp': a variable of the C++ type 'FILE'; lsolid reads "
            "variables of numbers only (docs/dialects/lpfg.md)");
  EXPECT_EQ(located_error_of([] {
              (void)kLpfg.parse(
                  "#include <lpfgall.h>\n#include \"mine.h\"\n"
                  "Axiom: F(1);\n");
            }),
            "2:1: #include \"mine.h\": no such file beside this one "
            "(mine.h)");
  // A model reads nothing outside its folder, and never quotes it.
  EXPECT_EQ(located_error_of([] {
              (void)kLpfg.parse(
                  "#include <lpfgall.h>\n#include \"/etc/passwd\"\n"
                  "Axiom: F(1);\n");
            }),
            "2:1: #include \"/etc/passwd\": an absolute name; a model reads "
            "only files in its own folder (--include-dir allows another)");
  EXPECT_EQ(located_error_of([] {
              (void)kLpfg.parse(
                  "#include <lpfgall.h>\n#include \"../../../etc/passwd\"\n"
                  "Axiom: F(1);\n");
            }),
            "2:1: #include \"../../../etc/passwd\": a name that leaves the "
            "folder ('..'); a model reads only files in its own folder "
            "(--include-dir allows another)");
}

// `using` only brings names into scope, which the expressions know by their
// plain names: read as nothing. A type is refused as one (a published file's
// `using namespace std;` was refused as "groups, structures or types").
TEST(Lpfg, ReadsUsingAsNothingAndNamesWhatItRefuses) {
  const std::string body =
      "derivation length: 1;\nmodule A();\nAxiom: A();\n"
      "A() : { produce F(sin(0.5)) A(); }\n";
  EXPECT_EQ(
      interpret(kLpfg.parse(std::string(kHead) +
                            "using namespace std;\nusing std::sin;\n" + body))
          .segments.size(),
      1U);
  EXPECT_EQ(
      located_error_of([&] {
        (void)kLpfg.parse(std::string(kHead) + "typedef float real;\n" + body);
      }),
      "4:1: 'typedef float real': a C++ type; lsolid reads modules of "
      "numbers only (docs/dialects/lpfg.md)");
}

}  // namespace
}  // namespace lsys
