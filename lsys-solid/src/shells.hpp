// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "lsolid/mesh.hpp"

namespace lsolid {

/// An undirected edge as one key: its two vertex indices, the smaller in
/// the high half.
[[nodiscard]] inline std::uint64_t edge_key(std::uint32_t a,
                                            std::uint32_t b) noexcept {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32U) | std::max(a, b);
}

/// The edge-connected shells of a mesh: triangles joined through shared
/// edges (triangles that share only a vertex stay apart).
struct ShellLabels {
  /// Per triangle, its shell, numbered from 0 in the order of each shell's
  /// first triangle.
  std::vector<std::uint32_t> of_triangle;
  std::size_t count = 0;
};

/// The triangles round each vertex, in triangle order (a triangle with a
/// vertex twice is listed twice there): those of vertex v are
/// `triangles[first[v]]` up to `triangles[first[v + 1]]`. `first` has an
/// entry for every vertex a triangle uses, and one past.
struct VertexStars {
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> triangles;
};

/// The stars of `mesh`'s vertices.
[[nodiscard]] VertexStars vertex_stars(const TriangleMesh& mesh);

/// Labels each triangle with its shell.
[[nodiscard]] ShellLabels label_shells(const TriangleMesh& mesh);

/// The signed volume of each shell, summed about its first triangle's first
/// vertex rather than the origin, so that a small shell far from the
/// origin keeps its digits: positive for a piece of solid, negative for a
/// cavity inside one.
[[nodiscard]] std::vector<double> shell_volumes(const TriangleMesh& mesh,
                                                const ShellLabels& shells);

}  // namespace lsolid
