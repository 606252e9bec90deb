// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <optional>
#include <vector>

namespace lsolid {

/// A connected region of the plane: its boundary and a triangulation of its
/// inside that uses only the boundary's vertices.
struct PlanarRegion {
  std::vector<glm::dvec2> points;  ///< each boundary vertex once
  /// The outer boundary counter-clockwise first, then the holes clockwise,
  /// as indices into `points`; no vertex is on two rings or twice on one.
  std::vector<std::vector<std::uint32_t>> rings;
  /// Counter-clockwise triangles covering the region exactly.
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

/// The union of simple polygons (either orientation), computed exactly
/// (CGAL's Boolean set operations on Epeck) and rounded to doubles, as
/// regions that touch nothing else: two leaf polygons that overlap or share
/// an edge become one region.
/// @returns nothing if a polygon is not simple, or if the rounded union
///   cannot be triangulated without new points or has a ring that touches
///   itself or another (a pinch point would make a non-manifold plate).
[[nodiscard]] std::optional<std::vector<PlanarRegion>> polygon_union(
    const std::vector<std::vector<glm::dvec2>>& polygons);

}  // namespace lsolid
