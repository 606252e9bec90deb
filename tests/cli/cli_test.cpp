// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "support/run_command.hpp"

namespace lsolid {
namespace {

using testing::lsolid;
using testing::read_text;
using testing::run_command;

const std::filesystem::path kSource = LSOLID_SOURCE_DIR;
const std::filesystem::path kDiagnostics = kSource / "tests/data/diagnostics";

TEST(Cli, DerivePrintsTheString) {
  const auto r = run_command(lsolid() + " derive hilbert-cube.ls -n 1",
                             kSource / "printables");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "B-F+CFC+F-D&F^D-F+&&CFC+F+B//\n");
}

TEST(Cli, DerivePrintsParametersInShortestForm) {
  const auto r = run_command(lsolid() + " derive honda-2.1a.ls -n 1",
                             kSource / "printables");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out,
            "!(10)F(1)[&(45)B(0.6,7.069999999999999)]/(137.5)"
            "A(0.9,7.069999999999999)\n");
}

TEST(Cli, DeriveStatsPrintsLengthCountsAndDepth) {
  const auto r = run_command(lsolid() + " derive abop-1.25-bush.ls --stats",
                             kSource / "printables");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out,
            "{\"length\": 77399, \"modules\": {\"!\": 3279, \"&\": 3279, "
            "\"'\": 6038, \"+\": 5136, \"-\": 3852, \"/\": 22596, \"A\": 2187, "
            "\"F\": 3891, \"L\": 2607, \"S\": 1284, \"[\": 4563, \"]\": 4563, "
            "\"^\": 2568, \"f\": 7704, \"{\": 1284, \"|\": 1284, \"}\": 1284}, "
            "\"max_depth\": 7}\n");
}

TEST(Cli, DefinesAndSeedsComeFromTheCommandLine) {
  const auto r = run_command(lsolid() +
                                 " derive honda-2.1a.ls -n 1 --define wr=0.5 "
                                 "--define r2=0.5",
                             kSource / "printables");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "!(10)F(1)[&(45)B(0.5,5)]/(137.5)A(0.9,5)\n");
}

TEST(Cli, SkeletonJsonHasPointsRadiiAndColours) {
  const auto r = run_command(lsolid() + " skeleton hilbert-cube.ls -n 1 --json",
                             kSource / "printables");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::string head =
      "{\"units\": \"model\", \"segments\": [\n"
      "{\"p0\": [0,0,0], \"p1\": [1,0,0], \"r0\": 0.15, \"r1\": 0.15, "
      "\"color\": 0},\n";
  EXPECT_EQ(r.out.substr(0, head.size()), head);
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 9);
  EXPECT_NE(r.out.find("\"polygons\": []}"), std::string::npos);
  EXPECT_EQ(r.out.find("NaN"), std::string::npos);
}

TEST(Cli, SkeletonSummarisesWithoutJson) {
  const auto r = run_command(lsolid() + " skeleton hilbert-cube.ls",
                             kSource / "printables");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out,
            "segments: 63\npolygons: 0\nbounds: [0, 0, 0] to [3, 3, 3] model "
            "units\n");
}

TEST(Cli, HelpShowsExamplesAndVersionShowsTheVersion) {
  const auto help = run_command(lsolid() + " --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("Examples:"), std::string::npos);
  EXPECT_NE(help.out.find("lsolid derive"), std::string::npos);
  const auto version = run_command(lsolid() + " --version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_EQ(version.out, "lsolid 0.1.0\n");
}

TEST(Cli, BadUsageExitsWithTwo) {
  EXPECT_EQ(run_command(lsolid() + " derive").exit_code, 2);
  EXPECT_EQ(run_command(lsolid() + " derive nonexistent.ls").exit_code, 2);
  EXPECT_EQ(run_command(lsolid() + " frobnicate").exit_code, 2);
  const auto r = run_command(lsolid() + " derive hilbert-cube.ls -n -3",
                             kSource / "printables");
  EXPECT_EQ(r.exit_code, 2);
}

TEST(Cli, ReportsABadDefineWithACaret) {
  const auto r =
      run_command(lsolid() + " derive honda-2.1a.ls --define r2=0.5.5",
                  kSource / "printables");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "--define:1:4: error: bad number '0.5.5'\nr2=0.5.5\n   ^\n");
}

// Every file in tests/data/diagnostics has the exact stderr beside it.
class Diagnostics : public ::testing::TestWithParam<std::string> {};

TEST_P(Diagnostics, PrintsFileLineColumnMessageAndCaret) {
  const std::string name = GetParam();
  const auto r =
      run_command(lsolid() + " skeleton " + name + ".ls", kDiagnostics);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, read_text(kDiagnostics / (name + ".stderr")));
}

INSTANTIATE_TEST_SUITE_P(
    Golden, Diagnostics,
    ::testing::Values("bad-number", "division-by-zero", "duplicate-definition",
                      "missing-arrow", "too-many-segments",
                      "unbalanced-bracket", "undefined-name", "unknown-setting",
                      "unterminated-comment", "wrong-parameter-count",
                      "wrong-turtle-parameters"),
    [](const auto& test) {
      std::string name = test.param;
      for (char& c : name) {
        if (c == '-') c = '_';
      }
      return name;
    });

TEST(Diagnostics, EveryGoldenFileIsTested) {
  std::size_t count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kDiagnostics)) {
    if (entry.path().extension() == ".ls") ++count;
  }
  EXPECT_EQ(count, 11U);
}

}  // namespace
}  // namespace lsolid
