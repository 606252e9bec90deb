// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
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
  [[nodiscard]] std::size_t size() const noexcept { return entries_.size(); }
  [[nodiscard]] bool empty() const noexcept { return entries_.empty(); }
  /// The name id of module i. @pre `i < size()`.
  [[nodiscard]] SymbolId symbol(std::size_t i) const {
    return entries_[i].symbol;
  }
  /// The actual parameters of module i. @pre `i < size()`.
  [[nodiscard]] std::span<const double> parameters(std::size_t i) const {
    return {params_.data() + entries_[i].first_parameter,
            entries_[i].parameter_count};
  }
  /// The parameters of module i, to overwrite (cpfg's queries are answered
  /// in place). @pre `i < size()`.
  [[nodiscard]] std::span<double> mutable_parameters(std::size_t i) {
    return {params_.data() + entries_[i].first_parameter,
            entries_[i].parameter_count};
  }
  /// The derivation step that created module i. @pre `i < size()`.
  [[nodiscard]] std::uint32_t generation(std::size_t i) const {
    return entries_[i].generation;
  }
  /// True if some module has this name.
  [[nodiscard]] bool contains(SymbolId symbol) const noexcept {
    for (const Entry& e : entries_) {
      if (e.symbol == symbol) return true;
    }
    return false;
  }

  /// Appends a module.
  /// @pre `parameter_count() + parameters.size()` fits 32 bits.
  void push_back(SymbolId symbol, std::span<const double> parameters,
                 std::uint32_t generation) {
    entries_.push_back(Entry{symbol, generation,
                             static_cast<std::uint32_t>(params_.size()),
                             static_cast<std::uint32_t>(parameters.size())});
    if (!parameters.empty()) {
      params_.insert(params_.end(), parameters.begin(), parameters.end());
    }
  }
  /// Appends module i of another string.
  void push_back(const ModuleString& other, std::size_t i) {
    push_back(other.symbol(i), other.parameters(i), other.generation(i));
  }
  /// Removes every module, keeping the capacity.
  void clear() noexcept {
    entries_.clear();
    params_.clear();
  }
  /// The number of parameter values of all modules.
  [[nodiscard]] std::size_t parameter_count() const noexcept {
    return params_.size();
  }
  /// The bytes the string holds, counting the room reserved for growth.
  [[nodiscard]] std::size_t memory_bytes() const noexcept {
    return entries_.capacity() * sizeof(Entry) +
           params_.capacity() * sizeof(double);
  }
  /// memory_bytes() after appending a module of `parameters` values, when
  /// a full array doubles its room (as std::vector does).
  [[nodiscard]] std::size_t memory_bytes_after_push(
      std::size_t parameters) const noexcept {
    const auto grown = [](std::size_t size, std::size_t capacity,
                          std::size_t more) {
      return size + more <= capacity ? capacity
                                     : std::max(2 * capacity, size + more);
    };
    return grown(entries_.size(), entries_.capacity(), 1) * sizeof(Entry) +
           grown(params_.size(), params_.capacity(), parameters) *
               sizeof(double);
  }
  /// Keeps the modules i with `keep[i]`, in order, in place.
  /// @pre `keep.size() == size()`.
  void retain(const std::vector<bool>& keep);
  /// Reserves room for `modules` modules and `parameters` values.
  void reserve(std::size_t modules, std::size_t parameters) {
    entries_.reserve(modules);
    params_.reserve(parameters);
  }

 private:
  // One record per module keeps appending to a single array in the hot
  // loop of the deriver.
  struct Entry {
    SymbolId symbol;
    std::uint32_t generation;
    std::uint32_t first_parameter;
    std::uint32_t parameter_count;
  };
  std::vector<Entry> entries_;
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
