// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Each published system of tests/data/dialects/ that lsolid reads is built
// into a mesh that `lsolid` calls printable and `lsolid check` accepts, at
// the small n corpus.tsv gives for CI.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/corpus.hpp"
#include "support/run_command.hpp"

namespace {

using lsolid::testing::buildable;
using lsolid::testing::Entry;
using lsolid::testing::kCorpus;
using lsolid::testing::name_of;

class CorpusBuild : public ::testing::TestWithParam<Entry> {};

TEST_P(CorpusBuild, BuildsAPrintableMesh) {
  const Entry& e = GetParam();
  const auto stl = std::filesystem::temp_directory_path() /
                   ("lsolid_corpus_" + std::to_string(::getpid()) + "_" +
                    name_of(e) + ".stl");
  std::string command = lsolid::testing::lsolid() + " '" +
                        (kCorpus / e.file).string() + "' -o '" + stl.string() +
                        "'";
  if (!e.system.empty()) command += " --system '" + e.system + "'";
  // `8`, `-`, or either and options: `- --profile round`.
  const std::size_t space = e.build.find(' ');
  const std::string n = e.build.substr(0, space);
  if (!n.empty() && n != "-") command += " -n " + n;
  if (space != std::string::npos) command += e.build.substr(space);
  const auto built = lsolid::testing::run_command(command);
  ASSERT_EQ(built.exit_code, 0) << built.out << built.err;
  EXPECT_NE(built.out.find("check: printable"), std::string::npos) << built.out;
  const auto checked = lsolid::testing::run_command(
      lsolid::testing::lsolid() + " check '" + stl.string() + "'");
  EXPECT_EQ(checked.exit_code, 0) << checked.out;
  std::filesystem::remove(stl);
}

INSTANTIATE_TEST_SUITE_P(Published, CorpusBuild,
                         ::testing::ValuesIn(buildable()),
                         [](const auto& test) { return name_of(test.param); });

}  // namespace
