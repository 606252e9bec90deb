// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Meshing the skeleton into few, well-conditioned boolean operands
// (docs/design.md, "Parts"): one swept tube per
// unbranched chain, with rings shared between segments and mitred at bends,
// so that no internal caps exist; branch points meshed directly as the
// convex hull of the rings of the tubes that meet there (B-Mesh, Ji et al.
// 2010; SQM, Bærentzen et al. 2012), stitched to the tubes, so that a tree
// needs no boolean at all; joints that enclose the end caps of tubes where a
// hull does not fit, so that no caps coincide; plates for leaves. Ring
// frames are parallel-transported along a chain (rotation-minimising, as in
// Wang et al. 2008's double reflection, here by the equivalent minimal
// rotation per bend), and each part gets its own ring phase, so that
// overlapping parts never share vertices or faces exactly.
#include "lsolid/parts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <unordered_map>

#include "cgal/part_queries.hpp"
#include "cgal/polygon_union.hpp"
#include "lsolid/errors.hpp"
#include "lsolid/validate.hpp"
#include "parts/thickened_sheet.hpp"
#include "union_find.hpp"

namespace lsolid {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kMaxBendDeg = 100.0;  // a sharper bend breaks the chain
constexpr double kMitreBudget = 0.8;   // of a segment's length, for mitres
constexpr double kJointMargin = 1.06;  // joint inradius over the largest cap
constexpr double kGolden = 0.6180339887498949;
constexpr double kClearance = 1.6;  // mitres reach up to 1/cos(50°) of r
constexpr double kPathClearance =
    2.5;  // half a turn of radius 1.25 r, and more
// Hull junctions (see plan_hull).
constexpr double kJunctionMargin = 0.05;     // of the widest radius
constexpr double kJunctionMinOffset = 0.5;   // of the tube's own radius
constexpr double kJunctionMinSpread = 1e-3;  // 1 - cos of the closest pair
constexpr int kMaxRounds = 8;
constexpr double kOnAxis = 0.1;  // of the stem radius: a leaf starts there
constexpr double kStraight = 1.0 - 1e-12;  // cos of a bend too small to see
// Leaf polygons within this fraction of the model's size of each other's
// planes are in one plane: turtle paths that meet again differ by rounding
// errors of about 1e-15 of the size.
constexpr double kCoplanar = 1e-9;
constexpr double kParallel = 1.0 - 1e-9;  // |cos| of parallel leaf normals
constexpr double kPlateMargin = 1.05;
// A sheet at most this many plate thicknesses across may become its
// thickened points' convex hull when it cannot be thickened cleanly.
constexpr double kHullSheetWalls = 8.0;  // plate over the thinnest tube

glm::dvec3 direction(const lsys::Segment& s) {
  return glm::normalize(s.p1 - s.p0);
}

double length(const lsys::Segment& s) { return glm::length(s.p1 - s.p0); }

glm::dvec3 any_perpendicular(const glm::dvec3& d) {
  const glm::dvec3 axis = std::fabs(d.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0)
                                               : glm::dvec3(0.0, 1.0, 0.0);
  return glm::normalize(glm::cross(d, axis));
}

// Rodrigues' rotation of v about the unit axis k by angle θ (cos c, sin s).
glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& k, double c,
                  double s) {
  return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1.0 - c);
}

// The minimal rotation taking unit `from` to unit `to`, applied to v.
glm::dvec3 transport(const glm::dvec3& v, const glm::dvec3& from,
                     const glm::dvec3& to) {
  const glm::dvec3 axis = glm::cross(from, to);
  const double s = glm::length(axis);
  if (s < 1e-15) return v;  // parallel: chains never bend by 180°
  return rotate(v, axis / s, glm::dot(from, to), s);
}

// The largest side of the skeleton's box, at least 1 mm.
double size_of(const lsys::Skeleton& skeleton) {
  Box box;
  const auto add = [&](const glm::dvec3& p) {
    box.min = glm::min(box.min, p);
    box.max = glm::max(box.max, p);
  };
  for (const lsys::Segment& s : skeleton.segments) {
    add(s.p0);
    add(s.p1);
  }
  for (const lsys::Polygon& polygon : skeleton.polygons) {
    for (const glm::dvec3& p : polygon.points) add(p);
  }
  for (const lsys::Sphere& s : skeleton.spheres) {
    add(s.center - glm::dvec3(s.diameter / 2.0));
    add(s.center + glm::dvec3(s.diameter / 2.0));
  }
  for (const lsys::Sheet& sheet : skeleton.sheets) {
    for (const glm::dvec3& p : sheet.points) add(p);
  }
  const glm::dvec3 extent = box.max - box.min;
  return std::max({1.0, extent.x, extent.y, extent.z});
}

double bend_deg(const glm::dvec3& a, const glm::dvec3& b) {
  return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * 180.0 / kPi;
}

// Nodes are keyed by their exact coordinates: segments that meet share them
// exactly, since the turtle does not move between them.
struct NodeKey {
  std::uint64_t x, y, z;
  bool operator==(const NodeKey&) const = default;
};
struct NodeKeyHash {
  std::size_t operator()(const NodeKey& k) const noexcept {
    return static_cast<std::size_t>(k.x * 0x9E3779B97F4A7C15ULL ^
                                    (k.y + 0x632BE59BD9B4E019ULL) * 31U ^ k.z);
  }
};
NodeKey node_key(const glm::dvec3& p) {
  return {std::bit_cast<std::uint64_t>(p.x + 0.0),
          std::bit_cast<std::uint64_t>(p.y + 0.0),
          std::bit_cast<std::uint64_t>(p.z + 0.0)};
}

// Where a tube's ring at a junction lies: in `segment`, at `local_mm` from
// the segment's end at the junction's side.
struct RingPlace {
  std::int32_t segment = -1;
  double local_mm = 0.0;
};

// A branch point: where a segment's children start (or several chains start
// at the same point), and how it is meshed.
struct Junction {
  glm::dvec3 at{0.0};
  std::int32_t incoming = -1;          // the segment that ends here, or -1
  std::vector<std::int32_t> outgoing;  // the segments that start here
  // Per tube, the incoming first, then the outgoing: the distance from `at`
  // to its ring, the straight stretch the ring may lie on, and where in it
  // the ring lies (tubes that run straight on may have the ring beyond
  // their first segment).
  std::vector<double> offsets_mm;
  std::vector<std::vector<std::int32_t>> stretches;
  std::vector<double> stretch_mm;
  std::vector<RingPlace> places;
  // Meshed as the convex hull of the tubes' rings, stitched to the tubes
  // without a boolean; otherwise the tubes run to `at` and a joint sphere
  // encloses their caps, for the union to merge.
  bool hull = false;
};

// A piece of a stitched part: its triangles index the shared vertex pool, so
// that pieces meeting at a ring share its vertices exactly.
struct Piece {
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::string label;
  int color = 0;
  std::int32_t hull_of = -1;           // the junction this hull meshes
  std::vector<std::int32_t> attached;  // hull junctions at a tube's ends
};

// A tube's ring at a hull junction, in the order in which the tube's side
// faces use its edges (ring[i] to ring[i + 1]).
struct Ring {
  std::vector<std::uint32_t> vertices;
};

class PartBuilder {
 public:
  PartBuilder(const lsys::Skeleton& skeleton, const PartOptions& options)
      : skeleton_(skeleton), options_(options), scale_mm_(size_of(skeleton)) {}

  PartSet build() {
    choose_continuations();
    find_junctions();
    for (int round = 0;; ++round) {
      std::vector<std::int32_t> revert = mesh_round();
      if (revert.empty()) break;
      for (const std::int32_t j : revert) {
        junctions_[static_cast<std::size_t>(j)].hull = false;
      }
      if (round + 1 >= kMaxRounds) {
        // Without hulls every part is a closed tube, sphere or plate.
        for (Junction& j : junctions_) j.hull = false;
      }
    }
    std::size_t index = 0;
    for (const Joint& joint : joints_) {
      set_.parts.push_back(
          Part{sphere(joint.center, joint.radius, index++),
               fmt::format("joint at ({:.3f}, {:.3f}, {:.3f}) mm",
                           joint.center.x, joint.center.y, joint.center.z),
               joint.color});
      ++set_.joints;
    }
    // `@O` balls, each its own part of its own colour (scale_to_print made
    // them a wall across at least).
    for (const lsys::Sphere& b : skeleton_.spheres) {
      set_.parts.push_back(
          Part{ball(b.center, b.diameter / 2.0, index++),
               fmt::format("sphere at ({:.3f}, {:.3f}, {:.3f}) mm", b.center.x,
                           b.center.y, b.center.z),
               b.color});
      ++set_.spheres;
    }
    for (std::size_t i = 0; i < skeleton_.sheets.size(); ++i) add_sheet(i);
    return std::move(set_);
  }

 private:
  struct Joint {
    glm::dvec3 center;
    double radius;  // the largest cap it must enclose
    int color;      // of the first segment that asked for it
  };

  // Meshes everything with the current choice of hull junctions. Returns the
  // junctions whose hulls failed or made a stitched part cut itself; if
  // there are any, the round's output is discarded.
  std::vector<std::int32_t> mesh_round() {
    set_ = PartSet{};
    pool_.clear();
    pieces_.clear();
    rings_.assign(junctions_.size(), {});
    joints_.clear();
    joint_index_.clear();
    for (std::size_t i = 0; i < skeleton_.segments.size(); ++i) {
      if (!is_continuation_[i]) walk_chain(static_cast<std::int32_t>(i));
    }
    std::vector<std::int32_t> revert = build_hulls();
    if (!revert.empty()) return revert;
    revert = assemble();
    if (!revert.empty()) return revert;
    add_plates();
    return {};
  }

  // The continuation of a segment is the child that turns least (and by at
  // most kMaxBendDeg), the later one on a tie: `F[+F]F` continues with the
  // last F, the main axis.
  void choose_continuations() {
    const auto& segments = skeleton_.segments;
    continuation_.assign(segments.size(), -1);
    is_continuation_.assign(segments.size(), false);
    std::vector<double> best(segments.size(), kMaxBendDeg + 1e-9);
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const std::int32_t parent = segments[i].parent;
      if (parent < 0) continue;
      const double bend =
          bend_deg(direction(segments[static_cast<std::size_t>(parent)]),
                   direction(segments[i]));
      if (bend <= best[static_cast<std::size_t>(parent)]) {
        best[static_cast<std::size_t>(parent)] = bend;
        continuation_[static_cast<std::size_t>(parent)] =
            static_cast<std::int32_t>(i);
      }
    }
    for (const std::int32_t c : continuation_) {
      if (c >= 0) is_continuation_[static_cast<std::size_t>(c)] = true;
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
    start_junction_.assign(segments.size(), -1);
    end_junction_.assign(segments.size(), -1);
    const auto add = [&](Junction j) {
      const auto index = static_cast<std::int32_t>(junctions_.size());
      if (j.incoming >= 0)
        end_junction_[static_cast<std::size_t>(j.incoming)] = index;
      for (const std::int32_t o : j.outgoing)
        start_junction_[static_cast<std::size_t>(o)] = index;
      junctions_.push_back(std::move(j));
    };
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const std::vector<std::int32_t>& c = children[i];
      if (c.size() >= 2 || (c.size() == 1 && continuation_[i] != c[0])) {
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
    incoming_ring_.assign(segments.size(), -1);
    for (Junction& j : junctions_) plan_hull(j);
    for (Junction& j : junctions_) {
      if (j.hull) place_rings(j);
    }
    for (std::size_t j = 0; j < junctions_.size(); ++j) {
      if (junctions_[j].hull && junctions_[j].incoming >= 0) {
        incoming_ring_[static_cast<std::size_t>(
            junctions_[j].places.front().segment)] =
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
      const std::int32_t next = continuation_[static_cast<std::size_t>(i)];
      if (end_junction_[static_cast<std::size_t>(i)] >= 0 || next < 0 ||
          !runs_straight_on(i, next))
        return out;
      out.push_back(i = next);
    }
  }
  std::vector<std::int32_t> stretch_in(std::int32_t last) const {
    std::vector<std::int32_t> out{last};
    for (std::int32_t i = last;;) {
      const std::int32_t parent = seg(i).parent;
      if (start_junction_[static_cast<std::size_t>(i)] >= 0 || parent < 0 ||
          continuation_[static_cast<std::size_t>(parent)] != i ||
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
          e == 0 ? start_junction_[static_cast<std::size_t>(stretch.back())]
                 : end_junction_[static_cast<std::size_t>(stretch.back())];
      if (far >= 0 && junctions_[static_cast<std::size_t>(far)].hull) {
        const Junction& k = junctions_[static_cast<std::size_t>(far)];
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

  // The hull junction at the start of segment i, or -1.
  std::int32_t hull_at_start(std::int32_t i) const {
    const std::int32_t j = start_junction_[static_cast<std::size_t>(i)];
    return j >= 0 && junctions_[static_cast<std::size_t>(j)].hull ? j : -1;
  }
  // The hull junction whose incoming ring lies in segment i, or -1.
  std::int32_t ring_ahead(std::int32_t i) const {
    const std::int32_t j = incoming_ring_[static_cast<std::size_t>(i)];
    return j >= 0 && junctions_[static_cast<std::size_t>(j)].hull ? j : -1;
  }
  const RingPlace& place_of(std::int32_t junction, std::int32_t tube) const {
    const Junction& j = junctions_[static_cast<std::size_t>(junction)];
    const std::size_t skip = j.incoming >= 0 ? 1 : 0;
    if (tube == j.incoming) return j.places.front();
    const auto it = std::find(j.outgoing.begin(), j.outgoing.end(), tube);
    return j.places[skip + static_cast<std::size_t>(it - j.outgoing.begin())];
  }

  void add_joint(const glm::dvec3& center, double radius, int color) {
    const auto [it, inserted] =
        joint_index_.emplace(node_key(center), joints_.size());
    if (inserted) {
      joints_.push_back(Joint{center, radius, color});
    } else {
      joints_[it->second].radius = std::max(joints_[it->second].radius, radius);
    }
  }

  // The largest tube radius at the end of segment i, where its children
  // start.
  double node_radius(std::int32_t i) const {
    double r = seg(i).end_diameter / 2.0;
    const std::int32_t c = continuation_[static_cast<std::size_t>(i)];
    if (c >= 0) r = std::max(r, seg(c).start_diameter / 2.0);
    return r;
  }

  // Follows continuations from a chain's first segment, breaking where a
  // mitre would not fit and at hull junctions, and emits one tube per
  // unbroken run. At a hull junction a run ends or starts at the tube's
  // ring; the segments between ring and junction are inside the hull.
  void walk_chain(std::int32_t first) {
    std::int32_t run_start = hull_at_start(first);
    double start_local = 0.0;
    if (run_start >= 0) {
      const RingPlace& place = place_of(run_start, first);
      first = place.segment;
      start_local = place.local_mm;
    } else if (seg(first).parent >= 0) {
      add_joint(seg(first).p0,
                std::max(seg(first).start_diameter / 2.0,
                         node_radius(seg(first).parent)),
                seg(seg(first).parent).color);
    }
    std::vector<std::int32_t> run{first};
    run_.start(first);
    double start_extent = start_local;
    for (;;) {
      const std::int32_t last = run.back();
      const std::int32_t junction = ring_ahead(last);
      if (junction >= 0) {
        const Junction& j = junctions_[static_cast<std::size_t>(junction)];
        emit_tube(run, run_start, start_local, junction,
                  j.places.front().local_mm);
        const std::int32_t next =
            continuation_[static_cast<std::size_t>(j.incoming)];
        if (next < 0) return;
        const RingPlace& place = place_of(junction, next);
        run.assign(1, place.segment);
        run_.start(place.segment);
        run_start = junction;
        start_local = start_extent = place.local_mm;
        continue;
      }
      const std::int32_t next = continuation_[static_cast<std::size_t>(last)];
      if (next < 0) break;
      const double theta = bend_deg(direction(seg(last)), direction(seg(next)));
      const double r =
          std::max(seg(last).end_diameter, seg(next).start_diameter) / 2.0;
      const double extent = r * std::tan(theta * kPi / 360.0);
      const std::int32_t ahead = ring_ahead(next);
      const double end_need = ahead < 0
                                  ? 0.0
                                  : junctions_[static_cast<std::size_t>(ahead)]
                                        .places.front()
                                        .local_mm;
      if ((!options_.split_colors || seg(next).color == seg(last).color) &&
          start_extent + extent <= kMitreBudget * length(seg(last)) &&
          extent + end_need <= kMitreBudget * length(seg(next)) &&
          !run_.comes_near(next)) {
        run.push_back(next);
        run_.add(next);
        start_extent = extent;
        continue;
      }
      emit_tube(run, run_start, start_local, -1, 0.0);
      add_joint(seg(last).p1, r, seg(last).color);
      run.assign(1, next);
      run_.start(next);
      run_start = -1;
      start_local = start_extent = 0.0;
    }
    emit_tube(run, run_start, start_local, -1, 0.0);
  }

  // The segments of the tube being built, in a grid, to tell when the next
  // segment would pass so close to an earlier one that the tube would cut
  // itself (space-filling curves turn back on themselves; a tube must not).
  // Segments close along the path are left out: the mitre budget keeps the
  // path's radius of curvature above 1.25 r, so a tube can only come back to
  // itself after a path of more than half a turn.
  class RunGrid {
   public:
    RunGrid(const lsys::Skeleton& skeleton, double tolerance_mm)
        : segments_(skeleton.segments), tolerance_mm_(tolerance_mm) {
      double longest = 0.0;
      double widest = 0.0;
      for (const lsys::Segment& s : segments_) {
        longest = std::max(longest, glm::length(s.p1 - s.p0));
        widest = std::max({widest, s.start_diameter, s.end_diameter});
      }
      // Segments closer than the clearance have midpoints in adjacent cells
      // (corners stand out by at most 1 / cos(π/6) of the radius).
      cell_ = std::max(longest + kClearance * 1.16 * widest, 1e-9);
    }
    void start(std::int32_t first) {
      cells_.clear();
      path_start_.clear();
      path_length_ = 0.0;
      last_ = -1;
      add(first);
    }
    void add(std::int32_t i) {
      if (last_ >= 0) cells_[key(centre(last_))].push_back(last_);
      last_ = i;  // the newest stays out: it touches the next one
      path_start_[i] = path_length_;
      path_length_ += length_of(i);
    }
    // True if segment i comes within the sum of the radii (widened for
    // mitres) of a segment of the run other than the newest.
    bool comes_near(std::int32_t i) const {
      const glm::dvec3 c = centre(i);
      for (int dx = -1; dx <= 1; ++dx) {
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dz = -1; dz <= 1; ++dz) {
            auto k = key(c);
            k[0] += dx;
            k[1] += dy;
            k[2] += dz;
            const auto it = cells_.find(k);
            if (it == cells_.end()) continue;
            for (const std::int32_t j : it->second) {
              const double reach = radius(i) + radius(j);
              const double along =
                  path_length_ - path_start_.at(j) - length_of(j);
              if (along > kPathClearance * reach &&
                  distance(i, j) < kClearance * reach) {
                return true;
              }
            }
          }
        }
      }
      return false;
    }

   private:
    using Key = std::array<std::int64_t, 3>;
    struct KeyHash {
      std::size_t operator()(const Key& k) const noexcept {
        return static_cast<std::size_t>(k[0] * 73856093LL ^ k[1] * 19349663LL ^
                                        k[2] * 83492791LL);
      }
    };
    glm::dvec3 centre(std::int32_t i) const {
      const lsys::Segment& s = segments_[static_cast<std::size_t>(i)];
      return (s.p0 + s.p1) / 2.0;
    }
    double length_of(std::int32_t i) const {
      const lsys::Segment& s = segments_[static_cast<std::size_t>(i)];
      return glm::length(s.p1 - s.p0);
    }
    double radius(std::int32_t i) const {
      const lsys::Segment& s = segments_[static_cast<std::size_t>(i)];
      return tube_corner_radius(
          std::max(s.start_diameter, s.end_diameter) / 2.0, tolerance_mm_);
    }
    Key key(const glm::dvec3& p) const {
      return {static_cast<std::int64_t>(std::floor(p.x / cell_)),
              static_cast<std::int64_t>(std::floor(p.y / cell_)),
              static_cast<std::int64_t>(std::floor(p.z / cell_))};
    }
    // The distance between two segments (Lumelsky's closest points).
    double distance(std::int32_t i, std::int32_t j) const {
      const lsys::Segment& a = segments_[static_cast<std::size_t>(i)];
      const lsys::Segment& b = segments_[static_cast<std::size_t>(j)];
      const glm::dvec3 d1 = a.p1 - a.p0;
      const glm::dvec3 d2 = b.p1 - b.p0;
      const glm::dvec3 r = a.p0 - b.p0;
      const double aa = glm::dot(d1, d1);
      const double ee = glm::dot(d2, d2);
      const double f = glm::dot(d2, r);
      const double c = glm::dot(d1, r);
      const double bb = glm::dot(d1, d2);
      const double denom = aa * ee - bb * bb;
      double s = denom > 1e-18 * aa * ee
                     ? std::clamp((bb * f - c * ee) / denom, 0.0, 1.0)
                     : 0.0;
      double t = (bb * s + f) / ee;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / aa, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((bb - c) / aa, 0.0, 1.0);
      }
      return glm::length(a.p0 + d1 * s - (b.p0 + d2 * t));
    }

    const std::vector<lsys::Segment>& segments_;
    double tolerance_mm_;
    double cell_ = 0.0;
    std::unordered_map<Key, std::vector<std::int32_t>, KeyHash> cells_;
    std::unordered_map<std::int32_t, double> path_start_;  // along the run
    double path_length_ = 0.0;
    std::int32_t last_ = -1;
  };

  // A tube along the run; its ends lie `offset` inside the run at hull
  // junctions, where they are open rings for the hull, and are capped
  // elsewhere.
  void emit_tube(const std::vector<std::int32_t>& run, std::int32_t start_hull,
                 double start_local, std::int32_t end_hull, double end_local) {
    const std::size_t k = run.size();
    std::vector<glm::dvec3> centers(k + 1);
    std::vector<double> radii(k + 1);
    const lsys::Segment& head = seg(run[0]);
    const lsys::Segment& tail = seg(run[k - 1]);
    const double s0 = start_local / length(head);
    const double s1 = end_local / length(tail);
    centers[0] = head.p0 + (head.p1 - head.p0) * s0;
    radii[0] =
        (head.start_diameter + (head.end_diameter - head.start_diameter) * s0) /
        2.0;
    for (std::size_t j = 1; j < k; ++j) {
      centers[j] = seg(run[j]).p0;
      radii[j] =
          std::max(seg(run[j - 1]).end_diameter, seg(run[j]).start_diameter) /
          2.0;
    }
    centers[k] = tail.p1 + (tail.p0 - tail.p1) * s1;
    radii[k] =
        (tail.end_diameter + (tail.start_diameter - tail.end_diameter) * s1) /
        2.0;
    const double largest = *std::max_element(radii.begin(), radii.end());
    const int m = tube_sides(largest, options_.tolerance_mm);

    // The ring frame of the first segment, turned by this tube's own phase.
    glm::dvec3 d = direction(head);
    const double phase =
        std::fmod(static_cast<double>(set_.tubes) * kGolden, 1.0) * 2.0 * kPi /
        m;
    glm::dvec3 a =
        rotate(any_perpendicular(d), d, std::cos(phase), std::sin(phase));

    const auto base = static_cast<std::uint32_t>(pool_.size());
    const auto ring = [&](const glm::dvec3& center, double radius,
                          const glm::dvec3& dir, const glm::dvec3& axis_a,
                          const glm::dvec3* mitre_normal) {
      const glm::dvec3 b = glm::cross(dir, axis_a);
      // Corners beyond the circle, flat sides on it: a tube is never
      // thinner than its width (the printer's wall), and tubes whose
      // circles touch overlap, so the union fuses them.
      const double corner = radius / std::cos(kPi / m);
      for (int i = 0; i < m; ++i) {
        const double angle = 2.0 * kPi * i / m;
        glm::dvec3 q =
            corner * (std::cos(angle) * axis_a + std::sin(angle) * b);
        if (mitre_normal != nullptr) {
          q -=
              dir * (glm::dot(q, *mitre_normal) / glm::dot(dir, *mitre_normal));
        }
        pool_.push_back(center + q);
      }
    };
    ring(centers[0], radii[0], d, a, nullptr);
    for (std::size_t j = 1; j < k; ++j) {
      const glm::dvec3 next = direction(seg(run[j]));
      const glm::dvec3 mitre = glm::normalize(d + next);
      ring(centers[j], radii[j], d, a, &mitre);
      a = glm::normalize(transport(a, d, next));
      d = next;
    }
    ring(centers[k], radii[k], d, a, nullptr);

    const auto v = [m, base](std::size_t ring_index, int i) {
      return base + static_cast<std::uint32_t>(
                        ring_index * static_cast<std::size_t>(m) +
                        static_cast<std::size_t>((i + m) % m));
    };
    Piece piece;
    for (std::size_t j = 0; j < k; ++j) {
      for (int i = 0; i < m; ++i) {
        piece.triangles.push_back({v(j, i), v(j, i + 1), v(j + 1, i + 1)});
        piece.triangles.push_back({v(j, i), v(j + 1, i + 1), v(j + 1, i)});
      }
    }
    if (start_hull >= 0) {
      Ring r;
      for (int i = 0; i < m; ++i) r.vertices.push_back(v(0, i));
      rings_[static_cast<std::size_t>(start_hull)].push_back(std::move(r));
      piece.attached.push_back(start_hull);
    } else {
      for (int i = 1; i + 1 < m; ++i)
        piece.triangles.push_back({v(0, 0), v(0, i + 1), v(0, i)});
    }
    if (end_hull >= 0) {
      Ring r;  // the side faces run from (k, i + 1) to (k, i)
      for (int i = m; i > 0; --i) r.vertices.push_back(v(k, i));
      rings_[static_cast<std::size_t>(end_hull)].push_back(std::move(r));
      piece.attached.push_back(end_hull);
    } else {
      for (int i = 1; i + 1 < m; ++i)
        piece.triangles.push_back({v(k, 0), v(k, i), v(k, i + 1)});
    }
    const std::int32_t front = run.front();
    const std::int32_t back = run.back();
    piece.label = front == back
                      ? fmt::format("tube of segment {}", front)
                      : fmt::format("tube of segments {}-{}", front, back);
    piece.color = seg(front).color;
    pieces_.push_back(std::move(piece));
    ++set_.tubes;
  }

  // The hull of each hull junction's rings, without the rings' own faces:
  // a surface whose boundary is exactly the rings, in the orientation that
  // closes the tubes. Returns the junctions where that did not come out.
  std::vector<std::int32_t> build_hulls() {
    std::vector<std::int32_t> failed;
    hull_piece_.assign(junctions_.size(), -1);
    for (std::size_t j = 0; j < junctions_.size(); ++j) {
      const Junction& junction = junctions_[j];
      if (!junction.hull) continue;
      const std::vector<Ring>& rings = rings_[j];
      const std::size_t expected =
          junction.outgoing.size() + (junction.incoming >= 0 ? 1 : 0);
      std::vector<glm::dvec3> points;
      std::vector<std::uint32_t> global;
      std::vector<std::size_t> ring_of;
      for (std::size_t r = 0; r < rings.size(); ++r) {
        for (const std::uint32_t g : rings[r].vertices) {
          points.push_back(pool_[g]);
          global.push_back(g);
          ring_of.push_back(r);
        }
      }
      Piece piece;
      std::size_t removed = 0;
      std::vector<bool> used(points.size(), false);
      for (const auto& t : convex_hull_triangles(points)) {
        for (const std::uint32_t i : t) used[i] = true;
        if (ring_of[t[0]] == ring_of[t[1]] && ring_of[t[1]] == ring_of[t[2]]) {
          ++removed;
          continue;
        }
        piece.triangles.push_back({global[t[0]], global[t[1]], global[t[2]]});
      }
      if (rings.size() != expected || !is_ring_bounded(piece, rings, removed) ||
          std::find(used.begin(), used.end(), false) != used.end()) {
        failed.push_back(static_cast<std::int32_t>(j));
        continue;
      }
      piece.hull_of = static_cast<std::int32_t>(j);
      piece.color = seg(junction.incoming).color;
      piece.label = fmt::format("junction at ({:.3f}, {:.3f}, {:.3f}) mm",
                                junction.at.x, junction.at.y, junction.at.z);
      hull_piece_[j] = static_cast<std::int32_t>(pieces_.size());
      pieces_.push_back(std::move(piece));
      ++set_.junctions;
    }
    return failed;
  }

  // True if the hull piece's open edges are exactly the rings' edges, each
  // reversed (ring[i + 1] to ring[i]), and the faces taken out are exactly
  // the rings' triangulations.
  static bool is_ring_bounded(const Piece& piece,
                              const std::vector<Ring>& rings,
                              std::size_t removed) {
    std::size_t expected_removed = 0;
    std::unordered_map<std::uint64_t, int> directed;
    const auto key = [](std::uint32_t a, std::uint32_t b) {
      return (static_cast<std::uint64_t>(a) << 32U) | b;
    };
    for (const auto& t : piece.triangles) {
      for (int e = 0; e < 3; ++e) ++directed[key(t[e], t[(e + 1) % 3])];
    }
    std::size_t ring_edges = 0;
    for (const Ring& r : rings) {
      const std::size_t m = r.vertices.size();
      expected_removed += m - 2;
      for (std::size_t i = 0; i < m; ++i) {
        const std::uint32_t a = r.vertices[i];
        const std::uint32_t b = r.vertices[(i + 1) % m];
        const auto it = directed.find(key(b, a));
        if (it == directed.end() || it->second != 1 ||
            directed.count(key(a, b)))
          return false;
        ++ring_edges;
      }
    }
    if (removed != expected_removed) return false;
    std::size_t open = 0;
    for (const auto& [k, count] : directed) {
      if (count != 1) return false;
      const auto a = static_cast<std::uint32_t>(k >> 32U);
      const auto b = static_cast<std::uint32_t>(k & 0xFFFFFFFFU);
      if (!directed.count(key(b, a))) ++open;
    }
    return open == ring_edges;
  }

  // Joins pieces stitched at hull junctions into parts. A part whose pieces
  // cut each other (a branch running into another of the same tree) is
  // not a valid operand: the junctions that join the offending piece to the
  // rest are returned, to be left to the union in the next round.
  std::vector<std::int32_t> assemble() {
    UnionFind groups(pieces_.size());
    for (std::size_t p = 0; p < pieces_.size(); ++p) {
      for (const std::int32_t j : pieces_[p].attached) {
        const std::int32_t h = hull_piece_[static_cast<std::size_t>(j)];
        if (h >= 0)
          groups.join(static_cast<std::uint32_t>(p),
                      static_cast<std::uint32_t>(h));
      }
    }
    std::unordered_map<std::size_t, std::vector<std::size_t>> members;
    std::vector<std::size_t> order;
    for (std::size_t p = 0; p < pieces_.size(); ++p) {
      auto [it, inserted] =
          members.try_emplace(groups.find(static_cast<std::uint32_t>(p)));
      if (inserted) order.push_back(it->first);
      it->second.push_back(p);
    }
    std::vector<std::int32_t> revert;
    std::vector<Part> parts;
    for (const std::size_t root : order) {
      const std::vector<std::size_t>& group = members.at(root);
      TriangleMesh mesh;
      std::vector<std::size_t> piece_of;
      std::unordered_map<std::uint32_t, std::uint32_t> local;
      std::size_t tubes = 0;
      for (const std::size_t p : group) {
        if (pieces_[p].hull_of < 0) ++tubes;
        for (const auto& t : pieces_[p].triangles) {
          std::array<std::uint32_t, 3> out{};
          for (int c = 0; c < 3; ++c) {
            const auto [it, inserted] = local.try_emplace(
                t[c], static_cast<std::uint32_t>(mesh.vertices.size()));
            if (inserted) mesh.vertices.push_back(pool_[t[c]]);
            out[c] = it->second;
          }
          mesh.triangles.push_back(out);
          piece_of.push_back(p);
        }
      }
      if (group.size() > 1) {
        for (const auto& [f, g] : intersecting_triangle_pairs(mesh)) {
          isolate(pieces_[piece_of[f]], pieces_[piece_of[g]], revert);
        }
      }
      parts.push_back(
          Part{std::move(mesh),
               group.size() == 1
                   ? pieces_[group[0]].label
                   : fmt::format("{} tubes joined at {} junctions, from the {}",
                                 tubes, group.size() - tubes,
                                 pieces_[group[0]].label),
               pieces_[group[0]].color});
    }
    if (!revert.empty()) {
      std::sort(revert.begin(), revert.end());
      revert.erase(std::unique(revert.begin(), revert.end()), revert.end());
      return revert;
    }
    set_.parts = std::move(parts);
    return {};
  }

  // Separates two intersecting pieces of one part: a hull is given up; a
  // tube is cut loose from the hulls at its ends.
  static void isolate(const Piece& p, const Piece& q,
                      std::vector<std::int32_t>& revert) {
    if (p.hull_of >= 0) {
      revert.push_back(p.hull_of);
    } else if (q.hull_of >= 0) {
      revert.push_back(q.hull_of);
    } else if (!p.attached.empty()) {
      revert.insert(revert.end(), p.attached.begin(), p.attached.end());
    } else {
      revert.insert(revert.end(), q.attached.begin(), q.attached.end());
    }
  }

  // A UV sphere whose faces all lie farther than `radius` from the centre,
  // so that it encloses every cap of that radius at the centre.
  // A joint: a sphere that encloses the corners of caps of `radius`.
  TriangleMesh sphere(const glm::dvec3& center, double radius,
                      std::size_t index) {
    return ball(
        center,
        tube_corner_radius(radius, options_.tolerance_mm) * kJointMargin,
        index);
  }

  // A UV sphere whose faces all lie `needed` or farther from the centre,
  // as a tube's sides touch its circle; its turn by the golden angle per
  // `index` keeps neighbours' seams apart.
  TriangleMesh ball(const glm::dvec3& center, double needed,
                    std::size_t index) {
    const int longitudes =
        std::max(8, tube_sides(needed, options_.tolerance_mm));
    const int latitudes = std::max(4, longitudes / 2);
    const double phase = std::fmod(static_cast<double>(index) * kGolden, 1.0) *
                         2.0 * kPi / longitudes;
    TriangleMesh mesh;
    mesh.vertices.push_back({0.0, 0.0, 1.0});
    for (int lat = 1; lat < latitudes; ++lat) {
      const double polar = kPi * lat / latitudes;
      for (int lon = 0; lon < longitudes; ++lon) {
        const double azimuth = 2.0 * kPi * lon / longitudes + phase;
        mesh.vertices.push_back({std::sin(polar) * std::cos(azimuth),
                                 std::sin(polar) * std::sin(azimuth),
                                 std::cos(polar)});
      }
    }
    mesh.vertices.push_back({0.0, 0.0, -1.0});
    const auto south = static_cast<std::uint32_t>(mesh.vertices.size() - 1);
    const auto at = [&](int lat, int lon) {
      return static_cast<std::uint32_t>(1 + (lat - 1) * longitudes +
                                        (lon + longitudes) % longitudes);
    };
    for (int lon = 0; lon < longitudes; ++lon) {
      mesh.triangles.push_back({0, at(1, lon), at(1, lon + 1)});
      mesh.triangles.push_back(
          {south, at(latitudes - 1, lon + 1), at(latitudes - 1, lon)});
      for (int lat = 1; lat + 1 < latitudes; ++lat) {
        mesh.triangles.push_back(
            {at(lat, lon), at(lat + 1, lon), at(lat + 1, lon + 1)});
        mesh.triangles.push_back(
            {at(lat, lon), at(lat + 1, lon + 1), at(lat, lon + 1)});
      }
    }
    // Scale so that the nearest face plane is `needed` away.
    double inradius = 1.0;
    for (const auto& t : mesh.triangles) {
      const glm::dvec3 n =
          glm::normalize(glm::cross(mesh.vertices[t[1]] - mesh.vertices[t[0]],
                                    mesh.vertices[t[2]] - mesh.vertices[t[0]]));
      inradius =
          std::min(inradius, std::fabs(glm::dot(n, mesh.vertices[t[0]])));
    }
    for (glm::dvec3& p : mesh.vertices) p = center + p * (needed / inradius);
    return mesh;
  }

  // A polygon ready to become a plate: its outline without collinear
  // points and its unit (Newell) normal.
  struct Outline {
    std::vector<glm::dvec3> points;
    glm::dvec3 normal{0.0};
    double area = 0.0;
    Box box;
  };

  std::optional<Outline> outline(const lsys::Polygon& polygon) const {
    Outline out{.points = without_collinear(polygon.points)};
    glm::dvec3 newell(0.0);
    for (std::size_t i = 0; i < out.points.size(); ++i) {
      newell +=
          glm::cross(out.points[i], out.points[(i + 1) % out.points.size()]);
      out.box.min = glm::min(out.box.min, out.points[i]);
      out.box.max = glm::max(out.box.max, out.points[i]);
    }
    out.area = glm::length(newell) / 2.0;
    const double thickness = options_.wall_mm;
    if (out.points.size() < 3 || out.area < 1e-6 * thickness * thickness) {
      return std::nullopt;
    }
    out.normal = newell / (2.0 * out.area);
    return out;
  }

  // Whether two outlines lie in one plane (every point of each within
  // kCoplanar of the other's plane, normals parallel either way) and their
  // boxes meet, so that their plates would meet face on face.
  [[nodiscard]] bool share_plane(const Outline& a, const Outline& b) const {
    const double reach = kCoplanar * scale_mm_;
    for (int k = 0; k < 3; ++k) {
      if (a.box.min[k] > b.box.max[k] + reach ||
          b.box.min[k] > a.box.max[k] + reach) {
        return false;
      }
    }
    if (std::fabs(glm::dot(a.normal, b.normal)) < kParallel) return false;
    const auto within = [&](const Outline& from, const Outline& plane) {
      for (const glm::dvec3& p : from.points) {
        if (std::fabs(glm::dot(p - plane.points[0], plane.normal)) > reach)
          return false;
      }
      return true;
    };
    return within(a, b) && within(b, a);
  }

  // Leaf polygons that lie in one plane and overlap or share edges (a fan
  // of triangles, layered petals) are united in that plane and each region
  // of the union becomes one plate (cgal/polygon_union.cpp says why); the
  // others become a plate each.
  void add_plates() {
    const auto& polygons = skeleton_.polygons;
    std::vector<std::optional<Outline>> outlines;
    outlines.reserve(polygons.size());
    for (const lsys::Polygon& polygon : polygons) {
      outlines.push_back(outline(polygon));
    }
    // Candidate pairs by sweeping the boxes along x.
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < outlines.size(); ++i) {
      if (outlines[i]) order.push_back(i);
    }
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return outlines[a]->box.min.x < outlines[b]->box.min.x ||
             (outlines[a]->box.min.x == outlines[b]->box.min.x && a < b);
    });
    UnionFind groups(polygons.size());
    const double reach = kCoplanar * scale_mm_;
    for (std::size_t k = 0; k < order.size(); ++k) {
      const Outline& a = *outlines[order[k]];
      for (std::size_t m = k + 1; m < order.size(); ++m) {
        const Outline& b = *outlines[order[m]];
        if (b.box.min.x > a.box.max.x + reach) break;
        const bool same_color =
            !options_.split_colors ||
            polygons[order[k]].color == polygons[order[m]].color;
        if (same_color && share_plane(a, b)) groups.join(order[k], order[m]);
      }
    }
    std::map<std::size_t, std::vector<std::size_t>> members;
    for (std::size_t i = 0; i < polygons.size(); ++i) {
      if (!outlines[i]) {
        ++set_.skipped_polygons;
        continue;
      }
      members[groups.find(i)].push_back(i);
    }
    // In order of each group's first polygon, for reproducible parts.
    std::vector<std::vector<std::size_t>> ordered;
    for (auto& [root, list] : members) ordered.push_back(std::move(list));
    std::sort(ordered.begin(), ordered.end(),
              [](const auto& a, const auto& b) { return a[0] < b[0]; });
    for (const std::vector<std::size_t>& group : ordered) {
      if (group.size() == 1 || !options_.unite_coplanar_polygons ||
          !add_united_plates(group, outlines)) {
        for (const std::size_t i : group) add_plate(*outlines[i], i);
      }
      for (const std::size_t i : group) add_tip_joint(polygons[i]);
    }
  }

  // The plates of the union of coplanar polygons, in the plane of the
  // largest. False (and nothing added) if the union cannot be made.
  bool add_united_plates(const std::vector<std::size_t>& group,
                         const std::vector<std::optional<Outline>>& outlines) {
    std::size_t largest = group[0];
    for (const std::size_t i : group) {
      if (outlines[i]->area > outlines[largest]->area) largest = i;
    }
    const glm::dvec3 n = outlines[largest]->normal;
    const glm::dvec3 origin = outlines[largest]->points[0];
    const glm::dvec3 u = any_perpendicular(n);
    const glm::dvec3 w = glm::cross(n, u);
    std::vector<std::vector<glm::dvec2>> flat;
    for (const std::size_t i : group) {
      std::vector<glm::dvec2> points;
      for (const glm::dvec3& p : outlines[i]->points) {
        points.emplace_back(glm::dot(p - origin, u), glm::dot(p - origin, w));
      }
      flat.push_back(std::move(points));
    }
    const std::optional<std::vector<PlanarRegion>> regions =
        polygon_union(flat);
    if (!regions) return false;
    const std::string label = polygon_list(group);
    std::vector<Part> plates;
    for (const PlanarRegion& region : *regions) {
      std::vector<glm::dvec3> points;
      for (const glm::dvec2& p : region.points) {
        points.push_back(origin + u * p.x + w * p.y);
      }
      plates.push_back(Part{plate(points, n, region.rings, region.triangles),
                            "leaf plate of " + label,
                            skeleton_.polygons[group[0]].color});
      // Back in 3D, a region with points a few ulps apart can make a plate
      // that cuts itself; the polygons are then plates of their own, as
      // the union would otherwise refuse the part.
      if (!validate(plates.back().mesh).is_printable()) return false;
    }
    for (Part& p : plates) set_.parts.push_back(std::move(p));
    set_.plates += plates.size();
    return true;
  }

  static std::string polygon_list(const std::vector<std::size_t>& group) {
    if (group.size() <= 3) {
      std::string out = "polygons " + std::to_string(group[0]);
      for (std::size_t k = 1; k < group.size(); ++k) {
        out +=
            (k + 1 == group.size() ? " and " : ", ") + std::to_string(group[k]);
      }
      return out;
    }
    return fmt::format("polygons {}, {} and {} more, united in their plane",
                       group[0], group[1], group.size() - 2);
  }

  // Plates are a little thicker than the thinnest tube across its corners:
  // veins drawn in a leaf at the thinnest width then lie inside it, where
  // tubes flush with its faces cut them in long slivers (ABOP fig. 5.5's
  // cordate leaf took 3.5 times as long).
  double plate_thickness() const {
    return plate_thickness_mm(options_.wall_mm, options_.tolerance_mm);
  }

  // A plate: the region offset by half the plate's thickness to each side
  // of its plane, walled along its rings (outer counter-clockwise and holes
  // clockwise seen from +n, triangles counter-clockwise).
  TriangleMesh plate(
      const std::vector<glm::dvec3>& points, const glm::dvec3& n,
      const std::vector<std::vector<std::uint32_t>>& rings,
      const std::vector<std::array<std::uint32_t, 3>>& faces) const {
    const double thickness = plate_thickness();
    const auto count = static_cast<std::uint32_t>(points.size());
    TriangleMesh mesh;
    for (const glm::dvec3& p : points)
      mesh.vertices.push_back(p - n * (thickness / 2.0));
    for (const glm::dvec3& p : points)
      mesh.vertices.push_back(p + n * (thickness / 2.0));
    for (const auto& f : faces) {
      mesh.triangles.push_back({f[0] + count, f[1] + count, f[2] + count});
      mesh.triangles.push_back({f[0], f[2], f[1]});
    }
    for (const std::vector<std::uint32_t>& ring : rings) {
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const std::uint32_t i = ring[k];
        const std::uint32_t j = ring[(k + 1) % ring.size()];
        mesh.triangles.push_back({i, j, j + count});
        mesh.triangles.push_back({i, j + count, i + count});
      }
    }
    return mesh;
  }

  // A sheet (a predefined surface, cpfg's `~l`) thickened as plates are:
  // along its normals, or if that cuts itself (a leaf's pointed tip bends
  // sharply for the thickness) swept along its mean normal, or else along
  // its normals but thinner where they cut (a swept leaf's hooked edges
  // where it narrows to its tip), with a warning. A sheet a few
  // walls across that neither way makes clear of itself (a bud 3 mm wide,
  // a leaf just emerging) is printed as the convex hull of its points
  // thickened, which a print that small barely tells apart; a larger one
  // would print wrong, so it ends the build, named.
  void add_sheet(std::size_t index) {
    const lsys::Sheet& sheet = skeleton_.sheets[index];
    const double thickness = plate_thickness();
    const glm::dvec3 at = sheet.points[sheet.triangles[0][0]];
    std::string label = fmt::format("surface {} at ({:.3f}, {:.3f}, {:.3f}) mm",
                                    index, at.x, at.y, at.z);
    for (const SheetOffset way :
         {SheetOffset::Normals, SheetOffset::MeanNormal}) {
      std::optional<TriangleMesh> mesh = thicken_sheet(sheet, thickness, way);
      if (!mesh || !validate(*mesh).is_printable()) continue;
      set_.parts.push_back(
          Part{std::move(*mesh), std::move(label), sheet.color});
      ++set_.sheets;
      return;
    }
    if (std::optional<ThinnedSheet> thinned =
            thicken_sheet_thinning(sheet, thickness);
        thinned && validate(thinned->mesh).is_printable()) {
      set_.parts.push_back(
          Part{std::move(thinned->mesh), std::move(label), sheet.color});
      ++set_.sheets;
      ++set_.thinned_sheets;
      set_.thinnest_sheet_mm = std::min(set_.thinnest_sheet_mm,
                                        thinned->thinnest_fraction * thickness);
      return;
    }
    Box box;
    for (const glm::dvec3& p : sheet.points) {
      box.min = glm::min(box.min, p);
      box.max = glm::max(box.max, p);
    }
    const glm::dvec3 size = box.size();
    const double across = std::max({size.x, size.y, size.z});
    if (across <= kHullSheetWalls * thickness) {
      // Each point moved half the thickness along each axis both ways: the
      // hull holds the sheet thickened along any normal.
      TriangleMesh hull;
      for (const glm::dvec3& p : sheet.points) {
        for (int axis = 0; axis < 3; ++axis) {
          glm::dvec3 d(0.0);
          d[axis] = thickness / 2.0;
          hull.vertices.push_back(p - d);
          hull.vertices.push_back(p + d);
        }
      }
      hull.triangles = convex_hull_triangles(hull.vertices);
      remove_unused_vertices(hull);
      set_.parts.push_back(
          Part{std::move(hull), std::move(label), sheet.color});
      ++set_.sheets;
      ++set_.hulled_sheets;
      return;
    }
    throw GeometryError(fmt::format(
        "{}, {:.1f} mm across, bends too sharply to thicken to {:.2f} mm "
        "without cutting itself; draw it larger or give a thinner --wall",
        label, across, thickness));
  }

  void add_plate(const Outline& outline, std::size_t index) {
    const std::vector<std::array<std::uint32_t, 3>> faces =
        triangulate(outline.points, outline.normal);
    if (faces.empty()) {  // the outline crosses itself: no plate to make
      ++set_.skipped_polygons;
      return;
    }
    std::vector<std::uint32_t> ring(outline.points.size());
    for (std::uint32_t i = 0; i < ring.size(); ++i) ring[i] = i;
    set_.parts.push_back(
        Part{plate(outline.points, outline.normal, {ring}, faces),
             fmt::format("leaf plate of polygon {}", index),
             skeleton_.polygons[index].color});
    ++set_.plates;
  }

  // A plate that starts on its stem's axis, where the stem goes on, cuts
  // through the tube and fuses with it in the union. At a tip the plate
  // would meet the tube's cap face on: a joint encloses that corner.
  void add_tip_joint(const lsys::Polygon& polygon) {
    if (polygon.parent < 0) return;
    const lsys::Segment& stem = seg(polygon.parent);
    const double stem_radius = node_radius(polygon.parent);
    const double from_end = glm::length(polygon.points.front() - stem.p1);
    const auto i = static_cast<std::size_t>(polygon.parent);
    const bool goes_on = continuation_[i] >= 0 || end_junction_[i] >= 0;
    if (from_end <= stem_radius &&
        !(goes_on && from_end <= kOnAxis * stem_radius)) {
      add_joint(stem.p1, std::max(stem_radius, 0.75 * options_.wall_mm),
                stem.color);
    }
  }

  std::vector<glm::dvec3> without_collinear(
      const std::vector<glm::dvec3>& in) const {
    std::vector<glm::dvec3> out = in;
    bool removed = true;
    while (removed && out.size() >= 3) {
      removed = false;
      for (std::size_t i = 0; i < out.size(); ++i) {
        const glm::dvec3& a = out[(i + out.size() - 1) % out.size()];
        const glm::dvec3& b = out[i];
        const glm::dvec3& c = out[(i + 1) % out.size()];
        const double span = glm::length(c - a) + glm::length(b - a);
        if (glm::length(glm::cross(b - a, c - a)) <= 1e-9 * span * span) {
          out.erase(out.begin() + static_cast<std::ptrdiff_t>(i));
          removed = true;
          break;
        }
      }
    }
    return out;
  }

  // Ear clipping in the polygon's plane; nothing if the outline is not
  // simple (a plate of a crossing outline would cut itself).
  static std::vector<std::array<std::uint32_t, 3>> triangulate(
      const std::vector<glm::dvec3>& points, const glm::dvec3& n) {
    const glm::dvec3 u = any_perpendicular(n);
    const glm::dvec3 w = glm::cross(n, u);
    std::vector<glm::dvec2> p;
    for (const glm::dvec3& q : points)
      p.push_back({glm::dot(q, u), glm::dot(q, w)});
    const auto cross = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
      return (p[b].x - p[a].x) * (p[c].y - p[a].y) -
             (p[b].y - p[a].y) * (p[c].x - p[a].x);
    };
    const auto size = static_cast<std::uint32_t>(points.size());
    for (std::uint32_t i = 0; i < size; ++i) {
      for (std::uint32_t j = i + 2; j < size; ++j) {
        if (i == 0 && j == size - 1) continue;  // adjacent through the wrap
        const std::uint32_t a = i, b = (i + 1) % size, c = j,
                            d = (j + 1) % size;
        const double d1 = cross(a, b, c), d2 = cross(a, b, d);
        const double d3 = cross(c, d, a), d4 = cross(c, d, b);
        if (((d1 <= 0 && d2 >= 0) || (d1 >= 0 && d2 <= 0)) &&
            ((d3 <= 0 && d4 >= 0) || (d3 >= 0 && d4 <= 0))) {
          return {};
        }
      }
    }
    std::vector<std::uint32_t> left(points.size());
    for (std::uint32_t i = 0; i < left.size(); ++i) left[i] = i;
    std::vector<std::array<std::uint32_t, 3>> out;
    while (left.size() > 3) {
      bool clipped = false;
      for (std::size_t i = 0; i < left.size() && !clipped; ++i) {
        const std::uint32_t a = left[(i + left.size() - 1) % left.size()];
        const std::uint32_t b = left[i];
        const std::uint32_t c = left[(i + 1) % left.size()];
        if (cross(a, b, c) <= 0.0) continue;
        bool is_ear = true;
        for (const std::uint32_t q : left) {
          if (q == a || q == b || q == c) continue;
          if (cross(a, b, q) >= 0.0 && cross(b, c, q) >= 0.0 &&
              cross(c, a, q) >= 0.0) {
            is_ear = false;
            break;
          }
        }
        if (!is_ear) continue;
        out.push_back({a, b, c});
        left.erase(left.begin() + static_cast<std::ptrdiff_t>(i));
        clipped = true;
      }
      if (!clipped) return {};
    }
    out.push_back({left[0], left[1], left[2]});
    return out;
  }

  const lsys::Skeleton& skeleton_;
  PartOptions options_;
  double scale_mm_;  // the skeleton's largest extent, at least 1 mm
  std::vector<std::int32_t> continuation_;
  std::vector<bool> is_continuation_;
  std::vector<Junction> junctions_;
  std::vector<std::int32_t> start_junction_;  // per segment, or -1
  std::vector<std::int32_t> end_junction_;    // per segment, or -1
  // Per segment: the junction whose incoming ring lies in it, or -1.
  std::vector<std::int32_t> incoming_ring_;
  RunGrid run_{skeleton_, options_.tolerance_mm};
  // One round's meshing.
  std::vector<glm::dvec3> pool_;  // the vertices of all pieces
  std::vector<Piece> pieces_;
  std::vector<std::vector<Ring>> rings_;  // per junction
  std::vector<std::int32_t> hull_piece_;  // per junction, or -1
  std::vector<Joint> joints_;  // in order of creation, for reproducibility
  std::unordered_map<NodeKey, std::size_t, NodeKeyHash> joint_index_;
  PartSet set_;
};

}  // namespace

int tube_sides(double radius_mm, double tolerance_mm) {
  // The flat sides touch the circle; the corners stand out by
  // r (1 / cos(π/m) - 1), which must stay within the tolerance. Clamped
  // before converting: a tolerance far below the radius makes the step 0
  // and the quotient infinite, which no int holds.
  const double step = std::acos(radius_mm / (radius_mm + tolerance_mm));
  if (!(step > 0.0)) return 128;
  return static_cast<int>(std::clamp(std::ceil(kPi / step), 6.0, 128.0));
}

double tube_corner_radius(double radius_mm, double tolerance_mm) {
  return radius_mm / std::cos(kPi / tube_sides(radius_mm, tolerance_mm));
}

double plate_thickness_mm(double wall_mm, double tolerance_mm) {
  return 2.0 * kPlateMargin * tube_corner_radius(wall_mm / 2.0, tolerance_mm);
}

PartSet build_parts(const lsys::Skeleton& skeleton,
                    const PartOptions& options) {
  return PartBuilder(skeleton, options).build();
}

}  // namespace lsolid
