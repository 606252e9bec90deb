// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <vector>

#include "lsolid/colors.hpp"
#include "lsolid/mesh.hpp"

namespace lsolid {

/// File formats lsolid reads or writes.
enum class MeshFormat {
  StlBinary,
  StlAscii,
  Off,
  Scad,     ///< an OpenSCAD module around one polyhedron(); written only
  ThreeMf,  ///< 3MF, unit millimetre, colours as base materials (lib3mf)
  Obj,      ///< Wavefront OBJ with an MTL file of the colours beside it
};

/// The format a path's extension names (`.stl` binary, `.off`, `.scad`,
/// `.3mf`, `.obj`); `ascii` picks ASCII STL.
/// @throws IoError for any other extension.
[[nodiscard]] MeshFormat format_for(const std::filesystem::path& path,
                                    bool ascii = false);

/// Reads an STL (binary or ASCII, told apart by content), OFF, 3MF or OBJ
/// file; the meshes of a 3MF or the objects of an OBJ become one mesh. STL
/// vertices with equal coordinates are merged.
/// @throws IoError when the file cannot be read (missing, not a regular
///   file); lsys::ParseError when it is malformed, at its line and column
///   in a text format (ASCII STL, OFF, OBJ).
[[nodiscard]] TriangleMesh read_mesh(const std::filesystem::path& path);

/// Reads a file's volumes and colours: a 3MF's mesh objects with the
/// colour index of each triangle from materials named "colour N" (as
/// lsolid writes them), an OBJ's objects with their `usemtl colour_N`;
/// any other file is one volume of colour 0.
/// @throws IoError and lsys::ParseError as read_mesh.
[[nodiscard]] std::vector<ColoredMesh> read_colored(
    const std::filesystem::path& path);

/// Writes a mesh so that the file is either complete or absent: the data
/// goes to a temporary file in the same folder, which is renamed over `path`
/// only when complete. An existing file is untouched on failure.
/// @throws IoError.
void write_mesh(const TriangleMesh& mesh, const std::filesystem::path& path,
                MeshFormat format);

/// Writes volumes with their colours, as write_mesh does: in 3MF, one
/// object (with one part per volume when there are several) whose
/// triangles carry base materials in palette_color; in OBJ, an object per
/// volume and `usemtl colour_N` groups, with `name.mtl` beside it giving
/// each colour's `Kd` (written first, then the OBJ). Colour indices take
/// their colours from `colors` (see palette_color). STL, OFF and SCAD get
/// all volumes as one mesh, without colour.
/// @throws IoError.
void write_colored(const std::vector<ColoredMesh>& volumes,
                   const std::filesystem::path& path, MeshFormat format,
                   const std::vector<Rgb>& colors = {});

}  // namespace lsolid
