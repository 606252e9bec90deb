// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include "lsolid/mesh.hpp"

namespace lsolid {

/// The symmetric Hausdorff distance between two surfaces in millimetres:
/// the farthest any point of one lies from the other. Exact to within
/// `error_bound_mm` (CGAL's bounded-error Hausdorff distance); slow where
/// large coplanar faces of the two coincide. Not part of the library's
/// interface: the tests' independent check of the deviation that the
/// decimation measures by sampling, compiled here so that it shares the
/// CGAL translation units' one policy (lsys-solid/CMakeLists.txt).
/// @pre both meshes are non-empty triangle meshes that CGAL can stitch into
///   oriented surfaces.
/// @throws GeometryError if one cannot be stitched.
[[nodiscard]] double hausdorff_distance_mm(const TriangleMesh& a,
                                           const TriangleMesh& b,
                                           double error_bound_mm);

}  // namespace lsolid
