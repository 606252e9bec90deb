// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "lsys/source.hpp"

namespace lsys::dialects {

class CompanionFiles;

/// How cpfg's preprocessing differs from plain C's.
struct PreprocessOptions {
  /// `NAME=VALUE` texts (`--define`): a macro of that name is kept as a
  /// constant whatever its body, so that the grammar gives it the value.
  std::vector<std::string> defines;
  /// A line break followed by a tab continues the line, as cpfg's lexer
  /// reads its files; the break becomes a blank.
  bool tab_continues = false;
  /// A line break followed by a blank or a tab continues the line, as
  /// L-System Explorer reads its files; statement blocks span lines.
  bool indent_continues = false;
  /// Numeric macros stay `#define` constants (the `.l`); without it every
  /// macro expands as text (the `.v`, which knows no constants).
  bool keep_constants = true;
  /// Macros defined before the text, as `-D` gives them (cpfg passes the
  /// names of a function set this way); always expanded.
  std::vector<std::pair<std::string, std::string>> predefined;
  /// `//` starts a comment, as in C; L-system Explorer's preprocessor
  /// keeps it, as two rolls (`F//`).
  bool line_comments = true;
  /// Headers whose `#include <…>` or `#include "…"` is dropped (lpfg's
  /// `lpfgall.h` and C's `math.h`, whose names lsolid knows already);
  /// another `#include "…"` reads the file through `companions`, and
  /// another `#include <…>` is an error.
  std::vector<std::string> ignored_headers;
  /// The files the model may read; without them `#include "…"` is an
  /// error. Not owned.
  CompanionFiles* companions = nullptr;
};

/// Runs the C preprocessor that cpfg runs on its `.l` and `.v` files
/// (docs/dialects/cpfg.md): `/* */` and `//` comments, `#define` with and
/// without parameters, `#undef`, `#if`/`#ifdef`/`#ifndef`/`#elif`/`#else`/
/// `#endif`, `\` line splices, `#include "file"` of a file beside the
/// source (its text an expansion of the directive; CompanionFiles says
/// which files may be read). The whole work is bounded: an argument is
/// expanded only where the macro's body uses it, and the text written, the
/// bytes scanned while expanding and the `#include`s read are limited. A macro
/// whose body is a number, a parenthesised expression of numbers and such
/// macros, or one such macro is a constant: its `#define` line stays and its
/// uses are not expanded, so that the grammar reads it as a constant
/// (`--define`, the viewer's controls) with the same value as textual expansion
/// gives. Other directive lines become empty; every line stays on its line, and
/// diagnostics point to the original text (SourceFile's spans).
/// @throws ParseError at an `#include` of a system header or of a file
///   that is not there or may not be read (and in the included file), at
///   the line whose expansion passes a limit, an unknown directive,
///   `#error`, an unbalanced `#if`, a malformed `#define`, or a macro
///   called with the wrong number of arguments.
[[nodiscard]] std::shared_ptr<const SourceFile> preprocess(
    const SourceFile& source, const PreprocessOptions& options);

}  // namespace lsys::dialects
