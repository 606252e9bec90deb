// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/grammar.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "support/core_helpers.hpp"

namespace lsys {
namespace {

using testing::parse;

TEST(Grammar, ReservesTheFirstIdsForBracketsAndCut) {
  const Grammar g = parse("\u03C9: F");
  EXPECT_EQ(g.alphabet.name(kBranchOpen), "[");
  EXPECT_EQ(g.alphabet.name(kBranchClose), "]");
  EXPECT_EQ(g.alphabet.name(kCut), "%");
}

TEST(Grammar, FlattensAConstantSuccessor) {
  const Grammar g = parse("\u03C9: A\nA \u2192 F(2)[+(30)G]B(1,2)");
  const Successor& s = g.productions.at(0).successor;
  ASSERT_EQ(s.size(), 6U);
  EXPECT_TRUE(s.is_constant());
  EXPECT_EQ(s.parameter_begins(),
            (std::vector<std::uint32_t>{0, 1, 1, 2, 2, 2, 4}));
  EXPECT_EQ(s.constant_values(), (std::vector<double>{2, 30, 1, 2}));
}

TEST(Grammar, InstantiatesAParametricSuccessorFromSlots) {
  const Grammar g = parse("\u03C9: A(1,2)\nA(l,w) \u2192 F(l*2)A(w,l+w)");
  const Successor& s = g.productions.at(0).successor;
  EXPECT_FALSE(s.is_constant());
  std::vector<double> out;
  const std::vector<double> slots{3.0, 4.0};
  s.instantiate(slots, out);
  EXPECT_EQ(out, (std::vector<double>{6, 4, 7}));
}

TEST(Grammar, KeepsProductionKindsApart) {
  const Grammar g = parse(
      "\u03C9: A\nA \u2192 B\nA < B \u2192 C\ndecomposition:\nC \u2192 D\n"
      "homomorphism:\nD \u2192 F\n");
  ASSERT_EQ(g.productions.size(), 2U);
  EXPECT_FALSE(g.productions[0].is_context_sensitive());
  EXPECT_TRUE(g.productions[1].is_context_sensitive());
  EXPECT_EQ(g.decompositions.size(), 1U);
  EXPECT_EQ(g.homomorphisms.size(), 1U);
}

TEST(Grammar, GivesEverySymbolItsTurtleCommand) {
  const Grammar g = parse("aliases: x=F\n\u03C9: F+x@v{.}A");
  ASSERT_EQ(g.commands.size(), g.alphabet.size());
  EXPECT_EQ(g.commands[*g.alphabet.find("x")], TurtleCommand::Draw);
  EXPECT_EQ(g.commands[*g.alphabet.find("@v")], TurtleCommand::RollToVertical);
  EXPECT_EQ(g.commands[*g.alphabet.find("A")], TurtleCommand::None);
}

}  // namespace
}  // namespace lsys
