// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/dialect.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/core_helpers.hpp"

namespace lsys {
namespace {

TEST(Dialect, TellsEachNotationFromItsFirstLines) {
  EXPECT_EQ(detect_dialect("# Lparser\n12   # recursion\n20\n30\nF\n@\n"),
            Dialect::Lparser);
  EXPECT_EQ(detect_dialect("; comment\nKoch1 { ; A. Mariano\n angle 6\n}\n"),
            Dialect::Fractint);
  EXPECT_EQ(detect_dialect("{ a nameless block is a comment\n}\nKoch {\n}\n"),
            Dialect::Fractint);
  EXPECT_EQ(detect_dialect("a = 1\nAxiom: F\nproduction:\nF --> FF\n"),
            Dialect::Lpy);
  EXPECT_EQ(detect_dialect("n=2\n\u03B4=90\nF\nF \u2192 F+F\n"), Dialect::Ls);
  // A `.ls` polygon axiom is not a Fractint system, nor a lone number an
  // Lparser header.
  EXPECT_EQ(detect_dialect("{.-f+f.}\nn=1\n"), Dialect::Ls);
  EXPECT_EQ(detect_dialect("2\nF\nF -> FF\n"), Dialect::Ls);
  EXPECT_EQ(detect_dialect("A \u2192 {F}\nA\n"), Dialect::Ls);
}

TEST(Dialect, TrustsTheFileNameWhereTheTextCouldBeEither) {
  // lsolid's notation reads L-Py-shaped files: named .ls, they stay its own.
  const char* lpy_shaped =
      "n=2\nangle=90\nAxiom: F-F-F-F\nproduction:\nF --> F+F-F-FF+F+F-F\n";
  EXPECT_EQ(detect_dialect(lpy_shaped, "island.ls"), Dialect::Ls);
  EXPECT_EQ(detect_dialect(lpy_shaped, "island.lpy"), Dialect::Lpy);
  EXPECT_EQ(detect_dialect("Axiom: F\ninterpretation:\n", "a.lpy"),
            Dialect::Lpy);
  // A polygon axiom is not a Fractint system, least of all in a .ls file.
  EXPECT_EQ(detect_dialect("L{.F.F.}\nn=1\n", "leaf.ls"), Dialect::Ls);
  EXPECT_EQ(detect_dialect("Koch {\n angle 6\n}\n", "k.ls"), Dialect::Ls);
  // Lparser reads its numbers with sscanf: words may follow them.
  EXPECT_EQ(detect_dialect("2   recursion\n22  angle\n10\nF\n@\n", "t.ls"),
            Dialect::Lparser);
  // A comment block on one line, then the system.
  EXPECT_EQ(detect_dialect("comment { one line }\nKoch {\n angle 6\n}\n"),
            Dialect::Fractint);
}

TEST(Dialect, TellsTheNotationOfEveryPrintable) {
  // printables/ names files of other notations by their notation.
  const auto dir = testing::source_dir() / "printables";
  int own = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() == ".v") continue;  // a cpfg view file
    Dialect expected = Dialect::Ls;
    if (name.starts_with("lparser-")) expected = Dialect::Lparser;
    if (name.starts_with("fractint-")) expected = Dialect::Fractint;
    if (name.starts_with("lpy-")) expected = Dialect::Lpy;
    if (name.starts_with("cpfg-")) expected = Dialect::Cpfg;
    if (expected == Dialect::Ls && entry.path().extension() != ".ls") continue;
    own += expected == Dialect::Ls ? 1 : 0;
    std::ifstream in(entry.path(), std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    EXPECT_EQ(detect_dialect(text.str()), expected) << name;
  }
  EXPECT_GT(own, 30);
}

TEST(Dialect, NamesEachNotationAsDashDashDialectTakesIt) {
  for (Dialect d :
       {Dialect::Ls, Dialect::Lparser, Dialect::Fractint, Dialect::Lpy,
        Dialect::Cpfg, Dialect::Lowclouds, Dialect::Lpfg}) {
    EXPECT_EQ(dialect_named(dialect_name(d)), d);
  }
  EXPECT_EQ(dialect_name(Dialect::Lparser), "lparser");
  EXPECT_EQ(dialect_name(Dialect::Cpfg), "cpfg");
  EXPECT_FALSE(dialect_named("lindenmayer.js"));
}

TEST(Dialect, IsForcedByTheParseOptions) {
  // Two numbers and a rule: Lparser by default; as `.ls`, an axiom line
  // `2` and a setting would be refused, so force a reading that works.
  const char* text = "1\n90\n10\nF\nF=F+F\n@\n";
  EXPECT_EQ(testing::located_error_of([&] {
              (void)parse_grammar_text(text, {.dialect = Dialect::Ls});
            }).substr(0, 4),
            "2:1:");
  const Grammar g = parse_grammar_text(text);
  EXPECT_EQ(g.settings.angle_deg, 90.0);
}

}  // namespace
}  // namespace lsys
