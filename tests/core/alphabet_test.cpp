// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/alphabet.hpp"

#include <gtest/gtest.h>

namespace lsys {
namespace {

TEST(Alphabet, GivesEachNameOneDenseId) {
  Alphabet a;
  EXPECT_EQ(a.intern("F"), 0U);
  EXPECT_EQ(a.intern("plant"), 1U);
  EXPECT_EQ(a.intern("F"), 0U);
  EXPECT_EQ(a.size(), 2U);
  EXPECT_EQ(a.name(1), "plant");
  EXPECT_FALSE(a.find("G").has_value());
}

TEST(Alphabet, MatchesTheLongestDeclaredName) {
  Alphabet a;
  a.intern("seg");
  a.intern("se");
  EXPECT_EQ(a.match_length("segF"), 3U);
  EXPECT_EQ(a.match_length("sF"), 1U);
  EXPECT_EQ(a.match_length("\u2227F"), 3U);  // one code point, three bytes
}

TEST(Alphabet, TellsMultiCharacterNames) {
  Alphabet a;
  const SymbolId wedge = a.intern("wedge");
  const SymbolId pitch = a.intern("\u2227");
  EXPECT_TRUE(a.is_multi_character(wedge));
  EXPECT_FALSE(a.is_multi_character(pitch));
}

}  // namespace
}  // namespace lsys
