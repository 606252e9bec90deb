// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The plan of the tubes: which child continues each segment's tube, and
// where branches meet at hull junctions (B-Mesh, Ji et al. 2010; SQM,
// Bærentzen et al. 2012) whose rings fit on their tubes.
#include "parts/branch_graph.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "parts/geometry.hpp"

namespace lsolid {
namespace {

constexpr double kMaxBendDeg = 100.0;  // a sharper bend breaks the chain
// Hull junctions (see plan_hull).
constexpr double kJunctionMargin = 0.05;     // of the widest radius
constexpr double kJunctionMinOffset = 0.5;   // of the tube's own radius
constexpr double kJunctionMinSpread = 1e-3;  // 1 - cos of the closest pair
constexpr double kStraight = 1.0 - 1e-12;    // cos of a bend too small to see

class Planner {
 public:
  Planner(const lsys::Skeleton& skeleton, const PartOptions& options)
      : skeleton_(skeleton), options_(options) {}

  BranchGraph plan() {
    choose_continuations();
    find_junctions();
    return std::move(graph_);
  }

 private:
  // The continuation of a segment is the child that turns least (and by at
  // most kMaxBendDeg), the later one on a tie: `F[+F]F` continues with the
  // last F, the main axis.
  void choose_continuations() {
    const auto& segments = skeleton_.segments;
    graph_.continuation.assign(segments.size(), -1);
    graph_.is_continuation.assign(segments.size(), false);
    std::vector<double> best(segments.size(), kMaxBendDeg + 1e-9);
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const std::int32_t parent = segments[i].parent;
      if (parent < 0) continue;
      const double bend =
          bend_deg(direction(segments[static_cast<std::size_t>(parent)]),
                   direction(segments[i]));
      if (bend <= best[static_cast<std::size_t>(parent)]) {
        best[static_cast<std::size_t>(parent)] = bend;
        graph_.continuation[static_cast<std::size_t>(parent)] =
            static_cast<std::int32_t>(i);
      }
    }
    for (const std::int32_t c : graph_.continuation) {
      if (c >= 0) graph_.is_continuation[static_cast<std::size_t>(c)] = true;
    }
  }

  // Branch points: the end of a segment with a child other than its
  // continuation, and a point where several chains start.
  void find_junctions() {
    const auto& segments = skeleton_.segments;
    std::vector<std::vector<std::int32_t>> children(segments.size());
    std::unordered_map<NodeKey, std::vector<std::int32_t>, NodeKeyHash> roots;
    std::vector<NodeKey> root_order;
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const auto self = static_cast<std::int32_t>(i);
      if (segments[i].parent >= 0) {
        children[static_cast<std::size_t>(segments[i].parent)].push_back(self);
      } else {
        auto [it, inserted] = roots.try_emplace(node_key(segments[i].p0));
        if (inserted) root_order.push_back(it->first);
        it->second.push_back(self);
      }
    }
    graph_.start_junction.assign(segments.size(), -1);
    graph_.end_junction.assign(segments.size(), -1);
    const auto add = [&](Junction j) {
      const auto index = static_cast<std::int32_t>(graph_.junctions.size());
      if (j.incoming >= 0)
        graph_.end_junction[static_cast<std::size_t>(j.incoming)] = index;
      for (const std::int32_t o : j.outgoing)
        graph_.start_junction[static_cast<std::size_t>(o)] = index;
      graph_.junctions.push_back(std::move(j));
    };
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const std::vector<std::int32_t>& c = children[i];
      if (c.size() >= 2 || (c.size() == 1 && graph_.continuation[i] != c[0])) {
        add(Junction{.at = segments[i].p1,
                     .incoming = static_cast<std::int32_t>(i),
                     .outgoing = c});
      }
    }
    for (const NodeKey& key : root_order) {
      const std::vector<std::int32_t>& starts = roots.at(key);
      if (starts.size() >= 2) {
        add(Junction{.at = seg(starts[0]).p0, .outgoing = starts});
      }
    }
    graph_.incoming_ring.assign(segments.size(), -1);
    for (Junction& j : graph_.junctions) plan_hull(j);
    for (Junction& j : graph_.junctions) {
      if (j.hull) place_rings(j);
    }
    for (std::size_t j = 0; j < graph_.junctions.size(); ++j) {
      if (graph_.junctions[j].hull && graph_.junctions[j].incoming >= 0) {
        graph_.incoming_ring[static_cast<std::size_t>(
            graph_.junctions[j].places.front().segment)] =
            static_cast<std::int32_t>(j);
      }
    }
  }

  bool runs_straight_on(std::int32_t a, std::int32_t b) const {
    return glm::dot(direction(seg(a)), direction(seg(b))) > kStraight;
  }

  // The segments a tube runs straight along from a junction, away from it,
  // up to the next junction (whose segment is included) or bend.
  std::vector<std::int32_t> stretch_out(std::int32_t first) const {
    std::vector<std::int32_t> out{first};
    for (std::int32_t i = first;;) {
      const std::int32_t next =
          graph_.continuation[static_cast<std::size_t>(i)];
      if (graph_.end_junction[static_cast<std::size_t>(i)] >= 0 || next < 0 ||
          !runs_straight_on(i, next))
        return out;
      out.push_back(i = next);
    }
  }

  std::vector<std::int32_t> stretch_in(std::int32_t last) const {
    std::vector<std::int32_t> out{last};
    for (std::int32_t i = last;;) {
      const std::int32_t parent = seg(i).parent;
      if (graph_.start_junction[static_cast<std::size_t>(i)] >= 0 ||
          parent < 0 ||
          graph_.continuation[static_cast<std::size_t>(parent)] != i ||
          !runs_straight_on(parent, i))
        return out;
      out.push_back(i = parent);
    }
  }

  // Chooses, for every tube at the junction, the distance from the branch
  // point to its ring such that each ring is a face of the convex hull of
  // all rings: every other ring lies below its plane by a margin. For rings
  // t and u at angle α, at distances s_t and s_u, with radius r_u, this
  // needs s_t >= s_u cos α + r_u sin α + margin, solved here by iterating
  // to the least fixed point. The hull is then a B-Mesh-style junction
  // (Ji et al. 2010). A ring may lie beyond the tube's first segment where
  // the tube runs straight on. Tubes too close in direction leave the
  // junction to the union.
  void plan_hull(Junction& j) const {
    // Without an incoming tube the hull of the rings would leave the
    // starting point out (the foot of a plant): the union joins those.
    if (j.incoming < 0) return;
    std::vector<glm::dvec3> dirs;
    std::vector<double> radii;
    const auto end_of = [&](std::vector<std::int32_t> stretch, double sign) {
      dirs.push_back(sign * direction(seg(stretch[0])));
      double radius = 0.0;
      double along = 0.0;
      for (const std::int32_t i : stretch) {
        radius = std::max(
            {radius, seg(i).start_diameter / 2.0, seg(i).end_diameter / 2.0});
        along += length(seg(i));
      }
      radii.push_back(tube_corner_radius(radius, options_.tolerance_mm));
      j.stretches.push_back(std::move(stretch));
      j.stretch_mm.push_back(along);
    };
    end_of(stretch_in(j.incoming), -1.0);
    for (const std::int32_t o : j.outgoing) end_of(stretch_out(o), 1.0);
    // A part has one colour: where colours meet, the union joins the tubes
    // (and --multi-material gives each colour its own volume).
    if (options_.split_colors) {
      const int color = seg(j.incoming).color;
      for (const std::vector<std::int32_t>& stretch : j.stretches) {
        for (const std::int32_t i : stretch) {
          if (seg(i).color != color) return;
        }
      }
    }
    const std::size_t n = dirs.size();
    const double widest = *std::max_element(radii.begin(), radii.end());
    const double margin = kJunctionMargin * widest;
    std::vector<double> offsets(n);
    for (std::size_t t = 0; t < n; ++t) {
      offsets[t] = kJunctionMinOffset * radii[t];
    }
    for (std::size_t t = 0; t < n; ++t) {
      for (std::size_t u = 0; u < n; ++u) {
        if (t != u && 1.0 - glm::dot(dirs[t], dirs[u]) < kJunctionMinSpread)
          return;
      }
    }
    // Each pass raises an offset to what the others require; the fixed
    // point is reached geometrically fast unless two tubes are nearly
    // parallel, which the spread test excludes.
    for (int pass = 0; pass < 200; ++pass) {
      bool changed = false;
      for (std::size_t t = 0; t < n; ++t) {
        for (std::size_t u = 0; u < n; ++u) {
          if (t == u) continue;
          const double c = glm::dot(dirs[t], dirs[u]);
          const double needed =
              offsets[u] * c +
              radii[u] * std::sqrt(std::max(0.0, 1.0 - c * c)) + margin;
          if (needed > offsets[t] * (1.0 + 1e-12)) {
            offsets[t] = needed;
            changed = true;
          }
        }
      }
      if (!changed) {
        j.offsets_mm = std::move(offsets);
        j.hull = true;
        return;
      }
    }
  }

  // Keeps a hull junction only if every ring fits on its stretch, leaving
  // room for the ring of a hull junction at the stretch's far end. (A mitre
  // there is checked as the chain is walked, and broken if it does not fit.)
  void place_rings(Junction& j) {
    for (std::size_t e = 0; e < j.offsets_mm.size(); ++e) {
      const std::vector<std::int32_t>& stretch = j.stretches[e];
      double room = kMitreBudget * j.stretch_mm[e];
      const std::int32_t far =
          e == 0
              ? graph_.start_junction[static_cast<std::size_t>(stretch.back())]
              : graph_.end_junction[static_cast<std::size_t>(stretch.back())];
      if (far >= 0 && graph_.junctions[static_cast<std::size_t>(far)].hull) {
        const Junction& k = graph_.junctions[static_cast<std::size_t>(far)];
        double theirs = 0.0;
        if (e == 0) {  // our incoming tube is one of their outgoing ones
          const auto it =
              std::find(k.outgoing.begin(), k.outgoing.end(), stretch.back());
          theirs = k.offsets_mm[1 + static_cast<std::size_t>(
                                        it - k.outgoing.begin())];
        } else {
          theirs = k.offsets_mm[0];
        }
        room -= theirs;
      }
      if (j.offsets_mm[e] > room) {
        j.hull = false;
        j.places.clear();
        return;
      }
      double before = 0.0;
      for (const std::int32_t i : stretch) {
        const double l = length(seg(i));
        if (before + l > j.offsets_mm[e]) {
          j.places.push_back({i, j.offsets_mm[e] - before});
          break;
        }
        before += l;
      }
    }
  }

  const lsys::Segment& seg(std::int32_t i) const {
    return skeleton_.segments[static_cast<std::size_t>(i)];
  }

  const lsys::Skeleton& skeleton_;
  const PartOptions& options_;
  BranchGraph graph_;
};

}  // namespace

std::int32_t BranchGraph::hull_at_start(std::int32_t i) const {
  const std::int32_t j = start_junction[static_cast<std::size_t>(i)];
  return j >= 0 && junctions[static_cast<std::size_t>(j)].hull ? j : -1;
}

std::int32_t BranchGraph::ring_ahead(std::int32_t i) const {
  const std::int32_t j = incoming_ring[static_cast<std::size_t>(i)];
  return j >= 0 && junctions[static_cast<std::size_t>(j)].hull ? j : -1;
}

const RingPlace& BranchGraph::place_of(std::int32_t junction,
                                       std::int32_t tube) const {
  const Junction& j = junctions[static_cast<std::size_t>(junction)];
  const std::size_t skip = j.incoming >= 0 ? 1 : 0;
  if (tube == j.incoming) return j.places.front();
  const auto it = std::find(j.outgoing.begin(), j.outgoing.end(), tube);
  return j.places[skip + static_cast<std::size_t>(it - j.outgoing.begin())];
}

BranchGraph plan_branches(const lsys::Skeleton& skeleton,
                          const PartOptions& options) {
  return Planner(skeleton, options).plan();
}

double node_radius(const lsys::Skeleton& skeleton, const BranchGraph& graph,
                   std::int32_t i) {
  const auto& segments = skeleton.segments;
  double r = segments[static_cast<std::size_t>(i)].end_diameter / 2.0;
  const std::int32_t c = graph.continuation[static_cast<std::size_t>(i)];
  if (c >= 0)
    r = std::max(r, segments[static_cast<std::size_t>(c)].start_diameter / 2.0);
  return r;
}

}  // namespace lsolid
