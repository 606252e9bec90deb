// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <unordered_map>
#include <vector>

#include "lsolid/mesh.hpp"
#include "lsolid/parts.hpp"
#include "lsys/skeleton.hpp"
#include "parts/branch_graph.hpp"
#include "parts/geometry.hpp"

namespace lsolid {

/// A joint sphere asked for at a node.
struct Joint {
  glm::dvec3 center{0.0};
  double radius = 0.0;  ///< the largest cap it must enclose
  int color = 0;        ///< of the first segment that asked for it
};

/// The joints asked for at nodes: one per node, as wide as the widest cap
/// there, in the order first asked (for reproducible parts).
class JointSet {
 public:
  /// Asks for a joint enclosing caps of `radius` at `center`.
  void add(const glm::dvec3& center, double radius, int color);
  /// As add, and the joint takes `color` even where one was asked for
  /// already: the colour of what it joins when it is a volume of its own.
  void claim(const glm::dvec3& center, double radius, int color);
  [[nodiscard]] const std::vector<Joint>& joints() const { return joints_; }

 private:
  std::vector<Joint> joints_;
  std::unordered_map<NodeKey, std::size_t, NodeKeyHash> index_;
};

/// One round of meshing the tubes with the graph's current hull junctions.
struct TubeRound {
  /// The hull junctions that failed or made a stitched part cut itself;
  /// when not empty, the round's parts are to be discarded and the round
  /// run again without them.
  std::vector<std::int32_t> revert;
  /// Tubes joined at hull junctions into closed parts, in order of their
  /// first piece.
  std::vector<Part> parts;
  std::size_t tubes = 0;
  std::size_t junctions = 0;  ///< hull junctions meshed
  /// Joints where tubes meet without a hull.
  JointSet joints;
};

/// Meshes one swept tube per unbroken chain of segments, with mitred bends
/// and rings shared between segments, and the convex hull of the rings at
/// each hull junction, stitched to its tubes into one part without a
/// boolean; checks each stitched part for self-intersection.
[[nodiscard]] TubeRound mesh_tubes(const lsys::Skeleton& skeleton,
                                   const BranchGraph& graph,
                                   const PartOptions& options);

}  // namespace lsolid
