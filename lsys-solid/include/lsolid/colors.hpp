// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lsolid/mesh.hpp"

namespace lsolid {

/// An sRGB colour, as 3MF's `displaycolor` and an MTL's `Kd` give it.
struct Rgb {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  bool operator==(const Rgb&) const = default;
};

/// The colour of a turtle colour index (ABOP's `'`, cpfg's `;`): from
/// `colors` if given (an index past its end takes the last), else lsolid's
/// palette: 0 bark brown, 1 dark green, 2 green, 3 leaf green, 4 yellow,
/// 5 orange, 6 red, 7 purple, 8 white, 9 blue, then round again. Negative
/// indices are taken as 0.
[[nodiscard]] Rgb palette_color(int index, const std::vector<Rgb>& colors = {});

/// The material a colour index prints in: the lowest index of the same
/// colour, so that indices given one colour become one material (and with
/// `--multi-material` one volume).
[[nodiscard]] int material_index(int index,
                                 const std::vector<Rgb>& colors = {});

/// `#RRGGBB`.
[[nodiscard]] std::string hex(Rgb color);

/// A mesh and the turtle's colour index of each of its triangles: the
/// whole model, or one volume of one colour for printers with one extruder
/// per colour.
struct ColoredMesh {
  TriangleMesh mesh;
  std::vector<int> colors;  ///< one per triangle; empty means all 0
};

/// The colour of each triangle of `mesh` (the union of `parts`, maybe
/// decimated): that of the part whose surface lies nearest its centre, the
/// lower colour index where two are as near.
/// @pre every part's colour is that of all its triangles
///   (PartOptions::split_colors).
[[nodiscard]] std::vector<int> color_triangles(const TriangleMesh& mesh,
                                               const std::vector<Part>& parts);

}  // namespace lsolid
