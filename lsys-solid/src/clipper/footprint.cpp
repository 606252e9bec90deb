// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The union of a flat model's outlines with Clipper 6.4 (Angus Johnson;
// Debian's libpolyclipping-dev), which implements Vatti's sweep ("A generic
// solution to polygon clipping", CACM 35(7), 1992) on integer coordinates:
// every intersection is found and rounded to the grid, so the result is
// exact up to that rounding and never fails on the coincident and
// collinear edges that planar L-systems are full of (Koch curves, ABOP
// fig. 1.24's plants, whose branches share endpoints and directions). The
// 3D union of the same tubes took minutes on those figures (docs/design.md,
// "Lying flat"). Clipper lives in this file only.
#include "lsolid/footprint.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <polyclipping/clipper.hpp>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "lsolid/errors.hpp"
#include "lsolid/parts.hpp"

namespace lsolid {
namespace {

using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

// Clipper's coordinates must stay within ±hiRange; a millimetre model a
// kilometre wide needs 2^40, far inside it (solid.cpp refuses larger).
constexpr double kMostCells = 4.0e18;
// How far, in grid steps, a union that touches itself is grown, in turn.
constexpr std::array<double, 3> kGrowSteps{2.0, 3.0, 5.0};

cInt to_grid(double mm) {
  const double cells = std::round(mm * kFootprintCellsPerMm);
  if (!(std::fabs(cells) < kMostCells)) {
    throw GeometryError("a footprint point lies too far from the origin");
  }
  return static_cast<cInt>(cells);
}

Path to_path(const std::vector<glm::dvec2>& polygon) {
  Path path;
  path.reserve(polygon.size());
  for (const glm::dvec2& p : polygon) {
    const IntPoint q(to_grid(p.x), to_grid(p.y));
    if (!path.empty() && path.back() == q) continue;
    path.push_back(q);
  }
  while (path.size() > 1 && path.front() == path.back()) path.pop_back();
  return path;
}

// Whether a counter-clockwise path turns left (or goes straight) at
// every corner, exactly: products of differences of grid coordinates
// below 2^30 fit in 64 bits; a path reaching beyond counts as not convex.
bool is_convex(const Path& path) {
  const std::size_t n = path.size();
  for (std::size_t i = 0; i < n; ++i) {
    const IntPoint& a = path[i];
    const IntPoint& b = path[(i + 1) % n];
    const IntPoint& c = path[(i + 2) % n];
    const bool small =
        std::max({std::abs(a.X), std::abs(a.Y), std::abs(b.X), std::abs(b.Y),
                  std::abs(c.X), std::abs(c.Y)}) < (cInt{1} << 30);
    if (!small) return false;
    const cInt cross = (b.X - a.X) * (c.Y - b.Y) - (b.Y - a.Y) * (c.X - b.X);
    if (cross < 0) return false;
  }
  return true;
}

// Points shared by two rings, or twice on one: where the region pinches.
// Clipper's strictly simple output splits a ring that touches itself into
// rings that share the point.
bool has_shared_point(const Paths& rings) {
  std::set<std::pair<cInt, cInt>> seen;
  for (const Path& ring : rings) {
    for (const IntPoint& p : ring) {
      if (!seen.emplace(p.X, p.Y).second) return true;
    }
  }
  return false;
}

// A vertex of one ring on an edge of another: the region pinches there too.
// Rings are compared only where their boxes meet.
bool touches_another_ring(const Paths& rings) {
  struct RingBox {
    cInt x0, y0, x1, y1;
  };
  std::vector<RingBox> boxes;
  boxes.reserve(rings.size());
  for (const Path& ring : rings) {
    RingBox b{ring[0].X, ring[0].Y, ring[0].X, ring[0].Y};
    for (const IntPoint& p : ring) {
      b.x0 = std::min(b.x0, p.X);
      b.y0 = std::min(b.y0, p.Y);
      b.x1 = std::max(b.x1, p.X);
      b.y1 = std::max(b.y1, p.Y);
    }
    boxes.push_back(b);
  }
  std::vector<std::size_t> order(rings.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return boxes[a].x0 < boxes[b].x0;
  });
  for (std::size_t k = 0; k < order.size(); ++k) {
    const RingBox& a = boxes[order[k]];
    for (std::size_t m = k + 1; m < order.size(); ++m) {
      const RingBox& b = boxes[order[m]];
      if (b.x0 > a.x1) break;
      if (b.y0 > a.y1 || a.y0 > b.y1) continue;
      const auto on_boundary = [&](std::size_t from, std::size_t of) {
        const RingBox& box = boxes[of];
        for (const IntPoint& p : rings[from]) {
          if (p.X < box.x0 || p.X > box.x1 || p.Y < box.y0 || p.Y > box.y1) {
            continue;
          }
          if (ClipperLib::PointInPolygon(p, rings[of]) == -1) return true;
        }
        return false;
      };
      if (on_boundary(order[k], order[m]) || on_boundary(order[m], order[k])) {
        return true;
      }
    }
  }
  return false;
}

// The union of `paths`, less that of `minus` if any.
Paths unite(const Paths& paths, const Paths& minus = {}) {
  ClipperLib::Clipper clipper;
  clipper.StrictlySimple(true);
  clipper.AddPaths(paths, ClipperLib::ptSubject, true);
  clipper.AddPaths(minus, ClipperLib::ptClip, true);
  Paths out;
  if (!clipper.Execute(
          minus.empty() ? ClipperLib::ctUnion : ClipperLib::ctDifference, out,
          ClipperLib::pftNonZero, ClipperLib::pftNonZero)) {
    throw GeometryError("the union of the footprint's outlines failed");
  }
  return out;
}

Paths grown(const Paths& rings, double cells) {
  ClipperLib::ClipperOffset offset;
  offset.AddPaths(rings, ClipperLib::jtMiter, ClipperLib::etClosedPolygon);
  Paths out;
  offset.Execute(out, cells);
  return unite(out);
}

Footprint to_footprint(const Paths& rings) {
  Footprint out;
  out.rings.reserve(rings.size());
  for (const Path& ring : rings) {
    std::vector<glm::dvec2> points;
    points.reserve(ring.size());
    for (const IntPoint& p : ring) {
      points.emplace_back(static_cast<double>(p.X) / kFootprintCellsPerMm,
                          static_cast<double>(p.Y) / kFootprintCellsPerMm);
    }
    out.rings.push_back(std::move(points));
  }
  return out;
}

// Non-zero winding over all polygons would let a clockwise polygon cancel
// a counter-clockwise one where they overlap (a leaf drawn clockwise lost
// its middle under its veins): each polygon is first made positive on its
// own, a convex one by turning it round, any other by Clipper.
Paths positive_paths(const std::vector<std::vector<glm::dvec2>>& polygons) {
  Paths paths;
  paths.reserve(polygons.size());
  for (const std::vector<glm::dvec2>& polygon : polygons) {
    Path path = to_path(polygon);
    if (path.size() < 3) continue;
    if (!ClipperLib::Orientation(path)) ClipperLib::ReversePath(path);
    if (is_convex(path)) {
      paths.push_back(std::move(path));
      continue;
    }
    Paths positive;
    ClipperLib::SimplifyPolygon(path, positive, ClipperLib::pftNonZero);
    for (Path& part : positive) paths.push_back(std::move(part));
  }
  return paths;
}

}  // namespace

std::vector<glm::dvec2> branch_outline(const glm::dvec2& p0, double r0_mm,
                                       const glm::dvec2& p1, double r1_mm,
                                       double tolerance_mm) {
  if (p0 == p1) return {};
  const glm::dvec2 d = glm::normalize(p1 - p0);
  const glm::dvec2 across(-d.y, d.x);
  const double w0 = tube_corner_radius(r0_mm, tolerance_mm);
  const double w1 = tube_corner_radius(r1_mm, tolerance_mm);
  return {p0 - across * w0, p1 - across * w1, p1 + across * w1,
          p0 + across * w0};
}

std::vector<glm::dvec2> node_outline(const glm::dvec2& center, double r_mm,
                                     double tolerance_mm) {
  const int sides = tube_sides(r_mm, tolerance_mm);
  const double corner = tube_corner_radius(r_mm, tolerance_mm);
  std::vector<glm::dvec2> out;
  out.reserve(static_cast<std::size_t>(sides));
  for (int k = 0; k < sides; ++k) {
    const double a = 2.0 * std::numbers::pi * (k + 0.5) / sides;
    out.emplace_back(center.x + corner * std::cos(a),
                     center.y + corner * std::sin(a));
  }
  return out;
}

bool is_simple_polygon(const std::vector<glm::dvec2>& polygon) {
  const Path path = to_path(polygon);
  if (path.size() < 3) return false;
  const double area = std::fabs(ClipperLib::Area(path));
  if (!(area > 0.0)) return false;
  Paths simple;
  ClipperLib::SimplifyPolygon(path, simple, ClipperLib::pftNonZero);
  // One ring covering what the polygon encloses: a polygon that crosses
  // itself splits into several, or loses area where it winds back.
  return simple.size() == 1 &&
         std::fabs(std::fabs(ClipperLib::Area(simple[0])) - area) <=
             1e-9 * area;
}

Footprint footprint_union(const std::vector<std::vector<glm::dvec2>>& polygons,
                          const std::vector<std::vector<glm::dvec2>>& minus) {
  Paths rings = unite(positive_paths(polygons), positive_paths(minus));
  // A pinched region cannot be walled as a 2-manifold; grown by a few
  // nanometres, the rings that touched at a point overlap and merge, and
  // holes touching the boundary come away from it.
  for (std::size_t attempt = 0;
       has_shared_point(rings) || touches_another_ring(rings); ++attempt) {
    if (attempt == kGrowSteps.size()) {
      throw GeometryError(
          "the footprint's outline touches itself at a point, and growing "
          "it by a few nanometres did not separate it");
    }
    rings = grown(rings, kGrowSteps[attempt]);
  }
  // Largest first, then by position: the same rings in the same order for
  // the same input, whatever order Clipper found them in.
  std::sort(rings.begin(), rings.end(), [](const Path& a, const Path& b) {
    const double area_a = std::fabs(ClipperLib::Area(a));
    const double area_b = std::fabs(ClipperLib::Area(b));
    if (area_a != area_b) return area_a > area_b;
    return std::pair(a.front().X, a.front().Y) <
           std::pair(b.front().X, b.front().Y);
  });
  return to_footprint(rings);
}

double area(const Footprint& footprint) {
  double sum = 0.0;
  for (const std::vector<glm::dvec2>& ring : footprint.rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const glm::dvec2& a = ring[i];
      const glm::dvec2& b = ring[(i + 1) % ring.size()];
      sum += a.x * b.y - b.x * a.y;
    }
  }
  return sum / 2.0;
}

}  // namespace lsolid
