// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/repeated_segments.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <map>
#include <tuple>
#include <vector>

namespace lsolid {
namespace {

// Ends on a grid of this fraction of the extent: turtles that retrace a
// branch arrive at its points again through other rotations, a few ulps
// apart. Points that straddle a grid line are not matched, which leaves both
// segments, as without this step.
constexpr double kGridFraction = 1e-9;

using EndKey = std::tuple<std::int64_t, std::int64_t, std::int64_t>;

}  // namespace

WithoutRepeats without_repeated_segments(const lsys::Skeleton& skeleton) {
  WithoutRepeats out;
  out.skeleton = skeleton;
  const std::vector<lsys::Segment>& in = skeleton.segments;
  if (in.empty()) return out;
  glm::dvec3 lo = in.front().p0;
  glm::dvec3 hi = lo;
  for (const lsys::Segment& s : in) {
    lo = glm::min(glm::min(lo, s.p0), s.p1);
    hi = glm::max(glm::max(hi, s.p0), s.p1);
  }
  const double cell = std::max(glm::length(hi - lo), 1e-300) * kGridFraction;
  const auto key = [&](const glm::dvec3& p) {
    const glm::dvec3 q = glm::round((p - lo) / cell);
    return EndKey{static_cast<std::int64_t>(q.x),
                  static_cast<std::int64_t>(q.y),
                  static_cast<std::int64_t>(q.z)};
  };
  // Each segment's stand-in: itself, or the earlier segment it repeats.
  std::vector<std::int32_t> kept_as(in.size());
  std::map<std::tuple<EndKey, EndKey, int>, std::vector<std::int32_t>> seen;
  std::vector<lsys::Segment> segments = in;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const lsys::Segment& s = in[i];
    kept_as[i] = static_cast<std::int32_t>(i);
    auto& same_ends = seen[{key(s.p0), key(s.p1), s.color}];
    for (const std::int32_t k : same_ends) {
      lsys::Segment& earlier = segments[static_cast<std::size_t>(k)];
      const bool within = s.start_diameter <= earlier.start_diameter &&
                          s.end_diameter <= earlier.end_diameter;
      const bool around = s.start_diameter >= earlier.start_diameter &&
                          s.end_diameter >= earlier.end_diameter;
      if (!within && !around) continue;
      earlier.start_diameter =
          std::max(earlier.start_diameter, s.start_diameter);
      earlier.end_diameter = std::max(earlier.end_diameter, s.end_diameter);
      kept_as[i] = k;
      break;
    }
    if (kept_as[i] == static_cast<std::int32_t>(i)) {
      same_ends.push_back(static_cast<std::int32_t>(i));
    }
  }
  // New indices of the segments kept; parents follow their stand-ins.
  std::vector<std::int32_t> index(in.size(), -1);
  out.skeleton.segments.clear();
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (kept_as[i] != static_cast<std::int32_t>(i)) continue;
    index[i] = static_cast<std::int32_t>(out.skeleton.segments.size());
    out.skeleton.segments.push_back(segments[i]);
  }
  const auto renumber = [&](std::int32_t parent) {
    return parent < 0 ? parent
                      : index[static_cast<std::size_t>(
                            kept_as[static_cast<std::size_t>(parent)])];
  };
  for (lsys::Segment& s : out.skeleton.segments) s.parent = renumber(s.parent);
  for (lsys::Polygon& p : out.skeleton.polygons) p.parent = renumber(p.parent);
  for (lsys::Sphere& s : out.skeleton.spheres) s.parent = renumber(s.parent);
  out.dropped = in.size() - out.skeleton.segments.size();
  return out;
}

}  // namespace lsolid
