// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <optional>

#include "lsolid/mesh.hpp"

namespace lsolid {

/// What lies above the plane z = `z_mm`, closed again by a flat face in that
/// plane: the underside a planar model lies on. Computed exactly (CGAL's
/// clip with clip_volume on exact coordinates), then rounded to doubles.
/// Nothing when CGAL cannot cut it or close the cut.
/// @pre `mesh` is closed, outward and free of self-intersections.
[[nodiscard]] std::optional<TriangleMesh> cut_below(const TriangleMesh& mesh,
                                                    double z_mm);

}  // namespace lsolid
