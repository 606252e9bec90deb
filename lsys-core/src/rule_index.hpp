// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "lsys/grammar.hpp"

namespace lsys {

/// The productions of one kind (productions, decompositions or
/// homomorphisms) indexed by predecessor symbol, in file order.
class RuleIndex {
 public:
  RuleIndex(const std::vector<Production>& rules, std::size_t alphabet_size);

  /// The rules whose predecessor is `symbol`, in file order.
  [[nodiscard]] std::span<const Production* const> rules_for(
      SymbolId symbol) const noexcept {
    return by_symbol_[symbol];
  }
  /// True if some rule rewrites `symbol`.
  [[nodiscard]] bool has_rules(SymbolId symbol) const noexcept {
    return !by_symbol_[symbol].empty();
  }
  /// The only rule of `symbol` when it is unconditional, deterministic and
  /// context-free (the common D0L case), else null.
  [[nodiscard]] const Production* only_rule(SymbolId symbol) const noexcept {
    return only_[symbol];
  }
  /// The first context-free rule whose arity matches and whose condition
  /// holds for these parameters, else null. For a rule with statements,
  /// `slots` receives the values its successor reads (the parameters as
  /// the statements left them, then the rule's local variables); other
  /// rules read `parameters` as they are.
  /// @pre `slots` is given when a rule has statements.
  /// @throws ParseError when a condition or a statement fails.
  [[nodiscard]] const Production* first_applicable(
      SymbolId symbol, std::span<const double> parameters,
      Variables* variables = nullptr,
      std::vector<double>* slots = nullptr) const;

 private:
  std::vector<std::vector<const Production*>> by_symbol_;
  std::vector<const Production*> only_;
};

/// True if a rule's condition holds (or it has none).
/// @throws ParseError when the condition fails to evaluate.
[[nodiscard]] inline bool condition_holds(const Production& rule,
                                          std::span<const double> slots,
                                          Variables* variables = nullptr) {
  if (rule.guard && rule.guard->evaluate(slots) == 0.0) return false;
  return !rule.condition || rule.condition->evaluate(slots, variables) != 0.0;
}

/// cpfg (CPFG Reference Manual §3.2): the statements before a rule's
/// condition run on every match, those after it only when it holds.
/// `slots` holds the bound parameters; the rule's locals are added.
/// @throws ParseError when a condition or a statement fails.
[[nodiscard]] inline bool statements_and_condition_hold(
    const Production& rule, std::vector<double>& slots, Variables* variables) {
  if (rule.guard && rule.guard->evaluate(slots) == 0.0) return false;
  slots.resize(slots.size() + static_cast<std::size_t>(rule.local_count), 0.0);
  if (rule.undo_unless_applied && variables != nullptr) {
    Variables before = *variables;
    if (rule.before) rule.before->execute(slots, variables);
    if (!condition_holds(rule, slots, variables)) {
      *variables = std::move(before);
      return false;
    }
  } else {
    if (rule.before) rule.before->execute(slots, variables);
    if (!condition_holds(rule, slots, variables)) return false;
  }
  if (rule.after) rule.after->execute(slots, variables);
  return true;
}

/// The modules that an L-Py body which builds its successor
/// (Production::successor_from_body, Grammar::axiom_body) has just
/// produced, moved out of `variables` so that rules run while they are
/// used cannot overwrite them.
/// @throws ParseError at `offset` when their brackets do not balance.
[[nodiscard]] EmittedModules take_emitted(Variables& variables,
                                          const SourceFile& source,
                                          std::size_t offset);

}  // namespace lsys
