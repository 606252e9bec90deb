// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// A flat model's footprint walled into a solid: its rings go into a
// constrained Delaunay triangulation (CGAL's Constrained_Delaunay_
// triangulation_2 on Epick: the rings' points lie on the 2^-20 mm grid
// and no two rings cross, so no point is constructed), whose faces inside
// an odd number of rings cover the footprint exactly (the nesting count of
// CGAL's polygon_triangulation example).
#include "kernel.hpp"

#include "lsolid/footprint.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cstdint>
#include <deque>
#include <unordered_map>

#include "lsolid/errors.hpp"

namespace lsolid {
namespace {

struct FaceInfo {
  int nesting = -1;  // how many rings enclose the face; -1: not yet known
};
using VertexBase =
    CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Inexact>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<
    Inexact, CGAL::Triangulation_face_base_with_info_2<FaceInfo, Inexact>>;
// No_constraint_intersection_requiring_constructions_tag: rings that cross
// are a bug upstream, reported as such, not mended with new points.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<
    Inexact, CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>,
    CGAL::No_constraint_intersection_requiring_constructions_tag>;
using Face = Cdt::Face_handle;

// Faces reached from `start` without crossing a ring get `nesting`; the
// faces across a ring edge are queued in `border` for the next level.
void mark(Cdt& cdt, Face start, int nesting, std::deque<Cdt::Edge>& border) {
  if (start->info().nesting != -1) return;
  std::deque<Face> queue{start};
  while (!queue.empty()) {
    const Face f = queue.front();
    queue.pop_front();
    if (f->info().nesting != -1) continue;
    f->info().nesting = nesting;
    for (int k = 0; k < 3; ++k) {
      const Face n = f->neighbor(k);
      if (n->info().nesting != -1) continue;
      if (cdt.is_constrained(Cdt::Edge(f, k))) {
        border.emplace_back(f, k);
      } else {
        queue.push_back(n);
      }
    }
  }
}

}  // namespace

TriangleMesh extrude(const Footprint& footprint, double height_mm) {
  Cdt cdt;
  std::size_t points = 0;
  for (const std::vector<glm::dvec2>& ring : footprint.rings) {
    std::vector<Inexact::Point_2> polyline;
    polyline.reserve(ring.size());
    for (const glm::dvec2& p : ring) polyline.emplace_back(p.x, p.y);
    points += ring.size();
    try {
      cdt.insert_constraint(polyline.begin(), polyline.end(), true);
    } catch (const std::exception&) {
      throw GeometryError(
          "cannot wall the footprint: two of its rings cross (a bug in "
          "lsolid; please report it with this file)");
    }
  }
  if (cdt.number_of_vertices() != points) {
    throw GeometryError(
        "cannot wall the footprint: two of its rings share a point (a bug in "
        "lsolid; please report it with this file)");
  }
  std::deque<Cdt::Edge> border;
  mark(cdt, cdt.infinite_face(), 0, border);
  while (!border.empty()) {
    const Cdt::Edge e = border.front();
    border.pop_front();
    const Face n = e.first->neighbor(e.second);
    if (n->info().nesting == -1) {
      mark(cdt, n, e.first->info().nesting + 1, border);
    }
  }
  TriangleMesh mesh;
  const auto n = static_cast<std::uint32_t>(cdt.number_of_vertices());
  mesh.vertices.resize(2 * static_cast<std::size_t>(n));
  std::uint32_t index = 0;
  for (const auto v : cdt.finite_vertex_handles()) {
    v->info() = index;
    const glm::dvec2 p(v->point().x(), v->point().y());
    mesh.vertices[index] = glm::dvec3(p, 0.0);
    mesh.vertices[index + n] = glm::dvec3(p, height_mm);
    ++index;
  }
  const auto inside = [&](Face f) {
    return !cdt.is_infinite(f) && f->info().nesting % 2 == 1;
  };
  std::unordered_map<std::uint32_t, std::uint32_t> next;
  std::size_t boundary = 0;
  for (const Face f : cdt.finite_face_handles()) {
    if (!inside(f)) continue;
    const std::uint32_t a = f->vertex(0)->info();
    const std::uint32_t b = f->vertex(1)->info();
    const std::uint32_t c = f->vertex(2)->info();
    mesh.triangles.push_back({a + n, b + n, c + n});
    mesh.triangles.push_back({a, c, b});
    for (int k = 0; k < 3; ++k) {
      if (inside(f->neighbor(k))) continue;
      // The edge from ccw(k) to cw(k) has the face on its left.
      const std::uint32_t from = f->vertex(Cdt::ccw(k))->info();
      const std::uint32_t to = f->vertex(Cdt::cw(k))->info();
      if (!next.emplace(from, to).second) {
        throw GeometryError(
            "cannot wall the footprint: its outline touches itself at a "
            "point (a bug in lsolid; please report it with this file)");
      }
      mesh.triangles.push_back({from, to, to + n});
      mesh.triangles.push_back({from, to + n, from + n});
      ++boundary;
    }
  }
  // Every ring edge, and nothing else, bounds the inside.
  if (boundary != points) {
    throw GeometryError(
        "cannot wall the footprint: its rings do not bound it (a bug in "
        "lsolid; please report it with this file)");
  }
  return mesh;
}

}  // namespace lsolid
