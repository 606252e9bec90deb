// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace lsys::expressions {

// A logical line of Python: its first and last bytes of code (comments
// and trailing blanks left out), and its indentation in columns.
struct PythonLine {
  std::size_t begin;
  std::size_t end;
  int indent;
};

/// True for a byte of a Python or C name.
[[nodiscard]] bool is_word_byte(char c);

/// True when bytes from `at` hold the word `word` whole.
[[nodiscard]] bool starts_word(std::string_view text, std::size_t at,
                               std::size_t end, std::string_view word);

/// Python's lines in bytes [begin, end) of `text`: a line goes on while a
/// bracket is open or it ends with `\`; `#` outside strings starts a
/// comment; a tab indents to the next multiple of 8 (Python's tokenizer).
/// The first line may start inside a line (after a rule's colon).
[[nodiscard]] std::vector<PythonLine> python_lines(std::string_view text,
                                                   std::size_t begin,
                                                   std::size_t end);

/// The first `:` of bytes [from, end) outside brackets and strings, or
/// npos.
[[nodiscard]] std::size_t python_colon(std::string_view text, std::size_t from,
                                       std::size_t end);

}  // namespace lsys::expressions
