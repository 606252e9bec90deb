// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <optional>

#include "lsys/derivation.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/grammar.hpp"
#include "lsys/module_string.hpp"
#include "lsys/skeleton.hpp"

namespace lsys {

/// Choices that override the file while interpreting.
struct InterpretOptions {
  /// Overrides the file's `roll` setting.
  std::optional<RollConvention> roll;
};

/// Derives the grammar and walks the result with the 3D turtle, applying the
/// homomorphism to each module first (docs/turtle.md).
/// @throws ParseError as Derivation; when more segments are drawn than
///   `derivation.max_segments`; for a colour index outside 0 to
///   kMaxColorIndex; and when a position or width overflows. Errors of
///   values are placed at the first module of the grammar that can make
///   them (a module string keeps no source places).
[[nodiscard]] Skeleton interpret(const Grammar& grammar,
                                 const DerivationOptions& derivation = {},
                                 const InterpretOptions& options = {});

/// The error for a skeleton with no segment and no polygon, which cannot be
/// built: placed at what makes it empty where that can be known (the `step`
/// setting when it is 0, an `F(0)`), else at the axiom.
/// @pre `skeleton` has no segment and no polygon.
[[nodiscard]] ParseError nothing_drawn_error(const Grammar& grammar,
                                             const Skeleton& skeleton);

/// The error for a width the build cannot meet, with `message`: placed at
/// the first width module (`!`) whose constant parameter makes a diameter
/// of at least `width` model units, else at the setting of the initial width
/// when that is at least `width`, else at the first width module with a
/// computed parameter, else at the setting of the initial width, else at the
/// axiom.
[[nodiscard]] ParseError width_error(const Grammar& grammar, double width,
                                     std::string message);

}  // namespace lsys
