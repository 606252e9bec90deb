// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>

#include "lsolid/mesh.hpp"

namespace lsolid {

/// A UV sphere about `center` whose faces all lie `needed` or farther from
/// it, as a tube's sides touch its circle (as many meridians as
/// tube_sides gives, at least 8); turned by `index` golden steps of a
/// meridian so that neighbouring balls' seams lie apart. Closed and
/// outward-oriented.
/// @pre needed > 0, tolerance_mm > 0.
[[nodiscard]] TriangleMesh uv_ball(const glm::dvec3& center, double needed,
                                   std::size_t index, double tolerance_mm);

/// A joint: a UV sphere about `center` that encloses the corners of every
/// tube cap of `radius` there (its faces 1.06 times as far as the corners),
/// so no cap coincides with another part.
[[nodiscard]] TriangleMesh joint_sphere(const glm::dvec3& center, double radius,
                                        std::size_t index, double tolerance_mm);

}  // namespace lsolid
