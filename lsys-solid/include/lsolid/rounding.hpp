// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>

#include "lsolid/mesh.hpp"

namespace lsolid {

/// What rounding had to mend.
struct RoundingStats {
  int passes = 0;  ///< rounds of repair needed
  std::size_t slivers_removed =
      0;  ///< almost degenerate faces collapsed or flipped
  std::size_t faces_rebuilt = 0;  ///< self-intersecting faces replaced
  /// Rebuilds CGAL refused (its preconditions) and that were left to the
  /// next pass.
  std::size_t repairs_refused = 0;
  /// The volume of the result less that of the input, in mm³, summed over
  /// calls.
  double volume_change_mm3 = 0.0;
};

/// How to round.
struct RoundingOptions {
  /// Round to floats, as STL and 3MF store them; otherwise to doubles
  /// (OFF and OBJ are written at full precision).
  bool float_coordinates = true;
};

/// A rounded mesh and what it took.
struct Rounded {
  TriangleMesh mesh;
  RoundingStats stats;
};

/// Adds what a later rounding of the same model mended to `total`: the
/// counts and the volume change add up; `passes` becomes the later one's.
void accumulate(RoundingStats& total, const RoundingStats& later);

/// Rounds a union's coordinates to what the file will store (floats for STL)
/// and mends what rounding breaks. An exact union has slivers, edges of
/// 10⁻⁸ mm and near-tangent sheets (docs/design.md, "Rounding"); rounding
/// them makes degenerate and self-intersecting faces. Each pass rounds,
/// collapses edges shorter than 10⁻⁴ mm, flips caps lower than that, and
/// rebuilds the faces that still intersect (CGAL's
/// experimental::remove_self_intersections), until none is left. Every
/// coordinate of the result is representable in the output format, so
/// validating the result validates the file.
/// @pre the mesh is closed and 2-manifold.
/// @throws GeometryError if it is not a 2-manifold.
[[nodiscard]] Rounded round_and_repair(const TriangleMesh& mesh,
                                       const RoundingOptions& options = {});

}  // namespace lsolid
