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
  /// One flag per triangle of the mesh: whether it is one of those faces.
  std::vector<bool> triangles;
};

/// Overhang areas below this are left to bridging, not supports.
inline constexpr double kSupportArea = 5.0;

/// The overhang of a mesh standing on z = its lowest point: its triangles
/// whose normal points more than `limit_deg` below the horizontal and that
/// do not lie on the bed (within 10⁻³ mm of it), and their area.
[[nodiscard]] OverhangReport overhang(const TriangleMesh& mesh,
                                      double limit_deg = 45.0);

}  // namespace lsolid
