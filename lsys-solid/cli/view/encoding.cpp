// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "view/encoding.hpp"

#include <bit>
#include <cstdint>
#include <cstring>

namespace lsolid::cli::view {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the page reads little-endian numbers as they are in memory");

void put_u32(std::string& out, std::uint32_t v) {
  char bytes[4];
  std::memcpy(bytes, &v, 4);
  out.append(bytes, 4);
}

void put_f32(std::string& out, double v) {
  const auto f = static_cast<float>(v);
  char bytes[4];
  std::memcpy(bytes, &f, 4);
  out.append(bytes, 4);
}

void put_point(std::string& out, const glm::dvec3& p) {
  put_f32(out, p.x);
  put_f32(out, p.y);
  put_f32(out, p.z);
}

std::uint32_t color_of(int color) {
  return static_cast<std::uint32_t>(color < 0 ? 0 : color);
}

}  // namespace

std::string encode_skeleton(const lsys::Skeleton& skeleton) {
  std::string out = "LSK1";
  put_u32(out, static_cast<std::uint32_t>(skeleton.segments.size()));
  put_u32(out, static_cast<std::uint32_t>(skeleton.polygons.size()));
  out.reserve(out.size() + skeleton.segments.size() * 36);
  for (const lsys::Segment& s : skeleton.segments) {
    put_point(out, s.p0);
    put_point(out, s.p1);
    put_f32(out, s.start_diameter / 2.0);
    put_f32(out, s.end_diameter / 2.0);
    put_u32(out, color_of(s.color));
  }
  for (const lsys::Polygon& polygon : skeleton.polygons) {
    put_u32(out, static_cast<std::uint32_t>(polygon.points.size()));
    put_u32(out, color_of(polygon.color));
    for (const glm::dvec3& p : polygon.points) put_point(out, p);
  }
  return out;
}

std::string encode_mesh(const TriangleMesh& mesh,
                        const std::vector<int>& colors,
                        const std::vector<bool>& overhang) {
  std::string out = "LSM1";
  put_u32(out, static_cast<std::uint32_t>(mesh.vertices.size()));
  put_u32(out, static_cast<std::uint32_t>(mesh.triangles.size()));
  out.reserve(out.size() + mesh.vertices.size() * 12 +
              mesh.triangles.size() * 20);
  for (const glm::dvec3& p : mesh.vertices) put_point(out, p);
  for (const auto& t : mesh.triangles) {
    for (const std::uint32_t v : t) put_u32(out, v);
  }
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    put_u32(out, colors.empty() ? 0 : color_of(colors[i]));
  }
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    put_u32(out, !overhang.empty() && overhang[i] ? 1 : 0);
  }
  return out;
}

}  // namespace lsolid::cli::view
