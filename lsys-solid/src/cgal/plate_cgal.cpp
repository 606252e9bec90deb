// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Leaf polygons that lie in one plane and overlap or share edges (ABOP
// fig. 5.5's cordate leaf is a fan of 22 triangles on shared edges;
// Lparser's leaves overlap in layers) are united in the plane before they
// become plates. United as solids they would meet face on face, with
// coplanar caps and coincident walls, which the exact 3D union turns into
// slivers that rounding then folds. The 2D union is exact (CGAL's Boolean
// set operations over Epeck); its regions are triangulated with a
// constrained Delaunay triangulation whose inside is found by nesting
// level, as in the CGAL 2D triangulation manual's polygon example.
#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <deque>
#include <map>

#include "plate_geometry.hpp"

namespace lsolid {
namespace {

using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPolygon = CGAL::Polygon_2<Exact>;
using ExactRegion = CGAL::Polygon_with_holes_2<Exact>;

using Inexact = CGAL::Exact_predicates_inexact_constructions_kernel;
struct FaceInfo {
  int nesting = -1;  // even: outside, odd: inside the region
};
using VertexBase =
    CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Inexact>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<
    Inexact, CGAL::Triangulation_face_base_with_info_2<FaceInfo, Inexact>>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<
    Inexact, CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>,
    CGAL::No_constraint_intersection_tag>;

// Nesting levels: faces reached from the infinite face without crossing a
// constraint are at level 0, and each constrained edge crossed adds one.
void mark_nesting(Cdt& cdt) {
  std::deque<Cdt::Edge> borders;
  const auto flood = [&](Cdt::Face_handle start, int level) {
    std::deque<Cdt::Face_handle> queue{start};
    while (!queue.empty()) {
      const Cdt::Face_handle f = queue.front();
      queue.pop_front();
      if (f->info().nesting != -1) continue;
      f->info().nesting = level;
      for (int i = 0; i < 3; ++i) {
        const Cdt::Face_handle next = f->neighbor(i);
        if (next->info().nesting != -1) continue;
        if (cdt.is_constrained(Cdt::Edge(f, i))) {
          borders.emplace_back(f, i);
        } else {
          queue.push_back(next);
        }
      }
    }
  };
  flood(cdt.infinite_face(), 0);
  while (!borders.empty()) {
    const auto [f, i] = borders.front();
    borders.pop_front();
    const Cdt::Face_handle next = f->neighbor(i);
    if (next->info().nesting == -1) flood(next, f->info().nesting + 1);
  }
}

std::optional<PlanarRegion> triangulated(const ExactRegion& exact) {
  PlanarRegion region;
  // Rounding may bring two exact points onto one double: that region would
  // pinch, so it is refused.
  std::map<std::pair<double, double>, std::uint32_t> seen;
  const auto add_ring = [&](const ExactPolygon& ring) {
    std::vector<std::uint32_t> indices;
    for (auto v = ring.vertices_begin(); v != ring.vertices_end(); ++v) {
      const glm::dvec2 p(CGAL::to_double(v->x()), CGAL::to_double(v->y()));
      const auto index = static_cast<std::uint32_t>(region.points.size());
      if (!seen.emplace(std::pair(p.x, p.y), index).second) return false;
      region.points.push_back(p);
      indices.push_back(index);
    }
    region.rings.push_back(std::move(indices));
    return true;
  };
  if (!add_ring(exact.outer_boundary())) return std::nullopt;
  for (auto hole = exact.holes_begin(); hole != exact.holes_end(); ++hole) {
    if (!add_ring(*hole)) return std::nullopt;
  }
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  for (std::uint32_t i = 0; i < region.points.size(); ++i) {
    const Cdt::Vertex_handle v =
        cdt.insert(Inexact::Point_2(region.points[i].x, region.points[i].y));
    v->info() = i;
    handles.push_back(v);
  }
  try {
    for (const std::vector<std::uint32_t>& ring : region.rings) {
      for (std::size_t k = 0; k < ring.size(); ++k) {
        cdt.insert_constraint(handles[ring[k]],
                              handles[ring[(k + 1) % ring.size()]]);
      }
    }
  } catch (const std::exception&) {
    // Rounded rings that cross would need new points.
    return std::nullopt;
  }
  if (cdt.number_of_vertices() != region.points.size()) return std::nullopt;
  mark_nesting(cdt);
  for (const Cdt::Face_handle f : cdt.finite_face_handles()) {
    if (f->info().nesting % 2 != 1) continue;
    region.triangles.push_back(
        {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  }
  // Every boundary edge must border exactly one inside triangle, on its
  // left: otherwise the rounded rings no longer bound this region.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const auto& t : region.triangles) {
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  }
  for (const std::vector<std::uint32_t>& ring : region.rings) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const auto it = edges.find({ring[k], ring[(k + 1) % ring.size()]});
      if (it == edges.end() || it->second != 1) return std::nullopt;
    }
  }
  return region;
}

}  // namespace

std::optional<std::vector<PlanarRegion>> polygon_union(
    const std::vector<std::vector<glm::dvec2>>& polygons) {
  CGAL::Polygon_set_2<Exact> united;
  for (const std::vector<glm::dvec2>& points : polygons) {
    ExactPolygon polygon;
    for (const glm::dvec2& p : points) {
      const Exact::Point_2 q(p.x, p.y);
      if (polygon.size() > 0 && *(polygon.vertices_end() - 1) == q) continue;
      polygon.push_back(q);
    }
    if (polygon.size() > 1 &&
        *polygon.vertices_begin() == *(polygon.vertices_end() - 1)) {
      polygon.erase(polygon.vertices_end() - 1);
    }
    if (polygon.size() < 3 || !polygon.is_simple()) return std::nullopt;
    if (polygon.orientation() == CGAL::COLLINEAR) continue;
    if (polygon.is_clockwise_oriented()) polygon.reverse_orientation();
    united.join(polygon);
  }
  std::vector<ExactRegion> exact;
  united.polygons_with_holes(std::back_inserter(exact));
  std::vector<PlanarRegion> regions;
  for (const ExactRegion& e : exact) {
    std::optional<PlanarRegion> region = triangulated(e);
    if (!region) return std::nullopt;
    regions.push_back(std::move(*region));
  }
  return regions;
}

}  // namespace lsolid
