// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "shells.hpp"

#include <algorithm>
#include <glm/geometric.hpp>

#include "union_find.hpp"

namespace lsolid {

VertexStars vertex_stars(const TriangleMesh& mesh) {
  std::uint32_t vertices = 0;
  for (const auto& t : mesh.triangles) {
    vertices = std::max({vertices, t[0] + 1, t[1] + 1, t[2] + 1});
  }
  VertexStars out;
  out.first.assign(std::size_t{vertices} + 1, 0);
  for (const auto& t : mesh.triangles) {
    for (const std::uint32_t v : t) ++out.first[v + 1];
  }
  for (std::size_t v = 0; v < vertices; ++v) out.first[v + 1] += out.first[v];
  out.triangles.resize(out.first.back());
  std::vector<std::uint32_t> next(out.first.begin(), out.first.end() - 1);
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    for (const std::uint32_t v : mesh.triangles[f])
      out.triangles[next[v]++] = f;
  }
  return out;
}

ShellLabels label_shells(const TriangleMesh& mesh) {
  const std::size_t n = mesh.triangles.size();
  // A triangle is joined to the later ones round its side's first vertex
  // that also hold the side's second (each pair once: sharing a side is
  // symmetric). A hash map from each edge to its first triangle was most of
  // fill_cavities, which the build runs twice on the union (blog tree B:
  // 1.7 million triangles, 5 million edges).
  const VertexStars stars = vertex_stars(mesh);
  UnionFind shells(n);
  for (std::uint32_t f = 0; f < n; ++f) {
    const auto& t = mesh.triangles[f];
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = t[k];
      const std::uint32_t b = t[(k + 1) % 3];
      for (std::uint32_t e = stars.first[a]; e < stars.first[a + 1]; ++e) {
        const std::uint32_t g = stars.triangles[e];
        if (g <= f) continue;
        const auto& u = mesh.triangles[g];
        // Two distinct vertices of a triangle are an edge of it; a side
        // from a vertex to itself (a degenerate triangle) is one only of a
        // triangle with that vertex twice.
        const bool shares = a != b
                                ? u[0] == b || u[1] == b || u[2] == b
                                : (u[0] == a) + (u[1] == a) + (u[2] == a) >= 2;
        if (shares) shells.join(f, g);
      }
    }
  }
  ShellLabels out;
  out.of_triangle.resize(n);
  constexpr std::uint32_t kNone = ~std::uint32_t{0};
  std::vector<std::uint32_t> label_of_root(n, kNone);
  for (std::uint32_t f = 0; f < n; ++f) {
    std::uint32_t& label = label_of_root[shells.find(f)];
    if (label == kNone) label = static_cast<std::uint32_t>(out.count++);
    out.of_triangle[f] = label;
  }
  return out;
}

std::vector<double> shell_volumes(const TriangleMesh& mesh,
                                  const ShellLabels& shells) {
  std::vector<double> volume(shells.count, 0.0);
  std::vector<bool> started(shells.count, false);
  std::vector<glm::dvec3> origin(shells.count);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const std::uint32_t s = shells.of_triangle[f];
    const auto& t = mesh.triangles[f];
    const glm::dvec3& a = mesh.vertices[t[0]];
    const glm::dvec3& b = mesh.vertices[t[1]];
    const glm::dvec3& c = mesh.vertices[t[2]];
    if (!started[s]) {
      started[s] = true;
      origin[s] = a;
    }
    const glm::dvec3& o = origin[s];
    volume[s] += glm::dot(a - o, glm::cross(b - o, c - o)) / 6.0;
  }
  return volume;
}

}  // namespace lsolid
