// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/grammar.hpp"

#include <algorithm>

namespace lsys {

void Successor::push_back(SymbolId symbol, std::vector<Expression> parameters,
                          std::size_t offset) {
  symbols_.push_back(symbol);
  offsets_.push_back(static_cast<std::uint32_t>(offset));
  for (Expression& e : parameters) {
    uses_variables_ = uses_variables_ || e.uses_variables();
    if (is_constant_ && e.is_constant()) {
      constant_values_.push_back(e.constant_value());
    } else if (is_constant_) {
      is_constant_ = false;
      constant_values_.clear();
      constant_values_.shrink_to_fit();
    }
    expressions_.push_back(std::move(e));
  }
  begins_.push_back(static_cast<std::uint32_t>(expressions_.size()));
}

void Successor::reserve(std::size_t modules) {
  symbols_.reserve(modules);
  offsets_.reserve(modules);
  begins_.reserve(modules + 1);
}

void Successor::shrink_to_fit() {
  symbols_.shrink_to_fit();
  offsets_.shrink_to_fit();
  begins_.shrink_to_fit();
  expressions_.shrink_to_fit();
  constant_values_.shrink_to_fit();
}

void Successor::instantiate(std::span<const double> slots,
                            std::vector<double>& out,
                            Variables* variables) const {
  out.resize(expressions_.size());
  for (std::size_t i = 0; i < expressions_.size(); ++i) {
    out[i] = expressions_[i].evaluate(slots, variables);
  }
}

Variables initial_variables(const Grammar& grammar) {
  Variables variables;
  variables.globals.assign(grammar.globals.size(), 0.0);
  std::copy_n(grammar.initial_globals.begin(),
              std::min(grammar.initial_globals.size(), grammar.globals.size()),
              variables.globals.begin());
  return variables;
}

}  // namespace lsys
