// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once
#include "lsys/expression.hpp"
#include "lsys/grammar.hpp"
#include "lsys/module_string.hpp"

namespace lsys {

/// True when the axiom or a production writes a query module (cpfg's `?P`,
/// `?H`, `?L`, `?U`), whose answers need the whole string each step.
[[nodiscard]] bool uses_queries(const Grammar& grammar);

/// Walks `modules` with the turtle, as interpret does, and writes the
/// position or frame where each query module stands into its parameters
/// (at most three; fewer when the module has fewer).
/// @throws ParseError as interpret, for what the walk meets.
void answer_queries(const Grammar& grammar, ModuleString& modules,
                    Variables* variables);

}  // namespace lsys
