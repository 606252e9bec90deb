// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include "lsys/source.hpp"
#include "lsys/surface.hpp"

namespace lsys::dialects {

/// How a view file's `surface:` line asks for a surface to be meshed.
struct SurfaceOptions {
  double size = 1.0;    ///< model units for the file's SIZE
  int s_divisions = 0;  ///< per patch, 0: the file's PRECISION, else 5
  int t_divisions = 0;
};

/// Reads a cpfg surface file (`.s`, vlab's bezieredit) and meshes its
/// bicubic Bézier patches into triangles, as cpfg does
/// (docs/dialects/cpfg.md): the contact point at the origin, the file's
/// HEADING and UP turned onto the turtle's, sizes scaled by size / SIZE.
/// @throws ParseError at what does not read as such a file.
[[nodiscard]] Surface read_cpfg_surface(const SourceFile& file,
                                        const SurfaceOptions& options);

}  // namespace lsys::dialects
