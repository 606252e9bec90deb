// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>

namespace lsolid {

/// A triangle of a mesh: its vertices' indices and their positions.
struct IndexedTriangle {
  std::array<std::uint32_t, 3> ids{};
  std::array<glm::dvec3, 3> points{};
};

/// True when the triangle's corners are collinear or repeated, decided with
/// exact predicates.
[[nodiscard]] bool is_degenerate(const IndexedTriangle& t);

/// True when two triangles of one mesh meet anywhere but at the vertices or
/// the edge they share (told apart by index), decided with exact predicates
/// as CGAL's self-intersection test decides it. Triangles sharing all three
/// vertices, or a degenerate one, count as meeting.
[[nodiscard]] bool triangles_intersect(const IndexedTriangle& a,
                                       const IndexedTriangle& b);

}  // namespace lsolid
