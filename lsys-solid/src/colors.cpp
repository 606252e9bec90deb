// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/colors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>

#include "surface_distance.hpp"

namespace lsolid {
namespace {

// Filament-like colours for plants: bark, three greens for stems and
// leaves, then flower colours. ABOP's figures use colour maps of this kind
// (stem brown, leaves green, petals bright); cpfg reads them from a
// colourmap file, which lsolid does not.
constexpr std::array<Rgb, 10> kPalette{{{0x7B, 0x4A, 0x2A},
                                        {0x2E, 0x6B, 0x2E},
                                        {0x4C, 0x9A, 0x2A},
                                        {0x8C, 0xC6, 0x3F},
                                        {0xF2, 0xC0, 0x14},
                                        {0xE8, 0x73, 0x1A},
                                        {0xC8, 0x20, 0x2F},
                                        {0x7A, 0x3E, 0x9D},
                                        {0xF2, 0xF2, 0xF2},
                                        {0x2A, 0x5C, 0xAA}}};

}  // namespace

Rgb palette_color(int index, const std::vector<Rgb>& colors) {
  const auto i = static_cast<std::size_t>(std::max(index, 0));
  if (!colors.empty()) return colors[std::min(i, colors.size() - 1)];
  return kPalette[i % kPalette.size()];
}

int material_index(int index, const std::vector<Rgb>& colors) {
  // Every colour there is appears among the first `period` indices.
  const int period =
      static_cast<int>(colors.empty() ? kPalette.size() : colors.size());
  const Rgb color = palette_color(index, colors);
  for (int i = 0; i < period; ++i) {
    if (palette_color(i, colors) == color) return i;
  }
  return 0;
}

std::string hex(Rgb color) {
  return fmt::format("#{:02X}{:02X}{:02X}", color.r, color.g, color.b);
}

std::vector<int> color_triangles(const TriangleMesh& mesh,
                                 const std::vector<Part>& parts) {
  std::vector<int> colors(mesh.triangles.size(), 0);
  std::map<int, TriangleMesh> surfaces;
  for (const Part& part : parts) append(surfaces[part.color], part.mesh);
  if (surfaces.size() <= 1) {
    if (!surfaces.empty())
      colors.assign(colors.size(), surfaces.begin()->first);
    return colors;
  }
  std::vector<std::pair<int, SurfaceDistance>> index;
  index.reserve(surfaces.size());
  for (const auto& [color, surface] : surfaces) {
    index.emplace_back(color, SurfaceDistance(surface));
  }
  // Far enough for any part's surface near a triangle of the union: the
  // decimation tolerance is a fraction of a millimetre.
  constexpr double kLimitMm = 10.0;
  // The colour nearest each triangle, ties to the lower colour. The colour
  // of the triangle before is asked first (neighbours mostly share one),
  // the others only as far as the nearest found yet: a surface asked for
  // the whole 10 mm searches a cube of thousands of cells when it is not
  // near, which made this lookup take most of a coloured build's time.
  std::size_t hint = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const glm::dvec3 centre = (mesh.vertices[tri[0]] + mesh.vertices[tri[1]] +
                               mesh.vertices[tri[2]]) /
                              3.0;
    std::size_t chosen = hint;
    double best = index[hint].second.distance(centre, kLimitMm);
    for (std::size_t k = 0; k < index.size(); ++k) {
      if (k == hint) continue;
      // Past the best, so that a tie is told from a farther surface, by
      // enough that its square is too (the search compares squares).
      const double limit = std::min(kLimitMm, best + 1e-6);
      const double d = index[k].second.distance(centre, limit);
      if (d < best || (d == best && k < chosen)) {
        best = d;
        chosen = k;
      }
    }
    colors[t] = index[chosen].first;
    hint = chosen;
  }
  return colors;
}

}  // namespace lsolid
