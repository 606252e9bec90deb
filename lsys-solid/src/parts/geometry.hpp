// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <boost/container_hash/hash.hpp>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <numbers>

#include "lsys/rotation.hpp"
#include "lsys/skeleton.hpp"

namespace lsolid {

/// The small vector helpers of the part builder.

inline constexpr double kPi = std::numbers::pi;

/// The unit direction of a segment.
[[nodiscard]] inline glm::dvec3 direction(const lsys::Segment& s) {
  return glm::normalize(s.p1 - s.p0);
}

/// A segment's length.
[[nodiscard]] inline double length(const lsys::Segment& s) {
  return glm::length(s.p1 - s.p0);
}

/// A unit vector across the unit vector `d`.
[[nodiscard]] inline glm::dvec3 any_perpendicular(const glm::dvec3& d) {
  const glm::dvec3 axis = std::fabs(d.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0)
                                               : glm::dvec3(0.0, 1.0, 0.0);
  return glm::normalize(glm::cross(d, axis));
}

/// The minimal rotation taking unit `from` to unit `to`, applied to v.
[[nodiscard]] inline glm::dvec3 transport(const glm::dvec3& v,
                                          const glm::dvec3& from,
                                          const glm::dvec3& to) {
  const glm::dvec3 axis = glm::cross(from, to);
  const double s = glm::length(axis);
  if (s < 1e-15) return v;  // parallel: chains never bend by 180°
  return lsys::rotate_about(v, axis / s, glm::dot(from, to), s);
}

/// The angle between two unit directions, in degrees.
[[nodiscard]] inline double bend_deg(const glm::dvec3& a, const glm::dvec3& b) {
  return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * 180.0 / kPi;
}

/// A node of the skeleton keyed by its exact coordinates: segments that
/// meet share them exactly, since the turtle does not move between them.
using NodeKey = std::array<std::uint64_t, 3>;

/// The key of a point (-0 and +0 alike).
[[nodiscard]] inline NodeKey node_key(const glm::dvec3& p) {
  return {std::bit_cast<std::uint64_t>(p.x + 0.0),
          std::bit_cast<std::uint64_t>(p.y + 0.0),
          std::bit_cast<std::uint64_t>(p.z + 0.0)};
}

/// A hash of node keys for unordered containers.
using NodeKeyHash = boost::hash<NodeKey>;

}  // namespace lsolid
