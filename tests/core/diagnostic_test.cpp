// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/diagnostic.hpp"

#include <gtest/gtest.h>

#include <string>

namespace lsys {
namespace {

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
  const Diagnostic d{.file = "t.ls",
                     .line = 2,
                     .column = 14,
                     .message = "bad",
                     .source_line = "F]\x1B]0;pwned\x07\x1B[2JX"};
  EXPECT_EQ(format_diagnostic(d),
            "t.ls:2:14: error: bad\n"
            "F]<U+001B>]0;pwned<U+0007><U+001B>[2JX\n" +
                std::string(34, ' ') + "^\n");
  // Invalid bytes, bidirectional overrides and the file name too.
  EXPECT_EQ(format_diagnostic(Diagnostic{.file = "a\x1B[2J.ls",
                                         .line = 1,
                                         .column = 3,
                                         .message = "x\x07",
                                         .source_line = "\xFF\u202EF"}),
            "a<U+001B>[2J.ls:1:3: error: x<U+0007>\n"
            "<FF><U+202E>F\n"
            "            ^\n");
}

TEST(Diagnostic, ClipsALongLineToAWindowAroundTheCaret) {
  std::string line(20'000'000, 'F');
  line[10'000'000] = ']';
  const std::string text = format_diagnostic(Diagnostic{.file = "t.ls",
                                                        .line = 1,
                                                        .column = 10'000'001,
                                                        .message = "bad",
                                                        .source_line = line});
  EXPECT_EQ(text, "t.ls:1:10000001: error: bad\n\u2026" + std::string(50, 'F') +
                      "]" + std::string(49, 'F') + "\u2026\n" +
                      std::string(51, ' ') + "^\n");
  // Near the start the window begins at column 1.
  EXPECT_EQ(format_diagnostic(Diagnostic{.file = "t.ls",
                                         .line = 1,
                                         .column = 3,
                                         .message = "bad",
                                         .source_line = line}),
            "t.ls:1:3: error: bad\n" + std::string(100, 'F') + "\u2026\n  ^\n");
}

TEST(Diagnostic, PutsTheCaretPastTheEndOfTheLineWhenTheColumnIsThere) {
  EXPECT_EQ(format_diagnostic(Diagnostic{.file = "t.ls",
                                         .line = 1,
                                         .column = 4,
                                         .message = "expected ')'",
                                         .source_line = "F(1"}),
            "t.ls:1:4: error: expected ')'\nF(1\n   ^\n");
}

}  // namespace
}  // namespace lsys
