// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <optional>

#include "lsolid/mesh.hpp"
#include "lsys/skeleton.hpp"

namespace lsolid {

/// Which way a sheet's points move when it is thickened.
enum class SheetOffset {
  /// Along the sheet's normal at each point: a plate of even thickness,
  /// which cuts itself where the sheet bends sharply for its thickness.
  Normals,
  /// All along the sheet's mean normal: the sheet swept along one
  /// direction, thicker where it slants to it, and cutting itself only if
  /// it overlaps itself seen along that direction.
  MeanNormal,
};

/// A sheet (a curved leaf from a predefined surface) thickened to a closed
/// solid: each point moved to either side, far enough that each triangle's
/// copies lie half of `thickness_mm` from it, the two faces joined by a
/// wall along the sheet's boundary. Returns nothing when the sheet has no
/// consistent two sides (an edge that three triangles share, a twisted
/// band), a point without a normal (triangles folded back onto each other
/// there), or, along the mean normal, a triangle slanted by more than 75°
/// to it. The result is closed and outward-oriented; whether it cuts
/// itself is for the caller to check.
/// @pre the sheet's triangles have three distinct points each.
[[nodiscard]] std::optional<TriangleMesh> thicken_sheet(
    const lsys::Sheet& sheet, double thickness_mm, SheetOffset offset_along);

/// Where a sheet thickened along its normals cuts itself, the points of
/// the triangles that cut others move half as far, until nothing cuts or
/// they move kThinnestSheet of the way: the plate is thinner only where it
/// folds more sharply than its thickness can follow (the tip of a leaf
/// swept from a contour, whose hooked cross-section shrinks there).
struct ThinnedSheet {
  TriangleMesh mesh;  ///< closed and outward-oriented
  /// The least fraction of the thickness a point kept (1: none thinned).
  double thinnest_fraction = 1.0;
};

/// The least fraction of the thickness thinning leaves a point.
inline constexpr double kThinnestSheet = 1.0 / 64.0;

/// The sheet thickened along its normals, thinned where that cuts itself
/// (ThinnedSheet). Returns nothing when thicken_sheet along the normals
/// does, when the points kThinnestSheet of the way still cut, or when
/// thinning touches more than a quarter of the sheet's area (a sheet
/// folded flat along its length is no leaf with a sharp edge).
[[nodiscard]] std::optional<ThinnedSheet> thicken_sheet_thinning(
    const lsys::Sheet& sheet, double thickness_mm);

/// How a sheet became a part.
enum class SheetKind {
  Even,     ///< thickened along its normals or its mean normal
  Thinned,  ///< thinner where it folds sharply (thicken_sheet_thinning)
  Hulled,   ///< the convex hull of its points thickened
};

/// A sheet as a part, and how it was made.
struct SheetPart {
  Part part;
  SheetKind kind = SheetKind::Even;
  /// The least thickness left, for SheetKind::Thinned.
  double thinnest_mm = 0.0;
};

/// A sheet (a predefined surface, cpfg's `~l`) thickened to `thickness_mm`
/// as plates are: along its normals, or if that cuts itself swept along its
/// mean normal, or else along its normals but thinner where they cut. A
/// sheet at most eight thicknesses across that no way makes clear of
/// itself becomes the convex hull of its points thickened. `index` names
/// it in the part's label.
/// @throws GeometryError for a larger sheet that cannot be thickened
///   without cutting itself.
[[nodiscard]] SheetPart sheet_part(const lsys::Sheet& sheet, std::size_t index,
                                   double thickness_mm);

}  // namespace lsolid
