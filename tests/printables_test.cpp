// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The gallery as a test: every printables/*.ls file parses, derives and is
// walked by the turtle, giving the counts its `// expect:` line states.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "lsys/interpretation.hpp"
#include "lsys/parser.hpp"
#include "lsys/source.hpp"

namespace {

const std::filesystem::path kPrintables =
    std::filesystem::path(LSOLID_SOURCE_DIR) / "printables";

std::vector<std::string> printable_names() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(kPrintables)) {
    if (entry.path().extension() == ".ls") {
      names.push_back(entry.path().stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

struct Expectation {
  std::size_t segments = 0;
  std::size_t polygons = 0;
};

Expectation expectation(const std::string& text) {
  std::smatch match;
  static const std::regex kLine(R"(// expect: segments (\d+), polygons (\d+))");
  if (!std::regex_search(text, match, kLine)) {
    ADD_FAILURE() << "no '// expect: segments N, polygons M' line";
    return {};
  }
  return {std::stoul(match[1]), std::stoul(match[2])};
}

class Printable : public ::testing::TestWithParam<std::string> {};

TEST_P(Printable, DerivesTheStatedSkeleton) {
  const auto source = lsys::load_source(kPrintables / (GetParam() + ".ls"));
  ASSERT_TRUE(source->text().starts_with("//"))
      << "each printable starts with a comment naming its source";
  const Expectation expected = expectation(source->text());
  const lsys::Grammar grammar = lsys::parse_grammar(source);
  const lsys::Skeleton skeleton = lsys::interpret(grammar);
  EXPECT_EQ(skeleton.segments.size(), expected.segments);
  EXPECT_EQ(skeleton.polygons.size(), expected.polygons);
  EXPECT_EQ(skeleton.degenerate_polygons, 0U);
  for (const lsys::Segment& s : skeleton.segments) {
    ASSERT_TRUE(std::isfinite(s.p1.x) && std::isfinite(s.p1.y) &&
                std::isfinite(s.p1.z));
    ASSERT_GE(s.start_diameter, 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(Gallery, Printable,
                         ::testing::ValuesIn(printable_names()),
                         [](const auto& test) {
                           std::string name = test.param;
                           std::replace_if(
                               name.begin(), name.end(),
                               [](char c) {
                                 return std::isalnum(
                                            static_cast<unsigned char>(c)) == 0;
                               },
                               '_');
                           return name;
                         });

}  // namespace
