// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

namespace lsolid {

/// The print settings a maker gets without asking, each stated once: the
/// option structs of every stage and the command line's help take them
/// from here.

/// The thinnest wall: a 0.4 mm nozzle's two perimeters.
inline constexpr double kDefaultWallMm = 0.8;
/// How far a tube's flat sides may lie inside its circle's corners, and
/// how far decimation may move the surface.
inline constexpr double kDefaultToleranceMm = 0.05;
/// The longest side of a model given no height, size or scale.
inline constexpr double kDefaultSizeMm = 100.0;

}  // namespace lsolid
