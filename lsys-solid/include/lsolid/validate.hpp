// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "lsolid/mesh.hpp"

namespace lsolid {

/// One edge-connected shell of a mesh.
struct Shell {
  std::size_t triangles = 0;
  /// Positive for a piece of solid, negative for a cavity inside one.
  double volume_mm3 = 0.0;
  Box bounds;
};

/// What `validate` found. A mesh is printable when it is closed, edge- and
/// vertex-manifold, consistently and outward oriented, free of degenerate
/// faces and of self-intersections (tested with exact predicates), and
/// encloses a positive volume.
struct ValidationReport {
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  std::size_t boundary_edges = 0;         ///< edges of one triangle: holes
  std::size_t non_manifold_edges = 0;     ///< edges of three or more
  std::size_t non_manifold_vertices = 0;  ///< vertices whose fan is split
  std::size_t misoriented_edges = 0;      ///< edges both triangles run alike
  std::size_t degenerate_faces = 0;       ///< repeated or collinear corners
  /// Self-intersections are tested only on edge-manifold meshes.
  bool self_intersections_checked = false;
  std::size_t self_intersecting_pairs = 0;
  /// Outward orientation (CGAL's does_bound_a_volume) is tested only on
  /// closed, manifold meshes without self-intersections.
  bool orientation_checked = false;
  bool is_outward = false;
  std::size_t shells = 0;  ///< edge-connected components
  /// Every shell, the largest volume first. A slicer prints each shell of
  /// positive volume as a piece of its own: more than one, and the model
  /// falls apart into loose parts.
  std::vector<Shell> shell_list;
  int genus = -1;  ///< total over shells; -1 unless closed, manifold
  double volume_mm3 = 0.0;
  Box bounds;

  /// True when a slicer can take the mesh without repair.
  [[nodiscard]] bool is_printable() const noexcept {
    return triangles > 0 && boundary_edges == 0 && non_manifold_edges == 0 &&
           non_manifold_vertices == 0 && misoriented_edges == 0 &&
           degenerate_faces == 0 && self_intersections_checked &&
           self_intersecting_pairs == 0 && orientation_checked && is_outward &&
           volume_mm3 > 0.0;
  }
  /// The shells of positive volume: the separate pieces it prints as.
  [[nodiscard]] std::size_t pieces() const noexcept;
  /// One line per problem, empty when printable.
  [[nodiscard]] std::vector<std::string> problems() const;
};

/// Checks a mesh as it stands (snap it first, lsolid/precision.hpp, to
/// check what a file will hold).
[[nodiscard]] ValidationReport validate(const TriangleMesh& mesh);

}  // namespace lsolid
