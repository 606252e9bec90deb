// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "parts/balls.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "golden.hpp"
#include "lsolid/parts.hpp"
#include "parts/geometry.hpp"

namespace lsolid {
namespace {

constexpr double kJointMargin = 1.06;  // joint inradius over the largest cap

}  // namespace

TriangleMesh uv_ball(const glm::dvec3& center, double needed, std::size_t index,
                     double tolerance_mm) {
  const int longitudes = std::max(8, tube_sides(needed, tolerance_mm));
  const int latitudes = std::max(4, longitudes / 2);
  const double phase = std::fmod(static_cast<double>(index) * kGolden, 1.0) *
                       2.0 * kPi / longitudes;
  TriangleMesh mesh;
  mesh.vertices.push_back({0.0, 0.0, 1.0});
  for (int lat = 1; lat < latitudes; ++lat) {
    const double polar = kPi * lat / latitudes;
    for (int lon = 0; lon < longitudes; ++lon) {
      const double azimuth = 2.0 * kPi * lon / longitudes + phase;
      mesh.vertices.push_back({std::sin(polar) * std::cos(azimuth),
                               std::sin(polar) * std::sin(azimuth),
                               std::cos(polar)});
    }
  }
  mesh.vertices.push_back({0.0, 0.0, -1.0});
  const auto south = static_cast<std::uint32_t>(mesh.vertices.size() - 1);
  const auto at = [&](int lat, int lon) {
    return static_cast<std::uint32_t>(1 + (lat - 1) * longitudes +
                                      (lon + longitudes) % longitudes);
  };
  for (int lon = 0; lon < longitudes; ++lon) {
    mesh.triangles.push_back({0, at(1, lon), at(1, lon + 1)});
    mesh.triangles.push_back(
        {south, at(latitudes - 1, lon + 1), at(latitudes - 1, lon)});
    for (int lat = 1; lat + 1 < latitudes; ++lat) {
      mesh.triangles.push_back(
          {at(lat, lon), at(lat + 1, lon), at(lat + 1, lon + 1)});
      mesh.triangles.push_back(
          {at(lat, lon), at(lat + 1, lon + 1), at(lat, lon + 1)});
    }
  }
  // Scale so that the nearest face plane is `needed` away.
  double inradius = 1.0;
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 n =
        glm::normalize(glm::cross(mesh.vertices[t[1]] - mesh.vertices[t[0]],
                                  mesh.vertices[t[2]] - mesh.vertices[t[0]]));
    inradius = std::min(inradius, std::fabs(glm::dot(n, mesh.vertices[t[0]])));
  }
  for (glm::dvec3& p : mesh.vertices) p = center + p * (needed / inradius);
  return mesh;
}

TriangleMesh joint_sphere(const glm::dvec3& center, double radius,
                          std::size_t index, double tolerance_mm) {
  return uv_ball(center,
                 tube_corner_radius(radius, tolerance_mm) * kJointMargin, index,
                 tolerance_mm);
}

}  // namespace lsolid
