// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <vector>

#include "commands.hpp"
#include "json.hpp"
#include "lsolid/defaults.hpp"
#include "lsolid/units.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/module_string.hpp"
#include "lsys/parser.hpp"
#include "lsys/source.hpp"
#include "output.hpp"

namespace lsolid::cli {

void add_grammar_options(CLI::App& command, GrammarInput& input, bool with_roll,
                         bool is_file_required) {
  auto* file = command.add_option("FILE", input.file, "the .ls file")
                   ->check(CLI::ExistingFile);
  if (is_file_required) file->required();
  command
      .add_option("-n,--derivation-length", input.derivation_length,
                  fmt::format("derivation steps (0 to {}), overriding the "
                              "file's n",
                              lsys::kMaxDerivationLength))
      ->type_name("N");
  command
      .add_option("--seed", input.seed,
                  "seed of stochastic productions (0 to 2^53), overriding "
                  "the file's")
      ->type_name("N");
  command
      .add_option("--define", input.defines,
                  "NAME=VALUE: set a constant, overriding #define")
      ->allow_extra_args(false);
  command
      .add_option("--dialect", input.dialect,
                  "the file's notation: ls, lparser, fractint, lpy, cpfg, "
                  "lowclouds or lpfg "
                  "(default: detected from the file)")
      ->check(CLI::IsMember(
          {"ls", "lparser", "fractint", "lpy", "cpfg", "lowclouds", "lpfg"}));
  command
      .add_option("--system", input.system,
                  "in a file of several systems (Fractint), the one to read")
      ->type_name("NAME");
  command
      .add_option("--view", input.view_file,
                  "cpfg's view file (default: the .v of the same name, or "
                  "the folder's only .v)")
      ->type_name("FILE.v");
  command
      .add_option("--include-dir", input.include_dirs,
                  "a folder whose files the model may read besides its own "
                  "(#include, a view's function, surface and contour files); "
                  "may be given again")
      ->type_name("DIR")
      ->check(CLI::ExistingDirectory)
      ->allow_extra_args(false);
  const lsys::DerivationOptions defaults;
  command
      .add_option("--max-segments", input.max_segments,
                  "refuse to draw more segments than this (default " +
                      std::to_string(defaults.max_segments) + ")")
      ->type_name("N");
  command
      .add_option("--max-modules", input.max_modules,
                  "refuse to derive longer strings than this (default " +
                      std::to_string(defaults.max_modules) + ")")
      ->type_name("N");
  command
      .add_option("--max-memory", input.max_memory,
                  "refuse to hold a derived string whole (contexts, cuts) in "
                  "more MiB than this (default " +
                      std::to_string(defaults.max_memory_bytes >> 20U) + ")")
      ->type_name("MIB");
  if (with_roll) {
    command
        .add_option("--roll", input.roll,
                    "which way / and \\ roll: lpfg (L-Py, default) or cpfg")
        ->check(CLI::IsMember({"lpfg", "cpfg"}));
  }
}

lsys::Grammar load_grammar(const GrammarInput& input) {
  lsys::Grammar grammar = lsys::parse_grammar(
      lsys::load_source(input.file),
      lsys::ParseOptions{.defines = input.defines,
                         .extra_settings = print_setting_names(),
                         .dialect = input.dialect
                                        ? lsys::dialect_named(*input.dialect)
                                        : std::nullopt,
                         .system = input.system,
                         .view_file = input.view_file,
                         .include_dirs = input.include_dirs});
  for (const std::string& warning : grammar.warnings) {
    std::fprintf(stderr, "warning: %s\n", warning.c_str());
  }
  return grammar;
}

void add_print_options(CLI::App& command, PrintInput& input) {
  command.add_option(
      "--wall", input.wall,
      fmt::format("minimum wall: thinnest branch and leaf thickness "
                  "(default {:g}mm)",
                  kDefaultWallMm));
  auto* height = command.add_option("--height", input.height,
                                    "scale the model to this height");
  auto* size = command.add_option(
      "--size", input.size,
      fmt::format("scale the longest side to this (default {:g}mm)",
                  kDefaultSizeMm));
  auto* scale =
      command.add_option("--scale", input.scale, "millimetres per model unit");
  height->excludes(size)->excludes(scale);
  size->excludes(scale);
  command.add_option("--tolerance", input.tolerance,
                     fmt::format("chord error of tube cross-sections, and how "
                                 "far decimation may move the surface "
                                 "(default {:g}mm)",
                                 kDefaultToleranceMm));
  command.add_option("--base", input.base,
                     "auto: a disc under a model that would stand on a small "
                     "footprint (default); disc; none");
  command.add_option("--colors", input.colors,
                     "the colour of each turtle colour index in .3mf and .obj, "
                     "e.g. '#7B4A2A #7B4A2A #8CC63F' (later indices take the "
                     "last; indices of one colour print as one material)");
  command.add_option("--profile", input.profile,
                     "a planar model lying flat: flat, its outline extruded "
                     "(default); round, round tubes cut flat underneath "
                     "(slower)");
}

PrintSettings print_settings(const lsys::Grammar& grammar,
                             const PrintInput& input) {
  PrintOverrides given;
  if (input.wall) given.wall_mm = parse_length_mm(*input.wall, "--wall");
  if (input.height)
    given.height_mm = parse_length_mm(*input.height, "--height");
  if (input.size) given.size_mm = parse_length_mm(*input.size, "--size");
  if (input.scale) {
    given.scale_mm_per_unit = parse_length_mm(*input.scale, "--scale");
  }
  if (input.tolerance) {
    given.tolerance_mm = parse_length_mm(*input.tolerance, "--tolerance");
  }
  if (input.base) given.base = parse_base(*input.base, "--base");
  if (input.colors) given.colors = parse_colors(*input.colors, "--colors");
  if (input.profile) given.profile = parse_profile(*input.profile, "--profile");
  return resolve_print_settings(grammar, given);
}

std::uint64_t parse_whole_number(const std::string& text,
                                 const std::string& option, std::uint64_t least,
                                 std::uint64_t most) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  // from_chars takes no sign, space or exponent; it reports overflow.
  if (text.empty() || error != std::errc() || stop != end || value < least ||
      value > most) {
    throw lsys::ParseError(lsys::Diagnostic{
        .file = option,
        .line = 1,
        .column = 1,
        .message = "expected a whole number from " + std::to_string(least) +
                   " to " + std::to_string(most) + ", not '" + text + "'",
        .source_line = text});
  }
  return value;
}

lsys::DerivationOptions derivation_options(const GrammarInput& input) {
  lsys::DerivationOptions options;
  if (input.derivation_length) {
    options.derivation_length = static_cast<int>(
        parse_whole_number(*input.derivation_length, "--derivation-length", 0,
                           lsys::kMaxDerivationLength));
  }
  if (input.seed) {
    options.seed =
        parse_whole_number(*input.seed, "--seed", 0, lsys::kMaxWholeNumber);
  }
  if (input.max_segments) {
    options.max_segments = parse_whole_number(
        *input.max_segments, "--max-segments", 1, lsys::kMaxWholeNumber);
  }
  if (input.max_modules) {
    options.max_modules = parse_whole_number(
        *input.max_modules, "--max-modules", 1, lsys::kMaxWholeNumber);
  }
  if (input.max_memory) {
    options.max_memory_bytes =
        parse_whole_number(*input.max_memory, "--max-memory", 1,
                           std::uint64_t{1} << 30U)
        << 20U;
  }
  return options;
}

lsys::InterpretOptions interpret_options(const GrammarInput& input) {
  lsys::InterpretOptions options;
  if (input.roll) {
    options.roll = *input.roll == "cpfg" ? lsys::RollConvention::Cpfg
                                         : lsys::RollConvention::Lpfg;
  }
  return options;
}

void run_derive(const DeriveCommand& command) {
  const lsys::Grammar grammar = load_grammar(command.input);
  lsys::Derivation derivation(grammar, derivation_options(command.input));
  Output out(stdout);
  lsys::ModuleString chunk;
  if (!command.stats) {
    bool has_previous = false;
    lsys::SymbolId previous = 0;
    while (derivation.next(chunk)) {
      for (std::size_t i = 0; i < chunk.size(); ++i) {
        lsys::append_module_separated(out.text(), grammar.alphabet, chunk, i,
                                      has_previous ? &previous : nullptr);
        previous = chunk.symbol(i);
        has_previous = true;
      }
      out.flush_if_large();
    }
    out.text() += '\n';
    out.flush();
    return;
  }
  std::vector<std::uint64_t> counts(grammar.alphabet.size(), 0);
  std::uint64_t length = 0;
  long long depth = 0;
  long long max_depth = 0;
  while (derivation.next(chunk)) {
    length += chunk.size();
    for (std::size_t i = 0; i < chunk.size(); ++i) {
      const lsys::SymbolId symbol = chunk.symbol(i);
      ++counts[symbol];
      if (symbol == lsys::kBranchOpen) max_depth = std::max(max_depth, ++depth);
      if (symbol == lsys::kBranchClose) --depth;
    }
  }
  std::vector<std::pair<std::string, std::uint64_t>> named;
  for (lsys::SymbolId s = 0; s < counts.size(); ++s) {
    if (counts[s] > 0) named.emplace_back(grammar.alphabet.name(s), counts[s]);
  }
  std::sort(named.begin(), named.end());
  Json modules = Json::object();
  for (const auto& [name, count] : named) modules[name] = count;
  out.text() += json_line(Json{{"length", length},
                               {"modules", std::move(modules)},
                               {"max_depth", max_depth}});
  out.flush();
}

}  // namespace lsolid::cli
