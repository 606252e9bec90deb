#include <cstdio>
// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Meshing the skeleton into few, well-conditioned boolean operands
// (shared/reference/geometry-and-printing.md §7): one swept tube per
// unbranched chain, with rings shared between segments and mitred at bends,
// so that no internal caps exist; joints that enclose the end caps of tubes
// meeting at a node, so that no caps coincide; plates for leaves. Ring
// frames are parallel-transported along a chain (rotation-minimising, as in
// Wang et al. 2008's double reflection, here by the equivalent minimal
// rotation per bend), and each part gets its own ring phase, so that
// overlapping parts never share vertices or faces exactly.
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <numbers>
#include <unordered_map>

#include "lsolid/parts.hpp"

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

class PartBuilder {
 public:
  PartBuilder(const lsys::Skeleton& skeleton, const PartOptions& options)
      : skeleton_(skeleton), options_(options) {}

  PartSet build() {
    choose_continuations();
    for (std::size_t i = 0; i < skeleton_.segments.size(); ++i) {
      if (!is_continuation_[i]) walk_chain(static_cast<std::int32_t>(i));
    }
    for (std::size_t i = 0; i < skeleton_.polygons.size(); ++i) {
      add_plate(skeleton_.polygons[i], i);
    }
    std::size_t index = 0;
    for (const Joint& joint : joints_) {
      set_.parts.push_back(
          Part{sphere(joint.center, joint.radius, index++),
               fmt::format("joint at ({:.3f}, {:.3f}, {:.3f}) mm",
                           joint.center.x, joint.center.y, joint.center.z)});
      ++set_.joints;
    }
    return std::move(set_);
  }

 private:
  struct Joint {
    glm::dvec3 center;
    double radius;  // the largest cap it must enclose
  };

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

  const lsys::Segment& seg(std::int32_t i) const {
    return skeleton_.segments[static_cast<std::size_t>(i)];
  }

  void add_joint(const glm::dvec3& center, double radius) {
    const auto [it, inserted] =
        joint_index_.emplace(node_key(center), joints_.size());
    if (inserted) {
      joints_.push_back(Joint{center, radius});
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
  // mitre would not fit, and emits one tube per unbroken run.
  void walk_chain(std::int32_t first) {
    if (seg(first).parent >= 0) {
      add_joint(seg(first).p0, std::max(seg(first).start_diameter / 2.0,
                                        node_radius(seg(first).parent)));
    }
    std::vector<std::int32_t> run{first};
    run_.start(first);
    double start_extent = 0.0;
    for (std::int32_t next = continuation_[static_cast<std::size_t>(first)];
         next >= 0; next = continuation_[static_cast<std::size_t>(next)]) {
      const std::int32_t last = run.back();
      const double theta = bend_deg(direction(seg(last)), direction(seg(next)));
      const double r =
          std::max(seg(last).end_diameter, seg(next).start_diameter) / 2.0;
      const double extent = r * std::tan(theta * kPi / 360.0);
      if (start_extent + extent <= kMitreBudget * length(seg(last)) &&
          extent <= kMitreBudget * length(seg(next)) &&
          !run_.comes_near(next)) {
        run.push_back(next);
        run_.add(next);
        start_extent = extent;
        continue;
      }
      emit_tube(run);
      add_joint(seg(last).p1, r);
      run.assign(1, next);
      run_.start(next);
      start_extent = 0.0;
    }
    emit_tube(run);
  }

  // The segments of the tube being built, in a grid, to tell when the next
  // segment would pass so close to an earlier one that the tube would cut
  // itself (space-filling curves turn back on themselves; a tube must not).
  // Segments close along the path are left out: the mitre budget keeps the
  // path's radius of curvature above 1.25 r, so a tube can only come back to
  // itself after a path of more than half a turn.
  class RunGrid {
   public:
    explicit RunGrid(const lsys::Skeleton& skeleton)
        : segments_(skeleton.segments) {
      double longest = 0.0;
      double widest = 0.0;
      for (const lsys::Segment& s : segments_) {
        longest = std::max(longest, glm::length(s.p1 - s.p0));
        widest = std::max({widest, s.start_diameter, s.end_diameter});
      }
      // Segments closer than the clearance have midpoints in adjacent cells.
      cell_ = std::max(longest + kClearance * widest, 1e-9);
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
      return std::max(s.start_diameter, s.end_diameter) / 2.0;
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
    double cell_ = 0.0;
    std::unordered_map<Key, std::vector<std::int32_t>, KeyHash> cells_;
    std::unordered_map<std::int32_t, double> path_start_;  // along the run
    double path_length_ = 0.0;
    std::int32_t last_ = -1;
  };

  void emit_tube(const std::vector<std::int32_t>& run) {
    const std::size_t k = run.size();
    std::vector<glm::dvec3> centers(k + 1);
    std::vector<double> radii(k + 1);
    centers[0] = seg(run[0]).p0;
    radii[0] = seg(run[0]).start_diameter / 2.0;
    for (std::size_t j = 1; j < k; ++j) {
      centers[j] = seg(run[j]).p0;
      radii[j] =
          std::max(seg(run[j - 1]).end_diameter, seg(run[j]).start_diameter) /
          2.0;
    }
    centers[k] = seg(run[k - 1]).p1;
    radii[k] = seg(run[k - 1]).end_diameter / 2.0;
    const double largest = *std::max_element(radii.begin(), radii.end());
    const int m = tube_sides(largest, options_.tolerance_mm);

    // The ring frame of the first segment, turned by this tube's own phase.
    glm::dvec3 d = direction(seg(run[0]));
    const double phase =
        std::fmod(static_cast<double>(set_.tubes) * kGolden, 1.0) * 2.0 * kPi /
        m;
    glm::dvec3 a =
        rotate(any_perpendicular(d), d, std::cos(phase), std::sin(phase));

    TriangleMesh mesh;
    mesh.vertices.reserve((k + 1) * static_cast<std::size_t>(m));
    const auto ring = [&](const glm::dvec3& center, double radius,
                          const glm::dvec3& dir, const glm::dvec3& axis_a,
                          const glm::dvec3* mitre_normal) {
      const glm::dvec3 b = glm::cross(dir, axis_a);
      for (int i = 0; i < m; ++i) {
        const double angle = 2.0 * kPi * i / m;
        glm::dvec3 q =
            radius * (std::cos(angle) * axis_a + std::sin(angle) * b);
        if (mitre_normal != nullptr) {
          q -=
              dir * (glm::dot(q, *mitre_normal) / glm::dot(dir, *mitre_normal));
        }
        mesh.vertices.push_back(center + q);
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

    const auto v = [m](std::size_t ring_index, int i) {
      return static_cast<std::uint32_t>(ring_index *
                                            static_cast<std::size_t>(m) +
                                        static_cast<std::size_t>((i + m) % m));
    };
    for (std::size_t j = 0; j < k; ++j) {
      for (int i = 0; i < m; ++i) {
        mesh.triangles.push_back({v(j, i), v(j, i + 1), v(j + 1, i + 1)});
        mesh.triangles.push_back({v(j, i), v(j + 1, i + 1), v(j + 1, i)});
      }
    }
    for (int i = 1; i + 1 < m; ++i) {
      mesh.triangles.push_back({v(0, 0), v(0, i + 1), v(0, i)});
      mesh.triangles.push_back({v(k, 0), v(k, i), v(k, i + 1)});
    }
    const std::int32_t front = run.front();
    const std::int32_t back = run.back();
    set_.parts.push_back(Part{
        std::move(mesh),
        front == back ? fmt::format("tube of segment {}", front)
                      : fmt::format("tube of segments {}-{}", front, back)});
    ++set_.tubes;
  }

  // A UV sphere whose faces all lie farther than `radius` from the centre,
  // so that it encloses every cap of that radius at the centre.
  TriangleMesh sphere(const glm::dvec3& center, double radius,
                      std::size_t index) {
    const double needed = radius * kJointMargin;
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

  void add_plate(const lsys::Polygon& polygon, std::size_t index) {
    std::vector<glm::dvec3> points = without_collinear(polygon.points);
    glm::dvec3 newell(0.0);
    for (std::size_t i = 0; i < points.size(); ++i) {
      newell += glm::cross(points[i], points[(i + 1) % points.size()]);
    }
    const double area = glm::length(newell) / 2.0;
    const double thickness = options_.wall_mm;
    if (points.size() < 3 || area < 1e-6 * thickness * thickness) {
      ++set_.skipped_polygons;
      return;
    }
    const glm::dvec3 n = newell / (2.0 * area);
    const std::vector<std::array<std::uint32_t, 3>> faces =
        triangulate(points, n);
    if (faces.empty()) {  // the outline crosses itself: no plate to make
      ++set_.skipped_polygons;
      return;
    }
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
    for (std::uint32_t i = 0; i < count; ++i) {
      const std::uint32_t j = (i + 1) % count;
      mesh.triangles.push_back({i, j, j + count});
      mesh.triangles.push_back({i, j + count, i + count});
    }
    set_.parts.push_back(
        Part{std::move(mesh), fmt::format("leaf plate of polygon {}", index)});
    ++set_.plates;
    // Fuse the plate to the segment it grows from.
    if (polygon.parent >= 0) {
      const lsys::Segment& stem = seg(polygon.parent);
      const double stem_radius = node_radius(polygon.parent);
      if (glm::length(polygon.points.front() - stem.p1) <= stem_radius) {
        add_joint(stem.p1, std::max(stem_radius, 0.75 * thickness));
      }
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
  std::vector<std::int32_t> continuation_;
  std::vector<bool> is_continuation_;
  RunGrid run_{skeleton_};
  std::vector<Joint> joints_;  // in order of creation, for reproducibility
  std::unordered_map<NodeKey, std::size_t, NodeKeyHash> joint_index_;
  PartSet set_;
};

}  // namespace

int tube_sides(double radius_mm, double tolerance_mm) {
  if (tolerance_mm >= radius_mm) return 6;
  const double step = std::acos(1.0 - tolerance_mm / radius_mm);
  return std::clamp(static_cast<int>(std::ceil(kPi / step)), 6, 128);
}

PartSet build_parts(const lsys::Skeleton& skeleton,
                    const PartOptions& options) {
  return PartBuilder(skeleton, options).build();
}

}  // namespace lsolid
