// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Each writer keeps a coordinate its own way: binary STL as float32, lib3mf
// 1.8 as text of six decimals (read by slicers as floats, by other tools
// as doubles), a `.scad` as the text we write, which OpenSCAD reads as
// doubles and exports again as STL of six significant digits. A mesh that
// is valid at one precision may intersect itself at another (the
// monopodial tree's 3MF read as doubles; ABOP fig. 1.26's `.scad` through
// OpenSCAD): so each output is snapped to the values every reader of its
// format gets alike, before the last check.
#include "lsolid/precision.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <unordered_map>

#include "lsolid/rounding.hpp"
#include "lsolid/validate.hpp"
#include "vertex_key.hpp"

namespace lsolid {
namespace {

// The text lib3mf 1.8 writes for a coordinate, read as a double: it is
// given a float, multiplies it by 10⁶ in float arithmetic and prints the
// product truncated toward zero as an integer of millionths (measured on
// 90,000 coordinates; printf's %f would round instead).
double six_decimals(double x) {
  const float f = to_float(x);
  const float millionths = to_float(static_cast<double>(f) * 1e6);
  return std::trunc(static_cast<double>(millionths)) / 1e6;
}

// The step of six significant digits at the reach: multiples of 10^-k stay
// exact while
// the reach is below 10^(6-k).
double decimal_step(double reach_mm) {
  const int digits_before_point =
      static_cast<int>(std::floor(std::log10(std::max(reach_mm, 1.0)))) + 1;
  return std::pow(10.0, digits_before_point - 6);
}

}  // namespace

double Precision::snap(double x) const {
  switch (kind) {
    case Kind::Double:
      return x;
    case Kind::Float:
      return to_float(x);
    case Kind::SixDecimals: {
      // The nearest value that lib3mf writes again when fed its own float.
      // Its float product keeps 24 bits of the millionths (steps of 8 at
      // 100 mm), so such values lie a few millionths apart.
      const double nearest = std::nearbyint(x * 1e6);
      double best = 0.0;
      bool found = false;
      for (int k = 0; k <= 64 && !found; ++k) {
        for (const double n : {nearest - k, nearest + k}) {
          const double candidate = n / 1e6;
          if (six_decimals(candidate) == candidate &&
              (!found || std::fabs(candidate - x) < std::fabs(best - x))) {
            best = candidate;
            found = true;
          }
        }
      }
      if (found) return best;
      // Beyond a metre: lib3mf's own steps toward zero reach one.
      double value = six_decimals(x);
      for (int i = 0; i < 64 && six_decimals(value) != value; ++i) {
        value = six_decimals(value);
      }
      return value;
    }
    case Kind::DecimalFloat: {
      // Six significant digits, as OpenSCAD's STL export writes them: the
      // step is 10⁻⁴ mm below 100 mm, 10⁻³ mm from there to 1 m.
      char text[32];
      std::snprintf(text, sizeof(text), "%.6g", x);
      return to_float(std::strtod(text, nullptr));
    }
  }
  return x;
}

Precision precision_for(MeshFormat format, double reach) {
  switch (format) {
    case MeshFormat::Off:
    case MeshFormat::Obj:
      return {.kind = Precision::Kind::Double};
    case MeshFormat::StlBinary:
    case MeshFormat::StlAscii:
      return {.kind = Precision::Kind::Float};
    case MeshFormat::ThreeMf:
      return {.kind = Precision::Kind::SixDecimals};
    case MeshFormat::Scad:
      return {.kind = Precision::Kind::DecimalFloat,
              .step_mm = decimal_step(reach)};
  }
  return {};
}

double reach_mm(const TriangleMesh& mesh) {
  double reach = 0.0;
  for (const glm::dvec3& p : mesh.vertices) {
    reach = std::max({reach, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  }
  return reach;
}

namespace {

using PointBits = std::array<std::uint64_t, 3>;

struct PointBitsHash {
  std::size_t operator()(const PointBits& b) const noexcept {
    std::uint64_t h = 0x9E3779B97F4A7C15ULL;
    for (const std::uint64_t v : b) h = (h ^ v) * 0xBF58476D1CE4E5B9ULL;
    return static_cast<std::size_t>(h ^ (h >> 31U));
  }
};

}  // namespace

TriangleMesh snapped(const TriangleMesh& mesh, const Precision& precision) {
  TriangleMesh out;
  std::unordered_map<PointBits, std::uint32_t, PointBitsHash> index;
  std::vector<std::uint32_t> remap(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const glm::dvec3 p = precision.snap(mesh.vertices[i]);
    // -0 and +0 are one vertex.
    const glm::dvec3 q(p.x + 0.0, p.y + 0.0, p.z + 0.0);
    const PointBits key{std::bit_cast<std::uint64_t>(q.x),
                        std::bit_cast<std::uint64_t>(q.y),
                        std::bit_cast<std::uint64_t>(q.z)};
    const auto [it, inserted] =
        index.emplace(key, static_cast<std::uint32_t>(out.vertices.size()));
    if (inserted) out.vertices.push_back(q);
    remap[i] = it->second;
  }
  out.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    out.triangles.push_back({remap[t[0]], remap[t[1]], remap[t[2]]});
  }
  return out;
}

ValidationReport validate_as_read(const TriangleMesh& mesh,
                                  const Precision& precision) {
  ValidationReport report = validate(mesh);
  if (!report.is_printable() || !precision.also_as_floats()) return report;
  ValidationReport as_floats =
      validate(snapped(mesh, {.kind = Precision::Kind::Float}));
  return as_floats.is_printable() ? report : as_floats;
}

Rounded round_for(const TriangleMesh& mesh, MeshFormat format) {
  Rounded rounded = round_and_repair(
      mesh,
      {.precision = precision_for(format, std::max(reach_mm(mesh), 1.0))});
  if (rounded.clean || format != MeshFormat::Scad) return rounded;
  rounded =
      round_and_repair(mesh, {.precision = {.kind = Precision::Kind::Float}});
  rounded.as_floats = true;
  return rounded;
}

std::optional<TriangleMesh> rounded_for(const TriangleMesh& mesh,
                                        MeshFormat format) {
  const Precision precision =
      precision_for(format, std::max(reach_mm(mesh), 1.0));
  TriangleMesh plain = snapped(mesh, precision);
  if (validate_as_read(plain, precision).is_printable()) return plain;
  const Rounded mended = round_for(mesh, format);
  const Precision kept =
      mended.as_floats ? Precision{.kind = Precision::Kind::Float} : precision;
  if (!validate_as_read(mended.mesh, kept).is_printable()) return std::nullopt;
  return mended.mesh;
}

std::optional<ColoredMesh> rounded_for(const ColoredMesh& colored,
                                       MeshFormat format) {
  std::optional<TriangleMesh> mesh = rounded_for(colored.mesh, format);
  if (!mesh) return std::nullopt;
  const auto color_of = [&](std::size_t t) {
    return t < colored.colors.size() ? colored.colors[t] : 0;
  };
  std::vector<int> colors;
  if (mesh->triangles.size() == colored.mesh.triangles.size()) {
    for (std::size_t t = 0; t < mesh->triangles.size(); ++t) {
      colors.push_back(color_of(t));
    }
    return ColoredMesh{.mesh = std::move(*mesh), .colors = std::move(colors)};
  }
  // Mended: each corner, snapped as the mesh was, keeps a colour of a
  // triangle it belonged to.
  const Precision precision =
      precision_for(format, std::max(reach_mm(colored.mesh), 1.0));
  std::unordered_map<PointBits, int, PointBitsHash> corner_color;
  const auto bits = [](const glm::dvec3& p) {
    return PointBits{std::bit_cast<std::uint64_t>(p.x + 0.0),
                     std::bit_cast<std::uint64_t>(p.y + 0.0),
                     std::bit_cast<std::uint64_t>(p.z + 0.0)};
  };
  for (std::size_t t = 0; t < colored.mesh.triangles.size(); ++t) {
    for (const std::uint32_t v : colored.mesh.triangles[t]) {
      corner_color.emplace(bits(precision.snap(colored.mesh.vertices[v])),
                           color_of(t));
    }
  }
  for (const auto& triangle : mesh->triangles) {
    int color = 0;
    for (const std::uint32_t v : triangle) {
      const auto it = corner_color.find(bits(mesh->vertices[v]));
      if (it != corner_color.end()) {
        color = it->second;
        break;
      }
    }
    colors.push_back(color);
  }
  return ColoredMesh{.mesh = std::move(*mesh), .colors = std::move(colors)};
}

}  // namespace lsolid
