// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "lsolid/colors.hpp"
#include "lsolid/mesh.hpp"

namespace lsolid {

/// Each format's decoder and encoder, one file each; mesh_io.cpp chooses
/// between them. Decoders throw lsys::ParseError for malformed content
/// (at its line and column in a text format), encoders return the file's
/// bytes.

/// Binary STL (stl.cpp). Vertices with equal float coordinates are merged.
/// @pre `data` holds 84 + 50 n bytes for the n triangles it counts.
[[nodiscard]] TriangleMesh decode_binary_stl(const std::string& data,
                                             const std::filesystem::path& path);
/// ASCII STL (stl.cpp), refused at the first word its grammar does not
/// allow.
[[nodiscard]] TriangleMesh decode_ascii_stl(const std::string& data,
                                            const std::filesystem::path& path);
/// Binary STL with facet normals as admesh recomputes them (stl.cpp).
[[nodiscard]] std::string encode_binary_stl(const TriangleMesh& mesh);
/// ASCII STL, floats to 9 digits (stl.cpp).
[[nodiscard]] std::string encode_ascii_stl(const TriangleMesh& mesh);

/// OFF, faces of any corner count fanned into triangles (off.cpp).
[[nodiscard]] TriangleMesh decode_off(const std::string& data,
                                      const std::filesystem::path& path);
/// OFF at full double precision (off.cpp).
[[nodiscard]] std::string encode_off(const TriangleMesh& mesh);

/// An OpenSCAD module named after the file around one polyhedron()
/// (scad.cpp).
[[nodiscard]] std::string encode_scad(const TriangleMesh& mesh,
                                      const std::filesystem::path& path);

/// Wavefront OBJ: an `o` or `g` starts a volume, `usemtl colour_N` sets the
/// colour of the faces that follow (obj.cpp).
[[nodiscard]] std::vector<ColoredMesh> decode_obj(
    const std::string& data, const std::filesystem::path& path);
/// OBJ of the volumes, naming the material file `mtl` (obj.cpp).
[[nodiscard]] std::string encode_obj(const std::vector<ColoredMesh>& volumes,
                                     const std::filesystem::path& mtl);
/// The MTL file of the colours the volumes use (obj.cpp).
[[nodiscard]] std::string encode_mtl(const std::vector<ColoredMesh>& volumes,
                                     const std::vector<Rgb>& colors);

/// 3MF through lib3mf, with the volumes as parts of one object that
/// PrusaSlicer reads (threemf.cpp).
/// @throws IoError when lib3mf fails.
[[nodiscard]] std::string encode_3mf(const std::vector<ColoredMesh>& volumes,
                                     const std::vector<Rgb>& colors = {});
/// A 3MF's mesh objects and the colours of their triangles (threemf.cpp).
/// @throws IoError when lib3mf cannot read it.
[[nodiscard]] std::vector<ColoredMesh> decode_3mf(
    const std::filesystem::path& path);

}  // namespace lsolid
