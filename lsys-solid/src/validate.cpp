// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Topological checks by counting edges; the geometric ones (degenerate
// faces, self-intersections, orientation) are in cgal/exact_checks.cpp.
#include "lsolid/validate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <span>
#include <unordered_map>

#include "cgal/exact_checks.hpp"
#include "shells.hpp"
#include "union_find.hpp"

namespace lsolid {
namespace {

struct EdgeUse {
  std::uint32_t faces = 0;
  std::uint32_t forward = 0;  // uses running from the smaller index
};

// Vertices whose incident triangles do not form one edge-connected fan.
std::size_t count_non_manifold_vertices(const TriangleMesh& mesh) {
  const VertexStars stars = vertex_stars(mesh);
  std::size_t count = 0;
  for (std::uint32_t v = 0; v + 1 < stars.first.size(); ++v) {
    const std::span<const std::uint32_t> faces(
        stars.triangles.data() + stars.first[v],
        stars.first[v + 1] - stars.first[v]);
    if (faces.size() < 2) continue;
    UnionFind fans(faces.size());
    std::unordered_map<std::uint32_t, std::uint32_t> first_by_neighbour;
    for (std::uint32_t i = 0; i < faces.size(); ++i) {
      for (const std::uint32_t w : mesh.triangles[faces[i]]) {
        if (w == v) continue;
        const auto [it, inserted] = first_by_neighbour.emplace(w, i);
        if (!inserted) fans.join(i, it->second);
      }
    }
    const std::uint32_t root = fans.find(0);
    for (std::uint32_t i = 1; i < faces.size(); ++i) {
      if (fans.find(i) != root) {
        ++count;
        break;
      }
    }
  }
  return count;
}

}  // namespace

ValidationReport validate(const TriangleMesh& mesh) {
  ValidationReport r;
  r.vertices = mesh.vertices.size();
  r.triangles = mesh.triangles.size();
  r.bounds = bounds(mesh);
  r.volume_mm3 = signed_volume(mesh);

  std::unordered_map<std::uint64_t, EdgeUse> edges;
  edges.reserve(mesh.triangles.size() * 2);
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[static_cast<std::size_t>(k)];
      const std::uint32_t b = t[static_cast<std::size_t>((k + 1) % 3)];
      if (a == b) continue;  // a degenerate face, counted below
      EdgeUse& use = edges[edge_key(a, b)];
      ++use.faces;
      if (a < b) ++use.forward;
    }
  }
  for (const auto& [key, use] : edges) {
    if (use.faces == 1) ++r.boundary_edges;
    if (use.faces > 2) ++r.non_manifold_edges;
    if (use.faces == 2 && use.forward != 1) ++r.misoriented_edges;
  }
  r.non_manifold_vertices = count_non_manifold_vertices(mesh);

  const ShellLabels shells = label_shells(mesh);
  const std::vector<double> volumes = shell_volumes(mesh, shells);
  r.shells = shells.count;
  r.shell_list.resize(r.shells);
  for (std::size_t s = 0; s < r.shells; ++s) {
    r.shell_list[s].volume_mm3 = volumes[s];
  }
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    Shell& shell = r.shell_list[shells.of_triangle[f]];
    ++shell.triangles;
    for (const std::uint32_t v : mesh.triangles[f]) {
      shell.bounds.min = glm::min(shell.bounds.min, mesh.vertices[v]);
      shell.bounds.max = glm::max(shell.bounds.max, mesh.vertices[v]);
    }
  }
  std::stable_sort(r.shell_list.begin(), r.shell_list.end(),
                   [](const Shell& x, const Shell& y) {
                     return x.volume_mm3 > y.volume_mm3;
                   });

  const bool is_edge_manifold = r.non_manifold_edges == 0;
  const bool is_closed_manifold = is_edge_manifold && r.boundary_edges == 0 &&
                                  r.non_manifold_vertices == 0 &&
                                  r.misoriented_edges == 0;
  if (is_closed_manifold) {
    // Euler: V - E + F = 2 - 2g for each closed orientable shell.
    const auto used = [&] {
      std::vector<bool> seen(mesh.vertices.size(), false);
      std::size_t n = 0;
      for (const auto& t : mesh.triangles) {
        for (const std::uint32_t v : t) {
          if (!seen[v]) {
            seen[v] = true;
            ++n;
          }
        }
      }
      return n;
    }();
    const auto chi = static_cast<long long>(used) -
                     static_cast<long long>(edges.size()) +
                     static_cast<long long>(mesh.triangles.size());
    r.genus =
        static_cast<int>((2 * static_cast<long long>(r.shells) - chi) / 2);
  }
  const ExactChecks exact =
      exact_checks(mesh, is_edge_manifold, is_closed_manifold);
  r.degenerate_faces = exact.degenerate_faces;
  r.self_intersections_checked = exact.self_intersections_checked;
  r.self_intersecting_pairs = exact.self_intersecting_pairs;
  r.orientation_checked = exact.orientation_checked;
  r.is_outward = exact.is_outward;
  return r;
}

std::size_t ValidationReport::pieces() const noexcept {
  return static_cast<std::size_t>(
      std::count_if(shell_list.begin(), shell_list.end(),
                    [](const Shell& s) { return s.volume_mm3 > 0.0; }));
}

std::vector<std::string> ValidationReport::problems() const {
  std::vector<std::string> out;
  const auto add = [&](std::size_t n, const char* what) {
    if (n > 0) out.push_back(fmt::format("{} {}", n, what));
  };
  if (triangles == 0) out.emplace_back("the mesh is empty");
  add(boundary_edges, "boundary edges (the mesh is not closed)");
  add(non_manifold_edges, "non-manifold edges");
  add(non_manifold_vertices, "non-manifold vertices");
  add(misoriented_edges, "edges whose triangles disagree on orientation");
  add(degenerate_faces, "degenerate faces");
  if (!self_intersections_checked) {
    out.emplace_back("self-intersections not checked (not edge-manifold)");
  }
  add(self_intersecting_pairs, "pairs of self-intersecting triangles");
  if (orientation_checked && !is_outward) {
    out.emplace_back(
        "the surface does not bound a volume with outward normals");
  }
  if (triangles > 0 && volume_mm3 <= 0.0)
    out.emplace_back("the volume is not positive");
  return out;
}

}  // namespace lsolid
