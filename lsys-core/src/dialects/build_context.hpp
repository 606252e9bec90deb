// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "dialects/draft.hpp"
#include "dialects/text_scan.hpp"
#include "lsys/expression.hpp"
#include "lsys/grammar.hpp"
#include "lsys/parser.hpp"

namespace lsys::dialects {

/// What the passes that build a grammar from a front end's draft share:
/// the file, the draft, the caller's options and the grammar as it grows
/// (build_grammar runs the passes: symbols.hpp, modules.hpp,
/// productions.hpp, blocks.hpp, settings_reader.hpp).
struct BuildContext {
  BuildContext(const TextScan& file, Draft drafted, const ParseOptions& given)
      : scan(file), draft(std::move(drafted)), options(given) {}

  TextScan scan;
  Draft draft;
  const ParseOptions& options;
  Grammar grammar;
  /// The constants expressions have read, filled while compiling (for the
  /// warning about a --define nothing uses).
  mutable std::set<std::string> used_constants;
  /// cpfg's and L-Py's arrays, whose elements are in grammar.globals.
  std::vector<ArrayVariable> arrays;
  /// cpfg's names that nothing defined, taken as variables of 0, and where.
  std::vector<std::pair<std::string, std::size_t>> undefined;

  /// The value of a constant: numbers and other constants only. A random
  /// number (L-system Explorer's `x = random()`) is drawn while deriving,
  /// never once for the whole file.
  /// @throws ParseError at `r` for anything else.
  [[nodiscard]] double constant(Range r) const;

  /// `scope` with the notation's statements added where it has them: cpfg's
  /// names, arrays and functions, or L-Py's locals, globals and modules.
  /// `locals` receives a rule's local variables (none for a block).
  [[nodiscard]] ExpressionScope statement_scope(
      ExpressionScope scope, std::vector<std::string>* locals);
};

}  // namespace lsys::dialects
