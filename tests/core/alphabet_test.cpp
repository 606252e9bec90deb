// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/alphabet.hpp"

#include <gtest/gtest.h>

#include <string>
#include <string_view>

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

TEST(Alphabet, TellsWhenTextStartsALongerName) {
  Alphabet a;
  a.intern("internode");
  EXPECT_TRUE(a.extends_to_longer_name("in"));
  EXPECT_TRUE(a.extends_to_longer_name("internode"));
  EXPECT_FALSE(a.extends_to_longer_name("inf"));
  EXPECT_FALSE(Alphabet().extends_to_longer_name("i"));
}

TEST(Alphabet, ExaminesEachByteOnceWhateverTheNumberOfNames) {
  // 16,000 names took 13 s to parse when each match tried every name.
  Alphabet a;
  std::string text;
  for (int i = 0; i < 16'000; ++i) {
    const std::string name = std::string("mod").append(std::to_string(i));
    a.intern(name);
    text.append(name).append("F");
  }
  std::size_t modules = 0;
  for (std::size_t i = 0; i < text.size(); ++modules) {
    i += a.match_length(std::string_view(text).substr(i));
  }
  EXPECT_EQ(modules, 32'000U);
  // A match may look one byte past the name (`F`) to see it ends there.
  EXPECT_LE(a.bytes_examined(), text.size() + modules);
}

}  // namespace
}  // namespace lsys
