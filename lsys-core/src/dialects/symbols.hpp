// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "dialects/build_context.hpp"
#include "lsys/turtle_command.hpp"

namespace lsys::dialects {

/// What each module name means in the notation: its turtle command (by the
/// notation or an alias), its parameter count, and whether the notation
/// refuses it or leaves it out.
class SymbolTable : protected TextScan {
 public:
  /// Interns the names the notation refuses and leaves out.
  explicit SymbolTable(BuildContext& context);

  /// `aliases: f=F` lines: a module drawn as a turtle symbol.
  void read_aliases();
  /// `module bud(x)` fixes bud's parameter count; `module leaf` only
  /// declares the name.
  void read_module_declarations();
  /// The command a name has in the notation, before aliases.
  [[nodiscard]] std::optional<TurtleCommand> notation_command(
      std::string_view name) const;
  /// The command of a symbol, aliases included.
  [[nodiscard]] TurtleCommand command_of(SymbolId symbol) const;
  /// Checks a module's parameter count against its command's, or against
  /// its first use where the notation fixes arities.
  /// @throws ParseError at `offset`.
  void check_arity(SymbolId symbol, int count, std::size_t offset);
  /// @throws ParseError at `offset` when the notation refuses the symbol.
  void reject_refused(SymbolId symbol, std::size_t offset) const;
  /// True when the notation leaves the symbol out (counting the use, for
  /// the warning).
  bool use_if_left_out(SymbolId symbol);
  /// A warning for each symbol left out that the file uses.
  void warn_of_left_out();
  /// Each symbol's command, default parameter and parameters read, into
  /// the grammar.
  void build_commands();

 private:
  struct LeftOut {
    const RefusedName* name;
    std::size_t uses = 0;
  };
  Draft& draft_;
  Grammar& grammar_;
  std::unordered_map<SymbolId, TurtleCommand> aliases_;
  // The ids of the names the notation refuses, and why.
  std::vector<std::pair<SymbolId, const RefusedName*>> refused_;
  std::map<SymbolId, LeftOut> left_out_;
  std::unordered_map<SymbolId, std::pair<int, std::size_t>> arity_;
};

}  // namespace lsys::dialects
