// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "lsolid/mesh.hpp"

namespace lsolid::exact_union {

/// How often the interval filter could not decide, per predicate.
struct FilterCounters {
  std::atomic<std::uint64_t> orient_2d{0};
  std::atomic<std::uint64_t> orient_2d_exact{0};
  std::atomic<std::uint64_t> along_edge{0};
  std::atomic<std::uint64_t> along_edge_exact{0};
};

/// What one union of two operands found and asked.
struct PairCounters {
  std::size_t crossings = 0;     ///< edge–face crossings, each decided once
  std::size_t cut_faces = 0;     ///< faces triangulated again
  std::size_t inside_tests = 0;  ///< surfaces no crossing touches, tested
};

/// The union of two operands, its new points rounded to doubles: those
/// from `first_new` on. `failure` says why there is none: a degeneracy
/// (`degenerate`: a vertex on a face, faces that touch, an edge through an
/// edge), which a shift of one operand removes, or a broken invariant.
struct PairUnion {
  TriangleMesh mesh;
  std::size_t first_new = 0;
  /// The faces where the operands meet (pieces of cut faces, faces whose
  /// boxes meet the other operand's box): rounding can only make these
  /// intersect.
  std::vector<std::uint32_t> contact_faces;
  bool degenerate = false;
  /// A degeneracy only where the operands' faces cross each other's planes
  /// (an edge through an edge, a vertex on a plane the face crosses), none
  /// where faces touch: a shift removes it and keeps faces that cross
  /// crossing.
  bool transversal = false;
  /// Among the faces that touch, the pairs of coplanar faces that face the
  /// same way (cubes side by side with their tops in one plane): growing an
  /// operand leaves a step as high as the growth between them, which the
  /// rounding to floats mends only where they are few.
  std::size_t alike_pairs = 0;
  /// Among the faces that touch, coplanar faces that face each other and
  /// overlap in more than an edge or a point, or a face on the inner side
  /// of the other's plane that meets it at an edge or a corner: solids that
  /// lie face on face or overlap there, which a growth joins. Solids that
  /// touch only at an edge or a point from outside the corefinement's
  /// shift parts or joins.
  bool face_on_face = false;
  std::string failure;
  PairCounters counters;
};

/// Whether a corner of face `face` of the union is a new point (the face
/// is a piece of a cut face): only those faces moved when the new points
/// were rounded.
/// @pre face < u.mesh.triangles.size()
[[nodiscard]] bool has_new_corner(const PairUnion& u, std::uint32_t face);

/// Whether rounding the new points kept the union free of degenerate and
/// intersecting faces (exact predicates on the rounded coordinates; only
/// faces in `u.contact_faces` can have changed or be met).
[[nodiscard]] bool rounding_kept_valid(const PairUnion& u);

/// The union of `a` and `b`: every edge–face crossing decided once, exactly,
/// on the input coordinates; cut faces triangulated with the crossings as
/// implicit points; inside and outside inherited across the surfaces
/// (docs/design.md, "The exact union engine").
/// @pre both are closed, outward-oriented 2-manifolds without
///   self-intersections, with double coordinates.
[[nodiscard]] PairUnion unite_pair(const TriangleMesh& a, const TriangleMesh& b,
                                   FilterCounters& filters);

}  // namespace lsolid::exact_union
