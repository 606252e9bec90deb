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

// Leaves out each ball that a larger or earlier one holds, to 10⁻⁹ of the
// balls' extent: cpfg's florigen and sympodial models draw the same bud
// twice, a few ulps apart, and two such balls of other seams meet along
// their whole surface, which the union does not survive (vlab's
// sympodial plant lost a tube). Returns how many were left out.
std::size_t drop_held_spheres(std::vector<lsys::Sphere>& balls) {
  if (balls.size() < 2) return 0;
  glm::dvec3 lo = balls.front().center;
  glm::dvec3 hi = lo;
  double widest = 0.0;
  for (const lsys::Sphere& b : balls) {
    lo = glm::min(lo, b.center);
    hi = glm::max(hi, b.center);
    widest = std::max(widest, b.diameter);
  }
  const double slack = (glm::length(hi - lo) + widest) * kGridFraction;
  // Cells as wide as the widest ball: a ball that holds another has its
  // centre in the same cell or a neighbour.
  const double cell = std::max(widest, 1e-300);
  const auto cell_of = [&](const glm::dvec3& p) {
    const glm::dvec3 q = glm::floor((p - lo) / cell);
    return EndKey{static_cast<std::int64_t>(q.x),
                  static_cast<std::int64_t>(q.y),
                  static_cast<std::int64_t>(q.z)};
  };
  std::vector<std::size_t> order(balls.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) {
                     return balls[a].diameter > balls[b].diameter;
                   });
  std::map<EndKey, std::vector<std::size_t>> kept;
  std::vector<bool> held(balls.size(), false);
  for (const std::size_t i : order) {
    const lsys::Sphere& b = balls[i];
    const auto [x, y, z] = cell_of(b.center);
    for (std::int64_t dx = -1; dx <= 1 && !held[i]; ++dx) {
      for (std::int64_t dy = -1; dy <= 1 && !held[i]; ++dy) {
        for (std::int64_t dz = -1; dz <= 1 && !held[i]; ++dz) {
          const auto it = kept.find(EndKey{x + dx, y + dy, z + dz});
          if (it == kept.end()) continue;
          for (const std::size_t k : it->second) {
            const lsys::Sphere& big = balls[k];
            if (glm::distance(b.center, big.center) + b.diameter / 2.0 <=
                big.diameter / 2.0 + slack) {
              held[i] = true;
              break;
            }
          }
        }
      }
    }
    if (!held[i]) kept[cell_of(b.center)].push_back(i);
  }
  std::vector<lsys::Sphere> out;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (!held[i]) out.push_back(balls[i]);
  }
  const std::size_t dropped = balls.size() - out.size();
  balls = std::move(out);
  return dropped;
}

}  // namespace

WithoutRepeats without_repeated_segments(const lsys::Skeleton& skeleton) {
  WithoutRepeats out;
  out.skeleton = skeleton;
  out.dropped_spheres = drop_held_spheres(out.skeleton.spheres);
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
  for (lsys::Sheet& s : out.skeleton.sheets) s.parent = renumber(s.parent);
  out.dropped = in.size() - out.skeleton.segments.size();
  return out;
}

}  // namespace lsolid
