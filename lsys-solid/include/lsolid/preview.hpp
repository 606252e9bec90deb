// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <vector>

#include "lsolid/mesh.hpp"

namespace lsolid {

/// An 8-bit RGB picture, rows from the top.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  ///< width × height × 3 bytes

  /// The colour at column x, row y (from the top).
  [[nodiscard]] glm::ivec3 at(int x, int y) const;
};

/// How to draw a preview.
struct PreviewOptions {
  int width_px = 960;
  int height_px = 720;
  /// The view: from this compass direction around the vertical (Z), and
  /// this far above the horizon: a three-quarter view.
  double azimuth_deg = -60.0;
  double elevation_deg = 25.0;
  glm::dvec3 color{0.80, 0.52, 0.26};  ///< the model's, 0–1
  /// One colour per triangle (0–1), drawn instead of `color`; empty: none.
  std::vector<glm::dvec3> triangle_colors;
  glm::dvec3 background{0.95, 0.95, 0.95};  ///< plain, 0–1
  int supersampling = 2;  ///< drawn this many times larger, then averaged
};

/// Renders the mesh shaded (two lights, flat shading) in orthographic
/// projection, fitted to the picture with a margin, with offscreen OpenGL
/// (Mesa's OSMesa, a software renderer: no display or GPU needed).
/// @pre `options.triangle_colors` is empty or has one entry per triangle.
/// @throws IoError if no OpenGL context can be made.
[[nodiscard]] Image render_preview(const TriangleMesh& mesh,
                                   const PreviewOptions& options = {});

/// Writes the picture as PNG (libpng), through a temporary file that is
/// renamed into place.
/// @throws IoError.
void write_png(const Image& image, const std::filesystem::path& path);

}  // namespace lsolid
