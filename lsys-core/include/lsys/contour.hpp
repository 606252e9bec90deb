// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec2.hpp>
#include <vector>

namespace lsys {

/// More points around a ring swept from a contour than this only cost time
/// (cpfg warns above 1024; its own views use up to 14).
inline constexpr int kMostContourSides = 256;

/// A cross-section for cpfg's generalized cylinders other than the circle
/// (`@#(id)` and the view file's `contour: id file.con`): a uniform cubic
/// B-spline in the plane of the cylinder's ring, its control points in
/// units of the ring's radius, x along cpfg's up and y along its right
/// (docs/dialects/cpfg.md). A point given k times in the file is here k
/// times, which is how vlab's contour editor makes the curve reach its end
/// points.
struct Contour {
  std::vector<glm::dvec2> control_points;
  /// A closed contour joins its last control point to its first.
  bool closed = false;
};

/// The contour's curve at `sides` + 1 points (the first and last its two
/// ends) spaced evenly by arc length, as cpfg places a ring's points.
/// @pre the contour is open, with at least 4 control points, and
///   `sides` ≥ 1.
[[nodiscard]] std::vector<glm::dvec2> sample_contour(const Contour& contour,
                                                     int sides);

}  // namespace lsys
