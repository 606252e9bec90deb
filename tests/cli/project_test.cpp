// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The README's promises about the project itself.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/run_command.hpp"

namespace lsolid {
namespace {

const std::filesystem::path kSource = LSOLID_SOURCE_DIR;

// The lines of the README's shell blocks.
std::vector<std::string> readme_commands() {
  const std::string readme = testing::read_text(kSource / "README.md");
  std::vector<std::string> commands;
  std::size_t pos = 0;
  while ((pos = readme.find("```sh\n", pos)) != std::string::npos) {
    pos += 6;
    const std::size_t end = readme.find("\n```", pos);
    commands.push_back(readme.substr(pos, end - pos));
    pos = end;
  }
  return commands;
}

TEST(Project, ReadmeQuickStartIsTwoCommands) {
  const auto commands = readme_commands();
  ASSERT_EQ(commands.size(), 2U);
  for (const std::string& c : commands) {
    EXPECT_EQ(c.find('\n'), std::string::npos) << c;
    EXPECT_TRUE(c.starts_with("scripts/install-deps && ")) << c;
  }
  EXPECT_NE(commands[0].find("build/lsolid"), std::string::npos);
  EXPECT_NE(commands[0].find("printables/"), std::string::npos);
  EXPECT_NE(commands[1].find("ctest"), std::string::npos);
}

TEST(Project, CiRunsTheReadmesTestCommand) {
  const auto commands = readme_commands();
  ASSERT_EQ(commands.size(), 2U);
  const std::string ci = testing::read_text(kSource / ".ci/run");
  EXPECT_NE(ci.find("\n" + commands[1] + "\n"), std::string::npos);
}

}  // namespace
}  // namespace lsolid
