// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

#include "lsolid/defaults.hpp"
#include "lsolid/mesh.hpp"
#include "lsolid/print_settings.hpp"
#include "lsys/skeleton.hpp"

namespace lsolid {

/// How the model was put on the bed.
struct Placement {
  /// The direction turned to +Z before moving: a planar skeleton's normal
  /// when it lies flat, otherwise +Z (no turn).
  glm::dvec3 plane_normal{0.0, 0.0, 1.0};
  glm::dvec3 moved_by_mm{0.0};  ///< the translation applied after the turn
  bool has_base = false;        ///< a disc was added under the model
  double base_radius_mm = 0.0;
  double base_thickness_mm = 0.0;
  /// The width of what the model stands on (without a base), across its
  /// narrower horizontal side.
  double footprint_mm = 0.0;
  /// A planar model was turned to lie flat; its underside is to be cut off
  /// at `cut_z_mm` (in the placed coordinates) for a flat contact face. The
  /// build cuts the united model and moves it down by that height.
  bool lies_flat = false;
  double cut_z_mm = 0.0;
  double cut_depth_mm = 0.0;  ///< how far below the skeleton's plane
  /// The cut model would not have been printable once rounded, so it was
  /// left whole, lying on its round undersides (`cut_z_mm` is then 0).
  bool cut_refused = false;
};

/// Where the placement puts a point of the millimetre skeleton: turned, then
/// moved as the parts were.
[[nodiscard]] glm::dvec3 on_bed(const Placement& placement,
                                const glm::dvec3& p);

/// The plane a planar skeleton is drawn in, in millimetres.
struct SkeletonPlane {
  glm::dvec3 normal{0.0, 0.0, 1.0};  ///< unit length
  glm::dvec3 point{0.0};             ///< a point of the plane
  double thinnest_radius_mm = 0.0;   ///< of its segments
};

/// The plane holding every segment and polygon of the skeleton, if there is
/// one (ABOP's planar figures: Koch curves, Sierpinski, the fig. 1.24 plants
/// drawn with + and - only); none for a straight line or a 3D model.
/// Points may stray from the plane by 10⁻⁹ of the model's size.
[[nodiscard]] std::optional<SkeletonPlane> skeleton_plane(
    const lsys::Skeleton& skeleton, double wall_mm);

/// How to put the parts on the bed.
struct PlacementOptions {
  Base base = Base::Auto;
  double wall_mm = kDefaultWallMm;  ///< sets the base disc's size
  /// The chord tolerance of the base disc's sides.
  double tolerance_mm = kDefaultToleranceMm;
  /// The plane of a planar skeleton (skeleton_plane): with Base::Auto the
  /// model lies flat in it.
  std::optional<SkeletonPlane> plane;
};

/// Parts placed on the bed, and how.
struct Placed {
  std::vector<Part> parts;  ///< moved, and with a base disc last if any
  Placement placement;
};

/// Puts the parts on the bed: centred on the origin in X and Y (with the
/// base, if any), their lowest point at z = 0 (the union's lowest point is a
/// part's vertex, so the written mesh rests there too). With `Base::Disc`, or
/// with `Base::Auto` where the model would stand on a footprint narrower (in
/// either direction) than a fifth of its height, a disc is added as a part
/// under the foot, and the model is lifted to sink its foot half-way into it:
/// the disc is centred under the foot, 2 walls thick (at least 1.2 mm), and
/// wide enough that the model's centre of mass (of its parts' volumes) lies
/// well inside it.
///
/// With `Base::Auto` and a `plane`, the model lies flat instead: turned so
/// that the plane is horizontal, with no disc, and `cut_z_mm` set half its
/// thinnest radius below the plane, so that every branch touches the bed
/// with a flat face and the thinnest keeps three quarters of its height.
/// @pre every part is closed and outward-oriented.
[[nodiscard]] Placed place_on_bed(std::vector<Part> parts,
                                  const PlacementOptions& options = {});

}  // namespace lsolid
