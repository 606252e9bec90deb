// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Fuzzes the exact union engine against the corefinement, its oracle: the
// bytes choose up to four boxes and prisms on a coarse grid, so that parts
// touch, share faces, repeat and nest far more often than a tree's parts
// do. Both engines must agree: both fail, or both give a closed 2-manifold
// of the same shells and the same volume.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "lsolid/boolean.hpp"
#include "lsolid/errors.hpp"
#include "lsolid/mesh.hpp"
#include "lsolid/validate.hpp"

namespace {

using lsolid::TriangleMesh;

TriangleMesh box(const glm::dvec3& lo, const glm::dvec3& hi) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) {
    m.vertices.emplace_back((i & 1) != 0 ? hi.x : lo.x,
                            (i & 2) != 0 ? hi.y : lo.y,
                            (i & 4) != 0 ? hi.z : lo.z);
  }
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},
                 {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},
                 {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

// A prism of `sides` around the z axis through `centre`, from z0 to z1.
TriangleMesh prism(const glm::dvec3& centre, double radius, double z0,
                   double z1, int sides) {
  TriangleMesh m;
  for (const double z : {z0, z1}) {
    for (int i = 0; i < sides; ++i) {
      const double t = 2 * std::numbers::pi * i / sides;
      m.vertices.emplace_back(centre.x + radius * std::cos(t),
                              centre.y + radius * std::sin(t), z);
    }
  }
  m.vertices.emplace_back(centre.x, centre.y, z0);
  m.vertices.emplace_back(centre.x, centre.y, z1);
  const auto n = static_cast<std::uint32_t>(sides);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    m.triangles.push_back({i, j, n + i});
    m.triangles.push_back({j, n + j, n + i});
    m.triangles.push_back({2 * n, j, i});
    m.triangles.push_back({2 * n + 1, n + i, n + j});
  }
  return m;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data,
                                      std::size_t size) {
  std::vector<lsolid::Part> parts;
  // Seven bytes a part: its kind, a corner and a size on a grid of 0.5.
  for (std::size_t at = 0; at + 7 <= size && parts.size() < 4; at += 7) {
    const auto grid = [&](std::size_t k) { return (data[at + k] % 8) * 0.5; };
    const glm::dvec3 lo(grid(1), grid(2), grid(3));
    const glm::dvec3 extent(grid(4) + 0.5, grid(5) + 0.5, grid(6) + 0.5);
    std::string label = "part ";
    label += std::to_string(parts.size());
    if (data[at] % 2 == 0) {
      parts.push_back({box(lo, lo + extent), label});
    } else {
      parts.push_back(
          {prism(lo, extent.x, lo.z, lo.z + extent.z, 3 + data[at] % 9),
           label});
    }
  }
  if (parts.size() < 2) return 0;
  lsolid::UnionResult exact;
  lsolid::UnionResult oracle;
  bool exact_failed = false;
  bool oracle_failed = false;
  try {
    exact = lsolid::union_parts(
        parts, {.engine = lsolid::UnionEngine::ExactCrossings});
  } catch (const lsolid::GeometryError&) {
    exact_failed = true;
  }
  try {
    oracle = lsolid::union_parts(parts,
                                 {.engine = lsolid::UnionEngine::Corefinement});
  } catch (const lsolid::GeometryError&) {
    oracle_failed = true;
  }
  if (exact_failed != oracle_failed) std::abort();
  if (exact_failed) return 0;
  const lsolid::ValidationReport a = lsolid::validate(exact.mesh);
  const lsolid::ValidationReport b = lsolid::validate(oracle.mesh);
  if (a.boundary_edges != 0 || a.non_manifold_edges != 0) std::abort();
  if (a.shells != b.shells) std::abort();
  const double va = lsolid::signed_volume(exact.mesh);
  const double vb = lsolid::signed_volume(oracle.mesh);
  if (std::fabs(va - vb) > 1e-6 * std::fabs(vb) + 1e-9) std::abort();
  return 0;
}
