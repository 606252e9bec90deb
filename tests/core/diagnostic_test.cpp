// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/diagnostic.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace lsys
