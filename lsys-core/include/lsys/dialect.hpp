// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string_view>

namespace lsys {

/// The notations lsolid reads, each by its own front end into the same
/// Grammar (docs/dialects/ has a page for each).
enum class Dialect {
  Ls,         ///< lsolid's own: ABOP, cpfg, Houdini as printed (language.md)
  Lparser,    ///< Laurens Lapré's Lparser: numeric header lines, `@` ends
  Fractint,   ///< Fractint `.l` files: `Name { … }` systems
  Lpy,        ///< L-Py's declarative part: `Axiom:`, `production:`
  Cpfg,       ///< cpfg `.l` files: C preprocessor, `Lsystem:`, a `.v` beside
  Lowclouds,  ///< L-system Explorer's `.ls`: `stemsize`, `name = value`
  Lpfg,       ///< lpfg `.l` files: `#include <lpfgall.h>`, C++ rule bodies
};

/// The notation of a text, from its file name's extension and its lines:
/// `.lpy` is L-Py; a file that includes `lpfgall.h` is lpfg; a file that starts
/// (after `#` comments) with two lines that each begin with a number is
/// Lparser; one whose first line (after
/// `;` comments and one-line `{ … }` blocks) is `Name {` is Fractint,
/// unless it is named `.ls`; one that is named neither `.ls` nor `.l` and
/// has `Axiom:` and `production:` lines is L-Py; one not named `.ls` with
/// a line `Lsystem: label` is cpfg; one with a line that sets L-system
/// Explorer's `stemsize`, `dlength` or `view`, or sets several variables
/// separated by `;` (`n=1; delta=22.5`), is Lowclouds' L-system Explorer,
/// whatever its name; anything else is lsolid's own (which reads L-Py- and
/// cpfg-shaped `.ls` files as it always has).
[[nodiscard]] Dialect detect_dialect(std::string_view text,
                                     std::string_view file_name = {});

/// The name `--dialect` takes: `ls`, `lparser`, `fractint`, `lpy`, `cpfg`,
/// `lowclouds`, `lpfg`.
[[nodiscard]] std::string_view dialect_name(Dialect dialect) noexcept;

/// The dialect of a name dialect_name gives, if it is one.
[[nodiscard]] std::optional<Dialect> dialect_named(std::string_view name);

}  // namespace lsys
