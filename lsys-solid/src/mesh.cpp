// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/mesh.hpp"

#include <algorithm>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <unordered_map>

#include "vertex_key.hpp"

namespace lsolid {

Box bounds(const TriangleMesh& mesh) {
  Box box;
  for (const auto& t : mesh.triangles) {
    for (const std::uint32_t v : t) {
      box.min = glm::min(box.min, mesh.vertices[v]);
      box.max = glm::max(box.max, mesh.vertices[v]);
    }
  }
  return box;
}

double signed_volume(const TriangleMesh& mesh) {
  double six_volume = 0.0;
  for (const auto& t : mesh.triangles) {
    const glm::dvec3& a = mesh.vertices[t[0]];
    const glm::dvec3& b = mesh.vertices[t[1]];
    const glm::dvec3& c = mesh.vertices[t[2]];
    six_volume += glm::dot(a, glm::cross(b, c));
  }
  return six_volume / 6.0;
}

void append(TriangleMesh& mesh, const TriangleMesh& part) {
  const auto offset = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), part.vertices.begin(),
                       part.vertices.end());
  for (const auto& t : part.triangles) {
    mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
}

TriangleMesh round_to_float(const TriangleMesh& mesh) {
  TriangleMesh out;
  std::unordered_map<FloatKey, std::uint32_t, FloatKeyHash> index;
  std::vector<std::uint32_t> remap(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const FloatKey key = float_key(mesh.vertices[i]);
    const auto [it, inserted] =
        index.emplace(key, static_cast<std::uint32_t>(out.vertices.size()));
    if (inserted) out.vertices.push_back(key_point(key));
    remap[i] = it->second;
  }
  out.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    out.triangles.push_back({remap[t[0]], remap[t[1]], remap[t[2]]});
  }
  return out;
}

}  // namespace lsolid
