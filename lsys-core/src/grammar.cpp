// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/grammar.hpp"

namespace lsys {

Successor::Successor(std::vector<ModuleTemplate> modules)
    : modules_(std::move(modules)) {
  symbols_.reserve(modules_.size());
  for (const ModuleTemplate& m : modules_) {
    symbols_.push_back(m.symbol);
    for (const Expression& e : m.parameters) {
      expressions_.push_back(e);
      is_constant_ = is_constant_ && e.is_constant();
    }
    begins_.push_back(static_cast<std::uint32_t>(expressions_.size()));
  }
  if (is_constant_) {
    constant_values_.reserve(expressions_.size());
    for (const Expression& e : expressions_) {
      constant_values_.push_back(e.constant_value());
    }
  }
}

void Successor::instantiate(std::span<const double> slots,
                            std::vector<double>& out) const {
  out.resize(expressions_.size());
  for (std::size_t i = 0; i < expressions_.size(); ++i) {
    out[i] = expressions_[i].evaluate(slots);
  }
}

}  // namespace lsys
