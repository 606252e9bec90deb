// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "lsolid/rounding.hpp"

namespace lsolid {

/// round_and_repair for a mesh some of whose faces are known to meet no
/// other of them: an exact union's faces that no crossing cut, which
/// neither meet each other nor move when the new points are rounded. While
/// snapping and the sliver repairs leave such a face as it is, its pairs
/// with the others are not tested in the first pass; the answer is the
/// same as round_and_repair's (the union's mends of blog tree B and of the
/// bush at n = 7 tested every pair of their largest operands before).
/// @pre settled.size() == mesh.triangles.size(), and no two faces marked in
///   `settled` meet but at the vertices or the edge they share.
/// @throws GeometryError as round_and_repair.
[[nodiscard]] Rounded round_and_repair(const TriangleMesh& mesh,
                                       const RoundingOptions& options,
                                       const std::vector<char>& settled);

}  // namespace lsolid
