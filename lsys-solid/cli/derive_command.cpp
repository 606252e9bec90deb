// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include <algorithm>
#include <cstdio>
#include <vector>

#include "commands.hpp"
#include "json.hpp"
#include "lsolid/units.hpp"
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
                  "derivation steps, overriding the file's n")
      ->check(CLI::Range(0, 10000));
  command
      .add_option("--seed", input.seed,
                  "seed of stochastic productions, overriding the file's")
      ->check(CLI::Range(0.0, 9007199254740992.0));
  command
      .add_option("--define", input.defines,
                  "NAME=VALUE: set a constant, overriding #define")
      ->allow_extra_args(false);
  command
      .add_option("--max-segments", input.max_segments,
                  "refuse to draw more segments than this")
      ->capture_default_str();
  command
      .add_option("--max-modules", input.max_modules,
                  "refuse to derive longer strings than this")
      ->capture_default_str();
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
                         .extra_settings = print_setting_names()});
  for (const std::string& warning : grammar.warnings) {
    std::fprintf(stderr, "warning: %s\n", warning.c_str());
  }
  return grammar;
}

void add_print_options(CLI::App& command, PrintInput& input) {
  command.add_option("--wall", input.wall,
                     "minimum wall: thinnest branch and leaf thickness "
                     "(default 0.8mm)");
  auto* height = command.add_option("--height", input.height,
                                    "scale the model to this height");
  auto* size = command.add_option(
      "--size", input.size, "scale the longest side to this (default 100mm)");
  auto* scale =
      command.add_option("--scale", input.scale, "millimetres per model unit");
  height->excludes(size)->excludes(scale);
  size->excludes(scale);
  command.add_option("--tolerance", input.tolerance,
                     "chord error of tube cross-sections, and how far "
                     "decimation may move the surface (default 0.05mm)");
  command.add_option("--base", input.base,
                     "auto: a disc under a model that would stand on a small "
                     "footprint (default); disc; none");
  command.add_option("--colors", input.colors,
                     "the colour of each turtle colour index in .3mf and .obj, "
                     "e.g. '#7B4A2A #7B4A2A #8CC63F' (later indices take the "
                     "last; indices of one colour print as one material)");
}

PrintSettings print_settings(const lsys::Grammar& grammar,
                             const PrintInput& input) {
  PrintSettings given;
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
  return resolve_print_settings(
      grammar, given, input.height || input.size || input.scale,
      input.wall.has_value(), input.tolerance.has_value(),
      input.base.has_value(), input.colors.has_value());
}

lsys::DerivationOptions derivation_options(const GrammarInput& input) {
  return {.derivation_length = input.derivation_length,
          .seed = input.seed,
          .max_segments = input.max_segments,
          .max_modules = input.max_modules};
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
  std::string& text = out.text();
  text += "{\"length\": " + std::to_string(length) + ", \"modules\": {";
  for (std::size_t i = 0; i < named.size(); ++i) {
    if (i > 0) text += ", ";
    append_json_string(text, named[i].first);
    text += ": " + std::to_string(named[i].second);
  }
  text += "}, \"max_depth\": " + std::to_string(max_depth) + "}\n";
  out.flush();
}

}  // namespace lsolid::cli
