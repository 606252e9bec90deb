// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Leaf plates (docs/design.md, "Parts"): each polygon a plate 5% thicker
// than the thinnest tube across its corners, coplanar polygons united in
// their plane first.
#include "parts/plates.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>

#include "cgal/polygon_union.hpp"
#include "lsolid/validate.hpp"
#include "parts/geometry.hpp"
#include "union_find.hpp"

namespace lsolid {
namespace {

// Leaf polygons within this fraction of the model's size of each other's
// planes are in one plane: turtle paths that meet again differ by rounding
// errors of about 1e-15 of the size.
constexpr double kCoplanar = 1e-9;
constexpr double kParallel = 1.0 - 1e-9;  // |cos| of parallel leaf normals

// A polygon ready to become a plate: its outline without collinear
// points and its unit (Newell) normal.
struct Outline {
  std::vector<glm::dvec3> points;
  glm::dvec3 normal{0.0};
  double area = 0.0;
  Box box;
};

class PlateBuilder {
 public:
  PlateBuilder(const lsys::Skeleton& skeleton, const PartOptions& options,
               double scale_mm)
      : skeleton_(skeleton), options_(options), scale_mm_(scale_mm) {}

  Plates build() {
    add_plates();
    find_shared_corners();
    return std::move(out_);
  }

 private:
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
    outlines_.reserve(polygons.size());
    for (const lsys::Polygon& polygon : polygons) {
      outlines_.push_back(outline(polygon));
    }
    const std::vector<std::optional<Outline>>& outlines = outlines_;
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
    made_.assign(polygons.size(), false);
    std::map<std::size_t, std::vector<std::size_t>> members;
    for (std::size_t i = 0; i < polygons.size(); ++i) {
      if (!outlines[i]) {
        ++out_.skipped;
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
      } else {
        for (const std::size_t i : group) made_[i] = true;
      }
      out_.tip_order.insert(out_.tip_order.end(), group.begin(), group.end());
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
    for (Part& p : plates) out_.parts.push_back(std::move(p));
    out_.plates += plates.size();
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

  void add_plate(const Outline& outline, std::size_t index) {
    const std::vector<std::array<std::uint32_t, 3>> faces =
        triangulate(outline.points, outline.normal);
    if (faces.empty()) {  // the outline crosses itself: no plate to make
      ++out_.skipped;
      return;
    }
    std::vector<std::uint32_t> ring(outline.points.size());
    for (std::uint32_t i = 0; i < ring.size(); ++i) ring[i] = i;
    out_.parts.push_back(
        Part{plate(outline.points, outline.normal, {ring}, faces),
             fmt::format("leaf plate of polygon {}", index),
             skeleton_.polygons[index].color});
    ++out_.plates;
    made_[index] = true;
  }

  // Plates in different planes that start from one point (five petals of
  // ABOP fig. 1.26's flower) have their end edges, across each plate at
  // that corner, cross at the point: a crossing of edges, not of an edge
  // and a face, that the union decides only as coincident points a few
  // ulps apart. Where no tube encloses the point (a colour's own volume
  // with --multi-material: the petals without the stem), rounding those
  // points folded the result. A joint there encloses the crossing.
  void find_shared_corners() {
    struct Corner {
      std::size_t first = 0;  // the first polygon with the corner
      bool shared = false;
    };
    std::unordered_map<NodeKey, Corner, NodeKeyHash> corners;
    std::vector<NodeKey> order;
    const auto& polygons = skeleton_.polygons;
    for (std::size_t i = 0; i < polygons.size(); ++i) {
      if (!made_[i]) continue;
      const Outline& here = *outlines_[i];
      for (const glm::dvec3& p : here.points) {
        const NodeKey key = node_key(p);
        const auto [it, inserted] = corners.emplace(key, Corner{i, false});
        if (inserted) {
          order.push_back(key);
        } else if (std::fabs(glm::dot(outlines_[it->second.first]->normal,
                                      here.normal)) < kParallel) {
          it->second.shared = true;
        }
      }
    }
    for (const NodeKey& key : order) {
      const Corner& corner = corners.at(key);
      if (!corner.shared) continue;
      out_.shared_corners.emplace_back(
          glm::dvec3(std::bit_cast<double>(key[0]),
                     std::bit_cast<double>(key[1]),
                     std::bit_cast<double>(key[2])),
          polygons[corner.first].color);
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
  const PartOptions& options_;
  double scale_mm_;  // the skeleton's largest extent, at least 1 mm
  std::vector<std::optional<Outline>> outlines_;  // per polygon
  std::vector<bool> made_;  // per polygon: whether it is in a plate
  Plates out_;
};

}  // namespace

Plates build_plates(const lsys::Skeleton& skeleton, const PartOptions& options,
                    double scale_mm) {
  return PlateBuilder(skeleton, options, scale_mm).build();
}

}  // namespace lsolid
