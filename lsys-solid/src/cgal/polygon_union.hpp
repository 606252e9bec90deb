// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>
#include <optional>
#include <vector>

namespace lsolid {

/// A connected region of the plane: a triangulation of it and its boundary.
struct PlanarRegion {
  /// The triangulation's vertices: the boundary's and, where polygon edges
  /// crossed inside the region, those crossings.
  std::vector<glm::dvec2> points;
  /// The boundary as indices into `points`, each ring with the region on
  /// its left (the outer one counter-clockwise, holes clockwise); no vertex
  /// is on two rings or twice on one.
  std::vector<std::vector<std::uint32_t>> rings;
  /// Counter-clockwise triangles covering the region exactly.
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

/// The union of simple polygons (either orientation), computed exactly
/// (a constrained Delaunay triangulation of their edges on Epeck, with
/// exact intersections) and rounded to doubles, as regions joined across
/// edges: two leaf polygons that overlap or share an edge become one region.
/// @returns nothing if a polygon is not simple, a region's boundary touches
///   itself at a vertex (the plate would not be a 2-manifold), or rounding
///   to doubles would merge two vertices or turn a triangle over.
[[nodiscard]] std::optional<std::vector<PlanarRegion>> polygon_union(
    const std::vector<std::vector<glm::dvec2>>& polygons);

}  // namespace lsolid
