// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "lsys/bounds.hpp"

namespace lsolid {

/// An indexed triangle mesh in millimetres. Triangles list vertex indices
/// counter-clockwise seen from outside (outward normals by the right-hand
/// rule).
struct TriangleMesh {
  std::vector<glm::dvec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

/// An axis-aligned box in millimetres; empty (`min > max`) until a point is
/// added.
using Box = lsys::Bounds;

/// A closed, outward-oriented solid of the model, before the union.
struct Part {
  TriangleMesh mesh;
  std::string label;  ///< what it is, for messages: "tube of segments 3-7"
  /// The turtle's colour index (ABOP's `'`): that of its first segment or
  /// its polygon; a joint takes its parent's. All it was built from has
  /// this colour when the parts were built with PartOptions::split_colors
  /// (parts.hpp).
  int color = 0;
};

/// The bounding box of the vertices that triangles use.
[[nodiscard]] Box bounds(const TriangleMesh& mesh);

/// The enclosed volume by the divergence theorem: positive for a closed mesh
/// with outward normals.
[[nodiscard]] double signed_volume(const TriangleMesh& mesh);

/// The bounding box of all parts.
[[nodiscard]] Box bounds(const std::vector<Part>& parts);

/// Appends `part` to `mesh` (a disjoint union of surfaces, no boolean).
void append(TriangleMesh& mesh, const TriangleMesh& part);

/// Drops the vertices no triangle uses, renumbering the rest in order.
void remove_unused_vertices(TriangleMesh& mesh);

/// A mesh with its cavities filled, and how many there were.
struct CavitiesFilled {
  TriangleMesh mesh;
  std::size_t removed = 0;  ///< shells removed
};

/// The mesh without the shells that enclose negative volume: sealed
/// cavities that a union leaves where parts surround empty space. Filling
/// them changes no outer surface. Shells without volume (under 10⁻¹² mm³,
/// such as a tiny cavity that rounding flattened) are removed too.
/// @pre the mesh is closed and consistently oriented.
[[nodiscard]] CavitiesFilled fill_cavities(TriangleMesh mesh);

}  // namespace lsolid
