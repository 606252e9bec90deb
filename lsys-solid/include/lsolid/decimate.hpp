// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <functional>
#include <optional>

#include "lsolid/mesh.hpp"

namespace lsolid {

/// How to decimate a printable mesh.
struct DecimateOptions {
  /// How far the surface may move, in millimetres: the quadric error bound
  /// (a squared distance, so it is set to the square of this).
  double tolerance_mm = 0.05;
  /// At most this many triangles. To reach it the tolerance is given up,
  /// never validity; the report says when it could not be reached.
  std::optional<std::size_t> max_triangles;
  /// No collapse turns a triangle's normal by more than this.
  double max_normal_deviation_deg = 45.0;
  /// No collapse makes a triangle longer than this times its height.
  double max_aspect_ratio = 10.0;
  /// Refuse collapses that would make the mesh intersect itself. Only
  /// tests and benchmarks turn this off, to show what it prevents.
  bool refuse_intersections = true;
  /// Measure the Hausdorff distance to the input afterwards.
  bool measure_deviation = true;
  /// Told the fraction of the collapses done (an estimate), 0 to 1.
  std::function<void(double fraction)> progress;
};

/// What decimation did.
struct DecimateStats {
  std::size_t triangles_before = 0;
  std::size_t triangles_after = 0;
  std::size_t collapses = 0;
  /// Collapses refused because a new triangle would cut the mesh.
  std::size_t refused_intersections = 0;
  /// The symmetric Hausdorff distance to the input in millimetres, or a
  /// negative number when not measured.
  double max_deviation_mm = -1.0;
  /// False when `max_triangles` was given and not reached.
  bool reached_max_triangles = true;
};

/// A decimated mesh and what it cost.
struct Decimated {
  TriangleMesh mesh;
  DecimateStats stats;
};

/// Removes triangles by halfedge collapses (OpenMesh's decimater with its
/// quadric, normal-flip and aspect-ratio modules) and refuses every collapse
/// whose new triangles would intersect the rest of the mesh, decided with
/// exact predicates. Vertices keep their coordinates, so a mesh already
/// rounded to floats stays so, and a valid input gives a valid output.
/// @pre `mesh` is closed, 2-manifold and free of self-intersections.
/// @throws GeometryError if OpenMesh cannot take it as a 2-manifold, or the
///   tolerance is not positive.
[[nodiscard]] Decimated decimate(const TriangleMesh& mesh,
                                 const DecimateOptions& options = {});

}  // namespace lsolid
