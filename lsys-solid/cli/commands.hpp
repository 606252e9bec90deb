// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <CLI/App.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lsys/derivation.hpp"
#include "lsys/grammar.hpp"
#include "lsys/interpretation.hpp"

namespace lsolid::cli {

/// What every command that reads a `.ls` file takes.
struct GrammarInput {
  std::string file;
  std::optional<int> derivation_length;
  std::optional<std::uint64_t> seed;
  std::vector<std::string> defines;
  std::uint64_t max_segments = lsys::DerivationOptions{}.max_segments;
  std::uint64_t max_modules = lsys::DerivationOptions{}.max_modules;
  std::optional<std::string> roll;
};

/// Registers FILE, -n, --seed, --define, --max-segments, --max-modules and
/// (with `with_roll`) --roll on a command.
void add_grammar_options(CLI::App& command, GrammarInput& input,
                         bool with_roll);

/// Reads the file with the command line's defines.
/// @throws lsys::ParseError.
[[nodiscard]] lsys::Grammar load_grammar(const GrammarInput& input);
[[nodiscard]] lsys::DerivationOptions derivation_options(
    const GrammarInput& input);
[[nodiscard]] lsys::InterpretOptions interpret_options(
    const GrammarInput& input);

/// `lsolid derive`: prints the derived string, or its statistics as JSON.
struct DeriveCommand {
  GrammarInput input;
  bool stats = false;
};
/// @throws lsys::ParseError, lsolid::IoError.
void run_derive(const DeriveCommand& command);

/// `lsolid skeleton`: prints the turtle's segments and polygons.
struct SkeletonCommand {
  GrammarInput input;
  bool json = false;
};
/// @throws lsys::ParseError, lsolid::IoError.
void run_skeleton(const SkeletonCommand& command);

}  // namespace lsolid::cli
