// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace lsys {

/// A predefined surface that a module draws where the turtle stands
/// (cpfg's `~l`, meshed from a `.s` file of Bézier patches): a triangle
/// mesh whose patches share the points on their common edges. Coordinates
/// are in the turtle's frame: x along left, y along the heading, z along
/// cpfg's up (which is lsolid's −up), with the contact point at the origin.
struct Surface {
  std::vector<glm::dvec3> points;
  /// Indices into `points`, three distinct each; patches keep their own
  /// orientation (a sheet has two sides).
  std::vector<std::array<std::uint32_t, 3>> triangles;
  /// Where the turtle goes after drawing it, in the same frame.
  glm::dvec3 end_point{0.0};
};

}  // namespace lsys
