// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "lsolid/parts.hpp"
#include "lsolid/print_settings.hpp"

namespace lsolid {

/// How the model was put on the bed.
struct Placement {
  glm::dvec3 moved_by_mm{0.0};  ///< the translation applied to every part
  bool has_base = false;        ///< a disc was added under the model
  double base_radius_mm = 0.0;
  double base_thickness_mm = 0.0;
  /// The width of what the model stands on (without a base), across its
  /// narrower horizontal side.
  double footprint_mm = 0.0;
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
/// @pre every part is closed and outward-oriented.
[[nodiscard]] Placement place_on_bed(std::vector<Part>& parts, Base base,
                                     double wall_mm, double tolerance_mm);

}  // namespace lsolid
