// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include "lsolid/mesh.hpp"

namespace lsolid {

/// How deep the surface of `a` reaches into the solid `b`: the largest
/// distance to `b`'s surface of those vertices, edge midpoints and triangle
/// centres of `a` that lie inside `b`; 0 when the solids only touch. A
/// sampled measure (CGAL's AABB tree and Side_of_triangle_mesh): two
/// volumes of a multi-material print must not overlap.
/// @pre `b` is closed and outward.
/// @throws GeometryError if `b` cannot be stitched.
[[nodiscard]] double overlap_depth_mm(const TriangleMesh& a,
                                      const TriangleMesh& b);

}  // namespace lsolid
