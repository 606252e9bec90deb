// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <span>
#include <vector>

#include "cell_grid.hpp"
#include "lsolid/mesh.hpp"

namespace lsolid {

/// The closest point of triangle abc to p: Ericson, "Real-Time Collision
/// Detection", 2005, §5.1.5 (ClosestPtPointTriangle), by Voronoi regions.
[[nodiscard]] inline glm::dvec3 closest_point_on_triangle(const glm::dvec3& p,
                                                          const glm::dvec3& a,
                                                          const glm::dvec3& b,
                                                          const glm::dvec3& c) {
  const glm::dvec3 ab = b - a;
  const glm::dvec3 ac = c - a;
  const glm::dvec3 ap = p - a;
  const double d1 = glm::dot(ab, ap);
  const double d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp);
  const double d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp);
  const double d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const double denominator = 1.0 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

/// The unit normal of triangle abc where it is well conditioned (its area
/// at least a thousandth of its longest edge's square, so that rounding
/// turns it by less than about 1e-12), else zero: a plane test with a zero
/// normal passes every point. The distance tests below reject by the plane
/// only what the closest point would reject too.
[[nodiscard]] inline glm::dvec3 well_conditioned_normal(const glm::dvec3& a,
                                                        const glm::dvec3& b,
                                                        const glm::dvec3& c) {
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double length = glm::length(n);
  const double longest = std::max(
      {glm::dot(b - a, b - a), glm::dot(c - b, c - b), glm::dot(a - c, a - c)});
  return length > 1e-3 * longest && length > 0.0 ? n / length : glm::dvec3(0.0);
}

/// Calls visit(key) once for each cell of `grid` that triangle abc passes
/// through: those whose centre lies within half a cell's diagonal of it (a
/// thousandth more, for rounding). Every point of the triangle lies in one
/// of them, so a query that meets the triangle visits one; a long sliver
/// fills far fewer cells than its box. A triangle whose box spans many cells
/// is split at its edges' midpoints until each piece's box spans few, so
/// the work follows the triangle's area, not its box's volume (a tube's side
/// a branch long lies across millions of cells of its box).
template <typename Visit>
void for_each_cell_through(const CellGrid& grid, const glm::dvec3& a,
                           const glm::dvec3& b, const glm::dvec3& c,
                           Visit visit) {
  constexpr double kPieceCells = 64.0;
  const double reach = 0.8669 * grid.cell_mm();
  std::vector<std::uint64_t> keys;
  // A triangle that is not split visits each cell of its box once, and
  // gives its cells to `visit` as it finds them; pieces of a split one may
  // share cells, which are gathered and given once each.
  bool split = false;
  const auto collect = [&](const auto& self, const glm::dvec3& p,
                           const glm::dvec3& q, const glm::dvec3& r) -> void {
    const glm::dvec3 lo = glm::min(glm::min(p, q), r);
    const glm::dvec3 hi = glm::max(glm::max(p, q), r);
    if (grid.count(lo, hi) > kPieceCells) {
      split = true;
      const glm::dvec3 pq = (p + q) * 0.5;
      const glm::dvec3 qr = (q + r) * 0.5;
      const glm::dvec3 rp = (r + p) * 0.5;
      self(self, p, pq, rp);
      self(self, pq, q, qr);
      self(self, rp, qr, r);
      self(self, qr, rp, pq);
      return;
    }
    // A centre farther than `reach` from the piece's plane is farther from
    // the piece: most of a sliver's box is, and the plane's distance costs a
    // dot product where the closest point costs a dozen. A thin piece (its
    // normal ill conditioned) skips this test; the margin covers rounding.
    const glm::dvec3 unit = well_conditioned_normal(p, q, r);
    const double offset = glm::dot(unit, p);
    const double slab = reach * (1.0 + 1e-9) + 1e-9 * grid.cell_mm();
    grid.for_each(lo, hi, [&](std::uint64_t key, const glm::dvec3& centre) {
      if (std::abs(glm::dot(unit, centre) - offset) > slab) return;
      const glm::dvec3 d = closest_point_on_triangle(centre, p, q, r) - centre;
      if (glm::dot(d, d) > reach * reach) return;
      if (split) {
        keys.push_back(key);
      } else {
        visit(key);
      }
    });
  };
  collect(collect, a, b, c);
  if (!split) return;
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  for (const std::uint64_t key : keys) visit(key);
}

/// A fixed surface that answers "is this point within d of it?" through a
/// uniform grid of its triangles. The decimation keeps one of the input to
/// test that new triangles do not stray from it.
class SurfaceDistance {
 public:
  /// Indexes the triangles of `mesh`, kept by reference, in cells as wide
  /// as the square root of its mean triangle area, or `min_cell_mm` if
  /// larger: a cell holds about one triangle's worth of surface. Edge
  /// lengths mislead both ways on a union's output: the 36 branches meeting
  /// at one node leave edges of hundredths of a millimetre round the node
  /// (cells that small made each query visit a hundred cells) and slivers a
  /// branch long from it (twice the mean edge was 37 mm there: thousands of
  /// triangles a cell, each query tried them all; 1.2 mm by area, and the
  /// decimation took 3.2 s instead of 8.6 s, with the same answers).
  explicit SurfaceDistance(const TriangleMesh& mesh, double min_cell_mm = 0.0);

  /// A second querier of the same surface and index, with its own query
  /// state, for another thread: the index is read only.
  [[nodiscard]] SurfaceDistance sharing() const {
    return SurfaceDistance(mesh_, index_);
  }

  /// The distance from `p` to the nearest triangle, or `limit_mm` if none
  /// lies nearer than that.
  [[nodiscard]] double distance(const glm::dvec3& p, double limit_mm) {
    // Searches a growing cube: a triangle within r of p has its box in the
    // cube of half-side r around p, so a nearest one found within r is the
    // nearest of all. Most points lie on or near the surface and stop at
    // the first cube, where the whole limit's cube would visit thousands
    // of cells.
    double reach = std::min(limit_mm, index_->grid.cell_mm() / 4.0);
    double best = limit_mm * limit_mm;
    for (;;) {
      ++stamp_;
      const auto test = [&](std::span<const std::uint32_t> cell) {
        for (const std::uint32_t i : cell) {
          if (seen_[i] == stamp_) continue;
          seen_[i] = stamp_;
          best = std::min(best, squared_distance(i, p));
        }
      };
      test(index_->large);
      index_->grid.for_each(p - reach, p + reach,
                            [&](std::uint64_t key, const glm::dvec3&) {
                              test(index_->cell(key));
                            });
      if (best <= reach * reach || reach >= limit_mm) break;
      reach = std::min(limit_mm, 2.0 * reach);
    }
    return std::sqrt(best);
  }

  /// True when one triangle lies within `distance_mm` of `a`, `b` and `c`:
  /// the distance to a triangle is a convex function, so that triangle then
  /// lies within `distance_mm` of every point of triangle abc. False says
  /// nothing: the points may still lie near different triangles.
  [[nodiscard]] bool covers(const glm::dvec3& a, const glm::dvec3& b,
                            const glm::dvec3& c, double distance_mm) {
    const double squared = distance_mm * distance_mm;
    // A triangle near all three corners is near `a`: its cells suffice.
    const double reach = distance_mm + kBoundsSlackMm;
    return any_near(a, distance_mm, [&](std::uint32_t i) {
      const Bounds& bounds = index_->bounds[i];
      return bounds.may_reach(a, reach) && bounds.may_reach(b, reach) &&
             bounds.may_reach(c, reach) && squared_distance(i, a) <= squared &&
             squared_distance(i, b) <= squared &&
             squared_distance(i, c) <= squared;
    });
  }

  /// True when two triangles that share an edge, among those that answered
  /// the last queries, lie within `distance_mm` of every point of triangle
  /// abc between them: abc is cut by the plane through their common edge
  /// and their mean normal, and each side of it is covered by the triangle
  /// on that side, by convexity as in covers (the corners of a side are
  /// those of abc there and the points where its sides cross the plane).
  /// That proves at once a piece of a triangle that lies across a crease of
  /// this surface, which no one triangle covers. False says nothing.
  [[nodiscard]] bool covers_in_two(const glm::dvec3& a, const glm::dvec3& b,
                                   const glm::dvec3& c, double distance_mm) {
    // The points where abc's sides cross the plane are rounded: the sides
    // are held a billionth of the distance and a picometre nearer, far
    // beyond that.
    const double near = distance_mm * (1.0 - 1e-9) - 1e-9;
    if (!(near > 0.0)) return false;
    const std::array<glm::dvec3, 3> corners{a, b, c};
    for (std::size_t x = 0; x < recent_.size() && recent_[x] != kNone; ++x) {
      for (std::size_t y = x + 1; y < recent_.size() && recent_[y] != kNone;
           ++y) {
        if (covered_between(recent_[x], recent_[y], corners, near * near))
          return true;
      }
    }
    return false;
  }

  /// Forgets which triangles answered the last queries, so that what
  /// covers_in_two proves next does not depend on them.
  void forget_answers() { recent_.fill(kNone); }

  /// True when some triangle lies within `distance_mm` of `p`.
  [[nodiscard]] bool within(const glm::dvec3& p, double distance_mm) {
    const double squared = distance_mm * distance_mm;
    const double reach = distance_mm + kBoundsSlackMm;
    return any_near(p, distance_mm, [&](std::uint32_t i) {
      return index_->bounds[i].may_reach(p, reach) &&
             squared_distance(i, p) <= squared;
    });
  }

 private:
  [[nodiscard]] double squared_distance(std::uint32_t i,
                                        const glm::dvec3& p) const {
    const auto& t = mesh_.triangles[i];
    const glm::dvec3 d =
        closest_point_on_triangle(p, mesh_.vertices[t[0]], mesh_.vertices[t[1]],
                                  mesh_.vertices[t[2]]) -
        p;
    return glm::dot(d, d);
  }

  // Whether triangles i and j share an edge and each covers the side of
  // triangle `t` that it lies on, within sqrt(squared) (covers_in_two).
  [[nodiscard]] bool covered_between(std::uint32_t i, std::uint32_t j,
                                     const std::array<glm::dvec3, 3>& t,
                                     double squared) const {
    const auto& ti = mesh_.triangles[i];
    const auto& tj = mesh_.triangles[j];
    // The corner of each that the other lacks; two shared corners.
    int alone_i = -1;
    int shared = 0;
    for (int k = 0; k < 3; ++k) {
      if (std::find(tj.begin(), tj.end(), ti[k]) != tj.end()) {
        ++shared;
      } else {
        alone_i = k;
      }
    }
    // Only two well-shaped triangles (their normals kept in their bounds):
    // a sliver's closest point is ill conditioned.
    const glm::dvec3& n_i = index_->bounds[i].normal;
    const glm::dvec3& n_j = index_->bounds[j].normal;
    if (shared != 2 || glm::dot(n_i, n_i) == 0.0 || glm::dot(n_j, n_j) == 0.0)
      return false;
    const glm::dvec3& p = mesh_.vertices[ti[(alone_i + 1) % 3]];
    const glm::dvec3& q = mesh_.vertices[ti[(alone_i + 2) % 3]];
    const glm::dvec3& r_i = mesh_.vertices[ti[alone_i]];
    std::uint32_t alone_j = tj[0];
    for (const std::uint32_t v : tj) {
      if (std::find(ti.begin(), ti.end(), v) == ti.end()) alone_j = v;
    }
    const glm::dvec3& r_j = mesh_.vertices[alone_j];
    // Any plane through pq would do; this one, between the two planes,
    // leaves each triangle on its own side where the crease is not folded.
    glm::dvec3 m = glm::cross(q - p, n_i + n_j);
    const double side_i = glm::dot(m, r_i - p);
    const double side_j = glm::dot(m, r_j - p);
    if (!(side_i > 0.0 && side_j < 0.0) && !(side_i < 0.0 && side_j > 0.0)) {
      return false;
    }
    if (side_i < 0.0) m = -m;
    std::array<double, 3> side{};
    for (int k = 0; k < 3; ++k) {
      side[k] = glm::dot(m, t[k] - p);
      if (std::isnan(side[k])) return false;  // neither side holds it
    }
    const auto near = [&](std::uint32_t f, const glm::dvec3& x) {
      return squared_distance(f, x) <= squared;
    };
    for (int k = 0; k < 3; ++k) {
      if (side[k] >= 0.0 && !near(i, t[k])) return false;
      if (side[k] <= 0.0 && !near(j, t[k])) return false;
      const int l = (k + 1) % 3;
      if ((side[k] > 0.0 && side[l] < 0.0) ||
          (side[k] < 0.0 && side[l] > 0.0)) {
        const glm::dvec3 x =
            t[k] + (t[l] - t[k]) * (side[k] / (side[k] - side[l]));
        if (!near(i, x) || !near(j, x)) return false;
      }
    }
    return true;
  }

  // Puts triangle i, which answered a query from its cell, first among the
  // recent ones. @pre i is not among them (they were asked first).
  void answered(std::uint32_t i) {
    std::copy_backward(recent_.begin(), recent_.end() - 1, recent_.end());
    recent_.front() = i;
  }

  // True when near(i) holds for a triangle i within `distance_mm` of `p`
  // (those are all it asks about). Queries come in runs of nearby points
  // (samples on one triangle, which mostly lies across a few faces of this
  // surface where a tube's sides meet): the triangles that answered the
  // last few queries mostly answer this one, so they are asked first, the
  // latest first. With the last one alone, a third of the decimation's
  // queries of the bush at n = 7 went on to their cells, a dozen triangles
  // each.
  template <typename Near>
  [[nodiscard]] bool any_near(const glm::dvec3& p, double distance_mm,
                              Near near) {
    for (std::size_t k = 0; k < recent_.size() && recent_[k] != kNone; ++k) {
      if (near(recent_[k])) {
        std::rotate(recent_.begin(), recent_.begin() + k,
                    recent_.begin() + k + 1);
        return true;
      }
    }
    const glm::dvec3 lo = p - distance_mm;
    const glm::dvec3 hi = p + distance_mm;
    const CellGrid& grid = index_->grid;
    if (grid.cell_of(lo) == grid.cell_of(hi)) {
      // Most queries (0.05 mm round a point, in cells of about a triangle)
      // fall in one cell, where no triangle is met twice: nothing to mark
      // (reading each triangle's mark was a tenth of `covers`' samples).
      for (const auto& list : {index_->cell(CellGrid::key(grid.cell_of(lo))),
                               std::span<const std::uint32_t>(index_->large)}) {
        for (const std::uint32_t i : list) {
          if (near(i)) {
            answered(i);
            return true;
          }
        }
      }
      return false;
    }
    ++stamp_;
    bool found = false;
    const auto test = [&](std::span<const std::uint32_t> cell) {
      for (const std::uint32_t i : cell) {
        if (seen_[i] == stamp_) continue;
        seen_[i] = stamp_;
        if (near(i)) {
          answered(i);
          found = true;
          return;
        }
      }
    };
    test(index_->large);
    grid.for_each(lo, hi, [&](std::uint64_t key, const glm::dvec3&) {
      if (!found) test(index_->cell(key));
    });
    return found;
  }

  static constexpr double kLargeCells = 8.0;
  static constexpr double kHugeCells = double(1 << 22);

  // What rules a triangle out of a query cheaply, before the closest point
  // (most of the decimation's distance tests, which ask "near all three
  // corners?" and mostly meet triangles of the next face round a crease):
  // its box and its plane. A point farther than r from either is farther
  // than r from the triangle. The box is in floats rounded outwards; the
  // plane is kept only for triangles whose normal is well conditioned (area
  // at least a thousandth of the longest edge's square), so that rounding
  // moves it by far less than kBoundsSlackMm, which every test adds: the
  // filter only rejects triangles the closest point would reject too, and
  // the answers, hence the bytes, stay as they were.
  struct Bounds {
    glm::vec3 lo;
    glm::vec3 hi;
    glm::dvec3 normal;  ///< well_conditioned_normal: zero, no plane test
    double offset;      ///< dot(normal, a)

    [[nodiscard]] bool may_reach(const glm::dvec3& p, double r) const {
      if (p.x < lo.x - r || p.y < lo.y - r || p.z < lo.z - r ||
          p.x > hi.x + r || p.y > hi.y + r || p.z > hi.z + r) {
        return false;
      }
      return std::abs(glm::dot(normal, p) - offset) <= r;
    }
  };
  static constexpr double kBoundsSlackMm = 1e-6;

  [[nodiscard]] static Bounds bounds_of(const glm::dvec3& a,
                                        const glm::dvec3& b,
                                        const glm::dvec3& c,
                                        const glm::dvec3& lo,
                                        const glm::dvec3& hi) {
    Bounds bounds{};
    for (int k = 0; k < 3; ++k) {
      bounds.lo[k] = std::nextafter(static_cast<float>(lo[k]), -HUGE_VALF);
      bounds.hi[k] = std::nextafter(static_cast<float>(hi[k]), HUGE_VALF);
    }
    bounds.normal = well_conditioned_normal(a, b, c);
    bounds.offset = glm::dot(bounds.normal, a);
    return bounds;
  }

  // The triangles by cell, shared by the queriers of one surface: each
  // cell's triangles are a range of `members`, in triangle order, found
  // through an open-addressing table of the filled cells' keys (a hash map
  // of vectors was a tenth of the decimation's distance tests, and its
  // million small vectors most of the index's building).
  struct Index {
    std::vector<Bounds> bounds;  ///< by triangle
    CellGrid grid;
    std::vector<std::uint64_t> slots;       ///< a cell's key, or kEmpty
    std::vector<std::uint32_t> slot_range;  ///< per slot: its range
    std::vector<std::uint32_t> starts;      ///< per range, and one past
    std::vector<std::uint32_t> members;
    std::vector<std::uint32_t> large;
    int slot_bits = 0;

    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};  ///< no key

    [[nodiscard]] std::size_t slot_of(std::uint64_t key) const {
      return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ULL) >>
                                      (64 - slot_bits));
    }

    [[nodiscard]] std::span<const std::uint32_t> cell(std::uint64_t key) const {
      const std::size_t mask = slots.size() - 1;
      for (std::size_t s = slot_of(key);; s = (s + 1) & mask) {
        if (slots[s] == key) {
          const std::uint32_t r = slot_range[s];
          return {members.data() + starts[r], starts[r + 1] - starts[r]};
        }
        if (slots[s] == kEmpty) return {};
      }
    }
  };

  SurfaceDistance(const TriangleMesh& mesh, std::shared_ptr<const Index> index)
      : mesh_(mesh),
        index_(std::move(index)),
        seen_(mesh.triangles.size(), 0) {}

  const TriangleMesh& mesh_;
  std::shared_ptr<const Index> index_;
  std::vector<std::uint32_t> seen_;
  std::uint32_t stamp_ = 0;
  static constexpr std::uint32_t kNone = ~std::uint32_t{0};
  // The triangles that answered the last queries, the latest first; kNone
  // past those.
  std::array<std::uint32_t, 4> recent_ = {kNone, kNone, kNone, kNone};
};

}  // namespace lsolid
