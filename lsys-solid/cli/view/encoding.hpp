// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "lsolid/mesh.hpp"
#include "lsys/skeleton.hpp"

namespace lsolid::cli::view {

/// The page's binary forms (little-endian, every number 4 bytes, so that
/// JavaScript reads them as typed arrays without copying; coordinates are
/// millimetres).

/// A skeleton: "LSK1"; the segment count and the polygon count (uint32);
/// per segment x0 y0 z0 x1 y1 z1 r0 r1 (float32) and its colour index
/// (uint32); per polygon its point count and colour index (uint32) and its
/// points (float32 x y z).
[[nodiscard]] std::string encode_skeleton(const lsys::Skeleton& skeleton);

/// A mesh: "LSM1"; the vertex count and the triangle count (uint32); the
/// vertices (float32 x y z); the triangles (uint32 × 3); per triangle its
/// colour index (uint32) and whether it overhangs (uint32 0 or 1).
/// @pre `colors` and `overhang` are empty or hold one entry per triangle.
[[nodiscard]] std::string encode_mesh(const TriangleMesh& mesh,
                                      const std::vector<int>& colors,
                                      const std::vector<bool>& overhang);

}  // namespace lsolid::cli::view
