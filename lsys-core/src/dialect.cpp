// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/dialect.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <utility>

#include "dialects/front_ends.hpp"

namespace lsys {
namespace {

constexpr std::array<std::pair<std::string_view, Dialect>, 7> kNames{{
    {"ls", Dialect::Ls},
    {"lparser", Dialect::Lparser},
    {"fractint", Dialect::Fractint},
    {"lpy", Dialect::Lpy},
    {"cpfg", Dialect::Cpfg},
    {"lowclouds", Dialect::Lowclouds},
    {"lpfg", Dialect::Lpfg},
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

// `12`, `22.5`, `1e1`, alone or before a blank: Lparser reads the number
// with sscanf and ignores the rest of the line.
bool is_number_line(std::string_view line) {
  const auto digit = [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
  };
  std::size_t i = 0;
  if (i < line.size() && (line[i] == '-' || line[i] == '+')) ++i;
  if (i == line.size() || !(digit(line[i]) || line[i] == '.')) return false;
  while (i < line.size() && (digit(line[i]) || line[i] == '.' ||
                             line[i] == 'e' || line[i] == 'E')) {
    ++i;
  }
  return i == line.size() || line[i] == ' ' || line[i] == '\t' ||
         line[i] == '#';
}

// `Koch1 {`, `Dragon{`, `My Plant {`: a name, then a brace, and nothing
// that a production or setting would hold before it. A block that closes
// on its own line is a comment to Fractint, not a system.
bool is_system_start(std::string_view line) {
  const std::size_t brace = line.find('{');
  if (brace == std::string_view::npos || brace == 0) return false;
  if (line.find('}', brace) != std::string_view::npos) return false;
  const std::string_view name = trimmed(line.substr(0, brace));
  if (name.empty()) return false;
  return std::none_of(name.begin(), name.end(), [](char c) {
    return c == '=' || c == '>' || c == '<' || c == ':' || c == '[' ||
           c == '(' || static_cast<unsigned char>(c) >= 0x80U;
  });
}

// `Lsystem: 1`, `lsystem:1`: cpfg's first statement, which no other
// notation writes.
bool is_lsystem_label(std::string_view line) {
  constexpr std::string_view kWord = "lsystem";
  if (line.size() < kWord.size()) return false;
  for (std::size_t i = 0; i < kWord.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(line[i])) != kWord[i])
      return false;
  }
  return trimmed(line.substr(kWord.size())).starts_with(":");
}

// `stemsize=0.2`, `dlength: 13`, `view = {…}`, or `n=1; delta=22.5`: lines
// that only L-system Explorer writes (lsolid's own notation refuses the
// first three as unknown settings and has no `;` between settings).
bool is_lowclouds_setting(std::string_view line) {
  std::size_t i = 0;
  while (i < line.size() &&
         (std::isalnum(static_cast<unsigned char>(line[i])) != 0 ||
          line[i] == '_')) {
    ++i;
  }
  const std::string_view word = line.substr(0, i);
  const std::string_view rest = trimmed(line.substr(i));
  if (word.empty() || rest.empty()) return false;
  const bool assigns = rest.front() == '=' && !rest.starts_with("==");
  if (rest.front() == ':' || assigns) {
    if (word == "stemsize" || word == "dlength" || word == "Dlength")
      return true;
    if (word == "view" && assigns) return true;
  }
  if (!assigns || rest.find("->") != std::string_view::npos ||
      rest.find('\xE2') != std::string_view::npos) {
    return false;
  }
  // `a = 1; b = 2`: a `;` followed by another assignment.
  const std::size_t semicolon = rest.find(';');
  if (semicolon == std::string_view::npos) return false;
  const std::string_view next = trimmed(rest.substr(semicolon + 1));
  std::size_t j = 0;
  while (j < next.size() &&
         (std::isalnum(static_cast<unsigned char>(next[j])) != 0 ||
          next[j] == '_')) {
    ++j;
  }
  const std::string_view after = trimmed(next.substr(j));
  return j > 0 && after.starts_with("=") && !after.starts_with("==");
}

bool ends_with(std::string_view name, std::string_view extension) {
  if (name.size() < extension.size()) return false;
  return std::equal(extension.begin(), extension.end(),
                    name.end() - static_cast<std::ptrdiff_t>(extension.size()),
                    [](char a, char b) {
                      return std::tolower(static_cast<unsigned char>(a)) == b;
                    });
}

}  // namespace

Dialect detect_dialect(std::string_view text, std::string_view file_name) {
  if (ends_with(file_name, ".lpy")) return Dialect::Lpy;
  // lpfg's files include its header, often after C's own.
  if (text.find("lpfgall.h") != std::string_view::npos &&
      text.find("#include") != std::string_view::npos) {
    return Dialect::Lpfg;
  }
  const bool named_ls = ends_with(file_name, ".ls");
  const bool named_l = ends_with(file_name, ".l");
  int numbers = 0;
  bool first = true;
  bool fractint = false;
  bool axiom = false;
  bool production = false;
  bool in_comment_block = false;
  bool lsystem = false;
  bool lowclouds = false;
  bool axiom_seen = false;
  bool lparser_keywords = false;
  for_each_line(text, [&](std::string_view line) {
    if (line.empty()) return true;
    if (first && line.front() == ';') return true;
    // A `{ … }` block without a name is a comment to Fractint (penrose.l
    // opens with one), and so is one that closes on its line; the system
    // after it decides.
    if (in_comment_block) {
      in_comment_block = line.front() != '}';
      return true;
    }
    if (first && line.find('{') != std::string_view::npos &&
        line.find('}', line.find('{')) != std::string_view::npos &&
        line.find_first_of("=>:") == std::string_view::npos) {
      return true;
    }
    if (first && line.front() == '{') {
      in_comment_block = true;
      return true;
    }
    if (first && !named_ls && is_system_start(line)) {
      fractint = true;
      return false;
    }
    if (first && line.front() != '#' &&
        dialects::is_lparser_keyword_line(line)) {
      lparser_keywords = true;
      return false;
    }
    if (numbers >= 0 && line.front() != '#') {
      numbers = is_number_line(line) ? numbers + 1 : -1;
    }
    if (line.front() != '#') first = false;
    lsystem = lsystem || is_lsystem_label(line);
    lowclouds = lowclouds || (!axiom_seen && is_lowclouds_setting(line));
    axiom_seen =
        axiom_seen || line.starts_with("axiom") || line.starts_with("Axiom");
    axiom = axiom || line.starts_with("Axiom:") || line.starts_with("Axiom :");
    production = production || line.starts_with("production:") ||
                 line.starts_with("production :");
    return !(axiom && production) && numbers < 2 && !lowclouds &&
           !(lsystem && !named_ls);
  });
  if (fractint) return Dialect::Fractint;
  if (numbers >= 2 || lparser_keywords) return Dialect::Lparser;
  if (lsystem && !named_ls) return Dialect::Cpfg;
  if (lowclouds) return Dialect::Lowclouds;
  if (axiom && production && !named_ls && !named_l) return Dialect::Lpy;
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
