// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "lsys/source.hpp"

namespace lsys::dialects {

/// Bytes [begin, end) of a source.
struct Range {
  std::size_t begin = 0;
  std::size_t end = 0;
  [[nodiscard]] bool empty() const { return begin >= end; }
};

/// A production's arrow: the text before it, ABOP's `-(p)` probability
/// written on it, and the text after it.
struct Arrow {
  Range lhs;
  std::optional<Range> probability;
  Range rhs;
};

[[nodiscard]] bool is_blank(char c);
/// Letters, digits, `_` and any byte of a multi-byte UTF-8 sequence.
[[nodiscard]] bool is_word_char(char c);
[[nodiscard]] bool is_identifier(std::string_view s);
[[nodiscard]] char lower(char c);
/// Blanks the `/* … */` comment that starts at `at` in `text` (a copy of
/// the source's text), keeping its line breaks; returns the offset of the
/// comment's last byte.
/// @throws ParseError at `at` when the comment does not end.
std::size_t blank_block_comment(const SourceFile& source, std::string& text,
                                std::size_t at);

/// The lexical layer every notation shares: a source and its text with
/// the notation's comments blanked out (same length, same line breaks, so
/// that every byte offset is the source's), and the searches the front ends
/// and the grammar builder make in it. Searches stop at paren depth.
class TextScan {
 public:
  /// @pre `clean.size() == source->text().size()`.
  TextScan(std::shared_ptr<const SourceFile> source, std::string clean);

  [[nodiscard]] const std::shared_ptr<const SourceFile>& source() const {
    return source_;
  }
  /// @throws ParseError at `offset`, always.
  [[noreturn]] void fail(std::size_t offset, std::string message) const;

  [[nodiscard]] Range trim(Range r) const;
  [[nodiscard]] std::string_view view(Range r) const {
    return text_.substr(r.begin, r.end - r.begin);
  }
  /// `what` in r (and nowhere after it: a search to the end of the text for
  /// each of many lines would be quadratic); npos if absent.
  [[nodiscard]] std::size_t find_in(Range r, std::string_view what) const;
  /// `token` at paren depth 0 in r, from `from` if given; npos if absent.
  [[nodiscard]] std::size_t find_top(
      Range r, std::string_view token,
      std::size_t from = std::string::npos) const;
  /// The lines of r, without their line breaks (not trimmed).
  [[nodiscard]] std::vector<Range> lines(Range r) const;
  /// r cut at each `separator` at paren depth 0.
  [[nodiscard]] std::vector<Range> split_top(Range r, char separator) const;
  /// A lone `=` at paren depth 0 (not `==`, `<=`, `>=`, `!=`, `:=`).
  [[nodiscard]] std::size_t find_equals(Range r) const;
  /// The arrow of a production: `→`, `⟶`, `-->`, `->`, `::=` at paren depth
  /// 0, or else a lone `=` when `allow_equals`.
  [[nodiscard]] std::optional<Arrow> find_arrow(Range r,
                                                bool allow_equals) const;
  /// Matches `spelling` (lower case; a space matches any run of blanks) at
  /// `pos`, ignoring case; returns the end of the match. A spelling ending
  /// in a letter does not match the start of a longer word.
  [[nodiscard]] std::optional<std::size_t> match_words(
      std::size_t pos, std::size_t end, std::string_view spelling) const;
  /// A directive line `#word rest`: the word and the rest, trimmed.
  [[nodiscard]] std::pair<std::string_view, Range> directive_parts(
      Range line) const;
  /// The name and the value of a `#define NAME value` whose text after
  /// `define` is `rest` (a `//` comment after the value left out).
  /// @throws ParseError without a name or a value.
  [[nodiscard]] std::pair<Range, Range> define_directive(Range rest) const;

 protected:
  std::shared_ptr<const SourceFile> source_;
  std::shared_ptr<const std::string> clean_;
  std::string_view text_;

 private:
  [[nodiscard]] Arrow make_arrow(Range r, std::size_t begin,
                                 std::size_t end) const;
};

}  // namespace lsys::dialects
