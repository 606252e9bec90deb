// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "lsys/alphabet.hpp"

namespace lsys {

/// A string of modules with actual parameter values (ABOP §1.10), stored
/// flat. Each module also records the derivation step that created it
/// (0 for the axiom), which per-generation width rules use.
class ModuleString {
 public:
  /// The number of modules.
  [[nodiscard]] std::size_t size() const noexcept { return symbols_.size(); }
  [[nodiscard]] bool empty() const noexcept { return symbols_.empty(); }
  /// The name id of module i. @pre `i < size()`.
  [[nodiscard]] SymbolId symbol(std::size_t i) const { return symbols_[i]; }
  /// The actual parameters of module i. @pre `i < size()`.
  [[nodiscard]] std::span<const double> parameters(std::size_t i) const {
    return {params_.data() + begins_[i], begins_[i + 1] - begins_[i]};
  }
  /// The derivation step that created module i. @pre `i < size()`.
  [[nodiscard]] std::uint32_t generation(std::size_t i) const {
    return generations_[i];
  }
  /// All name ids, in order.
  [[nodiscard]] std::span<const SymbolId> symbols() const noexcept {
    return symbols_;
  }

  /// Appends a module.
  void push_back(SymbolId symbol, std::span<const double> parameters,
                 std::uint32_t generation) {
    symbols_.push_back(symbol);
    generations_.push_back(generation);
    params_.insert(params_.end(), parameters.begin(), parameters.end());
    begins_.push_back(static_cast<std::uint32_t>(params_.size()));
  }
  /// Appends module i of another string.
  void push_back(const ModuleString& other, std::size_t i) {
    push_back(other.symbol(i), other.parameters(i), other.generation(i));
  }
  /// Removes every module, keeping the capacity.
  void clear() noexcept {
    symbols_.clear();
    generations_.clear();
    params_.clear();
    begins_.resize(1);
  }
  /// Reserves room for `modules` modules and `parameters` values.
  void reserve(std::size_t modules, std::size_t parameters) {
    symbols_.reserve(modules);
    generations_.reserve(modules);
    begins_.reserve(modules + 1);
    params_.reserve(parameters);
  }

 private:
  std::vector<SymbolId> symbols_;
  std::vector<std::uint32_t> generations_;
  std::vector<std::uint32_t> begins_{0};
  std::vector<double> params_;
};

/// Appends one module as text: its name, then `(1.5,10)` if it has
/// parameters, numbers in shortest round-trip form.
void append_module(std::string& out, const Alphabet& alphabet, SymbolId symbol,
                   std::span<const double> parameters);

/// Appends a number in shortest round-trip form (`0.1`, `1e+30`, `-2`).
void append_number(std::string& out, double value);

/// The text of a string of modules. Modules are concatenated, except that a
/// space separates two modules when either has a multi-character name, so
/// that the text reads back as the same modules.
[[nodiscard]] std::string to_string(const ModuleString& modules,
                                    const Alphabet& alphabet);

/// Appends module i of `modules` to `out` as `to_string` would, given the
/// symbol of the module before it (or none for the first).
void append_module_separated(std::string& out, const Alphabet& alphabet,
                             const ModuleString& modules, std::size_t i,
                             const SymbolId* previous);

}  // namespace lsys
