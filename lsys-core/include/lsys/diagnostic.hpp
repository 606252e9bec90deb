// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#include "lsys/source.hpp"

namespace lsys {

/// One error in the user's input: where it is and what is wrong.
struct Diagnostic {
  std::string file;         ///< file name as the user gave it
  int line = 0;             ///< 1-based; 0 when the error concerns the file
  int column = 0;           ///< 1-based, in code points; 0 with line 0
  std::string message;      ///< one sentence, no trailing period
  std::string source_line;  ///< the text of `line`, for the caret display
};

/// The one exception for bad input: a malformed `.ls` file, a bad
/// `--define`, an expression that divides by zero while deriving, or a
/// derivation that would exceed the size limits. `what()` is
/// `file:line:col: error: message`.
class ParseError : public std::runtime_error {
 public:
  explicit ParseError(Diagnostic diagnostic);
  /// The structured form, for printing with a caret.
  [[nodiscard]] const Diagnostic& diagnostic() const noexcept {
    return diagnostic_;
  }

 private:
  Diagnostic diagnostic_;
};

/// Builds the error for a byte offset of a source.
/// @pre `offset <= source.text().size()`.
[[nodiscard]] ParseError error_at(const SourceFile& source, std::size_t offset,
                                  std::string message);

/// Formats a diagnostic as compilers do: `file:line:col: error: message`,
/// then the source line and a caret under the column. Ends with a newline.
[[nodiscard]] std::string format_diagnostic(const Diagnostic& diagnostic);

}  // namespace lsys
