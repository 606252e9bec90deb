// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dialects/build_context.hpp"
#include "dialects/symbols.hpp"
#include "lsys/module_string.hpp"

namespace lsys::dialects {

/// A module as written: its symbol, where it stands, and the text of its
/// arguments.
struct RawModule {
  SymbolId symbol;
  std::size_t offset;
  std::vector<Range> arguments;
  std::optional<double> inline_value;  ///< Fractint's `\30`
};

/// The values an L-Py predecessor's parameters must have (`A(0)`), by the
/// slot of each.
using PatternValues = std::vector<std::pair<std::uint32_t, double>>;

/// Reads strings of modules: tokenised by longest match among the names
/// the file uses (ABOP fig. 1.26's `plant`, `internode`), their parameters
/// compiled, their arities and brackets checked.
class ModuleReader : protected TextScan {
 public:
  ModuleReader(BuildContext& context, SymbolTable& symbols)
      : TextScan(context.scan),
        context_(context),
        draft_(context.draft),
        grammar_(context.grammar),
        symbols_(symbols) {}

  /// The modules of `r`.
  [[nodiscard]] std::vector<RawModule> tokenize(Range r);
  /// A successor or an axiom: the modules of the ranges with their
  /// parameters compiled in `scope`, brackets balanced.
  [[nodiscard]] Successor modules(const std::vector<Range>& ranges,
                                  const ExpressionScope& scope);
  /// A predecessor or a context: module names whose parameters are formal
  /// names, appended to `slots` (an L-Py value such as `A(0)` takes a
  /// hidden slot whose value goes to `values`).
  [[nodiscard]] std::vector<PatternModule> pattern(
      Range r, std::vector<std::string>& slots, PatternValues& values,
      bool allow_brackets, const char* bracket_error);
  /// For a Python body that builds its successor: each `nproduce` or
  /// `produce` statement's modules, read as a successor is, go into `all`
  /// (Production::successor_from_body) and, as names and places of their
  /// arguments, to the statements' compiler.
  void read_successors_into(ExpressionScope& scope, Successor& all);

 private:
  // Calls `each` with every module of `r` in turn, so that a long axiom is
  // never held as tokens besides its successor.
  template <typename Each>
  void tokenize_each(Range r, const Each& each);
  // The `)` that closes the `(` at `open`, outside Python's strings.
  std::size_t skip_arguments(std::size_t open, std::size_t end) const;

  BuildContext& context_;
  Draft& draft_;
  Grammar& grammar_;
  SymbolTable& symbols_;
};

}  // namespace lsys::dialects
