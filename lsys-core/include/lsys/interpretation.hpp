// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <optional>

#include "lsys/derivation.hpp"
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
/// @throws ParseError as Derivation, and when more segments are drawn than
///   `derivation.max_segments`.
[[nodiscard]] Skeleton interpret(const Grammar& grammar,
                                 const DerivationOptions& derivation = {},
                                 const InterpretOptions& options = {});

/// Walks a given string of modules of the grammar's alphabet.
/// @throws ParseError when a homomorphism expression fails.
[[nodiscard]] Skeleton interpret_string(const Grammar& grammar,
                                        const ModuleString& modules,
                                        const InterpretOptions& options = {});

}  // namespace lsys
