// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec2.hpp>
#include <vector>

#include "lsolid/mesh.hpp"

namespace lsolid {

/// Points united in a plane (a footprint, coplanar leaves) lie on a grid
/// of this many cells a millimetre (2^20): about a nanometre, far below
/// print resolution, and far above the rounding errors of turtle paths
/// that meet again.
inline constexpr double kFootprintCellsPerMm = 1048576.0;

/// The region of the plane that a model lying flat covers, seen from above:
/// the union of its branches' and leaves' outlines, in millimetres, with
/// every point on a grid of 2^-20 mm.
struct Footprint {
  /// Closed rings, each with the region on its left: outer rings
  /// counter-clockwise, holes clockwise. No ring crosses or touches another
  /// or itself, and no two rings share a point.
  std::vector<std::vector<glm::dvec2>> rings;
};

/// The outline of a tapered branch seen from above, as its tube lies in the
/// plane: the quadrilateral from `p0` to `p1` as wide as the tube across its
/// corners at each end (tube_corner_radius of `r0_mm` and `r1_mm`), so never
/// narrower than the branch. Counter-clockwise; empty if p0 = p1.
/// @pre r0_mm > 0, r1_mm > 0, tolerance_mm > 0.
[[nodiscard]] std::vector<glm::dvec2> branch_outline(const glm::dvec2& p0,
                                                     double r0_mm,
                                                     const glm::dvec2& p1,
                                                     double r1_mm,
                                                     double tolerance_mm);

/// The outline of a node where branches meet, seen from above: the polygon
/// of tube_sides(r_mm) sides that touch the circle of radius `r_mm` about
/// `center`. Counter-clockwise.
/// @pre r_mm > 0, tolerance_mm > 0.
[[nodiscard]] std::vector<glm::dvec2> node_outline(const glm::dvec2& center,
                                                   double r_mm,
                                                   double tolerance_mm);

/// True when the polygon (either orientation) does not cross or touch
/// itself and has an area: a leaf outline the model can print.
[[nodiscard]] bool is_simple_polygon(const std::vector<glm::dvec2>& polygon);

/// The union of `polygons`, less the union of `minus`, on the 2^-20 mm
/// grid (Clipper, Vatti's sweep on integer coordinates). Each polygon
/// counts for the region it encloses, whatever its orientation; one that
/// crosses itself, wherever its winding number is not zero. Where the
/// result's boundary touches itself at a point, it is grown by a few grid
/// steps until it does not.
/// @throws GeometryError if the outlines reach beyond what the grid holds,
///   or the result still touches itself.
[[nodiscard]] Footprint footprint_union(
    const std::vector<std::vector<glm::dvec2>>& polygons,
    const std::vector<std::vector<glm::dvec2>>& minus = {});

/// The area the footprint covers, in mm².
[[nodiscard]] double area(const Footprint& footprint);

/// The closed solid standing on z = 0 with the footprint as its section,
/// `height_mm` high: the footprint triangulated (a constrained Delaunay
/// triangulation of the rings, CGAL) as the bottom and the top face,
/// walled along every ring. Outward-oriented, 2-manifold, its volume the
/// footprint's area times the height.
/// @pre height_mm > 0.
/// @throws GeometryError if the rings cross one another.
[[nodiscard]] TriangleMesh extrude(const Footprint& footprint,
                                   double height_mm);

}  // namespace lsolid
