// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "lsys/bounds.hpp"

namespace lsys {

/// What the turtle drew. Coordinates are in model units: one unit is the
/// default step of `F`. Z is up (the printing direction).
///
/// A drawn segment (ABOP's internode): a frustum from p0 to p1.
struct Segment {
  glm::dvec3 p0{0.0};
  glm::dvec3 p1{0.0};
  double start_diameter = 0.0;
  double end_diameter = 0.0;
  int color = 0;
  /// The segment this one continues from (the turtle drew it last and has
  /// not moved without drawing since), or -1. A branch's first segment
  /// names the segment it branches from.
  std::int32_t parent = -1;
};

/// A filled polygon from `{ … }` (ABOP §5.1): a leaf or petal.
struct Polygon {
  std::vector<glm::dvec3> points;  ///< at least 3, no two consecutive equal
  int color = 0;
  /// The segment drawn last before `{`, which the polygon grows from, or -1.
  std::int32_t parent = -1;
};

/// A ball from `@O` (cpfg's sphere): a berry, a bud, a joint's knob.
struct Sphere {
  glm::dvec3 center{0.0};
  double diameter = 0.0;
  int color = 0;
  /// The segment drawn last before it, which it sits on, or -1.
  std::int32_t parent = -1;
};

/// A curved leaf or petal from a predefined surface (cpfg's `~l`): a
/// triangle mesh without thickness, in model units. Its patches share the
/// points of their common edges; each triangle has three distinct points.
struct Sheet {
  std::vector<glm::dvec3> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  int color = 0;
  /// The segment drawn last before it, which it grows from, or -1.
  std::int32_t parent = -1;
};

/// The interpretation of a derived string.
struct Skeleton {
  std::vector<Segment> segments;
  std::vector<Polygon> polygons;
  std::vector<Sphere> spheres;
  std::vector<Sheet> sheets;
  /// Polygons dropped because fewer than 3 distinct points remained, and
  /// surfaces drawn at a scale that leaves them no area.
  std::size_t degenerate_polygons = 0;
  /// `{` never closed by `}` (dropped), and `}` without an open `{`.
  std::size_t unclosed_polygons = 0;
  std::size_t unmatched_polygon_ends = 0;
  /// Segments of length 0 (`F(0)`, or `F` with `step: 0`), or too short
  /// to move the turtle from where it stands, not drawn.
  std::size_t zero_length_segments = 0;
};

/// Whether the turtle drew nothing at all: no segment, polygon, sphere or
/// sheet.
[[nodiscard]] inline bool draws_nothing(const Skeleton& skeleton) noexcept {
  return skeleton.segments.empty() && skeleton.polygons.empty() &&
         skeleton.spheres.empty() && skeleton.sheets.empty();
}

/// The box of what the skeleton draws: segments' ends, polygons' and
/// sheets' points, and balls whole (tube widths are not counted). Empty
/// when it draws nothing.
[[nodiscard]] Bounds bounds(const Skeleton& skeleton);

}  // namespace lsys
