// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/module_string.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace lsys {
namespace {

TEST(ModuleString, PrintsParametersInShortestRoundTripForm) {
  Alphabet a;
  ModuleString s;
  const std::vector<double> params{1.5, 10.0, 0.1, -0.0, 1e30, 1.0 / 3.0};
  s.push_back(a.intern("A"), params, 0);
  s.push_back(a.intern("F"), {}, 1);
  EXPECT_EQ(to_string(s, a), "A(1.5,10,0.1,0,1e+30,0.3333333333333333)F");
  EXPECT_EQ(s.generation(1), 1U);
}

TEST(ModuleString, SeparatesMultiCharacterNamesWithSpaces) {
  Alphabet a;
  ModuleString s;
  for (const char* name : {"F", "seg", "[", "leaf", "]", "+", "+"}) {
    s.push_back(a.intern(name), {}, 0);
  }
  EXPECT_EQ(to_string(s, a), "F seg [ leaf ]++");
}

TEST(ModuleString, SeparatesModulesThatWouldReadAsALongerName) {
  Alphabet a;
  a.intern("ab");
  ModuleString s;
  s.push_back(a.intern("a"), {}, 0);
  s.push_back(a.intern("b"), {}, 0);
  s.push_back(a.intern("c"), {}, 0);
  EXPECT_EQ(to_string(s, a), "a bc");
}

TEST(ModuleString, KeepsParametersPerModule) {
  Alphabet a;
  ModuleString s;
  const std::vector<double> one{1.0};
  const std::vector<double> two{2.0, 3.0};
  s.push_back(a.intern("A"), one, 0);
  s.push_back(a.intern("B"), {}, 0);
  s.push_back(a.intern("C"), two, 0);
  ASSERT_EQ(s.size(), 3U);
  EXPECT_EQ(s.parameters(0).size(), 1U);
  EXPECT_TRUE(s.parameters(1).empty());
  EXPECT_EQ(s.parameters(2)[1], 3.0);
  s.clear();
  EXPECT_TRUE(s.empty());
}

}  // namespace
}  // namespace lsys
