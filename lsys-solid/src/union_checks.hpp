// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "lsolid/containment.hpp"
#include "lsolid/decimate.hpp"
#include "lsolid/mesh.hpp"

namespace lsolid {

/// What the union (or a flat model's footprint) must keep of its parts,
/// checked after rounding and again after decimation (docs/design.md, "The
/// union's invariant"): witnesses deep inside every part, and the largest
/// part's volume.
struct PartsKept {
  std::vector<Witness> witnesses;
  std::vector<std::string> labels;
  double largest_mm3 = 0.0;
  std::string largest;
};

/// The witnesses and the largest volume of the parts.
[[nodiscard]] PartsKept parts_kept(const std::vector<Part>& parts);

/// Every witness at least 10⁻³ mm deep lies inside `mesh`, and every piece
/// of it holds one; `what` names the result ("the union") and `advice` ends
/// the message. Returns how many witnesses were checked.
/// @throws GeometryError naming the parts lost, or the largest fragment: a
///   result that lost geometry is an error, never a printable model.
std::size_t check_witnesses(const TriangleMesh& mesh,
                            const std::vector<Witness>& witnesses,
                            const PartsKept& kept, std::string_view what,
                            std::string_view advice);

/// The union's invariant, checked on the rounded union before anything is
/// cut off or decimated: the witnesses (check_witnesses), and at least the
/// largest part's volume. Returns how many witnesses were checked.
/// @throws GeometryError naming what was lost.
std::size_t check_union_kept(const TriangleMesh& mesh, const PartsKept& kept);

/// The witnesses as they stand once a flat-lying model's underside is cut
/// at `cut_z_mm` and the model moved down: as deep as they lie above the
/// bed, those below it left out.
[[nodiscard]] std::vector<Witness> lowered(
    const std::vector<Witness>& witnesses, double cut_z_mm);

/// Whether decimation moved the surface past a witness that the union kept:
/// witnesses need only lie as deep as the surface may have moved (the
/// tolerance, or the deviation measured if larger).
[[nodiscard]] bool lost_in_decimation(const Decimated& decimated,
                                      const PartsKept& kept,
                                      double tolerance_mm, double cut_z_mm);

}  // namespace lsolid
