// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <utility>
#include <vector>

#include "lsolid/mesh.hpp"

namespace lsolid {

/// The triangles of the convex hull of `points`, as indices into `points`,
/// outward-oriented. Points inside the hull, or inside one of its faces, are
/// not used. Empty if the points span no volume.
[[nodiscard]] std::vector<std::array<std::uint32_t, 3>> convex_hull_triangles(
    const std::vector<glm::dvec3>& points);

/// The pairs of triangles of `mesh` that intersect other than along the
/// edge or at the vertex they share, decided with exact predicates: each
/// degenerate triangle paired with itself, then the others as (i, j),
/// i < j, in increasing order (intersecting_pairs), whatever the threads.
/// @pre `mesh` is an oriented 2-manifold (closed or not).
/// @throws GeometryError if it is not.
[[nodiscard]] std::vector<std::pair<std::uint32_t, std::uint32_t>>
intersecting_triangle_pairs(const TriangleMesh& mesh);

}  // namespace lsolid
