// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The tubes of the part builder (docs/design.md, "Parts"): one swept tube
// per unbranched chain, with rings shared between segments and mitred at
// bends, so that no internal caps exist, and branch points meshed as the
// convex hull of the rings of the tubes that meet there (B-Mesh, Ji et al.
// 2010; SQM, Bærentzen et al. 2012), stitched to the tubes, so that a tree
// needs no boolean at all. Ring frames are parallel-transported along a
// chain (rotation-minimising, as in Wang et al. 2008's double reflection,
// here by the equivalent minimal rotation per bend), and each tube gets its
// own ring phase, so that overlapping parts never share vertices or faces
// exactly.
#include "parts/tube_mesher.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "cell_grid.hpp"
#include "cgal/part_queries.hpp"
#include "golden.hpp"
#include "union_find.hpp"

namespace lsolid {
namespace {

constexpr double kClearance = 1.6;  // mitres reach up to 1/cos(50°) of r
constexpr double kPathClearance =
    2.5;  // half a turn of radius 1.25 r, and more

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
    grid_ = CellGrid(std::max(longest + kClearance * 1.16 * widest, 1e-9));
  }
  void start(std::int32_t first) {
    cells_.clear();
    path_start_.clear();
    path_length_ = 0.0;
    last_ = -1;
    add(first);
  }
  void add(std::int32_t i) {
    if (last_ >= 0) {
      cells_[CellGrid::key(grid_.cell_of(centre(last_)))].push_back(last_);
    }
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
          const auto it = cells_.find(
              CellGrid::key(grid_.cell_of(c) + glm::ivec3(dx, dy, dz)));
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
    return tube_corner_radius(std::max(s.start_diameter, s.end_diameter) / 2.0,
                              tolerance_mm_);
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
  CellGrid grid_;
  std::unordered_map<std::uint64_t, std::vector<std::int32_t>> cells_;
  std::unordered_map<std::int32_t, double> path_start_;  // along the run
  double path_length_ = 0.0;
  std::int32_t last_ = -1;
};

class TubeMesher {
 public:
  TubeMesher(const lsys::Skeleton& skeleton, const BranchGraph& graph,
             const PartOptions& options)
      : skeleton_(skeleton), graph_(graph), options_(options) {}

  TubeRound mesh() {
    rings_.assign(graph_.junctions.size(), {});
    for (std::size_t i = 0; i < skeleton_.segments.size(); ++i) {
      if (!graph_.is_continuation[i]) walk_chain(static_cast<std::int32_t>(i));
    }
    std::vector<std::int32_t> revert = build_hulls();
    if (revert.empty()) revert = assemble();
    return TubeRound{.revert = std::move(revert),
                     .parts = std::move(parts_),
                     .tubes = tubes_,
                     .junctions = junctions_,
                     .joints = std::move(joints_)};
  }

 private:
  // Follows continuations from a chain's first segment, breaking where a
  // mitre would not fit and at hull junctions, and emits one tube per
  // unbroken run. At a hull junction a run ends or starts at the tube's
  // ring; the segments between ring and junction are inside the hull.
  void walk_chain(std::int32_t first) {
    std::int32_t run_start = graph_.hull_at_start(first);
    double start_local = 0.0;
    if (run_start >= 0) {
      const RingPlace& place = graph_.place_of(run_start, first);
      first = place.segment;
      start_local = place.local_mm;
    } else if (seg(first).parent >= 0) {
      joints_.add(seg(first).p0,
                  std::max(seg(first).start_diameter / 2.0,
                           node_radius(skeleton_, graph_, seg(first).parent)),
                  seg(seg(first).parent).color);
    }
    std::vector<std::int32_t> run{first};
    run_.start(first);
    double start_extent = start_local;
    for (;;) {
      const std::int32_t last = run.back();
      const std::int32_t junction = graph_.ring_ahead(last);
      if (junction >= 0) {
        const Junction& j =
            graph_.junctions[static_cast<std::size_t>(junction)];
        emit_tube(run, run_start, start_local, junction,
                  j.places.front().local_mm);
        const std::int32_t next =
            graph_.continuation[static_cast<std::size_t>(j.incoming)];
        if (next < 0) return;
        const RingPlace& place = graph_.place_of(junction, next);
        run.assign(1, place.segment);
        run_.start(place.segment);
        run_start = junction;
        start_local = start_extent = place.local_mm;
        continue;
      }
      const std::int32_t next =
          graph_.continuation[static_cast<std::size_t>(last)];
      if (next < 0) break;
      const double theta = bend_deg(direction(seg(last)), direction(seg(next)));
      const double r =
          std::max(seg(last).end_diameter, seg(next).start_diameter) / 2.0;
      const double extent = r * std::tan(theta * kPi / 360.0);
      const std::int32_t ahead = graph_.ring_ahead(next);
      const double end_need =
          ahead < 0 ? 0.0
                    : graph_.junctions[static_cast<std::size_t>(ahead)]
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
      joints_.add(seg(last).p1, r, seg(last).color);
      run.assign(1, next);
      run_.start(next);
      run_start = -1;
      start_local = start_extent = 0.0;
    }
    emit_tube(run, run_start, start_local, -1, 0.0);
  }

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
        std::fmod(static_cast<double>(tubes_) * kGolden, 1.0) * 2.0 * kPi / m;
    glm::dvec3 a = lsys::rotate_about(any_perpendicular(d), d, std::cos(phase),
                                      std::sin(phase));

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
    ++tubes_;
  }

  // The hull of each hull junction's rings, without the rings' own faces:
  // a surface whose boundary is exactly the rings, in the orientation that
  // closes the tubes. Returns the junctions where that did not come out.
  std::vector<std::int32_t> build_hulls() {
    std::vector<std::int32_t> failed;
    hull_piece_.assign(graph_.junctions.size(), -1);
    // Each junction's ring vertices, in ring order.
    const auto ring_points = [&](std::size_t j) {
      std::vector<glm::dvec3> points;
      for (const Ring& ring : rings_[j]) {
        for (const std::uint32_t g : ring.vertices) points.push_back(pool_[g]);
      }
      return points;
    };
    // The hulls on oneTBB's threads, each on its own (half of the parts'
    // time on the bush at n = 7, its 805 hulls one after the other), then
    // taken in junction order: the same pieces whatever the threads.
    std::vector<std::vector<std::array<std::uint32_t, 3>>> hulls(
        graph_.junctions.size());
    tbb::parallel_for(std::size_t{0}, graph_.junctions.size(),
                      [&](std::size_t j) {
                        if (graph_.junctions[j].hull) {
                          hulls[j] = convex_hull_triangles(ring_points(j));
                        }
                      });
    for (std::size_t j = 0; j < graph_.junctions.size(); ++j) {
      const Junction& junction = graph_.junctions[j];
      if (!junction.hull) continue;
      const std::vector<Ring>& rings = rings_[j];
      const std::size_t expected =
          junction.outgoing.size() + (junction.incoming >= 0 ? 1 : 0);
      std::vector<std::uint32_t> global;
      std::vector<std::size_t> ring_of;
      for (std::size_t r = 0; r < rings.size(); ++r) {
        for (const std::uint32_t g : rings[r].vertices) {
          global.push_back(g);
          ring_of.push_back(r);
        }
      }
      Piece piece;
      std::size_t removed = 0;
      std::vector<bool> used(global.size(), false);
      for (const auto& t : hulls[j]) {
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
      ++junctions_;
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
    // The groups' meshes first, then their self-intersection tests at once
    // on oneTBB's threads (most of the parts' time on the bush at n = 7),
    // then the reverts in group order: the same whatever the threads.
    struct Group {
      TriangleMesh mesh;
      std::vector<std::size_t> piece_of;  // per triangle
      std::size_t tubes = 0;
      std::vector<std::pair<std::uint32_t, std::uint32_t>> crossing;
    };
    std::vector<Group> groups_meshed(order.size());
    for (std::size_t g = 0; g < order.size(); ++g) {
      Group& out = groups_meshed[g];
      std::unordered_map<std::uint32_t, std::uint32_t> local;
      for (const std::size_t p : members.at(order[g])) {
        if (pieces_[p].hull_of < 0) ++out.tubes;
        for (const auto& t : pieces_[p].triangles) {
          std::array<std::uint32_t, 3> corner{};
          for (int c = 0; c < 3; ++c) {
            const auto [it, inserted] = local.try_emplace(
                t[c], static_cast<std::uint32_t>(out.mesh.vertices.size()));
            if (inserted) out.mesh.vertices.push_back(pool_[t[c]]);
            corner[c] = it->second;
          }
          out.mesh.triangles.push_back(corner);
          out.piece_of.push_back(p);
        }
      }
    }
    if (options_.check_self_intersections) {
      tbb::parallel_for(std::size_t{0}, order.size(), [&](std::size_t g) {
        if (members.at(order[g]).size() > 1) {
          groups_meshed[g].crossing =
              intersecting_triangle_pairs(groups_meshed[g].mesh);
        }
      });
    }
    std::vector<std::int32_t> revert;
    std::vector<Part> parts;
    for (std::size_t g = 0; g < order.size(); ++g) {
      const std::vector<std::size_t>& group = members.at(order[g]);
      Group& meshed = groups_meshed[g];
      for (const auto& [f, h] : meshed.crossing) {
        isolate(pieces_[meshed.piece_of[f]], pieces_[meshed.piece_of[h]],
                revert);
      }
      parts.push_back(
          Part{std::move(meshed.mesh),
               group.size() == 1
                   ? pieces_[group[0]].label
                   : fmt::format("{} tubes joined at {} junctions, from the {}",
                                 meshed.tubes, group.size() - meshed.tubes,
                                 pieces_[group[0]].label),
               pieces_[group[0]].color});
    }
    if (!revert.empty()) {
      std::sort(revert.begin(), revert.end());
      revert.erase(std::unique(revert.begin(), revert.end()), revert.end());
      return revert;
    }
    parts_ = std::move(parts);
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

  const lsys::Segment& seg(std::int32_t i) const {
    return skeleton_.segments[static_cast<std::size_t>(i)];
  }

  const lsys::Skeleton& skeleton_;
  const BranchGraph& graph_;
  const PartOptions& options_;
  RunGrid run_{skeleton_, options_.tolerance_mm};
  std::vector<glm::dvec3> pool_;  // the vertices of all pieces
  std::vector<Piece> pieces_;
  std::vector<std::vector<Ring>> rings_;  // per junction
  std::vector<std::int32_t> hull_piece_;  // per junction, or -1
  JointSet joints_;
  std::vector<Part> parts_;
  std::size_t tubes_ = 0;
  std::size_t junctions_ = 0;
};

}  // namespace

void JointSet::add(const glm::dvec3& center, double radius, int color) {
  const auto [it, inserted] = index_.emplace(node_key(center), joints_.size());
  if (inserted) {
    joints_.push_back(Joint{center, radius, color});
  } else {
    joints_[it->second].radius = std::max(joints_[it->second].radius, radius);
  }
}

void JointSet::claim(const glm::dvec3& center, double radius, int color) {
  add(center, radius, color);
  joints_[index_.at(node_key(center))].color = color;
}

TubeRound mesh_tubes(const lsys::Skeleton& skeleton, const BranchGraph& graph,
                     const PartOptions& options) {
  return TubeMesher(skeleton, graph, options).mesh();
}

}  // namespace lsolid
