// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "shells.hpp"

#include <glm/geometric.hpp>
#include <unordered_map>

#include "union_find.hpp"

namespace lsolid {

ShellLabels label_shells(const TriangleMesh& mesh) {
  const std::size_t n = mesh.triangles.size();
  UnionFind shells(n);
  std::unordered_map<std::uint64_t, std::uint32_t> first_face;
  first_face.reserve(n * 2);
  for (std::uint32_t f = 0; f < n; ++f) {
    const auto& t = mesh.triangles[f];
    for (std::size_t k = 0; k < 3; ++k) {
      const auto [it, inserted] =
          first_face.emplace(edge_key(t[k], t[(k + 1) % 3]), f);
      if (!inserted) shells.join(f, it->second);
    }
  }
  ShellLabels out;
  out.of_triangle.resize(n);
  std::unordered_map<std::uint32_t, std::uint32_t> label_of_root;
  for (std::uint32_t f = 0; f < n; ++f) {
    const auto [it, inserted] = label_of_root.emplace(
        shells.find(f), static_cast<std::uint32_t>(label_of_root.size()));
    out.of_triangle[f] = it->second;
  }
  out.count = label_of_root.size();
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
