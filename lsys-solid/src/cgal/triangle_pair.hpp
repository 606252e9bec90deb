// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <utility>
#include <vector>

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

/// triangles_intersect for two triangles known not to be degenerate (a
/// caller that tests one triangle against many decides that once).
/// @pre !is_degenerate(a) && !is_degenerate(b)
[[nodiscard]] bool proper_triangles_intersect(const IndexedTriangle& a,
                                              const IndexedTriangle& b);

/// The pairs of `triangles` (of one mesh) that meet anywhere but at the
/// vertices or the edge they share, the pairs CGAL's self-intersection test
/// (PMP::self_intersections) finds on a Surface_mesh of the same faces and
/// vertices: first each degenerate triangle paired with itself (and with no
/// other), then the others as (i, j), i < j, in increasing order. The boxes
/// are searched (meeting_box_pairs) and the pairs whose boxes meet tested on
/// oneTBB's threads.
[[nodiscard]] std::vector<std::pair<std::uint32_t, std::uint32_t>>
intersecting_pairs(const std::vector<IndexedTriangle>& triangles);

/// intersecting_pairs, where the triangles i with `settled[i]` set are
/// known to meet no other settled triangle (a pass of rounding tested them
/// as they are): pairs of two settled triangles are neither searched nor
/// tested.
/// @pre settled.size() == triangles.size().
[[nodiscard]] std::vector<std::pair<std::uint32_t, std::uint32_t>>
intersecting_pairs(const std::vector<IndexedTriangle>& triangles,
                   const std::vector<char>& settled);

}  // namespace lsolid
