// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace lsys {

/// `v` rotated about the unit axis `k` by the angle whose cosine is `c` and
/// sine is `s`, right-handed (Rodrigues' rotation formula). The turtle's
/// tropism and heading changes and the mesher's ring frames all turn
/// vectors this way.
/// @pre `k` has unit length and c² + s² = 1.
[[nodiscard]] inline glm::dvec3 rotate_about(const glm::dvec3& v,
                                             const glm::dvec3& k, double c,
                                             double s) noexcept {
  return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1.0 - c);
}

}  // namespace lsys
