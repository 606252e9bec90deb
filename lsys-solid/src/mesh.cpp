// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/mesh.hpp"

#include <algorithm>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <unordered_map>

#include "shells.hpp"
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

Box bounds(const std::vector<Part>& parts) {
  Box box;
  for (const Part& part : parts) {
    const Box b = bounds(part.mesh);
    box.min = glm::min(box.min, b.min);
    box.max = glm::max(box.max, b.max);
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

void remove_unused_vertices(TriangleMesh& mesh) {
  constexpr std::uint32_t kUnused = 0xFFFFFFFFU;
  std::vector<std::uint32_t> remap(mesh.vertices.size(), kUnused);
  std::vector<glm::dvec3> kept;
  for (auto& t : mesh.triangles) {
    for (std::uint32_t& v : t) {
      if (remap[v] == kUnused) {
        remap[v] = static_cast<std::uint32_t>(kept.size());
        kept.push_back(mesh.vertices[v]);
      }
      v = remap[v];
    }
  }
  mesh.vertices = std::move(kept);
}

CavitiesFilled fill_cavities(TriangleMesh mesh) {
  const ShellLabels shells = label_shells(mesh);
  const std::vector<double> volumes = shell_volumes(mesh, shells);
  // A shell without volume (a cavity that rounding flattened) goes too.
  constexpr double kNoVolumeMm3 = 1e-12;
  const auto removed = static_cast<std::size_t>(
      std::count_if(volumes.begin(), volumes.end(),
                    [](double v) { return v < kNoVolumeMm3; }));
  if (removed == 0) return {.mesh = std::move(mesh), .removed = 0};
  std::vector<std::array<std::uint32_t, 3>> kept;
  kept.reserve(mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (volumes[shells.of_triangle[f]] >= kNoVolumeMm3) {
      kept.push_back(mesh.triangles[f]);
    }
  }
  mesh.triangles = std::move(kept);
  remove_unused_vertices(mesh);
  return {.mesh = std::move(mesh), .removed = removed};
}

}  // namespace lsolid
