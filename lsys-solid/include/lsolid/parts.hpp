// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "lsolid/defaults.hpp"
#include "lsolid/mesh.hpp"
#include "lsys/skeleton.hpp"

namespace lsolid {

/// How to mesh the skeleton.
struct PartOptions {
  /// The thinnest tube's width; leaf plates are 5% thicker than such a
  /// tube across its corners (0.93 mm for 0.8 mm), so that veins in a leaf
  /// lie inside it.
  double wall_mm = kDefaultWallMm;
  double tolerance_mm = kDefaultToleranceMm;  ///< chord error of tubes
  /// One colour per part: tubes end where the colour changes and branches
  /// of several colours meet at a joint sphere, not a hull. Coloured output
  /// needs it; it costs booleans in the union where colours change often.
  bool split_colors = false;
  /// Unite coplanar polygons that overlap or share edges before they become
  /// plates (for the 3D union, where they would meet face on face). A model
  /// printed as its extruded footprint needs no such union: its plates only
  /// witness what the footprint must hold.
  bool unite_coplanar_polygons = true;
  /// Test each part of tubes joined at hull junctions for cutting itself,
  /// and leave the junctions of those that do to the union. Off, the parts
  /// may cut themselves: only for measuring them (the size loop's first
  /// pass, whose parts have the same box unless a junction would be left).
  bool check_self_intersections = true;
};

/// The parts and what they came from.
struct PartSet {
  std::vector<Part> parts;
  std::size_t tubes = 0;
  /// Branch points meshed directly: the convex hull of the rings of the
  /// tubes that meet there, stitched to them (no boolean needed).
  std::size_t junctions = 0;
  /// Joint spheres, where a junction is left to the union, where a leaf
  /// starts at a tip and where plates in different planes share a corner.
  std::size_t joints = 0;
  std::size_t plates = 0;
  /// Balls of `@O`.
  std::size_t spheres = 0;
  /// Predefined surfaces (cpfg's `~l`), each thickened as a plate is.
  std::size_t sheets = 0;
  /// Of those, sheets a few walls across too bent to thicken cleanly, made
  /// the convex hull of their thickened points instead.
  std::size_t hulled_sheets = 0;
  /// Of those, sheets thinner than the plate where they fold more sharply
  /// than it is thick, and the least thickness left there.
  std::size_t thinned_sheets = 0;
  double thinnest_sheet_mm = std::numeric_limits<double>::infinity();
  /// Polygons without area or whose outline crosses itself: not printed.
  std::size_t skipped_polygons = 0;
};

/// Meshes a millimetre skeleton (see scale_to_print) into parts whose union
/// is the model: one swept tube per unbranched chain of segments, with
/// mitred bends and shared rings. Where branches meet at angles that leave
/// room, the tubes end in rings and the convex hull of the rings joins them
/// (B-Mesh), so that a whole tree can be one closed part; each such part is
/// checked not to cut itself, and junctions are given up until none does.
/// Elsewhere a joint sphere encloses the tubes' end caps for the union to
/// merge. Each polygon becomes a plate a little thicker than the wall
/// (coplanar polygons that overlap or share edges are united first), fused
/// by a joint to the segment it grows from. Each sheet becomes a plate as
/// thick, offset along the sheet's normals (or its mean normal); a sheet a
/// few walls across that bends too sharply for that becomes the convex
/// hull of its thickened points.
/// @throws GeometryError for a sheet that cannot be thickened without
/// cutting itself.
[[nodiscard]] PartSet build_parts(const lsys::Skeleton& skeleton,
                                  const PartOptions& options = {});

/// The number of sides of a tube of this radius whose flat sides touch the
/// circle and whose corners stand out from it by at most `tolerance_mm`
/// (6 to 128). A tube is thus never thinner than its width, and tubes whose
/// circles touch overlap.
[[nodiscard]] int tube_sides(double radius_mm, double tolerance_mm);

/// How far the corners of such a tube lie from its axis.
[[nodiscard]] double tube_corner_radius(double radius_mm, double tolerance_mm);

/// The thickness of leaf plates: 5% more than the thinnest tube (of
/// diameter `wall_mm`) across its corners, so that veins drawn in a leaf at
/// that width lie inside the plate rather than flush with its faces.
[[nodiscard]] double plate_thickness_mm(double wall_mm, double tolerance_mm);

}  // namespace lsolid
