// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "expressions/python_lines.hpp"

#include <cctype>

namespace lsys::expressions {

bool is_word_byte(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

bool starts_word(std::string_view text, std::size_t at, std::size_t end,
                 std::string_view word) {
  return text.substr(at, end - at).starts_with(word) &&
         (at + word.size() >= end || !is_word_byte(text[at + word.size()]));
}

std::vector<PythonLine> python_lines(std::string_view text, std::size_t begin,
                                     std::size_t end) {
  std::vector<PythonLine> lines;
  std::size_t i = begin;
  while (i < end) {
    std::size_t line_start = i;
    while (line_start > 0 && text[line_start - 1] != '\n') --line_start;
    int column = 0;
    std::size_t first = line_start;
    for (; first < end && (text[first] == ' ' || text[first] == '\t' ||
                           text[first] == '\r' || first < i);
         ++first) {
      column = text[first] == '\t' ? (column / 8 + 1) * 8 : column + 1;
    }
    int depth = 0;
    char quote = 0;
    std::size_t code_end = first;
    std::size_t j = first;
    // L-Py reads `produce …` and `nproduce …` to the end of the line as
    // L-system modules, where `[` and `]` are branches, not Python's
    // brackets (`nproduce [ +(60)` opens a branch a later line closes).
    bool statement_start = true;
    bool successor = false;
    for (; j < end; ++j) {
      const char c = text[j];
      if (statement_start && c != ' ' && c != '\t') {
        statement_start = false;
        successor = depth == 0 && (starts_word(text, j, end, "produce") ||
                                   starts_word(text, j, end, "nproduce"));
      }
      if (quote != 0) {
        if (c == '\\') {
          ++j;
        } else if (c == quote) {
          quote = 0;
        }
        code_end = j + 1;
        continue;
      }
      if (c == '#') {
        while (j < end && text[j] != '\n') ++j;
        if (depth > 0) continue;
        break;
      }
      if (c == '\n') {
        if (depth > 0) continue;
        std::size_t k = code_end;
        if (k > first && text[k - 1] == '\\') continue;
        break;
      }
      if (c == '\'' || c == '"') quote = c;
      if (!successor) {
        if (c == '(' || c == '[' || c == '{') ++depth;
        if ((c == ')' || c == ']' || c == '}') && depth > 0) --depth;
        if (c == ':' && depth == 0) statement_start = true;
      }
      if (c != ' ' && c != '\t' && c != '\r') code_end = j + 1;
    }
    if (code_end > first) lines.push_back(PythonLine{first, code_end, column});
    i = j + 1;
  }
  return lines;
}

std::size_t python_colon(std::string_view text, std::size_t from,
                         std::size_t end) {
  int depth = 0;
  char quote = 0;
  for (std::size_t j = from; j < end; ++j) {
    const char c = text[j];
    if (quote != 0) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '(' || c == '[' || c == '{') {
      ++depth;
    } else if (c == ')' || c == ']' || c == '}') {
      --depth;
    } else if (c == ':' && depth == 0) {
      return j;
    }
  }
  return std::string_view::npos;
}

}  // namespace lsys::expressions
