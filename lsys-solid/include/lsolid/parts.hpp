// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "lsolid/mesh.hpp"
#include "lsys/skeleton.hpp"

namespace lsolid {

/// A closed, outward-oriented solid of the model, before the union.
struct Part {
  TriangleMesh mesh;
  std::string label;  ///< what it is, for messages: "tube of segments 3-7"
};

/// How to mesh the skeleton.
struct PartOptions {
  double wall_mm = 0.8;        ///< leaf plate thickness
  double tolerance_mm = 0.05;  ///< chord error of tube cross-sections
};

/// The parts and what they came from.
struct PartSet {
  std::vector<Part> parts;
  std::size_t tubes = 0;
  std::size_t joints = 0;
  std::size_t plates = 0;
  /// Polygons without area or whose outline crosses itself: not printed.
  std::size_t skipped_polygons = 0;
};

/// Meshes a millimetre skeleton (see scale_to_print) into parts whose union
/// is the model: one swept tube per unbranched chain of segments, with
/// mitred bends and shared rings; a joint solid wherever chains meet or a
/// chain breaks at a sharp bend, enclosing the tubes' end caps; and a plate
/// of wall thickness for each polygon, fused by a joint to the segment it
/// grows from.
[[nodiscard]] PartSet build_parts(const lsys::Skeleton& skeleton,
                                  const PartOptions& options = {});

/// The number of sides of a tube of this radius whose flat sides stay
/// within `tolerance_mm` of the circle (at least 6).
[[nodiscard]] int tube_sides(double radius_mm, double tolerance_mm);

}  // namespace lsolid
