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

/// The millimetres per model unit that give the skeleton the height,
/// longest side or scale asked for (with none, the longest side becomes
/// kDefaultSizeMm), counting tube radii clamped to the wall. It reckons
/// with round tubes only; build_solid corrects it by measuring the placed
/// parts, whose mitres, joints and base reach beyond.
/// @throws GeometryError when the skeleton draws nothing or has no extent.
[[nodiscard]] double estimate_scale(const lsys::Skeleton& skeleton,
                                    const PrintSettings& settings);

/// A model-unit skeleton at `mm_per_unit`, with every diameter at least
/// `wall_mm`.
[[nodiscard]] ScaledSkeleton scale_skeleton(const lsys::Skeleton& skeleton,
                                            double mm_per_unit, double wall_mm);

/// scale_skeleton at estimate_scale: the skeleton in millimetres as the
/// print settings ask.
/// @throws GeometryError when the skeleton draws nothing or has no extent.
[[nodiscard]] ScaledSkeleton scale_to_print(const lsys::Skeleton& skeleton,
                                            const PrintSettings& settings);

}  // namespace lsolid
