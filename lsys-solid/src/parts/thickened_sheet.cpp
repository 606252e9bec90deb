// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// A leaf from cpfg's Bézier surfaces is a curved sheet without thickness.
// United as one plate per triangle (as polygons are), neighbouring plates
// meet at small dihedral angles in thin wedges, which the exact union turns
// into slivers and rounding back to doubles folds: a single 8 × 4 leaf
// crashed CGAL's corefinement. Offsetting the whole sheet along its normals
// gives one closed part instead, with no faces that meet face on face.
#include "parts/thickened_sheet.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <glm/geometric.hpp>
#include <map>
#include <utility>
#include <vector>

#include "cgal/part_queries.hpp"
#include "lsolid/errors.hpp"
#include "lsolid/validate.hpp"

namespace lsolid {
namespace {

// A sheet at most this many plate thicknesses across may become its
// thickened points' convex hull when it cannot be thickened cleanly.
constexpr double kHullSheetWalls = 8.0;

using Triangle = std::array<std::uint32_t, 3>;

// A sweep along a direction this slanted to some triangle (75.5°) would
// have to be four times the thickness.
constexpr double kSteepestSweep = 0.25;

// The most of a sheet's area that thinning may touch.
constexpr double kMostThinnedArea = 0.25;

// The triangles flipped where needed so that every edge two triangles share
// runs one way in one and the other way in the other. False if no such
// choice exists or an edge has more than two triangles.
bool orient(std::vector<Triangle>& triangles) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>>
      edges;
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = triangles[f][k];
      const std::uint32_t b = triangles[f][(k + 1) % 3];
      auto& faces = edges[{std::min(a, b), std::max(a, b)}];
      faces.push_back(f);
      if (faces.size() > 2) return false;
    }
  }
  // Whether f runs from a to b.
  const auto runs = [&](std::size_t f, std::uint32_t a, std::uint32_t b) {
    for (int k = 0; k < 3; ++k) {
      if (triangles[f][k] == a && triangles[f][(k + 1) % 3] == b) return true;
    }
    return false;
  };
  std::vector<int> state(triangles.size(), 0);  // 0 unseen, 1 kept, 2 done
  for (std::size_t start = 0; start < triangles.size(); ++start) {
    if (state[start] != 0) continue;
    state[start] = 1;
    std::deque<std::size_t> queue{start};
    while (!queue.empty()) {
      const std::size_t f = queue.front();
      queue.pop_front();
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = triangles[f][k];
        const std::uint32_t b = triangles[f][(k + 1) % 3];
        for (const std::size_t g : edges[{std::min(a, b), std::max(a, b)}]) {
          if (g == f) continue;
          const bool agrees = runs(g, b, a);
          if (state[g] != 0) {
            if (!agrees) return false;  // one-sided: a Möbius band
            continue;
          }
          if (!agrees) std::swap(triangles[g][1], triangles[g][2]);
          state[g] = 1;
          queue.push_back(g);
        }
      }
    }
  }
  return true;
}

// The sheet's triangles, oriented, and how far each point moves to
// either side, and along what.
struct Offsets {
  std::vector<Triangle> triangles;
  std::vector<glm::dvec3> normal;
  std::vector<double> offset;
};

std::optional<Offsets> offsets(const lsys::Sheet& sheet, double thickness_mm,
                               SheetOffset offset_along) {
  Offsets out{.triangles = sheet.triangles};
  std::vector<Triangle>& triangles = out.triangles;
  if (triangles.empty() || !orient(triangles)) return std::nullopt;
  const std::size_t count = sheet.points.size();
  std::vector<bool> used(count, false);
  for (const Triangle& t : triangles) {
    for (const std::uint32_t i : t) used[i] = true;
  }
  // Normals at the points weighted by each triangle's angle there
  // (Thürrner and Wüthrich 1998): they do not change when a triangle is
  // cut in two. Their sum, weighted by area, is the sheet's mean normal.
  std::vector<glm::dvec3>& normal = out.normal;
  normal.assign(count, glm::dvec3(0.0));
  std::vector<glm::dvec3> face_normal;
  face_normal.reserve(triangles.size());
  glm::dvec3 mean(0.0);
  for (const Triangle& t : triangles) {
    const glm::dvec3 n = glm::cross(sheet.points[t[1]] - sheet.points[t[0]],
                                    sheet.points[t[2]] - sheet.points[t[0]]);
    const double area = glm::length(n);
    mean += n;
    face_normal.push_back(area > 0.0 ? n / area : glm::dvec3(0.0));
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 p = sheet.points[t[k]];
      const glm::dvec3 u = sheet.points[t[(k + 1) % 3]] - p;
      const glm::dvec3 v = sheet.points[t[(k + 2) % 3]] - p;
      const double angle =
          std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
      normal[t[k]] += angle * face_normal.back();
    }
  }
  std::vector<double>& offset = out.offset;
  offset.assign(count, thickness_mm / 2.0);
  if (offset_along == SheetOffset::Normals) {
    for (std::size_t i = 0; i < count; ++i) {
      if (!used[i]) continue;  // remove_unused_vertices drops it below
      const double length = glm::length(normal[i]);
      if (!(length > 1e-9)) return std::nullopt;
      normal[i] /= length;
    }
    // Half the thickness from each triangle the point is on: more than
    // half along the point's normal where the sheet bends (at most twice,
    // where it bends by 60°).
    for (std::size_t f = 0; f < triangles.size(); ++f) {
      for (const std::uint32_t i : triangles[f]) {
        const double c = std::max(0.5, glm::dot(normal[i], face_normal[f]));
        offset[i] = std::max(offset[i], thickness_mm / 2.0 / c);
      }
    }
  } else {
    // One direction for all: the plate is the sheet swept along it, which
    // cuts itself only if the sheet overlaps itself seen along it. Where
    // the sheet slants to it, the sweep must be longer to stay as thick.
    const double length = glm::length(mean);
    if (!(length > 0.0)) return std::nullopt;
    const glm::dvec3 d = mean / length;
    double least = 1.0;
    for (const glm::dvec3& n : face_normal) {
      least = std::min(least, glm::dot(n, d));
    }
    if (!(least >= kSteepestSweep)) return std::nullopt;
    std::fill(normal.begin(), normal.end(), d);
    std::fill(offset.begin(), offset.end(), thickness_mm / 2.0 / least);
  }
  return out;
}

// The closed solid, point i of the sheet at i below and count + i above,
// each moved by its offset times `scale[i]`; unused points stay.
TriangleMesh solid(const lsys::Sheet& sheet, const Offsets& o,
                   const std::vector<double>& scale) {
  const std::size_t count = sheet.points.size();
  TriangleMesh mesh;
  mesh.vertices.reserve(2 * count);
  for (std::size_t i = 0; i < count; ++i) {
    mesh.vertices.push_back(sheet.points[i] -
                            scale[i] * o.offset[i] * o.normal[i]);
  }
  for (std::size_t i = 0; i < count; ++i) {
    mesh.vertices.push_back(sheet.points[i] +
                            scale[i] * o.offset[i] * o.normal[i]);
  }
  const auto top = static_cast<std::uint32_t>(count);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const Triangle& t : o.triangles) {
    mesh.triangles.push_back({t[0] + top, t[1] + top, t[2] + top});
    mesh.triangles.push_back({t[0], t[2], t[1]});
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k];
      const std::uint32_t b = t[(k + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  }
  // The wall: each boundary edge i → j of the top face, whose bottom copy
  // runs j → i, closed by a quad i, j, j', i'.
  for (const Triangle& t : o.triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = t[k];
      const std::uint32_t j = t[(k + 1) % 3];
      if (uses[{std::min(i, j), std::max(i, j)}] != 1) continue;
      mesh.triangles.push_back({i, j, j + top});
      mesh.triangles.push_back({i, j + top, i + top});
    }
  }
  return mesh;
}

// Without the unused points, and facing out.
TriangleMesh finished(TriangleMesh mesh) {
  remove_unused_vertices(mesh);
  if (signed_volume(mesh) < 0.0) {
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  }
  return mesh;
}

}  // namespace

std::optional<TriangleMesh> thicken_sheet(const lsys::Sheet& sheet,
                                          double thickness_mm,
                                          SheetOffset offset_along) {
  const std::optional<Offsets> o = offsets(sheet, thickness_mm, offset_along);
  if (!o) return std::nullopt;
  return finished(
      solid(sheet, *o, std::vector<double>(sheet.points.size(), 1.0)));
}

std::optional<ThinnedSheet> thicken_sheet_thinning(const lsys::Sheet& sheet,
                                                   double thickness_mm) {
  const std::optional<Offsets> o =
      offsets(sheet, thickness_mm, SheetOffset::Normals);
  if (!o) return std::nullopt;
  const std::size_t count = sheet.points.size();
  std::vector<double> scale(count, 1.0);
  for (;;) {
    TriangleMesh mesh = solid(sheet, *o, scale);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    try {
      pairs = intersecting_triangle_pairs(mesh);
    } catch (const GeometryError&) {
      return std::nullopt;  // not an oriented surface: nothing to thin
    }
    if (pairs.empty()) {
      // Thinning for more than a fold's edge would print a thinner plate,
      // not the one asked for.
      double area = 0.0;
      double thinned_area = 0.0;
      for (const Triangle& t : o->triangles) {
        const double a =
            glm::length(glm::cross(sheet.points[t[1]] - sheet.points[t[0]],
                                   sheet.points[t[2]] - sheet.points[t[0]]));
        area += a;
        if (scale[t[0]] < 1.0 || scale[t[1]] < 1.0 || scale[t[2]] < 1.0) {
          thinned_area += a;
        }
      }
      if (thinned_area > kMostThinnedArea * area) return std::nullopt;
      return ThinnedSheet{
          .mesh = finished(std::move(mesh)),
          .thinnest_fraction = *std::min_element(scale.begin(), scale.end())};
    }
    bool thinned = false;
    for (const auto& [f, g] : pairs) {
      for (const std::uint32_t face : {f, g}) {
        for (const std::uint32_t v : mesh.triangles[face]) {
          double& s = scale[v % count];
          if (s > kThinnestSheet) {
            s = std::max(kThinnestSheet, s / 2.0);
            thinned = true;
          }
        }
      }
    }
    if (!thinned) return std::nullopt;
  }
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
SheetPart sheet_part(const lsys::Sheet& sheet, std::size_t index,
                     double thickness) {
  const glm::dvec3 at = sheet.points[sheet.triangles[0][0]];
  std::string label = fmt::format("surface {} at ({:.3f}, {:.3f}, {:.3f}) mm",
                                  index, at.x, at.y, at.z);
  for (const SheetOffset way :
       {SheetOffset::Normals, SheetOffset::MeanNormal}) {
    std::optional<TriangleMesh> mesh = thicken_sheet(sheet, thickness, way);
    if (!mesh || !validate(*mesh).is_printable()) continue;
    return SheetPart{.part =
                         Part{std::move(*mesh), std::move(label), sheet.color}};
  }
  if (std::optional<ThinnedSheet> thinned =
          thicken_sheet_thinning(sheet, thickness);
      thinned && validate(thinned->mesh).is_printable()) {
    return SheetPart{
        .part = Part{std::move(thinned->mesh), std::move(label), sheet.color},
        .kind = SheetKind::Thinned,
        .thinnest_mm = thinned->thinnest_fraction * thickness};
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
    return SheetPart{
        .part = Part{std::move(hull), std::move(label), sheet.color},
        .kind = SheetKind::Hulled};
  }
  throw GeometryError(fmt::format(
      "{}, {:.1f} mm across, bends too sharply to thicken to {:.2f} mm "
      "without cutting itself; draw it larger or give a thinner --wall",
      label, across, thickness));
}

}  // namespace lsolid
