// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include "lsolid/mesh.hpp"

namespace lsolid {

/// The symmetric Hausdorff distance between two surfaces in millimetres:
/// the farthest any point of one lies from the other. Exact to within
/// `error_bound_mm` (CGAL's bounded-error Hausdorff distance); slow where
/// large coplanar faces of the two coincide.
/// @pre both meshes are non-empty triangle meshes that CGAL can stitch into
///   oriented surfaces.
/// @throws GeometryError if one cannot be stitched.
[[nodiscard]] double hausdorff_distance_mm(const TriangleMesh& a,
                                           const TriangleMesh& b,
                                           double error_bound_mm);

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
