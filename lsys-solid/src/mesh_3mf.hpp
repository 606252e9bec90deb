// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "lsolid/colors.hpp"

namespace lsolid {

/// A 3MF package (unit millimetre) of the volumes: one object of type model,
/// a mesh if there is one volume, else a components object with a mesh per
/// volume (PrusaSlicer reads those as the parts of one object). Triangles
/// carry base materials named "colour N" in palette_color(N, colors).
/// @throws IoError if lib3mf fails.
[[nodiscard]] std::string encode_3mf(const std::vector<ColoredMesh>& volumes,
                                     const std::vector<Rgb>& colors = {});

/// The mesh objects of a 3MF file in millimetres, with the colour index of
/// each triangle read from base materials named "colour N" (0 otherwise).
/// @throws IoError if lib3mf cannot read it.
[[nodiscard]] std::vector<ColoredMesh> decode_3mf(
    const std::filesystem::path& path);

}  // namespace lsolid
