// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/dialect.hpp"

#include <array>
#include <cctype>
#include <utility>

namespace lsys {
namespace {

constexpr std::array<std::pair<std::string_view, Dialect>, 4> kNames{{
    {"ls", Dialect::Ls},
    {"lparser", Dialect::Lparser},
    {"fractint", Dialect::Fractint},
    {"lpy", Dialect::Lpy},
}};

std::string_view trimmed(std::string_view s) {
  const auto blank = [](char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
  };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

// Calls `each` with each line's text, trimmed, until it returns false.
template <typename Each>
void for_each_line(std::string_view text, const Each& each) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  while (!text.empty()) {
    std::size_t end = text.find_first_of("\r\n");
    if (end == std::string_view::npos) end = text.size();
    if (!each(trimmed(text.substr(0, end)))) return;
    text.remove_prefix(std::min(text.size(), end + 1));
  }
}

// `12`, `22.5`, `-1`, with a comment or nothing after it.
bool is_number_line(std::string_view line) {
  std::size_t i = 0;
  if (i < line.size() && (line[i] == '-' || line[i] == '+')) ++i;
  const std::size_t digits = i;
  while (i < line.size() &&
         (std::isdigit(static_cast<unsigned char>(line[i])) != 0 ||
          line[i] == '.')) {
    ++i;
  }
  if (i == digits) return false;
  const std::string_view rest = trimmed(line.substr(i));
  return rest.empty() || rest.front() == '#';
}

// `Koch1 {`, `Dragon{`: one word, then a brace.
bool is_system_start(std::string_view line) {
  const std::size_t brace = line.find('{');
  if (brace == std::string_view::npos || brace == 0) return false;
  const std::string_view name = trimmed(line.substr(0, brace));
  if (name.empty()) return false;
  for (char c : name) {
    if (c == ' ' || c == '\t' || c == '=' || c == '>' || c == ':' || c == '[' ||
        c == '(' || static_cast<unsigned char>(c) >= 0x80U) {
      return false;
    }
  }
  return true;
}

}  // namespace

Dialect detect_dialect(std::string_view text) {
  int numbers = 0;
  bool first = true;
  bool fractint = false;
  bool axiom = false;
  bool production = false;
  bool in_comment_block = false;
  for_each_line(text, [&](std::string_view line) {
    if (line.empty()) return true;
    if (first && line.front() == ';') return true;
    // A nameless `{ … }` block is a comment to Fractint (penrose.l opens
    // with one); the system after it decides.
    if (in_comment_block) {
      in_comment_block = line.front() != '}';
      return true;
    }
    if (first && line.front() == '{' &&
        line.find('}') == std::string_view::npos) {
      in_comment_block = true;
      return true;
    }
    if (first && is_system_start(line)) {
      fractint = true;
      return false;
    }
    if (numbers >= 0 && line.front() != '#') {
      numbers = is_number_line(line) ? numbers + 1 : -1;
    }
    if (line.front() != '#') first = false;
    axiom = axiom || line.starts_with("Axiom:") || line.starts_with("Axiom :");
    production = production || line.starts_with("production:") ||
                 line.starts_with("production :");
    return !(axiom && production) && numbers < 2;
  });
  if (fractint) return Dialect::Fractint;
  if (numbers >= 2) return Dialect::Lparser;
  if (axiom && production) return Dialect::Lpy;
  return Dialect::Ls;
}

std::string_view dialect_name(Dialect dialect) noexcept {
  for (const auto& [name, d] : kNames) {
    if (d == dialect) return name;
  }
  return "ls";
}

std::optional<Dialect> dialect_named(std::string_view name) {
  for (const auto& [n, d] : kNames) {
    if (n == name) return d;
  }
  return std::nullopt;
}

}  // namespace lsys
