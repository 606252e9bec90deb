// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "lsolid/parts.hpp"
#include "lsys/skeleton.hpp"

namespace lsolid {

/// Of a segment's length, at most this much may go to mitres and rings.
inline constexpr double kMitreBudget = 0.8;

/// Where a tube's ring at a junction lies: in `segment`, at `local_mm` from
/// the segment's end at the junction's side.
struct RingPlace {
  std::int32_t segment = -1;
  double local_mm = 0.0;
};

/// A branch point: where a segment's children start (or several chains
/// start at the same point), and how it is meshed.
struct Junction {
  glm::dvec3 at{0.0};
  std::int32_t incoming = -1;          ///< the segment that ends here, or -1
  std::vector<std::int32_t> outgoing;  ///< the segments that start here
  /// Per tube, the incoming first, then the outgoing: the distance from
  /// `at` to its ring, the straight stretch the ring may lie on, and where
  /// in it the ring lies (tubes that run straight on may have the ring
  /// beyond their first segment).
  std::vector<double> offsets_mm;
  std::vector<std::vector<std::int32_t>> stretches;
  std::vector<double> stretch_mm;
  std::vector<RingPlace> places;
  /// Meshed as the convex hull of the tubes' rings, stitched to the tubes
  /// without a boolean; otherwise the tubes run to `at` and a joint sphere
  /// encloses their caps, for the union to merge.
  bool hull = false;
};

/// How the skeleton's segments chain into tubes and where they branch: the
/// plan the part builder meshes, round after round, giving up hull
/// junctions (Junction::hull) until no stitched part cuts itself.
struct BranchGraph {
  /// Per segment, the child that continues its tube, or -1.
  std::vector<std::int32_t> continuation;
  /// Per segment, whether it continues its parent's tube.
  std::vector<bool> is_continuation;
  std::vector<Junction> junctions;
  std::vector<std::int32_t> start_junction;  ///< per segment, or -1
  std::vector<std::int32_t> end_junction;    ///< per segment, or -1
  /// Per segment: the junction whose incoming ring lies in it, or -1.
  std::vector<std::int32_t> incoming_ring;

  /// The hull junction at the start of segment i, or -1.
  [[nodiscard]] std::int32_t hull_at_start(std::int32_t i) const;
  /// The hull junction whose incoming ring lies in segment i, or -1.
  [[nodiscard]] std::int32_t ring_ahead(std::int32_t i) const;
  /// Where the ring of `tube` (a segment meeting the junction) lies.
  /// @pre `tube` is the junction's incoming or one of its outgoing
  ///   segments, and the junction is a hull.
  [[nodiscard]] const RingPlace& place_of(std::int32_t junction,
                                          std::int32_t tube) const;
};

/// Chains each segment to the child that turns least (at most 100°), finds
/// the branch points, and plans a hull junction at each where the tubes'
/// rings fit (docs/design.md, "Parts").
[[nodiscard]] BranchGraph plan_branches(const lsys::Skeleton& skeleton,
                                        const PartOptions& options);

/// The largest tube radius at the end of segment i, where its children
/// start.
[[nodiscard]] double node_radius(const lsys::Skeleton& skeleton,
                                 const BranchGraph& graph, std::int32_t i);

}  // namespace lsolid
