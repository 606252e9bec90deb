// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/diagnostic.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "lsys/alphabet.hpp"

namespace lsys {
namespace {

// A source line is shown at most this many columns wide, clipped to a
// window around the caret.
constexpr std::size_t kShownColumns = 100;
constexpr std::size_t kColumnsBeforeCaret = 50;
// Longer messages (which quote the input) are cut.
constexpr std::size_t kShownMessageBytes = 400;

constexpr std::string_view kEllipsis = "\u2026";

// One code point of a line as shown: itself, or an escape for what a
// terminal would act on or cannot show.
struct Shown {
  std::string text;
  bool is_tab = false;
};

bool is_bidi_control(std::uint32_t c) {
  return c == 0x061CU || c == 0x200EU || c == 0x200FU ||
         (c >= 0x202AU && c <= 0x202EU) || (c >= 0x2066U && c <= 0x2069U);
}

std::size_t code_point_count(std::string_view text) {
  std::size_t count = 0;
  for (std::size_t i = 0; i < text.size();
       i += code_point_length(text.substr(i))) {
    ++count;
  }
  return count;
}

std::string hex(std::uint32_t value, int digits) {
  static constexpr std::string_view kDigits = "0123456789ABCDEF";
  std::string out(static_cast<std::size_t>(digits), '0');
  for (int k = digits - 1; k >= 0; --k, value >>= 4U) {
    out[static_cast<std::size_t>(k)] = kDigits[value & 0xFU];
  }
  return out;
}

// Decodes the code point at the start of `text`, or nothing for a byte
// that does not start a well-formed sequence.
std::optional<std::uint32_t> decode(std::string_view text, std::size_t length) {
  const auto lead = static_cast<unsigned char>(text[0]);
  if (length == 1) {
    return lead < 0x80U ? std::optional<std::uint32_t>(lead) : std::nullopt;
  }
  std::uint32_t c = lead & (0x7FU >> length);
  for (std::size_t k = 1; k < length; ++k) {
    const auto b = static_cast<unsigned char>(text[k]);
    if ((b & 0xC0U) != 0x80U) return std::nullopt;
    c = (c << 6U) | (b & 0x3FU);
  }
  // Overlong forms, surrogates and values past U+10FFFF are not UTF-8.
  static constexpr std::array<std::uint32_t, 5> kLeast{0, 0, 0x80, 0x800,
                                                       0x10000};
  if (c < kLeast[length] || (c >= 0xD800U && c < 0xE000U) || c > 0x10FFFFU) {
    return std::nullopt;
  }
  return c;
}

Shown shown(std::string_view text, std::size_t length) {
  const std::optional<std::uint32_t> c = decode(text, length);
  // (Appending piecewise avoids a GCC 12 -Wrestrict false alarm.)
  std::string escape(1, '<');
  if (!c) {  // every byte of an ill-formed sequence
    escape.clear();
    for (std::size_t k = 0; k < length; ++k) {
      escape.append(1, '<')
          .append(hex(static_cast<unsigned char>(text[k]), 2))
          .append(1, '>');
    }
    return {escape};
  }
  if (*c == '\t') return {"\t", true};
  if (*c < 0x20U || (*c >= 0x7FU && *c < 0xA0U) || is_bidi_control(*c)) {
    escape.append("U+").append(hex(*c, 4)).append(1, '>');
    return {escape};
  }
  return {std::string(text.substr(0, length))};
}

// Text of the file name or message, escaped as source lines are.
std::string escaped(std::string_view text, std::size_t most_bytes) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (out.size() >= most_bytes) {
      out += kEllipsis;
      break;
    }
    const std::size_t length = code_point_length(text.substr(i));
    const std::optional<std::uint32_t> c = decode(text.substr(i), length);
    out +=
        c && *c == '\t' ? std::string(" ") : shown(text.substr(i), length).text;
    i += length;
  }
  return out;
}

std::string headline(const Diagnostic& d) {
  std::string out = d.file;
  if (d.line > 0) {
    out += ':' + std::to_string(d.line) + ':' + std::to_string(d.column);
  }
  return out + ": error: " + d.message;
}

}  // namespace

ParseError::ParseError(Diagnostic diagnostic)
    : std::runtime_error(headline(diagnostic)),
      diagnostic_(std::move(diagnostic)) {}

ParseError error_at(const SourceFile& source, std::size_t offset,
                    std::string message) {
  const SourceLocation where = source.location(offset);
  return ParseError(
      Diagnostic{.file = source.name(),
                 .line = where.line,
                 .column = where.column,
                 .message = std::move(message),
                 .source_line = std::string(source.line_text(where.line))});
}

std::string format_diagnostic(const Diagnostic& diagnostic) {
  std::string out = escaped(diagnostic.file, kShownMessageBytes);
  if (diagnostic.line > 0) {
    out += ':' + std::to_string(diagnostic.line) + ':' +
           std::to_string(diagnostic.column);
  }
  out += ": error: " + escaped(diagnostic.message, kShownMessageBytes) + '\n';
  if (diagnostic.line <= 0) return out;
  // The code points around the caret as shown (a line may be megabytes
  // long); the caret goes under the first character of the shown form of
  // the code point at the column.
  const std::string_view line(diagnostic.source_line);
  const auto column =
      static_cast<std::size_t>(std::max(1, diagnostic.column) - 1);
  const std::size_t first = column > kColumnsBeforeCaret
                                ? column - kColumnsBeforeCaret
                                : std::size_t{0};
  std::size_t i = 0;
  std::size_t skipped = 0;
  for (; i < line.size() && skipped < first; ++skipped) {
    i += code_point_length(line.substr(i));
  }
  std::vector<Shown> points;
  while (i < line.size() &&
         points.size() < column - skipped + kShownColumns + 1) {
    const std::size_t length = code_point_length(line.substr(i));
    points.push_back(shown(line.substr(i), length));
    i += length;
  }
  const bool has_more = i < line.size();
  const std::size_t caret = column - std::min(column, skipped);
  const auto width = [&](std::size_t k) {
    return points[k].is_tab ? std::size_t{1} : code_point_count(points[k].text);
  };
  // Clip to a window around the caret, columns counted as shown.
  std::size_t begin = std::min(caret, points.size());
  std::size_t before = 0;
  while (begin > 0 && before + width(begin - 1) <= kColumnsBeforeCaret) {
    before += width(--begin);
  }
  std::size_t end = begin;
  std::size_t total = 0;
  while (end < points.size() && total + width(end) <= kShownColumns) {
    total += width(end++);
  }
  end = std::max(end, std::min(points.size(), caret + 1));
  std::string shown_line;
  std::string pad;
  if (begin > 0 || skipped > 0) {
    shown_line += kEllipsis;
    pad += ' ';
  }
  for (std::size_t k = begin; k < end; ++k) {
    shown_line += points[k].text;
    if (k < caret) {
      pad += points[k].is_tab ? std::string("\t") : std::string(width(k), ' ');
    }
  }
  if (end < points.size() || has_more) shown_line += kEllipsis;
  // A column past the end of the line (an error at its end) stays there.
  if (caret > points.size()) pad += std::string(caret - points.size(), ' ');
  return out + shown_line + '\n' + pad + "^\n";
}

}  // namespace lsys
