// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/source.hpp"

#include <gtest/gtest.h>

#include "lsys/diagnostic.hpp"

namespace lsys {
namespace {

TEST(SourceFile, CountsColumnsInCodePointsNotBytes) {
  const SourceFile source("x.ls", "n=2\n\u03B4=90\u00B0, n=3\n");
  // `n` of the second line is its byte 9 but column 8.
  const std::size_t offset = source.text().find("n=3");
  EXPECT_EQ(source.location(offset).line, 2);
  EXPECT_EQ(source.location(offset).column, 8);
  EXPECT_EQ(source.location(0).column, 1);
}

TEST(SourceFile, GivesLinesWithoutTheirBreaks) {
  const SourceFile source("x.ls", "first\r\nsecond\nthird");
  EXPECT_EQ(source.line_count(), 3);
  EXPECT_EQ(source.line_text(1), "first");
  EXPECT_EQ(source.line_text(2), "second");
  EXPECT_EQ(source.line_text(3), "third");
}

TEST(SourceFile, ReportsAMissingFileWithItsName) {
  try {
    (void)load_source("/nonexistent/tree.ls");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.diagnostic().file, "/nonexistent/tree.ls");
    EXPECT_EQ(e.diagnostic().line, 0);
    EXPECT_EQ(e.diagnostic().message,
              "cannot read file: No such file or directory");
  }
}

}  // namespace
}  // namespace lsys
