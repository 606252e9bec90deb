// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

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

/// Which triangles of a mesh standing on z = its lowest point overhang:
/// their normal points more than `limit_deg` below the horizontal, and they
/// do not lie on the bed (within 10⁻³ mm of it). One flag per triangle.
[[nodiscard]] std::vector<bool> overhanging_triangles(const TriangleMesh& mesh,
                                                      double limit_deg = 45.0);

/// The overhang of a mesh standing on z = its lowest point: the area of its
/// overhanging_triangles.
[[nodiscard]] OverhangReport overhang(const TriangleMesh& mesh,
                                      double limit_deg = 45.0);

}  // namespace lsolid
