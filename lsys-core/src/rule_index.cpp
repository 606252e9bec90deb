// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "rule_index.hpp"

#include <stdexcept>
#include <utility>

#include "lsys/diagnostic.hpp"

namespace lsys {

RuleIndex::RuleIndex(const std::vector<Production>& rules,
                     std::size_t alphabet_size)
    : by_symbol_(alphabet_size), only_(alphabet_size, nullptr) {
  for (const Production& rule : rules) {
    by_symbol_[rule.predecessor.symbol].push_back(&rule);
  }
  for (std::size_t s = 0; s < alphabet_size; ++s) {
    const auto& list = by_symbol_[s];
    if (list.size() == 1 && !list[0]->is_conditional() &&
        !list[0]->probability && !list[0]->has_statements() &&
        !list[0]->is_context_sensitive()) {
      only_[s] = list[0];
    }
  }
}

const Production* RuleIndex::first_applicable(
    SymbolId symbol, std::span<const double> parameters, Variables* variables,
    std::vector<double>* slots) const {
  for (const Production* rule : by_symbol_[symbol]) {
    if (rule->predecessor.parameter_count !=
        static_cast<int>(parameters.size())) {
      continue;
    }
    if (!rule->has_statements()) {
      if (condition_holds(*rule, parameters, variables)) return rule;
      continue;
    }
    if (slots == nullptr) {
      throw std::logic_error("first_applicable: statements need slots");
    }
    slots->assign(parameters.begin(), parameters.end());
    if (statements_and_condition_hold(*rule, *slots, variables)) return rule;
  }
  return nullptr;
}

EmittedModules take_emitted(Variables& variables, const SourceFile& source,
                            std::size_t offset) {
  EmittedModules out = std::move(variables.emitted);
  variables.emitted = EmittedModules{};
  // L-Py checks the string a body produced when the rule returns
  // (nproduce's pieces may open a branch that a later piece closes).
  int depth = 0;
  for (const SymbolId symbol : out.symbols) {
    if (symbol == kBranchOpen) ++depth;
    if (symbol == kBranchClose && --depth < 0) {
      throw error_at(source, offset,
                     "this body produced a ']' that no '[' before it opened");
    }
  }
  if (depth > 0) {
    throw error_at(source, offset,
                   "this body produced a '[' that it did not close");
  }
  return out;
}

}  // namespace lsys
