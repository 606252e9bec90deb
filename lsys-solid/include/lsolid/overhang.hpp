// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include "lsolid/mesh.hpp"

namespace lsolid {

/// Downward-facing surface a printer must print over air.
struct OverhangReport {
  /// Area of the faces that face down more steeply than the limit (their
  /// normal more than `limit_deg` below the horizontal), off the bed.
  double area_mm2 = 0.0;
  /// More than kSupportArea mm² of it: a slicer will want supports.
  bool needs_supports = false;
};

/// Overhang areas below this are left to bridging, not supports.
inline constexpr double kSupportArea = 5.0;

/// The overhang of a mesh standing on z = its lowest point. Faces lying on
/// the bed (within 10⁻³ mm of it) do not count.
[[nodiscard]] OverhangReport overhang(const TriangleMesh& mesh,
                                      double limit_deg = 45.0);

}  // namespace lsolid
