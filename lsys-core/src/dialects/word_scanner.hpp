// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include "lsys/diagnostic.hpp"
#include "lsys/source.hpp"

namespace lsys::dialects {

/// Reads a file of blank-separated words and numbers (vlab's `.func` and
/// `.s` files), placing each error where reading stopped.
class WordScanner {
 protected:
  explicit WordScanner(const SourceFile& file)
      : file_(file), text_(file.text()) {}

  /// @throws ParseError at the current place.
  [[noreturn]] void fail(std::string message) const {
    throw error_at(file_, std::min(pos_, text_.size()), std::move(message));
  }

  void skip_blanks() {
    while (pos_ < text_.size() &&
           std::isspace(static_cast<unsigned char>(text_[pos_])) != 0) {
      ++pos_;
    }
  }

  /// The next run of non-blank characters.
  std::string_view word() {
    skip_blanks();
    const std::size_t at = pos_;
    while (pos_ < text_.size() &&
           std::isspace(static_cast<unsigned char>(text_[pos_])) == 0) {
      ++pos_;
    }
    return text_.substr(at, pos_ - at);
  }

  /// Whether what follows the blanks starts with `w` (nothing is read).
  bool word_is(std::string_view w) {
    skip_blanks();
    return text_.substr(pos_).starts_with(w);
  }

  /// A finite number, with an optional `+`.
  double number() {
    skip_blanks();
    double value = 0.0;
    const char* first = text_.data() + pos_;
    if (pos_ < text_.size() && text_[pos_] == '+') ++first;
    const auto [ptr, ec] =
        std::from_chars(first, text_.data() + text_.size(), value);
    if (ec != std::errc() || ptr == first || !std::isfinite(value)) {
      fail("expected a number");
    }
    pos_ = static_cast<std::size_t>(ptr - text_.data());
    return value;
  }

  const SourceFile& file_;
  std::string_view text_;
  std::size_t pos_ = 0;
};

}  // namespace lsys::dialects
