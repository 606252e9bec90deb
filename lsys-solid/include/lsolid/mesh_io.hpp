// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>

#include "lsolid/mesh.hpp"

namespace lsolid {

/// File formats lsolid reads or writes.
enum class MeshFormat {
  StlBinary,
  StlAscii,
  Off,
  Scad,  ///< an OpenSCAD module around one polyhedron(); written only
};

/// The format a path's extension names (`.stl` binary, `.off`, `.scad`);
/// `ascii` picks ASCII STL.
/// @throws IoError for any other extension.
[[nodiscard]] MeshFormat format_for(const std::filesystem::path& path,
                                    bool ascii = false);

/// Reads an STL (binary or ASCII, told apart by content) or OFF file. STL
/// vertices with equal coordinates are merged.
/// @throws IoError when the file cannot be read or is malformed.
[[nodiscard]] TriangleMesh read_mesh(const std::filesystem::path& path);

/// Writes a mesh so that the file is either complete or absent: the data
/// goes to a temporary file in the same folder, which is renamed over `path`
/// only when complete. An existing file is untouched on failure.
/// @throws IoError.
void write_mesh(const TriangleMesh& mesh, const std::filesystem::path& path,
                MeshFormat format);

}  // namespace lsolid
