// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The union's invariant: every part lies inside the result. A union that
// rounding or repair has emptied in places (seen: leaf plates that met face
// on face vanished, and the model was still "printable") leaves points
// that were deep inside a part outside the result. The points are found by
// ray casting inside each part; the test is CGAL's Side_of_triangle_mesh,
// exact predicates on the result's coordinates (EPICK).
#include "kernel.hpp"

#include "lsolid/containment.hpp"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Side_of_triangle_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <unordered_map>
#include <vector>

#include "cgal/union/ray_parity.hpp"
#include "conversion.hpp"
#include "lsolid/errors.hpp"
#include "shells.hpp"

namespace lsolid {
namespace {

using Primitive = CGAL::AABB_face_graph_triangle_primitive<InexactMesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Inexact, Primitive>>;

constexpr std::size_t kFacesPerWitness = 64;

glm::dvec3 to_glm(const InexactPoint& p) { return {p.x(), p.y(), p.z()}; }

// The faces that span an area. CGAL refuses (as a precondition) to shoot a
// ray at a degenerate triangle, and a part or a decimated union may hold
// a few (parts of the blog's trees at full size); having no area, they
// stop no ray and change no side.
std::vector<InexactMesh::Face_index> faces_with_area(const InexactMesh& mesh) {
  std::vector<InexactMesh::Face_index> out;
  out.reserve(mesh.number_of_faces());
  for (const InexactMesh::Face_index f : mesh.faces()) {
    if (!CGAL::Polygon_mesh_processing::is_degenerate_triangle_face(f, mesh))
      out.push_back(f);
  }
  return out;
}

void add_witnesses(const Part& part, std::size_t index,
                   std::vector<Witness>& out) {
  // The union checks every part before it starts (GeometryError), so a
  // part that is no surface has no witnesses to give.
  const std::optional<InexactMesh> surface =
      to_surface_mesh<InexactMesh>(part.mesh);
  if (!surface || surface->number_of_faces() == 0) return;
  const InexactMesh& mesh = *surface;
  const std::vector<InexactMesh::Face_index> solid_faces =
      faces_with_area(mesh);
  Tree tree(solid_faces.begin(), solid_faces.end(), mesh);
  tree.accelerate_distance_queries();
  std::size_t k = 0;
  for (const InexactMesh::Face_index f : solid_faces) {
    if (k++ % kFacesPerWitness != 0) continue;
    const auto h = mesh.halfedge(f);
    const InexactPoint& a = mesh.point(mesh.source(h));
    const InexactPoint& b = mesh.point(mesh.target(h));
    const InexactPoint& c = mesh.point(mesh.target(mesh.next(h)));
    const Inexact::Vector_3 normal = CGAL::cross_product(b - a, c - a);
    const double length = std::sqrt(normal.squared_length());
    if (!(length > 0.0) || !std::isfinite(length)) continue;
    const InexactPoint centre = CGAL::centroid(a, b, c);
    // A unit direction: the normal of a sliver can be so short that the
    // ray's second point rounds back onto its first (the blog's trees at
    // full size), and CGAL refuses a degenerate ray.
    const Inexact::Ray_3 inward(centre, -normal / length);
    if (inward.is_degenerate()) continue;
    const auto hit = tree.first_intersection(
        inward, [f](const InexactMesh::Face_index g) { return g == f; });
    if (!hit) continue;
    const InexactPoint* exit = boost::get<InexactPoint>(&hit->first);
    if (exit == nullptr) continue;  // along a face: no clear inside
    const InexactPoint middle = CGAL::midpoint(centre, *exit);
    const double depth = std::sqrt(tree.squared_distance(middle));
    if (depth <= 0.0) continue;
    out.push_back(
        Witness{.part = index, .point = to_glm(middle), .depth_mm = depth});
  }
}

}  // namespace

std::vector<Witness> witnesses(const std::vector<Part>& parts) {
  std::vector<Witness> out;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    add_witnesses(parts[i], i, out);
  }
  return out;
}

std::vector<Witness> witnesses_outside(const TriangleMesh& mesh,
                                       const std::vector<Witness>& witnesses,
                                       double min_depth_mm) {
  std::vector<Witness> outside;
  if (witnesses.empty()) return outside;
  // Built first for its refusal of a mesh that is not a 2-manifold; the
  // faces are searched only where all three rays below meet an edge.
  const InexactMesh solid =
      surface_mesh_or_throw<InexactMesh>(mesh, "test points against");
  // Each witness by the parity of the faces that a ray from it along an
  // axis crosses (ray_parity.hpp), all witnesses in one pass over the
  // faces: a few thousand witnesses against a union of hundreds of
  // thousands of faces, where CGAL's Side_of_triangle_mesh first built an
  // AABB tree over all of them (blog tree B: 1.7 million faces). Where the
  // rays along all three axes meet an edge or a vertex, CGAL decides
  // (random rays). Exact both ways; a witness on the surface is not inside.
  std::vector<std::size_t> asked;
  std::vector<glm::dvec3> points;
  for (std::size_t i = 0; i < witnesses.size(); ++i) {
    if (witnesses[i].depth_mm < min_depth_mm) continue;
    asked.push_back(i);
    points.push_back(witnesses[i].point);
  }
  std::vector<std::optional<bool>> inside(asked.size());
  for (const int axis : {2, 0, 1}) {
    std::vector<std::size_t> open;
    std::vector<glm::dvec3> at;
    for (std::size_t k = 0; k < asked.size(); ++k) {
      if (inside[k]) continue;
      open.push_back(k);
      at.push_back(points[k]);
    }
    if (open.empty()) break;
    const std::vector<std::optional<exact_union::RaySide>> sides =
        exact_union::sides_by_ray(mesh, at, axis);
    for (std::size_t j = 0; j < open.size(); ++j) {
      if (sides[j])
        inside[open[j]] = *sides[j] == exact_union::RaySide::kInside;
    }
  }
  std::vector<InexactMesh::Face_index> solid_faces;
  std::optional<Tree> tree;
  for (std::size_t k = 0; k < asked.size(); ++k) {
    if (!inside[k]) {
      if (!tree) {
        solid_faces = faces_with_area(solid);
        tree.emplace(solid_faces.begin(), solid_faces.end(), solid);
      }
      inside[k] =
          !solid_faces.empty() &&
          CGAL::Side_of_triangle_mesh<InexactMesh, Inexact>(*tree)(InexactPoint(
              points[k].x, points[k].y, points[k].z)) == CGAL::ON_BOUNDED_SIDE;
    }
    if (!*inside[k]) outside.push_back(witnesses[asked[k]]);
  }
  return outside;
}

std::vector<Shell> unaccounted_pieces(const TriangleMesh& mesh,
                                      const std::vector<Witness>& witnesses,
                                      double min_depth_mm) {
  const std::size_t n = mesh.triangles.size();
  const ShellLabels shells = label_shells(mesh);
  // One shell holds every witness the union kept (checked apart).
  if (shells.count <= 1) return {};
  // Each shell as a mesh of its own (a vertex of two shells, where they
  // touch at a point, is copied into each).
  constexpr std::uint32_t kNone = 0xFFFFFFFFU;
  std::vector<TriangleMesh> pieces(shells.count);
  std::vector<std::uint32_t> local(mesh.vertices.size(), kNone);
  std::vector<std::size_t> owner(mesh.vertices.size(), 0);
  for (std::uint32_t f = 0; f < n; ++f) {
    const std::uint32_t shell = shells.of_triangle[f];
    TriangleMesh& piece = pieces[shell];
    std::array<std::uint32_t, 3> t{};
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh.triangles[f][k];
      if (local[v] == kNone || owner[v] != shell) {
        local[v] = static_cast<std::uint32_t>(piece.vertices.size());
        owner[v] = shell;
        piece.vertices.push_back(mesh.vertices[v]);
      }
      t[k] = local[v];
    }
    piece.triangles.push_back(t);
  }
  std::vector<Shell> out;
  for (const TriangleMesh& piece : pieces) {
    const double volume = signed_volume(piece);
    if (volume <= 0.0) continue;  // a cavity inside a piece
    const Box box = bounds(piece);
    std::vector<Witness> candidates;
    for (const Witness& w : witnesses) {
      if (w.depth_mm < min_depth_mm) continue;
      const glm::dvec3& p = w.point;
      if (p.x >= box.min.x && p.y >= box.min.y && p.z >= box.min.z &&
          p.x <= box.max.x && p.y <= box.max.y && p.z <= box.max.z) {
        candidates.push_back(w);
      }
    }
    if (witnesses_outside(piece, candidates, min_depth_mm).size() <
        candidates.size()) {
      continue;  // some witness lies inside this piece
    }
    out.push_back(Shell{.triangles = piece.triangles.size(),
                        .volume_mm3 = volume,
                        .bounds = box});
  }
  std::stable_sort(out.begin(), out.end(), [](const Shell& a, const Shell& b) {
    return a.volume_mm3 > b.volume_mm3;
  });
  return out;
}

}  // namespace lsolid
