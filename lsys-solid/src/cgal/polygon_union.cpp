// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Leaf polygons that lie in one plane and overlap or share edges (ABOP
// fig. 5.5's cordate leaf is a fan of 22 triangles on shared edges;
// Lparser's leaves overlap in layers) are united in the plane before they
// become plates. United as solids they would meet face on face, with
// coplanar caps and coincident walls, which the exact 3D union turns into
// slivers that rounding then folds. The union is made with a constrained
// Delaunay triangulation of every polygon's edges, intersections computed
// exactly (Epeck, Exact_intersections_tag): each face lies wholly inside or
// outside each polygon, so a face is in the union when its centroid is in
// some polygon, and the union's boundary is the edges between faces in and
// out. (CGAL's Boolean set operations would do the same, but their
// arrangement code does not compile with the precondition policy that every
// CGAL translation unit shares; see lsys-solid/CMakeLists.txt.)
#include "kernel.hpp"

#include "polygon_union.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <cmath>
#include <deque>
#include <map>
#include <utility>

#include "lsolid/footprint.hpp"

namespace lsolid {
namespace {

using ExactPolygon = CGAL::Polygon_2<Exact>;
struct FaceInfo {
  bool inside = false;
  int region = -1;
};
using FaceBase = CGAL::Constrained_triangulation_face_base_2<
    Exact, CGAL::Triangulation_face_base_with_info_2<FaceInfo, Exact>>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<
    Exact,
    CGAL::Triangulation_data_structure_2<
        CGAL::Triangulation_vertex_base_2<Exact>, FaceBase>,
    CGAL::Exact_intersections_tag>;
using Face = Cdt::Face_handle;
using Vertex = Cdt::Vertex_handle;

bool is_in(const Cdt& cdt, Face f) {
  return !cdt.is_infinite(f) && f->info().inside;
}

// Points of the plane on a grid of 2^-20 mm (about a nanometre). The turtle
// draws the same leaf twice a few ulps apart (35 of the 728 leaves of the
// blog's tree A at n = 6); united exactly, the copies left slivers that wide
// that rounding back to doubles folded into a plate that cut itself. On
// the grid they are one polygon.
double on_grid(double x) {
  return std::round(x * kFootprintCellsPerMm) / kFootprintCellsPerMm;
}

// The polygon as given, without repeated points; empty if it is not simple.
ExactPolygon simple_polygon(const std::vector<glm::dvec2>& points) {
  ExactPolygon polygon;
  for (const glm::dvec2& p : points) {
    const Exact::Point_2 q(on_grid(p.x), on_grid(p.y));
    if (polygon.size() > 0 && *(polygon.vertices_end() - 1) == q) continue;
    polygon.push_back(q);
  }
  if (polygon.size() > 1 &&
      *polygon.vertices_begin() == *(polygon.vertices_end() - 1)) {
    polygon.erase(polygon.vertices_end() - 1);
  }
  if (polygon.size() < 3 || !polygon.is_simple()) return {};
  return polygon;
}

// One region: the inside faces of `region`, their vertices rounded to
// doubles, and the boundary chained into rings.
std::optional<PlanarRegion> extract(const Cdt& cdt, int region) {
  PlanarRegion out;
  std::map<Vertex, std::uint32_t> index;
  std::map<std::pair<double, double>, Vertex> rounded;
  const auto index_of = [&](Vertex v) -> std::optional<std::uint32_t> {
    const auto it = index.find(v);
    if (it != index.end()) return it->second;
    const glm::dvec2 p(CGAL::to_double(v->point().x()),
                       CGAL::to_double(v->point().y()));
    // Two exact points that round to one double would pinch the plate.
    if (!rounded.emplace(std::pair(p.x, p.y), v).second) return std::nullopt;
    const auto i = static_cast<std::uint32_t>(out.points.size());
    out.points.push_back(p);
    index.emplace(v, i);
    return i;
  };
  // Boundary edges, oriented with the region on their left.
  std::map<std::uint32_t, std::uint32_t> next;
  for (const Face f : cdt.finite_face_handles()) {
    if (!f->info().inside || f->info().region != region) continue;
    std::array<std::uint32_t, 3> t{};
    for (int k = 0; k < 3; ++k) {
      const std::optional<std::uint32_t> i = index_of(f->vertex(k));
      if (!i) return std::nullopt;
      t[static_cast<std::size_t>(k)] = *i;
    }
    out.triangles.push_back(t);
    for (int k = 0; k < 3; ++k) {
      if (is_in(cdt, f->neighbor(k))) continue;
      const std::uint32_t from = t[static_cast<std::size_t>(Cdt::ccw(k))];
      const std::uint32_t to = t[static_cast<std::size_t>(Cdt::cw(k))];
      // A vertex with two boundary edges leaving it is a pinch point.
      if (!next.emplace(from, to).second) return std::nullopt;
    }
  }
  while (!next.empty()) {
    std::vector<std::uint32_t> ring;
    std::uint32_t at = next.begin()->first;
    while (true) {
      const auto it = next.find(at);
      if (it == next.end()) break;
      ring.push_back(at);
      at = it->second;
      next.erase(it);
    }
    if (ring.size() < 3 || at != ring.front()) return std::nullopt;
    out.rings.push_back(std::move(ring));
  }
  // Rounding must not turn a triangle over or flatten it.
  for (const auto& t : out.triangles) {
    const auto point = [&](std::uint32_t i) {
      return CGAL::Epick::Point_2(out.points[i].x, out.points[i].y);
    };
    if (CGAL::orientation(point(t[0]), point(t[1]), point(t[2])) !=
        CGAL::LEFT_TURN) {
      return std::nullopt;
    }
  }
  return out;
}

}  // namespace

std::optional<std::vector<PlanarRegion>> polygon_union(
    const std::vector<std::vector<glm::dvec2>>& polygons) {
  std::vector<ExactPolygon> simple;
  Cdt cdt;
  for (const std::vector<glm::dvec2>& points : polygons) {
    ExactPolygon polygon = simple_polygon(points);
    if (polygon.size() == 0) return std::nullopt;
    if (polygon.orientation() == CGAL::COLLINEAR) continue;
    for (std::size_t k = 0; k < polygon.size(); ++k) {
      cdt.insert_constraint(polygon.vertex(k),
                            polygon.vertex((k + 1) % polygon.size()));
    }
    simple.push_back(std::move(polygon));
  }
  // A face is in the union when its centroid is inside some polygon: no
  // polygon edge crosses a face, so the whole face is.
  for (const Face f : cdt.finite_face_handles()) {
    const Exact::Point_2 c = CGAL::centroid(
        f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    for (const ExactPolygon& polygon : simple) {
      if (polygon.bounded_side(c) == CGAL::ON_BOUNDED_SIDE) {
        f->info().inside = true;
        break;
      }
    }
  }
  // Regions: inside faces joined across edges that are not boundary.
  int regions = 0;
  for (const Face start : cdt.finite_face_handles()) {
    if (!start->info().inside || start->info().region >= 0) continue;
    std::deque<Face> queue{start};
    start->info().region = regions;
    while (!queue.empty()) {
      const Face f = queue.front();
      queue.pop_front();
      for (int k = 0; k < 3; ++k) {
        const Face n = f->neighbor(k);
        if (is_in(cdt, n) && n->info().region < 0) {
          n->info().region = regions;
          queue.push_back(n);
        }
      }
    }
    ++regions;
  }
  std::vector<PlanarRegion> out;
  for (int r = 0; r < regions; ++r) {
    std::optional<PlanarRegion> region = extract(cdt, r);
    if (!region) return std::nullopt;
    out.push_back(std::move(*region));
  }
  return out;
}

}  // namespace lsolid
