// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <limits>

namespace lsys {

/// An axis-aligned box: of a skeleton in model units, or of a mesh in
/// millimetres (lsolid::Box). Empty, `min > max` (infinities), until a
/// point is added.
struct Bounds {
  glm::dvec3 min{std::numeric_limits<double>::infinity()};
  glm::dvec3 max{-std::numeric_limits<double>::infinity()};

  /// True until a point is added.
  [[nodiscard]] bool empty() const noexcept { return min.x > max.x; }
  /// The extent along each axis.
  [[nodiscard]] glm::dvec3 size() const noexcept { return max - min; }
  /// Grows the box to hold `p`.
  void add(const glm::dvec3& p) noexcept {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
};

}  // namespace lsys
