// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/diagnostic.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>

namespace lsys {
namespace {

// The text of an error at a column of line 1.
std::string formatted(int column, std::string line, std::string message = "bad",
                      std::string file = "t.ls") {
  return format_diagnostic(Diagnostic{.file = std::move(file),
                                      .line = 1,
                                      .column = column,
                                      .message = std::move(message),
                                      .source_line = std::move(line)});
}

TEST(Diagnostic, PrintsFileLineColumnThenTheLineAndACaret) {
  const SourceFile source("tree.ls", "n=2\nA \u2192 B(1,\n");
  const ParseError e = error_at(source, source.text().find("B("), "oops");
  EXPECT_STREQ(e.what(), "tree.ls:2:5: error: oops");
  EXPECT_EQ(format_diagnostic(e.diagnostic()),
            "tree.ls:2:5: error: oops\n"
            "A \u2192 B(1,\n"
            "    ^\n");
}

TEST(Diagnostic, KeepsTabsSoTheCaretLinesUp) {
  const SourceFile source("t.ls", "\tA -> ?\n");
  const ParseError e = error_at(source, 6, "bad");
  EXPECT_EQ(format_diagnostic(e.diagnostic()),
            "t.ls:1:7: error: bad\n\tA -> ?\n\t     ^\n");
}

TEST(Diagnostic, OmitsLineAndCaretForWholeFileErrors) {
  EXPECT_EQ(
      format_diagnostic(Diagnostic{.file = "a.ls", .message = "no axiom"}),
      "a.ls: error: no axiom\n");
}

TEST(Diagnostic, EscapesControlCharactersAndKeepsTheCaretUnderTheColumn) {
  // A terminal would retitle its window and clear the screen.
  EXPECT_EQ(formatted(14, "F]\x1B]0;pwned\x07\x1B[2JX"),
            "t.ls:1:14: error: bad\n"
            "F]<U+001B>]0;pwned<U+0007><U+001B>[2JX\n" +
                std::string(34, ' ') + "^\n");
  // Invalid bytes, bidirectional overrides and the file name too.
  EXPECT_EQ(formatted(3, "\xFF\u202EF", "x\x07", "a\x1B[2J.ls"),
            "a<U+001B>[2J.ls:1:3: error: x<U+0007>\n"
            "<FF><U+202E>F\n"
            "            ^\n");
}

TEST(Diagnostic, EscapesEveryByteOfAnOverlongSequence) {
  // C0 AF would decode as '/', and was printed raw.
  EXPECT_EQ(formatted(3, "F\xC0\xAF]"),
            "t.ls:1:3: error: bad\nF<C0><AF>]\n         ^\n");
}

TEST(Diagnostic, ClipsALongLineToAWindowAroundTheCaret) {
  std::string line(20'000'000, 'F');
  line[10'000'000] = ']';
  const std::string text = formatted(10'000'001, line);
  EXPECT_EQ(text, "t.ls:1:10000001: error: bad\n\u2026" + std::string(50, 'F') +
                      "]" + std::string(49, 'F') + "\u2026\n" +
                      std::string(51, ' ') + "^\n");
  // Near the start the window begins at column 1.
  EXPECT_EQ(formatted(3, line),
            "t.ls:1:3: error: bad\n" + std::string(100, 'F') + "\u2026\n  ^\n");
}

TEST(Diagnostic, PutsTheCaretPastTheEndOfTheLineWhenTheColumnIsThere) {
  EXPECT_EQ(formatted(4, "F(1", "expected ')'"),
            "t.ls:1:4: error: expected ')'\nF(1\n   ^\n");
}

}  // namespace
}  // namespace lsys
