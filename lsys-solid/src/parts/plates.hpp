// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <utility>
#include <vector>

#include "lsolid/mesh.hpp"
#include "lsolid/parts.hpp"
#include "lsys/skeleton.hpp"

namespace lsolid {

/// The leaf plates of a skeleton's polygons.
struct Plates {
  std::vector<Part> parts;
  std::size_t plates = 0;
  /// Polygons without area or whose outline crosses itself: not printed.
  std::size_t skipped = 0;
  /// The polygons made plates, in the order their tip joints are to be
  /// asked for (by group of coplanar polygons, each group's in order).
  std::vector<std::size_t> tip_order;
  /// Corners that plates in different planes share exactly (the turtle
  /// drew their polygons from one point: the petals of a flower), each
  /// once, in the order of the first polygon there, with its colour.
  std::vector<std::pair<glm::dvec3, int>> shared_corners;
};

/// Each polygon as a plate a little thicker than the thinnest tube:
/// triangulated in its Newell plane, offset by half the plate's thickness
/// to each side, walled around. Polygons that lie in one plane (within
/// 10⁻⁹ of `scale_mm`) and overlap or share edges are united in that plane
/// first, when PartOptions::unite_coplanar_polygons is set, and each region
/// of their union becomes one plate.
[[nodiscard]] Plates build_plates(const lsys::Skeleton& skeleton,
                                  const PartOptions& options, double scale_mm);

}  // namespace lsolid
