// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>

#include "lsys/skeleton.hpp"

namespace lsolid {

/// A skeleton without its repeated segments, and how many were left out.
struct WithoutRepeats {
  lsys::Skeleton skeleton;
  std::size_t dropped = 0;  ///< segments drawn again over an earlier one
  std::size_t dropped_spheres = 0;  ///< balls inside another ball
};

/// Leaves out each segment that repeats an earlier one: the same start and
/// end (to 10⁻⁹ of the skeleton's extent, in the same direction), the same
/// colour, and a frustum that one of the two contains (no wider at either
/// end; the one kept takes the wider diameters). Segments and polygons that
/// hung from a segment left out hang from the one kept; the order of what
/// is kept is unchanged. So the printed shape is the same, but the union
/// does not meet two tubes face on face: ABOP fig. 1.24b draws 1,365 of its
/// 3,125 segments twice. Likewise each `@O` ball that a larger (or, of the
/// same size, an earlier) ball holds is left out.
[[nodiscard]] WithoutRepeats without_repeated_segments(
    const lsys::Skeleton& skeleton);

}  // namespace lsolid
