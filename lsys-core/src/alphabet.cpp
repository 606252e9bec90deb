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
    std::uint32_t node = 0;
    for (const char byte : name) {
      const auto [it, inserted] = edges_.try_emplace(
          std::uint64_t{node} * 256U + static_cast<unsigned char>(byte),
          static_cast<std::uint32_t>(ends_name_.size()));
      if (inserted) ends_name_.push_back(false);
      node = it->second;
    }
    ends_name_[node] = true;
  }
  return id;
}

std::optional<SymbolId> Alphabet::find(std::string_view name) const {
  const auto it = ids_.find(std::string(name));
  if (it == ids_.end()) return std::nullopt;
  return it->second;
}

std::optional<std::uint32_t> Alphabet::child(std::uint32_t node,
                                             char byte) const {
  ++bytes_examined_;
  const auto it = edges_.find(std::uint64_t{node} * 256U +
                              static_cast<unsigned char>(byte));
  if (it == edges_.end()) return std::nullopt;
  return it->second;
}

bool Alphabet::extends_to_longer_name(std::string_view text) const {
  // Every node of the trie lies on the path of some name.
  std::uint32_t node = 0;
  for (const char byte : text) {
    const auto next = child(node, byte);
    if (!next) return false;
    node = *next;
  }
  return node != 0;
}

std::size_t Alphabet::match_length(std::string_view text) const {
  std::size_t longest = 0;
  std::uint32_t node = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto next = child(node, text[i]);
    if (!next) break;
    node = *next;
    if (ends_name_[node]) longest = i + 1;
  }
  return longest > 0 ? longest : code_point_length(text);
}

}  // namespace lsys
