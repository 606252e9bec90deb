// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include "lsolid/print_settings.hpp"
#include "lsys/skeleton.hpp"

namespace lsolid {

/// A skeleton in millimetres, with every diameter at least the wall.
struct ScaledSkeleton {
  lsys::Skeleton skeleton;
  double mm_per_unit = 1.0;
};

/// Scales a model-unit skeleton to the requested height, longest side or
/// scale, counting tube radii (after clamping to the wall) in the size, and
/// clamps every diameter to at least `settings.wall_mm`.
/// @throws GeometryError when the skeleton draws nothing or has no extent.
[[nodiscard]] ScaledSkeleton scale_to_print(const lsys::Skeleton& skeleton,
                                            const PrintSettings& settings);

}  // namespace lsolid
