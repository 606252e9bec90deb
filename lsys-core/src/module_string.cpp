// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/module_string.hpp"

#include <algorithm>
#include <array>
#include <charconv>

namespace lsys {

void ModuleString::retain(const std::vector<bool>& keep) {
  std::size_t kept = 0;
  std::size_t values = 0;
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    if (!keep[i]) continue;
    Entry e = entries_[i];
    // Kept values only move toward the front, so copying forward is safe.
    std::copy_n(params_.begin() + e.first_parameter, e.parameter_count,
                params_.begin() + static_cast<std::ptrdiff_t>(values));
    e.first_parameter = static_cast<std::uint32_t>(values);
    values += e.parameter_count;
    entries_[kept++] = e;
  }
  entries_.resize(kept);
  params_.resize(values);
}

void append_number(std::string& out, double value) {
  if (value == 0.0) value = 0.0;  // print -0 as 0
  std::array<char, 32> buffer{};
  const auto result =
      std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  out.append(buffer.data(), result.ptr);
}

void append_module(std::string& out, const Alphabet& alphabet, SymbolId symbol,
                   std::span<const double> parameters) {
  out += alphabet.name(symbol);
  if (parameters.empty()) return;
  out += '(';
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    if (i > 0) out += ',';
    append_number(out, parameters[i]);
  }
  out += ')';
}

void append_module_separated(std::string& out, const Alphabet& alphabet,
                             const ModuleString& modules, std::size_t i,
                             const SymbolId* previous) {
  const SymbolId symbol = modules.symbol(i);
  // A space keeps modules apart where reading back would join them: next to
  // a multi-character name, and where two names would start a longer one.
  if (previous != nullptr &&
      (alphabet.is_multi_character(*previous) ||
       alphabet.is_multi_character(symbol) ||
       alphabet.extends_to_longer_name(alphabet.name(*previous) +
                                       alphabet.name(symbol)))) {
    out += ' ';
  }
  append_module(out, alphabet, symbol, modules.parameters(i));
}

std::string to_string(const ModuleString& modules, const Alphabet& alphabet) {
  std::string out;
  for (std::size_t i = 0; i < modules.size(); ++i) {
    const SymbolId previous = i > 0 ? modules.symbol(i - 1) : 0;
    append_module_separated(out, alphabet, modules, i,
                            i > 0 ? &previous : nullptr);
  }
  return out;
}

}  // namespace lsys
