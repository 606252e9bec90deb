// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The published systems of tests/data/dialects/ (where each comes from:
// tests/data/dialects/SOURCES.md), read verbatim in their own notations: each
// derives the segments that corpus.tsv states, counted independently of
// lsolid, or is refused with the stated message (corpus_build_test.cpp
// builds them).
#include "support/corpus.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "lsolid/print_settings.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/interpretation.hpp"
#include "lsys/parser.hpp"
#include "lsys/source.hpp"

namespace {

using lsolid::testing::corpus;
using lsolid::testing::Entry;
using lsolid::testing::kCorpus;
using lsolid::testing::name_of;

TEST(CorpusManifest, HoldsAtLeastFiveSystemsOfEachNotation) {
  for (const char* notation : {"lparser/", "fractint/", "lpy/", "cpfg/"}) {
    const auto entries = corpus();
    EXPECT_GE(std::count_if(entries.begin(), entries.end(),
                            [&](const Entry& e) {
                              return e.file.starts_with(notation) &&
                                     !e.expect.starts_with("error");
                            }),
              5)
        << notation;
  }
}

class Corpus : public ::testing::TestWithParam<Entry> {};

TEST_P(Corpus, DerivesWhatItsSourceDrawsOrIsRefusedByName) {
  const Entry& e = GetParam();
  lsys::ParseOptions options{.extra_settings = lsolid::print_setting_names(),
                             .system = e.system};
  try {
    lsys::Grammar grammar =
        lsys::parse_grammar(lsys::load_source(kCorpus / e.file), options);
    if (!e.n.empty()) grammar.settings.derivation_length = std::stoi(e.n);
    const lsys::Skeleton skeleton = lsys::interpret(grammar);
    std::ostringstream counts;
    counts << "segments " << skeleton.segments.size() << ", polygons "
           << skeleton.polygons.size();
    if (!skeleton.spheres.empty()) {
      counts << ", spheres " << skeleton.spheres.size();
    }
    if (!skeleton.sheets.empty()) {
      std::size_t triangles = 0;
      for (const lsys::Sheet& sheet : skeleton.sheets) {
        triangles += sheet.triangles.size();
      }
      counts << ", surfaces " << skeleton.sheets.size() << " of " << triangles
             << " triangles";
    }
    EXPECT_EQ(counts.str(), e.expect);
  } catch (const lsys::ParseError& error) {
    ASSERT_TRUE(e.expect.starts_with("error: ")) << error.what();
    EXPECT_NE(std::string(error.what()).find(e.expect.substr(7)),
              std::string::npos)
        << error.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Published, Corpus, ::testing::ValuesIn(corpus()),
                         [](const auto& test) { return name_of(test.param); });
}  // namespace
