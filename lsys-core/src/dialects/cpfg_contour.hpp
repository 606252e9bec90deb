// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include "lsys/contour.hpp"
#include "lsys/source.hpp"

namespace lsys::dialects {

/// Reads a contour file of vlab's contour editor (`.con`, versions 1.1 to
/// 1.3, or the older `num dim open|closed` header): its control points,
/// each repeated as many times as the file says, and whether it is closed
/// (docs/dialects/cpfg.md). A third coordinate must be 0.
/// @throws ParseError at what does not read as such a file, or at a
///   contour that is not a curve (fewer than 4 control points, or all in
///   one place).
[[nodiscard]] Contour read_cpfg_contour(const SourceFile& file);

}  // namespace lsys::dialects
