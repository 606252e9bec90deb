// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace lsys {

/// Identifies a module name within one grammar's alphabet.
using SymbolId = std::uint32_t;

/// The module names of a grammar (ABOP's alphabet V): single code points
/// such as `F` or `∧`, and declared multi-character names such as `plant`.
/// Ids are dense, starting at 0, and each name has exactly one id.
class Alphabet {
 public:
  /// The id of a name, adding it if new. A name of two or more code points
  /// becomes a candidate for longest-match tokenising.
  /// @pre `!name.empty()`.
  SymbolId intern(std::string_view name);
  /// The id of a name, if it is in the alphabet.
  [[nodiscard]] std::optional<SymbolId> find(std::string_view name) const;
  /// The name of an id.
  /// @pre `id < size()`.
  [[nodiscard]] const std::string& name(SymbolId id) const {
    return names_[id];
  }
  /// The number of names.
  [[nodiscard]] std::size_t size() const noexcept { return names_.size(); }
  /// The byte length of the module name that starts `text`: the longest
  /// multi-character name that is a prefix, else one code point.
  /// @pre `!text.empty()`.
  [[nodiscard]] std::size_t match_length(std::string_view text) const;
  /// True if some multi-character name starts with `text` (so that `text`
  /// written out would not read back as the modules it came from).
  [[nodiscard]] bool extends_to_longer_name(std::string_view text) const;
  /// True if the name has more than one code point.
  [[nodiscard]] bool is_multi_character(SymbolId id) const {
    return multi_[id];
  }
  /// The bytes match_length and extends_to_longer_name have examined so
  /// far: each looks at a byte at most once, whatever the number of names,
  /// so tokenising a text costs at most its length.
  [[nodiscard]] std::uint64_t bytes_examined() const noexcept {
    return bytes_examined_;
  }

 private:
  // The trie node reached from `node` by `byte`, if any.
  [[nodiscard]] std::optional<std::uint32_t> child(std::uint32_t node,
                                                   char byte) const;

  std::vector<std::string> names_;
  std::vector<bool> multi_;
  std::unordered_map<std::string, SymbolId> ids_;
  // A trie of the multi-character names over their bytes: node 0 is the
  // root, an edge is keyed by node × 256 + byte.
  std::unordered_map<std::uint64_t, std::uint32_t> edges_;
  std::vector<bool> ends_name_{false};
  mutable std::uint64_t bytes_examined_ = 0;
};

/// The byte length of the UTF-8 code point starting `text`: 1 for a byte
/// that does not start a complete sequence, so that scanning always
/// advances and an invalid byte never swallows the characters after it.
/// @pre `!text.empty()`.
[[nodiscard]] std::size_t code_point_length(std::string_view text) noexcept;

}  // namespace lsys
