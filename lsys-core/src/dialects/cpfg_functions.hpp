// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "lsys/source.hpp"

namespace lsys::dialects {

/// A function of cpfg's `func(id, x)`, drawn in vlab's funcedit: its name
/// and its values y at equally spaced x from 0 to 1.
struct CpfgFunction {
  std::string name;
  std::vector<double> samples;
};

/// Reads a `.func` file (one function) or a `.fset` gallery (several), as
/// vlab's tools write them (docs/dialects/cpfg.md): control points of a
/// clamped cubic B-spline (x, y), repeated by their multiplicity; y is
/// read off where the curve's x equals x, sampled as the file's
/// `samples:` says, else at 1,001 points.
/// @throws ParseError at what is not such a file.
[[nodiscard]] std::vector<CpfgFunction> read_cpfg_functions(
    const SourceFile& file);

}  // namespace lsys::dialects
