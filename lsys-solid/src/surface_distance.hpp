// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <unordered_map>
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
  const auto collect = [&](const auto& self, const glm::dvec3& p,
                           const glm::dvec3& q, const glm::dvec3& r) -> void {
    const glm::dvec3 lo = glm::min(glm::min(p, q), r);
    const glm::dvec3 hi = glm::max(glm::max(p, q), r);
    if (grid.count(lo, hi) > kPieceCells) {
      const glm::dvec3 pq = (p + q) * 0.5;
      const glm::dvec3 qr = (q + r) * 0.5;
      const glm::dvec3 rp = (r + p) * 0.5;
      self(self, p, pq, rp);
      self(self, pq, q, qr);
      self(self, rp, qr, r);
      self(self, qr, rp, pq);
      return;
    }
    grid.for_each(lo, hi, [&](std::uint64_t key, const glm::dvec3& centre) {
      const glm::dvec3 d = closest_point_on_triangle(centre, p, q, r) - centre;
      if (glm::dot(d, d) <= reach * reach) keys.push_back(key);
    });
  };
  collect(collect, a, b, c);
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
  explicit SurfaceDistance(const TriangleMesh& mesh, double min_cell_mm = 0.0)
      : mesh_(mesh), seen_(mesh.triangles.size(), 0) {
    auto index = std::make_shared<Index>();
    CellGrid& grid = index->grid;
    double area = 0.0;
    for (const auto& t : mesh.triangles) {
      const glm::dvec3& a = mesh.vertices[t[0]];
      area += glm::length(glm::cross(mesh.vertices[t[1]] - a,
                                     mesh.vertices[t[2]] - a)) /
              2.0;
    }
    grid = CellGrid(std::max(
        {min_cell_mm,
         mesh.triangles.empty()
             ? 1.0
             : std::sqrt(area / static_cast<double>(mesh.triangles.size())),
         1e-6}));
    for (std::uint32_t i = 0; i < mesh.triangles.size(); ++i) {
      const auto& t = mesh.triangles[i];
      const glm::dvec3& a = mesh.vertices[t[0]];
      const glm::dvec3& b = mesh.vertices[t[1]];
      const glm::dvec3& c = mesh.vertices[t[2]];
      const glm::dvec3 lo = glm::min(glm::min(a, b), c);
      const glm::dvec3 hi = glm::max(glm::max(a, b), c);
      const double cells = grid.count(lo, hi);
      if (cells > kHugeCells) {
        index->large.push_back(i);  // tested by every query
      } else if (cells > kLargeCells) {
        // A long sliver across many cells, such as the flat underside's:
        // only the cells it passes through.
        for_each_cell_through(grid, a, b, c, [&](std::uint64_t key) {
          index->cells[key].push_back(i);
        });
      } else {
        grid.for_each(lo, hi, [&](std::uint64_t key, const glm::dvec3&) {
          index->cells[key].push_back(i);
        });
      }
    }
    index_ = std::move(index);
  }

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
      const auto test = [&](const std::vector<std::uint32_t>& cell) {
        for (const std::uint32_t i : cell) {
          if (seen_[i] == stamp_) continue;
          seen_[i] = stamp_;
          best = std::min(best, squared_distance(i, p));
        }
      };
      test(index_->large);
      index_->grid.for_each(p - reach, p + reach,
                            [&](std::uint64_t key, const glm::dvec3&) {
                              const auto it = index_->cells.find(key);
                              if (it != index_->cells.end()) test(it->second);
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
    return any_near(a, distance_mm, [&](std::uint32_t i) {
      return squared_distance(i, a) <= squared &&
             squared_distance(i, b) <= squared &&
             squared_distance(i, c) <= squared;
    });
  }

  /// True when some triangle lies within `distance_mm` of `p`.
  [[nodiscard]] bool within(const glm::dvec3& p, double distance_mm) {
    const double squared = distance_mm * distance_mm;
    return any_near(p, distance_mm, [&](std::uint32_t i) {
      return squared_distance(i, p) <= squared;
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

  // True when near(i) holds for a triangle i within `distance_mm` of `p`
  // (those are all it asks about). Queries come in runs of nearby points
  // (samples on one triangle): the triangle that answered the last one
  // mostly answers this one, so it is asked first.
  template <typename Near>
  [[nodiscard]] bool any_near(const glm::dvec3& p, double distance_mm,
                              Near near) {
    if (hint_ < mesh_.triangles.size() && near(hint_)) return true;
    ++stamp_;
    bool found = false;
    const auto test = [&](const std::vector<std::uint32_t>& cell) {
      for (const std::uint32_t i : cell) {
        if (seen_[i] == stamp_) continue;
        seen_[i] = stamp_;
        if (near(i)) {
          hint_ = i;
          found = true;
          return;
        }
      }
    };
    test(index_->large);
    index_->grid.for_each(p - distance_mm, p + distance_mm,
                          [&](std::uint64_t key, const glm::dvec3&) {
                            if (found) return;
                            const auto it = index_->cells.find(key);
                            if (it != index_->cells.end()) test(it->second);
                          });
    return found;
  }

  static constexpr double kLargeCells = 8.0;
  static constexpr double kHugeCells = double(1 << 22);

  // The triangles by cell, shared by the queriers of one surface.
  struct Index {
    CellGrid grid;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells;
    std::vector<std::uint32_t> large;
  };

  SurfaceDistance(const TriangleMesh& mesh, std::shared_ptr<const Index> index)
      : mesh_(mesh),
        index_(std::move(index)),
        seen_(mesh.triangles.size(), 0) {}

  const TriangleMesh& mesh_;
  std::shared_ptr<const Index> index_;
  std::vector<std::uint32_t> seen_;
  std::uint32_t stamp_ = 0;
  std::uint32_t hint_ = ~std::uint32_t{0};  ///< the last triangle that answered
};

}  // namespace lsolid
