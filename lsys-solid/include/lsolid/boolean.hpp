// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <vector>

#include "lsolid/mesh.hpp"
#include "lsolid/parts.hpp"

namespace lsolid {

/// What the union did.
struct UnionStats {
  std::size_t booleans = 0;        ///< corefinement unions computed
  std::size_t concatenations = 0;  ///< pairs with disjoint boxes, joined
  std::size_t retries = 0;         ///< unions retried after a perturbation
  /// Unions whose new vertices could be rounded to doubles (see design.md).
  std::size_t rounded = 0;
};

/// The union of all parts.
struct UnionResult {
  TriangleMesh mesh;
  UnionStats stats;
};

/// Unions closed parts into one closed 2-manifold mesh with CGAL's
/// corefinement over exact constructions (Epeck), in a balanced pairing of
/// parts in Z-order of their boxes, so that neighbours meet first; pairs
/// whose boxes do not overlap are joined without a boolean. A pair that
/// fails is retried after translating one operand by 10⁻⁵ mm, twice.
/// The result is rounded to doubles once, at the end.
/// @pre every part is closed and outward-oriented.
/// @throws GeometryError naming the parts when a part is not a valid solid
///   or a union still fails.
[[nodiscard]] UnionResult union_parts(std::vector<Part> parts);

}  // namespace lsolid
