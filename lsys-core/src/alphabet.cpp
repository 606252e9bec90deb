// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/alphabet.hpp"

#include <algorithm>

namespace lsys {

std::size_t code_point_length(std::string_view text) noexcept {
  const auto lead = static_cast<unsigned char>(text.front());
  std::size_t length = 1;
  if (lead >= 0xF8U || (lead >= 0x80U && lead < 0xC0U)) {
    return 1;
  }
  if (lead >= 0xF0U) {
    length = 4;
  } else if (lead >= 0xE0U) {
    length = 3;
  } else if (lead >= 0xC0U) {
    length = 2;
  }
  // A lead byte without its continuation bytes is one invalid byte, so
  // that it cannot swallow the characters after it.
  if (length > text.size()) return 1;
  for (std::size_t k = 1; k < length; ++k) {
    if ((static_cast<unsigned char>(text[k]) & 0xC0U) != 0x80U) return 1;
  }
  return length;
}

SymbolId Alphabet::intern(std::string_view name) {
  if (const auto found = find(name)) return *found;
  const auto id = static_cast<SymbolId>(names_.size());
  names_.emplace_back(name);
  const bool multi = code_point_length(name) < name.size();
  multi_.push_back(multi);
  ids_.emplace(std::string(name), id);
  if (multi) {
    long_names_.emplace_back(name);
    std::stable_sort(long_names_.begin(), long_names_.end(),
                     [](const std::string& a, const std::string& b) {
                       return a.size() > b.size();
                     });
  }
  return id;
}

std::optional<SymbolId> Alphabet::find(std::string_view name) const {
  const auto it = ids_.find(std::string(name));
  if (it == ids_.end()) return std::nullopt;
  return it->second;
}

bool Alphabet::extends_to_longer_name(std::string_view text) const {
  for (const std::string& name : long_names_) {
    if (name.starts_with(text)) return true;
  }
  return false;
}

std::size_t Alphabet::match_length(std::string_view text) const {
  for (const std::string& name : long_names_) {
    if (text.starts_with(name)) return name.size();
  }
  return code_point_length(text);
}

}  // namespace lsys
