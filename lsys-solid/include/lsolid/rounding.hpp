// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <optional>

#include "lsolid/colors.hpp"
#include "lsolid/mesh.hpp"
#include "lsolid/precision.hpp"

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
  /// The result is the mesh repaired with slivers collapsed only where
  /// rebuilding alone made no progress: collapsing them all left faces that
  /// meet, or more of them after the first pass.
  bool slivers_kept = false;
  /// The ways of repairing carried to their end, summed over calls: a second
  /// when the first left faces that meet (round_and_repair).
  int ways_tried = 0;
};

/// How to round.
struct RoundingOptions {
  /// What the file keeps of a coordinate (floats for STL, doubles for OFF
  /// and OBJ, grids for 3MF and OpenSCAD).
  Precision precision;
  /// Whether a repair that leaves faces meeting is carried on the other way
  /// too (round_and_repair). The union's own mends, which have other ways
  /// out (a shift, the corefinement), carry on only the way their first
  /// passes chose.
  bool retry_keeping_slivers = true;
};

/// A rounded mesh and what it took.
struct Rounded {
  TriangleMesh mesh;
  RoundingStats stats;
  /// The last pass found no intersecting and no degenerate face (the
  /// passes did not run out first).
  bool clean = false;
  /// round_for rounded a `.scad` to floats, six significant digits being
  /// more than its faces could be mended at.
  bool as_floats = false;
};

/// Adds what a later rounding of the same model mended to `total`: the
/// counts and the volume change add up; `passes` becomes the later one's.
void accumulate(RoundingStats& total, const RoundingStats& later);

/// Rounds a union's coordinates to what the file will store (floats for STL,
/// RoundingOptions::precision) and mends what rounding breaks. An exact union
/// has slivers, edges of 10⁻⁸ mm and near-tangent sheets (docs/design.md,
/// "Rounding"); rounding them makes degenerate and self-intersecting faces.
/// Each pass rounds, collapses edges shorter than 10⁻⁴ mm, flips caps lower
/// than that, and rebuilds the faces that still intersect (CGAL's
/// experimental::remove_self_intersections), until none is left. The other
/// way collapses and flips slivers only where a pass of rebuilding made no
/// progress (RoundingStats::slivers_kept). When more than a hundred pairs of
/// faces meet after the first pass of the first way, the second makes its
/// first pass too and the way that left fewer goes on; if faces still meet
/// after its last pass, the other way is carried on, and kept if it leaves
/// none. Every
/// coordinate of the result is representable in the output format, so
/// validating the result validates the file.
/// @pre the mesh is closed and 2-manifold.
/// @throws GeometryError if it is not a 2-manifold.
[[nodiscard]] Rounded round_and_repair(const TriangleMesh& mesh,
                                       const RoundingOptions& options = {});

/// round_and_repair at the precision of `format` (precision_for, at the
/// mesh's reach). A `.scad` whose faces cannot all be mended at six
/// significant digits (blog tree C left 43 pairs of faces finer than 10⁻⁴
/// mm) is rounded to floats instead, which OpenSCAD reads exactly too, but
/// which its STL export may break (Rounded::as_floats).
/// @throws GeometryError as round_and_repair.
[[nodiscard]] Rounded round_for(const TriangleMesh& mesh, MeshFormat format);

/// A printable mesh as a file of `format` keeps it (precision_for):
/// snapped, and mended as round_and_repair mends where snapping breaks it;
/// nothing when it is not printable at that precision. Triangles keep
/// their order when snapping alone suffices (so a colour per triangle
/// still fits them).
[[nodiscard]] std::optional<TriangleMesh> rounded_for(const TriangleMesh& mesh,
                                                      MeshFormat format);

/// As rounded_for, keeping a colour per triangle: a triangle that mending
/// made new takes the colour of a triangle that had one of its corners.
[[nodiscard]] std::optional<ColoredMesh> rounded_for(const ColoredMesh& mesh,
                                                     MeshFormat format);

}  // namespace lsolid
