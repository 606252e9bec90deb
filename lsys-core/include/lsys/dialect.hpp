// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string_view>

namespace lsys {

/// The notations lsolid reads, each by its own front end into the same
/// Grammar (docs/dialects/ has a page for each).
enum class Dialect {
  Ls,        ///< lsolid's own: ABOP, cpfg, Houdini as printed (language.md)
  Lparser,   ///< Laurens Lapré's Lparser: numeric header lines, `@` ends
  Fractint,  ///< Fractint `.l` files: `Name { … }` systems
  Lpy,       ///< L-Py's declarative part: `Axiom:`, `production:`
};

/// The notation a text is written in, judged from its lines: an Lparser
/// file starts (after `#` comments) with lines holding one number each, a
/// Fractint file with `Name {`, an L-Py file has `Axiom:` and
/// `production:` lines; anything else is lsolid's own.
[[nodiscard]] Dialect detect_dialect(std::string_view text);

/// The name `--dialect` takes: `ls`, `lparser`, `fractint`, `lpy`.
[[nodiscard]] std::string_view dialect_name(Dialect dialect) noexcept;

/// The dialect of a name dialect_name gives, if it is one.
[[nodiscard]] std::optional<Dialect> dialect_named(std::string_view name);

}  // namespace lsys
