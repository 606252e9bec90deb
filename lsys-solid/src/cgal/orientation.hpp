// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec3.hpp>

namespace lsolid {

/// The sign of ((b − a) × (c − a)) · (d − a), decided exactly on the doubles
/// as they are (CGAL's filtered orientation): 0 when d lies in the plane
/// through a, b and c, or when a, b, c are collinear.
[[nodiscard]] int orientation_3(const glm::dvec3& a, const glm::dvec3& b,
                                const glm::dvec3& c, const glm::dvec3& d);

/// How triangle abc turns seen along coordinate `axis` (its projection
/// onto the next two coordinates, in cyclic order), decided exactly: the
/// sign of the axis's coordinate of (b − a) × (c − a).
/// @pre 0 <= axis < 3
[[nodiscard]] int projected_orientation(const glm::dvec3& a,
                                        const glm::dvec3& b,
                                        const glm::dvec3& c, int axis);

}  // namespace lsolid
