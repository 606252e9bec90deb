// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "lsolid/defaults.hpp"
#include "lsolid/mesh.hpp"

namespace lsolid {

/// How to decimate a printable mesh.
struct DecimateOptions {
  /// How far the surface may move, in millimetres: the quadric error bound
  /// (a squared distance, so it is set to the square of this).
  double tolerance_mm = kDefaultToleranceMm;
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
  /// Edges shorter than this (and than the tolerance) are collapsed last,
  /// under the same vetoes: slicers merge vertices closer than 0.03 mm
  /// (CuraEngine among them) and then find overlapping faces. 0 keeps them.
  double min_edge_mm = 0.03;
  /// The fraction of the tolerance that the vetoes aim at first: they test
  /// at sample points, and the surface strays a little past them between.
  double aim = 0.8;
  /// A mesh of this many triangles or more is cut in two across its
  /// longest side and the halves are decimated at once (two threads within
  /// the build's limit), the triangles crossing the cut kept, then the
  /// whole for what is left (Lparser's Menger cube at n = 4, 97,136
  /// triangles, was decimated on one thread from 100,000). The result
  /// depends on this, never on the number of threads.
  std::size_t halve_from_triangles = 50000;
  /// Told the fraction of the collapses done (an estimate), 0 to 1.
  std::function<void(double fraction)> progress;
  /// Called with each decimated mesh (once a run: a run whose deviation
  /// exceeds the tolerance is followed by another), while its deviation is
  /// measured, on another of the build's threads: the caller's check of
  /// the result, done where the measurement would leave a core idle. The
  /// call for the mesh returned is the last; when decimation is refused
  /// (Decimated::refused), no call was for the mesh returned.
  std::function<void(const TriangleMesh& result)> alongside;
};

/// What decimation did.
struct DecimateStats {
  std::size_t triangles_before = 0;
  std::size_t triangles_after = 0;
  std::size_t collapses = 0;
  /// Edges of the result shorter than `min_edge_mm`: those no collapse
  /// could remove without breaking the mesh or leaving the tolerance.
  std::size_t short_edges_left = 0;
  /// Collapses refused because a new triangle would cut the mesh.
  std::size_t refused_intersections = 0;
  /// The symmetric Hausdorff distance to the input in millimetres,
  /// sampled at every vertex and every 0.1 mm of every changed triangle
  /// (never cut short), or a negative number when not measured.
  double max_deviation_mm = -1.0;
  /// False when `max_triangles` was given and not reached.
  bool reached_max_triangles = true;
  double tolerance_mm = 0.0;  ///< the tolerance it was given
  /// Whether the measured deviation is within the tolerance (false too
  /// when it was not measured).
  bool within_tolerance = false;
  /// True when `max_triangles` was only reached by giving up the
  /// tolerance.
  bool beyond_tolerance_for_cap = false;
  /// Decimations run: one more each time the deviation measured exceeded
  /// the tolerance (the vetoes then aim lower), at most three.
  int attempts = 0;
};

/// A decimated mesh and what it cost, or why the mesh could not be
/// decimated.
struct Decimated {
  TriangleMesh mesh;  ///< the input itself when `refused` says why
  DecimateStats stats;
  /// Why nothing was decimated: the mesh is not a 2-manifold OpenMesh can
  /// take, or an exact test inside the decimation refused its triangles
  /// (CGAL's checks). Empty when decimated.
  std::string refused;
};

/// Removes triangles by halfedge collapses (OpenMesh's decimater with its
/// quadric, normal-flip and aspect-ratio modules) and refuses every collapse
/// whose new triangles would intersect the rest of the mesh, decided with
/// exact predicates. Vertices keep their coordinates, so a mesh already
/// rounded to floats stays so, and a valid input gives a valid output.
/// Where the deviation measured afterwards exceeds the tolerance, it starts
/// again from the input with the vetoes aiming lower (three runs at most);
/// `stats.within_tolerance` says whether that succeeded.
/// A mesh that is not a 2-manifold is returned as it is, with the reason
/// in `refused`.
/// @pre `mesh` is closed and free of self-intersections.
/// @throws GeometryError if the tolerance is not positive.
[[nodiscard]] Decimated decimate(const TriangleMesh& mesh,
                                 const DecimateOptions& options = {});

}  // namespace lsolid
