// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/turtle_command.hpp"

#include <gtest/gtest.h>

namespace lsys {
namespace {

TEST(TurtleCommand, KnowsAbopAndCpfgSpellings) {
  EXPECT_EQ(builtin_command("F"), TurtleCommand::Draw);
  EXPECT_EQ(builtin_command("f"), TurtleCommand::Move);
  EXPECT_EQ(builtin_command("^"), TurtleCommand::PitchUp);
  EXPECT_EQ(builtin_command("\u2227"), TurtleCommand::PitchUp);
  EXPECT_EQ(builtin_command("'"), TurtleCommand::ColorNext);
  EXPECT_EQ(builtin_command(";"), TurtleCommand::ColorNext);
  EXPECT_EQ(builtin_command("$"), TurtleCommand::RollToVertical);
  EXPECT_EQ(builtin_command("@v"), TurtleCommand::RollToVertical);
  EXPECT_FALSE(builtin_command("A").has_value());
  EXPECT_FALSE(builtin_command("FF").has_value());
}

TEST(TurtleCommand, LimitsParameterCounts) {
  EXPECT_EQ(max_parameters(TurtleCommand::Draw), 2);
  EXPECT_EQ(max_parameters(TurtleCommand::TurnLeft), 1);
  EXPECT_EQ(max_parameters(TurtleCommand::TurnAround), 0);
  EXPECT_EQ(min_parameters(TurtleCommand::SetTropism), 3);
  EXPECT_EQ(max_parameters(TurtleCommand::SetTropism), 3);
  EXPECT_EQ(min_parameters(TurtleCommand::Draw), 0);
}

}  // namespace
}  // namespace lsys
