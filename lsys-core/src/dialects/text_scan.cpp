// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "dialects/text_scan.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

#include "lsys/diagnostic.hpp"

namespace lsys::dialects {

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

bool is_word_char(char c) {
  const auto u = static_cast<unsigned char>(c);
  return std::isalnum(u) != 0 || c == '_' || u >= 0x80U;
}

bool is_identifier(std::string_view s) {
  if (s.empty()) return false;
  const auto first = static_cast<unsigned char>(s.front());
  if (std::isdigit(first) != 0) return false;
  return std::all_of(s.begin(), s.end(), is_word_char);
}

std::size_t blank_block_comment(const SourceFile& source, std::string& text,
                                std::size_t at) {
  const std::size_t close = text.find("*/", at + 2);
  if (close == std::string::npos)
    throw error_at(source, at, "unterminated comment '/*'");
  for (std::size_t j = at; j < close + 2; ++j) {
    if (text[j] != '\n') text[j] = ' ';
  }
  return close + 1;
}

char lower(char c) {
  return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
}

TextScan::TextScan(std::shared_ptr<const SourceFile> source, std::string clean)
    : source_(std::move(source)),
      clean_(std::make_shared<const std::string>(std::move(clean))),
      text_(*clean_) {}

void TextScan::fail(std::size_t offset, std::string message) const {
  throw error_at(*source_, offset, std::move(message));
}

Range TextScan::trim(Range r) const {
  while (r.begin < r.end && is_blank(text_[r.begin])) ++r.begin;
  while (r.end > r.begin && is_blank(text_[r.end - 1])) --r.end;
  return r;
}

std::size_t TextScan::find_in(Range r, std::string_view what) const {
  const std::size_t at = view(r).find(what);
  return at == std::string_view::npos ? std::string::npos : r.begin + at;
}

std::size_t TextScan::find_top(Range r, std::string_view token,
                               std::size_t from) const {
  int depth = 0;
  for (std::size_t i = from == std::string::npos ? r.begin : from; i < r.end;
       ++i) {
    const char c = text_[i];
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (depth == 0 && text_.substr(i, token.size()) == token &&
        i + token.size() <= r.end) {
      return i;
    }
  }
  return std::string::npos;
}

std::vector<Range> TextScan::lines(Range r) const {
  std::vector<Range> out;
  std::size_t start = r.begin;
  while (start < r.end) {
    std::size_t end = text_.find('\n', start);
    if (end == std::string::npos || end > r.end) end = r.end;
    out.push_back(Range{start, end});
    start = end + 1;
  }
  return out;
}

std::vector<Range> TextScan::split_top(Range r, char separator) const {
  std::vector<Range> pieces;
  int depth = 0;
  std::size_t start = r.begin;
  for (std::size_t i = r.begin; i < r.end; ++i) {
    if (text_[i] == '(') ++depth;
    if (text_[i] == ')') --depth;
    if (depth == 0 && text_[i] == separator) {
      pieces.push_back(Range{start, i});
      start = i + 1;
    }
  }
  pieces.push_back(Range{start, r.end});
  return pieces;
}

std::optional<Arrow> TextScan::find_arrow(Range r, bool allow_equals) const {
  int depth = 0;
  for (std::size_t i = r.begin; i < r.end; ++i) {
    const char c = text_[i];
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (depth != 0) continue;
    const std::string_view rest = text_.substr(i, r.end - i);
    std::size_t length = 0;
    for (std::string_view arrow : {"\u2192", "\u27F6", "-->", "->", "::="}) {
      if (rest.starts_with(arrow)) {
        length = arrow.size();
        break;
      }
    }
    if (length > 0) return make_arrow(r, i, i + length);
  }
  if (!allow_equals) return std::nullopt;
  if (const std::size_t e = find_equals(r); e != std::string::npos) {
    return make_arrow(r, e, e + 1);
  }
  return std::nullopt;
}

std::size_t TextScan::find_equals(Range r) const {
  int depth = 0;
  for (std::size_t i = r.begin; i < r.end; ++i) {
    const char c = text_[i];
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (depth != 0 || c != '=') continue;
    const char before = i > r.begin ? text_[i - 1] : ' ';
    const char after = i + 1 < r.end ? text_[i + 1] : ' ';
    if (std::string_view("<>!=:").find(before) != std::string_view::npos ||
        after == '=') {
      continue;
    }
    return i;
  }
  return std::string::npos;
}

// ABOP writes stochastic productions as `F -(.33)→ F[+F]F`.
Arrow TextScan::make_arrow(Range r, std::size_t begin, std::size_t end) const {
  Arrow arrow{Range{r.begin, begin}, std::nullopt, Range{end, r.end}};
  std::size_t q = begin;
  while (q > r.begin && is_blank(text_[q - 1])) --q;
  if (q == r.begin || text_[q - 1] != ')') return arrow;
  int depth = 0;
  std::size_t open = q - 1;
  for (;; --open) {
    if (text_[open] == ')') ++depth;
    if (text_[open] == '(') --depth;
    if (depth == 0 || open == r.begin) break;
  }
  if (depth != 0 || open == r.begin || text_[open - 1] != '-') return arrow;
  const Range before = trim(Range{r.begin, open - 1});
  if (before.empty()) return arrow;  // `-(a) → …` rewrites the module `-`
  arrow.lhs = Range{r.begin, open - 1};
  arrow.probability = Range{open + 1, q - 1};
  return arrow;
}

std::optional<std::size_t> TextScan::match_words(
    std::size_t pos, std::size_t end, std::string_view spelling) const {
  for (std::size_t k = 0; k < spelling.size(); ++k) {
    if (spelling[k] == ' ') {
      if (pos >= end || !is_blank(text_[pos])) return std::nullopt;
      while (pos < end && is_blank(text_[pos])) ++pos;
      continue;
    }
    if (pos >= end || lower(text_[pos]) != spelling[k]) return std::nullopt;
    ++pos;
  }
  if (pos < end && is_word_char(text_[pos]) && is_word_char(spelling.back())) {
    return std::nullopt;
  }
  return pos;
}

std::pair<std::string_view, Range> TextScan::directive_parts(Range line) const {
  std::size_t i = line.begin + 1;
  while (i < line.end && std::isalpha(static_cast<unsigned char>(text_[i]))) {
    ++i;
  }
  return {text_.substr(line.begin + 1, i - line.begin - 1),
          trim(Range{i, line.end})};
}

std::pair<Range, Range> TextScan::define_directive(Range rest) const {
  std::size_t j = rest.begin;
  while (j < rest.end && is_word_char(text_[j])) ++j;
  const Range name{rest.begin, j};
  if (name.empty() || !is_identifier(view(name))) {
    fail(rest.begin, "expected a name after #define");
  }
  // cpfg runs the C preprocessor, which takes `//` for a comment.
  Range value = trim(Range{j, rest.end});
  if (const std::size_t comment = find_in(value, "//");
      comment != std::string::npos) {
    value = trim(Range{value.begin, comment});
  }
  if (value.empty()) fail(j, "expected a value after the name");
  return {name, value};
}

}  // namespace lsys::dialects
