// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/derivation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "support/abop_systems.hpp"
#include "support/core_helpers.hpp"

namespace lsys {
namespace {

using testing::derived;
using testing::kHilbert;
using testing::parse;

struct Counts {
  std::size_t length = 0;
  std::map<std::string, std::size_t> modules;
  int max_depth = 0;
};

Counts count(const Grammar& g, DerivationOptions options = {}) {
  Derivation d(g, options);
  Counts c;
  ModuleString chunk;
  int depth = 0;
  while (d.next(chunk)) {
    c.length += chunk.size();
    for (std::size_t i = 0; i < chunk.size(); ++i) {
      const SymbolId s = chunk.symbol(i);
      ++c.modules[g.alphabet.name(s)];
      if (s == kBranchOpen) c.max_depth = std::max(c.max_depth, ++depth);
      if (s == kBranchClose) --depth;
    }
  }
  return c;
}

TEST(Derivation, AlgaeMatchesWikipedia) {
  const char* algae = "\u03C9: A\nA \u2192 AB\nB \u2192 A\n";
  const std::vector<std::string> expected{"A",
                                          "AB",
                                          "ABA",
                                          "ABAAB",
                                          "ABAABABA",
                                          "ABAABABAABAAB",
                                          "ABAABABAABAABABAABABA",
                                          "ABAABABAABAABABAABABAABAABABAABAAB"};
  for (int n = 0; n < static_cast<int>(expected.size()); ++n) {
    EXPECT_EQ(derived(algae, n), expected[static_cast<std::size_t>(n)]);
  }
}

TEST(Derivation, KochCurvesMatchPublishedStrings) {
  EXPECT_EQ(derived("\u03C9: F\nF \u2192 F+F-F-F+F", 2),
            "F+F-F-F+F+F+F-F-F+F-F+F-F-F+F-F+F-F-F+F+F+F-F-F+F");
  EXPECT_EQ(derived("\u03C9: F++F++F\nF \u2192 F-F++F-F", 1),
            "F-F++F-F++F-F++F-F++F-F++F-F");
}

TEST(Derivation, BranchingExamplesMatchPublishedStrings) {
  EXPECT_EQ(derived("\u03C9: 0\n1 \u2192 11\n0 \u2192 1[0]0", 3),
            "1111[11[1[0]0]1[0]0]11[1[0]0]1[0]0");
  EXPECT_EQ(derived("\u03C9: A\nB \u2192 BB\nA \u2192 B[A]A", 3),
            "BBBB[BB[B[A]A]B[A]A]BB[B[A]A]B[A]A");
  EXPECT_EQ(derived("\u03C9: X\nX \u2192 F[+X][-X]FX\nF \u2192 FF", 2),
            "FF[+F[+X][-X]FX][-F[+X][-X]FX]FFF[+X][-X]FX");
}

TEST(Derivation, HilbertCountsMatchTheClosedForm) {
  const Grammar g = parse(kHilbert);
  const std::vector<std::size_t> lengths{29, 271, 2155};
  for (int n = 1; n <= 3; ++n) {
    Counts c = count(g, {.derivation_length = n});
    EXPECT_EQ(c.length, lengths[static_cast<std::size_t>(n - 1)]);
    EXPECT_EQ(c.modules["F"], (1U << (3 * n)) - 1);  // 8^n - 1
  }
}

struct FigureCase {
  const char* name;
  const char* text;
  std::size_t length;
  std::size_t f_count;
  int max_depth;
};

class AbopFigure : public ::testing::TestWithParam<FigureCase> {};

TEST_P(AbopFigure, HasTheDerivedLengthAndSegmentCount) {
  const FigureCase& c = GetParam();
  Counts counts = count(parse(c.text));
  EXPECT_EQ(counts.length, c.length);
  EXPECT_EQ(counts.modules["F"], c.f_count);
  EXPECT_EQ(counts.max_depth, c.max_depth);
}

// ABOP fig. 1.24 a-f (p. 25, seed 000) and seed 004's figures; the counts
// follow from closed forms: each F of a D0L system rewrites to the same
// successor, so the count of each module after n steps is the n-th power
// of the production's count matrix applied to the axiom's counts.
INSTANTIATE_TEST_SUITE_P(
    Figures, AbopFigure,
    ::testing::Values(
        FigureCase{"a", "n=5\nF\nF \u2192 F[+F]F[-F]F", 7811, 3125, 5},
        FigureCase{"b", "n=5\nF\nF \u2192 F[+F]F[-F][F]", 9373, 3125, 5},
        FigureCase{"c", "n=4\nF\nF \u2192 FF-[-F+F+F]+[+F-F-F]", 11116, 4096,
                   4},
        FigureCase{"d", "n=7\nX\nX \u2192 F[+X]F[-X]+X\nF \u2192 FF", 13956,
                   4118, 7},
        FigureCase{"e", "n=7\nX\nX \u2192 F[+X][-X]FX\nF \u2192 FF", 12863,
                   4118, 7},
        FigureCase{"f", "n=5\nX\nX \u2192 F-[[X]+X]+F[+FX]-X\nF \u2192 FF",
                   6263, 1488, 10},
        FigureCase{"koch_island", "n=3\nF-F-F-F\nF \u2192 F-F+F+FF-F-F+F", 3803,
                   2048, 0},
        FigureCase{"koch_snowflake", "n=4\nF--F--F\nF \u2192 F+F--F+F", 1792,
                   768, 0}),
    [](const auto& test) { return std::string(test.param.name); });

TEST(Derivation, Seed004SierpinskiTriplesEachStep) {
  // A → B-A-B, B → A+B+A: 3^n drawing modules, (3^(n+1) - 1)/2 in all.
  const Grammar g = parse("\u03C9: A\nA \u2192 B-A-B\nB \u2192 A+B+A");
  for (int n = 0; n <= 6; ++n) {
    Counts c = count(g, {.derivation_length = n});
    std::size_t power = 1;
    for (int i = 0; i < n; ++i) power *= 3;
    EXPECT_EQ(c.modules["A"] + c.modules["B"], power);
    EXPECT_EQ(c.length, 2 * power - 1);
  }
}

TEST(Derivation, AbopParametricExampleGivesEachStep) {
  // ABOP §1.10.1, p. 43.
  const char* text =
      "\u03C9: B(2)A(4,4)\n"
      "p1: A(x,y): y<=3 \u2192 A(x*2,x+y)\n"
      "p2: A(x,y): y>3 \u2192 B(x)A(x/y,0)\n"
      "p3: B(x): x<1 \u2192 C\n"
      "p4: B(x): x>=1 \u2192 B(x-1)\n";
  EXPECT_EQ(derived(text, 1), "B(1)B(4)A(1,0)");
  EXPECT_EQ(derived(text, 2), "B(0)B(3)A(2,1)");
  EXPECT_EQ(derived(text, 3), "CB(2)A(4,3)");
  EXPECT_EQ(derived(text, 4), "CB(1)A(8,7)");
  EXPECT_EQ(derived(text, 5), "CB(0)B(8)A(1.1428571428571428,0)");
}

TEST(Derivation, SignalPropagatesWithLeftContext) {
  // ABOP §1.8, p. 30.
  const char* text = "\u03C9: baaaaaaa\nb < a \u2192 b\nb \u2192 a\n";
  const std::vector<std::string> expected{"abaaaaaa", "aabaaaaa", "aaabaaaa",
                                          "aaaabaaa", "aaaaabaa", "aaaaaaba"};
  for (int n = 1; n <= 6; ++n) {
    EXPECT_EQ(derived(text, n), expected[static_cast<std::size_t>(n - 1)]);
  }
}

TEST(Derivation, MatchesContextInBracketedStringsAsAbopPage32) {
  EXPECT_EQ(derived("\u03C9: A[X]BC\nA < B > C \u2192 Z", 1), "A[X]ZC");
  EXPECT_EQ(derived("\u03C9: ABD\nA < B > C \u2192 Z", 1), "ABD");
  EXPECT_EQ(
      derived("\u03C9: ABC[DE][SG[HI[JK]L]MNO]\nBC < S > G[H]M \u2192 Z", 1),
      "ABC[DE][ZG[HI[JK]L]MNO]");
  const char* ignoring = "ignore: +-\n\u03C9: A+B+C[DE][-S-G[HI[JK]L-]M-NO]\n";
  EXPECT_EQ(derived(std::string(ignoring) + "BC < S \u2192 Z", 1),
            "A+B+C[DE][-Z-G[HI[JK]L-]M-NO]");
  EXPECT_EQ(derived(std::string(ignoring) + "S > GM \u2192 Z", 1),
            "A+B+C[DE][-Z-G[HI[JK]L-]M-NO]");
  EXPECT_EQ(derived("\u03C9: SI[JK]L\nS > I[K]L \u2192 Z", 1), "SI[JK]L");
  EXPECT_EQ(derived("consider: BCS\n\u03C9: BxC[y]Sz\nBC < S \u2192 Z", 1),
            "BxC[y]Zz");
}

TEST(Derivation, TriesContextRulesInFileOrder) {
  const char* text =
      "\u03C9: ABCDEFGHI\nA < B > C \u2192 Y\nA < B > D \u2192 N\n"
      "G > HIJ \u2192 N\nG > HI \u2192 Y\nA > C \u2192 N\nA \u2192 Y\n";
  EXPECT_EQ(derived(text, 1), "YYCDEFYHI");
}

TEST(Derivation, AppliesDecompositionAfterEachStep) {
  const char* text =
      "\u03C9: A\nA \u2192 AB\ndecomposition:\nmaximum depth: 3\n"
      "B \u2192 CC\nC \u2192 D\n";
  EXPECT_EQ(derived(text, 0), "A");
  EXPECT_EQ(derived(text, 2), "ADDDD");
}

TEST(Derivation, CutsTheRestOfTheBranch) {
  // ABOP p. 73: `%` removes itself and the rest of its branch.
  EXPECT_EQ(derived("\u03C9: F[AF[G]F]F\nA \u2192 %", 1), "F[]F");
  EXPECT_EQ(derived("\u03C9: A[B]C\nB \u2192 F%G[H]I", 1), "A[F]C");
}

TEST(Derivation, KeepsTheGenerationThatCreatedEachModule) {
  const Grammar g = parse("\u03C9: fA\nA \u2192 fA");
  const ModuleString s = derive(g, {.derivation_length = 3});
  ASSERT_EQ(to_string(s, g.alphabet), "ffffA");
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(s.generation(i), i);
  EXPECT_EQ(s.generation(4), 3U);
}

TEST(Derivation, StochasticOutputDependsOnlyOnTheSeed) {
  const char* text =
      "\u03C9: F\nn=5\nF -(0.33)\u2192 F[+F]F[-F]F\nF -(0.33)\u2192 F[+F]F\n"
      "F -(0.34)\u2192 F[-F]F\n";
  const Grammar g = parse(text);
  const auto with_seed = [&](std::uint64_t seed) {
    return to_string(derive(g, {.seed = seed}), g.alphabet);
  };
  EXPECT_EQ(with_seed(1), with_seed(1));
  EXPECT_NE(with_seed(1), with_seed(2));
  EXPECT_NE(with_seed(2), with_seed(3));
  EXPECT_EQ(with_seed(0), to_string(derive(g), g.alphabet));
}

TEST(Derivation, StochasticChoicesFollowTheWeights) {
  // 100,000 independent choices among three weights.
  const Grammar g = parse(
      "\u03C9: A\nA \u2192 XXXXXXXXXX\nX -(1)\u2192 a\nX -(2)\u2192 b\n"
      "X -(7)\u2192 c\n");
  std::map<std::string, double> seen;
  double total = 0.0;
  for (std::uint64_t seed = 0; seed < 10000; ++seed) {
    const ModuleString s = derive(g, {.derivation_length = 2, .seed = seed});
    for (std::size_t i = 0; i < s.size(); ++i) {
      const SymbolId sym = s.symbol(i);
      ++seen[g.alphabet.name(sym)];
      ++total;
    }
  }
  EXPECT_EQ(total, 100000.0);
  EXPECT_NEAR(seen["a"] / total, 0.1, 0.005);
  EXPECT_NEAR(seen["b"] / total, 0.2, 0.005);
  EXPECT_NEAR(seen["c"] / total, 0.7, 0.005);
}

TEST(Derivation, NormalisesWeightsOverApplicableProductions) {
  // With x = 1 only the second and third apply: weights 1 and 3.
  const Grammar g = parse(
      "\u03C9: XXXXXXXXXXXXXXXXXXXX\nX \u2192 Y(1)\n"
      "Y(x) : x > 5 -(100)\u2192 a\nY(x) -(1)\u2192 b\nY(x) -(3)\u2192 c\n");
  double b = 0.0;
  double c = 0.0;
  for (std::uint64_t seed = 0; seed < 2000; ++seed) {
    const ModuleString s = derive(g, {.derivation_length = 2, .seed = seed});
    for (std::size_t i = 0; i < s.size(); ++i) {
      const SymbolId sym = s.symbol(i);
      const std::string& name = g.alphabet.name(sym);
      ASSERT_NE(name, "a");
      b += name == "b" ? 1.0 : 0.0;
      c += name == "c" ? 1.0 : 0.0;
    }
  }
  EXPECT_NEAR(b / (b + c), 0.25, 0.01);
}

// Adding a production that never applies but contains `%` makes the
// deriver rewrite whole strings; the result must not change.
TEST(Derivation, StreamingAndRewritingGiveTheSameString) {
  const std::vector<std::string> grammars{
      kHilbert,
      "\u03C9: F\nn=5\nF -(0.2)\u2192 F[+F]F[-F]F\nF -(0.5)\u2192 F[+F]F\n"
      "F -(0.3)\u2192 F[-F]F\n",
      "\u03C9: A(1)\nn=6\nA(x) : x < 4 -(1)\u2192 F(x)[+A(x+1)]A(x*2)\n"
      "A(x) -(2)\u2192 B(x)A(x+0.5)\nB(x) \u2192 F(x/2)\n"
      "decomposition:\nF(x) : x > 3 \u2192 F(x/2)F(x/2)\n",
  };
  for (const std::string& text : grammars) {
    const Grammar streaming = parse(text);
    const Grammar rewriting = parse(text + "\nproductions:\nQ \u2192 %\n");
    for (std::uint64_t seed = 0; seed < 5; ++seed) {
      Derivation a(streaming, {.seed = seed});
      Derivation b(rewriting, {.seed = seed});
      EXPECT_TRUE(a.is_streaming());
      EXPECT_FALSE(b.is_streaming());
      EXPECT_EQ(
          to_string(derive(streaming, {.seed = seed}), streaming.alphabet),
          to_string(derive(rewriting, {.seed = seed}), rewriting.alphabet));
    }
  }
}

TEST(Derivation, ServesTheStringInChunks) {
  const Grammar g = parse(kHilbert);
  Derivation d(g, {.derivation_length = 3});
  ModuleString chunk;
  std::size_t total = 0;
  while (d.next(chunk, 100)) {
    EXPECT_LE(chunk.size(), 100U);
    total += chunk.size();
  }
  EXPECT_EQ(total, 2155U);
}

TEST(Derivation, PredictsSizesFromTheCountMatrix) {
  const Grammar g = parse(kHilbert);
  const auto p = Derivation(g, {.derivation_length = 8}).prediction();
  ASSERT_TRUE(p.has_value());
  EXPECT_TRUE(p->is_exact);
  EXPECT_EQ(p->segments, 16777215.0);  // 8^8 - 1
  const Counts c = count(g, {.derivation_length = 4});
  EXPECT_EQ(Derivation(g, {.derivation_length = 4}).prediction()->modules,
            static_cast<double>(c.length));
  EXPECT_FALSE(Derivation(parse("\u03C9: A(1)\nA(x) : x < 3 \u2192 A(x+1)"),
                          {.derivation_length = 2})
                   .prediction());
}

TEST(Derivation, PredictionFollowsHomomorphismAndDecomposition) {
  const Grammar g = parse(
      "\u03C9: A\nA \u2192 AB\ndecomposition:\nB \u2192 CC\nhomomorphism:\n"
      "C \u2192 FGF\n");
  const auto p = Derivation(g, {.derivation_length = 5}).prediction();
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(p->modules, 11.0);  // A and ten C
  EXPECT_EQ(p->segments, 30.0);
}

TEST(Derivation, RefusesBeforeDerivingWhenThePredictionIsTooLarge) {
  const Grammar g = parse(kHilbert);
  try {
    Derivation d(g, {.derivation_length = 9});
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.diagnostic().line, 2);  // the axiom, since -n overrides n
    EXPECT_EQ(e.diagnostic().message,
              "n = 9 would draw 134217727 segments, more than the limit of "
              "20000000 (--max-segments)");
  }
  try {
    Derivation d(parse(kHilbert), {.max_modules = 100});
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.diagnostic().line, 1);  // the file's n
    EXPECT_EQ(e.diagnostic().column, 1);
    EXPECT_EQ(e.diagnostic().message,
              "n = 2 would derive a string of 271 modules, more than the "
              "limit of 100 (--max-modules)");
  }
}

TEST(Derivation, PredictsDeepDecompositionWithoutExpandingIt) {
  const Grammar g =
      parse("n=0\n\u03C9: A\ndecomposition:\nmaximum depth: 40\nA \u2192 AA");
  try {
    (void)derive(g, {.max_modules = 1000});
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.diagnostic().message,
              "n = 0 would derive a string of 1099511627776 modules, more than "
              "the limit of 1000 (--max-modules)");
  }
}

TEST(Derivation, RefusesAtOnceWhenEvenTheLeastGrowthIsTooMuch) {
  // Every alternative at least triples the F's: 3^30 > 20 million.
  const Grammar g = parse(
      "\u03C9: F\nn=30\nF -(0.33)\u2192 F[+F]F[-F]F\nF -(0.33)\u2192 F[+F]F\n"
      "F -(0.34)\u2192 F[-F]F\n");
  try {
    Derivation d(g);
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.diagnostic().message,
              "n = 30 would draw at least 205891132094649 segments, more than "
              "the limit of 20000000 (--max-segments)");
  }
  const Grammar context = parse("\u03C9: BA\nB < A \u2192 AA\nA \u2192 AA\n");
  EXPECT_THROW(Derivation(context, {.derivation_length = 100}), ParseError);
  // A condition may stop growth, so nothing is refused early here.
  const Grammar conditional =
      parse("\u03C9: A(1)\nA(x) : x < 3 \u2192 A(x+1)A(x+1)\n");
  EXPECT_NO_THROW(Derivation(conditional, {.derivation_length = 100}));
}

TEST(Derivation, CountsAsItGoesWhenSizesAreUnpredictable) {
  const Grammar g = parse("\u03C9: A(0)\nn=30\nA(x) : x >= 0 \u2192 A(x)FA(x)");
  try {
    (void)derive(g, {.max_segments = 1000});
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.diagnostic().message,
              "n = 30 draws more than the limit of 1000 segments "
              "(--max-segments)");
  }
}

// A recursive homomorphism whose conditions end it early draws far less
// than its bound (vlab's recursive leaf: 255 segments where the bound is
// astronomical): the turtle counts what it draws, and refuses only that.
TEST(Derivation, CountsTheSegmentsOfAConditionalHomomorphismAsTheyAreDrawn) {
  const std::string rules =
      "homomorphism:\nmaximum depth: 100\n"
      "A(t) : t >= 2 \u2192 M(t-2) A(t-1)\nM(t) \u2192 F[+A(t)][-A(t)]F\n"
      "A(t) : t < 2 \u2192 F(t)\n";
  EXPECT_EQ(interpret(parse("\u03C9: A(8)\nn=0\n" + rules)).segments.size(),
            255U);
  try {
    (void)interpret(parse("\u03C9: A(30)\nn=0\n" + rules),
                    {.max_segments = 1000});
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.diagnostic().message,
              "n = 0 draws more than the limit of 1000 segments "
              "(--max-segments)");
  }
}

// The message of the error that deriving `.ls` text with these options
// raises, or "no error".
std::string derive_error(const std::string& text, DerivationOptions options) {
  try {
    (void)derive(parse(text), options);
  } catch (const ParseError& e) {
    return e.diagnostic().message;
  }
  return "no error";
}

TEST(Derivation, HoldsTheModuleLimitWhenRewritingTheWholeString) {
  // Contexts make the whole string be rewritten; sizes depend on values.
  const std::string text =
      "\u03C9: A(1)\nn=40\nA(x) : x > 0 \u2192 A(x)A(x)\nF < F \u2192 F\n";
  EXPECT_EQ(derive_error(text, {.max_modules = 1000}),
            "n = 40 derives more than the limit of 1000 modules "
            "(--max-modules)");
}

TEST(Derivation, HoldsTheMemoryLimitWhenRewritingTheWholeString) {
  // It ran to 2.6 GB and out of memory: now it stops at the limit, counted
  // as the strings grow, before they grow past it.
  const std::string text =
      "\u03C9: A(1)\nn=40\nA(x) : x > 0 \u2192 A(x)A(x)\nF < F \u2192 F\n";
  const std::string message =
      derive_error(text, {.max_memory_bytes = std::uint64_t{16} << 20U});
  EXPECT_TRUE(message.starts_with(
      "n = 40 needs more than the limit of 16 MiB (--max-memory) in step "))
      << message;
  EXPECT_TRUE(message.ends_with(
      " modules; with contexts or cuts, the whole string is rewritten each "
      "step"))
      << message;
  // Cuts rewrite the whole string too; streaming is not limited by memory.
  EXPECT_TRUE(derive_error("\u03C9: A(1)\nn=40\nA(x) : x > 0 \u2192 "
                           "A(x)A(x)[%]\n",
                           {.max_memory_bytes = std::uint64_t{16} << 20U})
                  .starts_with("n = 40 needs more than the limit of 16 MiB"));
  EXPECT_EQ(derive_error("\u03C9: A(1)\nn=20\nA(x) : x > 0 \u2192 A(x)A(x)\n",
                         {.max_memory_bytes = 1}),
            "no error");
}

TEST(Derivation, RefusesAtOnceAWholeStringThatCannotFitTheMemoryLimit) {
  // 2^30 modules of at least 16 bytes are more than 2 GiB.
  EXPECT_EQ(derive_error("\u03C9: A\nn=30\nA \u2192 AA\nB < C \u2192 D\n",
                         {.max_modules = std::uint64_t{1} << 40U}),
            "n = 30 would hold a string of at least 1073741824 modules, more "
            "than the limit of 2048 MiB (--max-memory); with contexts or "
            "cuts, the whole string is rewritten each step");
}

TEST(Derivation, ReportsDivisionByZeroWhereItIsWritten) {
  const Grammar g = parse("\u03C9: A(1)\nA(x) \u2192 A(x/(x-1))");
  try {
    (void)derive(g, {.derivation_length = 1});
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.diagnostic().line, 2);
    EXPECT_EQ(e.diagnostic().column, 11);
    EXPECT_EQ(e.diagnostic().message, "division by zero");
  }
}

}  // namespace
}  // namespace lsys
