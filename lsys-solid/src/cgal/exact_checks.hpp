// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>

#include "lsolid/mesh.hpp"

namespace lsolid {

/// The checks of `validate` that need exact predicates (CGAL, EPICK).
struct ExactChecks {
  std::size_t degenerate_faces = 0;
  bool self_intersections_checked = false;
  std::size_t self_intersecting_pairs = 0;
  bool orientation_checked = false;
  bool is_outward = false;
};

/// @param is_edge_manifold no edge has more than two triangles.
/// @param is_closed_manifold also closed, vertex-manifold, consistently
///   oriented: then orientation is tested too.
[[nodiscard]] ExactChecks exact_checks(const TriangleMesh& mesh,
                                       bool is_edge_manifold,
                                       bool is_closed_manifold);

}  // namespace lsolid
