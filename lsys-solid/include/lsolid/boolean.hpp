// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "lsolid/mesh.hpp"

namespace lsolid {

/// Which union engine unites the parts.
enum class UnionEngine {
  /// lsolid's own: each edge–face crossing decided once, exactly, on the
  /// input coordinates, new points kept implicit until rounded
  /// (docs/design.md, "The exact union engine"); a union it cannot do is
  /// done by the corefinement, and counted (UnionStats::fallbacks).
  ExactCrossings,
  /// CGAL's corefinement over exact constructions (Epeck): the engine the
  /// exact one is checked against.
  Corefinement,
};

/// The engine's name as the command line and the report write it:
/// "exact" or "corefine".
[[nodiscard]] const char* engine_name(UnionEngine engine);

/// What the union did.
struct UnionStats {
  std::size_t booleans = 0;  ///< corefinement unions computed
  /// Parts added to a layer of parts with disjoint boxes, and pairs of
  /// groups with disjoint boxes: joined without a boolean.
  std::size_t concatenations = 0;
  std::size_t retries = 0;  ///< unions retried after a perturbation
  /// Unions that still failed and were redone with one operand's parts in
  /// two halves.
  std::size_t splits = 0;
  /// Unions whose new vertices could all be rounded to doubles before the
  /// next union (see design.md).
  std::size_t rounded = 0;
  /// Triangles of a part whose box meets the box of another part whose box
  /// meets the part's, counted once per such pair of parts: where the
  /// corefinement has work to do, and what its time follows.
  std::size_t contacts = 0;
  UnionEngine engine = UnionEngine::ExactCrossings;  ///< the engine asked for
  /// Unions the exact engine computed (the rest of `booleans` were
  /// corefinements).
  std::size_t exact_unions = 0;
  /// Unions the exact engine left to the corefinement because the operands
  /// touch (coplanar faces, a vertex on a face): the corefinement unites
  /// those exactly.
  std::size_t degenerate_unions = 0;
  std::string degenerate_reason;  ///< the first of those
  /// Unions where faces touch that the exact engine computed after growing
  /// the smaller operand by about a thousand units in the last place of its
  /// coordinates (1.5·10⁻¹¹ mm at 100 mm), so that the faces overlap.
  std::size_t grown = 0;
  /// Unions the exact engine gave back to the corefinement for any other
  /// reason (the safety net), and the first reason it gave.
  std::size_t fallbacks = 0;
  std::string fallback_reason;
  std::size_t crossings = 0;  ///< edge–face crossings the engine decided
  std::size_t cut_faces = 0;  ///< faces it triangulated again
  /// Predicates on implicit points, and those the interval filter could not
  /// decide (evaluated exactly): a rate above about 1% means a question
  /// whose answer is known is being asked.
  std::uint64_t predicates = 0;
  std::uint64_t filter_failures = 0;
  int threads = 1;  ///< the threads the union ran on
};

/// The union's time per contact (UnionStats::contacts) on the project's
/// 2-core machine: between 45 and 155 µs on ten models from 66,000 to
/// 620,000 contacts (docs/performance.md), so an estimate from it is good
/// to a factor of about two.
inline constexpr double kUnionSecondsPerContact = 80e-6;

/// The union of all parts.
struct UnionResult {
  TriangleMesh mesh;
  UnionStats stats;
};

/// What to tell while uniting.
struct UnionOptions {
  /// If not empty, called after each union with the fraction of the work
  /// done (weighted by the operands' sizes), ending with 1.
  std::function<void(double fraction)> progress;
  /// If not empty, called once before the first boolean with the seconds
  /// the union is expected to take: its contacts times
  /// kUnionSecondsPerContact.
  std::function<void(double seconds)> expect;
  UnionEngine engine = UnionEngine::ExactCrossings;
  /// The threads the exact engine may use; 0: as many as the machine has.
  /// The result is the same, byte for byte, whatever the number.
  int threads = 0;
};

/// Unions closed parts into one closed 2-manifold mesh with CGAL's
/// corefinement over exact constructions (Epeck). Parts whose boxes do not
/// meet are batched into layers (concatenated, no boolean), filled greedily
/// in Z-order of their boxes; the layers are united smallest first, and
/// pairs whose boxes do not overlap are joined without a boolean. A union
/// that fails is retried after translating one operand by 10⁻⁵ mm, twice;
/// if it still fails, the operand with more parts is united again in two
/// halves that are merged one after the other, recursively.
/// New points are rounded to doubles between unions where that keeps the
/// mesh valid; the result is rounded to doubles at the end.
/// @pre every part is closed and outward-oriented.
/// @throws GeometryError naming the parts when a part is not a valid solid
///   or a union still fails.
[[nodiscard]] UnionResult union_parts(std::vector<Part> parts,
                                      const UnionOptions& options = {});

/// What of `a` lies outside `b` (CGAL's corefinement over exact
/// constructions), rounded to doubles: the new vertices lie on `b`'s
/// surface to within a rounding error, so the result meets `b` on shared
/// faces without overlapping it. Empty when `b` covers `a`.
/// @pre both are closed, outward and free of self-intersections.
/// @throws GeometryError if CGAL fails.
[[nodiscard]] TriangleMesh subtract(const TriangleMesh& a,
                                    const TriangleMesh& b);

}  // namespace lsolid
