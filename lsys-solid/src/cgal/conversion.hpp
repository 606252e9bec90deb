// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "lsolid/errors.hpp"
#include "lsolid/mesh.hpp"
#include "triangle_pair.hpp"

namespace lsolid {

/// A mesh as CGAL's polygon soup: points and index triples.
template <typename Point>
struct PolygonSoup {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
};

/// The triangles as a polygon soup, for PMP's soup functions
/// (is_polygon_soup_a_polygon_mesh, polygon_soup_to_polygon_mesh), which
/// take fans completed out of order that add_face refuses.
template <typename Point>
PolygonSoup<Point> polygon_soup(const TriangleMesh& m) {
  PolygonSoup<Point> soup;
  soup.points.reserve(m.vertices.size());
  for (const glm::dvec3& p : m.vertices) {
    soup.points.emplace_back(p.x, p.y, p.z);
  }
  soup.polygons.reserve(m.triangles.size());
  for (const auto& t : m.triangles) {
    soup.polygons.push_back({t[0], t[1], t[2]});
  }
  return soup;
}

/// A CGAL Surface_mesh of the triangles, or nothing if they do not form a
/// 2-manifold with consistent orientation (no triangles: an empty mesh).
/// Faces are added one by one and, if that fails (a decimated mesh lists a
/// vertex's fan out of order, and add_face refuses to complete it), through
/// PMP's polygon soup.
template <typename Mesh>
std::optional<Mesh> to_surface_mesh(const TriangleMesh& m) {
  Mesh out;
  std::vector<typename Mesh::Vertex_index> vertices;
  vertices.reserve(m.vertices.size());
  for (const glm::dvec3& p : m.vertices) {
    vertices.push_back(out.add_vertex(typename Mesh::Point(p.x, p.y, p.z)));
  }
  for (const auto& t : m.triangles) {
    if (out.add_face(vertices[t[0]], vertices[t[1]], vertices[t[2]]) ==
        Mesh::null_face()) {
      auto soup = polygon_soup<typename Mesh::Point>(m);
      if (!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(
              soup.polygons)) {
        return std::nullopt;
      }
      Mesh stitched;
      CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(
          soup.points, soup.polygons, stitched);
      return stitched;
    }
  }
  return out;
}

/// The faces as triangles of the mesh's vertex indices and points, in face
/// order, for intersecting_pairs (the exact test CGAL's self_intersections
/// makes, on the threads).
/// @pre no face or vertex is marked removed (collect_garbage).
template <typename Mesh>
std::vector<IndexedTriangle> indexed_triangles(const Mesh& mesh) {
  CGAL_precondition(!mesh.has_garbage());
  std::vector<IndexedTriangle> out;
  out.reserve(mesh.number_of_faces());
  for (const auto f : mesh.faces()) {
    IndexedTriangle t;
    std::size_t k = 0;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      if (k == 3) break;
      const auto& p = mesh.point(v);
      t.ids[k] = static_cast<std::uint32_t>(v.idx());
      t.points[k] = glm::dvec3(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                               CGAL::to_double(p.z()));
      ++k;
    }
    out.push_back(t);
  }
  return out;
}

/// to_surface_mesh for a mesh that must be a 2-manifold, as `what` (a verb:
/// "round", "unite") needs.
/// @throws GeometryError naming `what` when it is not.
template <typename Mesh>
Mesh surface_mesh_or_throw(const TriangleMesh& m, const char* what) {
  std::optional<Mesh> out = to_surface_mesh<Mesh>(m);
  if (!out) {
    throw GeometryError(std::string("cannot ") + what +
                        " a mesh that is not a 2-manifold");
  }
  return std::move(*out);
}

/// The triangles of a Surface_mesh, with coordinates rounded to doubles.
template <typename Mesh>
TriangleMesh to_triangle_mesh(const Mesh& mesh) {
  TriangleMesh out;
  std::unordered_map<std::uint32_t, std::uint32_t> index;
  for (const auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    index.emplace(static_cast<std::uint32_t>(v),
                  static_cast<std::uint32_t>(out.vertices.size()));
    out.vertices.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                              CGAL::to_double(p.z()));
  }
  for (const auto f : mesh.faces()) {
    std::array<std::uint32_t, 3> t{};
    std::size_t k = 0;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      if (k < 3) t[k] = index.at(static_cast<std::uint32_t>(v));
      ++k;
    }
    if (k == 3) out.triangles.push_back(t);
  }
  return out;
}

/// The same surface with its vertices in lexicographic order of their
/// coordinates (exact comparisons) and its faces in order of their sorted
/// corners: a canonical order, the same whatever order the mesh was built
/// in. CGAL's corefinement orders its output by the addresses of boxes it
/// allocates (ID_FROM_BOX_ADDRESS), so the same union came out in another
/// order, and was then repaired differently, when a longer output file
/// name had shifted the heap (ABOP fig. 1.24a: 7,940 or 7,934 triangles).
/// @pre `mesh` is a triangle mesh without isolated vertices.
template <typename Mesh>
Mesh canonical_order(const Mesh& mesh) {
  using Index = typename Mesh::Vertex_index;
  std::vector<Index> order(mesh.vertices().begin(), mesh.vertices().end());
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) {
    return CGAL::compare_xyz(mesh.point(a), mesh.point(b)) == CGAL::SMALLER;
  });
  std::vector<std::size_t> rank(mesh.number_of_vertices() +
                                mesh.number_of_removed_vertices());
  std::vector<typename Mesh::Point> points;
  points.reserve(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    rank[static_cast<std::size_t>(order[i])] = i;
    points.push_back(mesh.point(order[i]));
  }
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(mesh.number_of_faces());
  for (const auto f : mesh.faces()) {
    std::array<std::size_t, 3> t{};
    std::size_t k = 0;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      if (k < 3) t[k] = rank[static_cast<std::size_t>(v)];
      ++k;
    }
    // The smallest corner first; the orientation stays.
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    faces.push_back(t);
  }
  std::sort(faces.begin(), faces.end());
  // Face by face where Surface_mesh can add them in this order; PMP's
  // soup conversion, which also checks the soup first (a third of this
  // function's time on the bush), only where a vertex's fan comes out of
  // order and add_face refuses to complete it.
  Mesh out;
  out.reserve(static_cast<typename Mesh::size_type>(points.size()),
              static_cast<typename Mesh::size_type>(3 * faces.size() / 2),
              static_cast<typename Mesh::size_type>(faces.size()));
  for (const auto& p : points) out.add_vertex(p);
  bool added = true;
  for (const auto& t : faces) {
    using V = typename Mesh::Vertex_index;
    if (out.add_face(V(static_cast<typename Mesh::size_type>(t[0])),
                     V(static_cast<typename Mesh::size_type>(t[1])),
                     V(static_cast<typename Mesh::size_type>(t[2]))) ==
        Mesh::null_face()) {
      added = false;
      break;
    }
  }
  if (added) return out;
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(faces.size());
  for (const auto& t : faces) polygons.push_back({t[0], t[1], t[2]});
  Mesh soup;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons,
                                                              soup);
  return soup;
}

}  // namespace lsolid
