// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Reading and writing by format: each format's encoder and decoder is in
// its own file (stl.cpp, off.cpp, obj.cpp, scad.cpp, threemf.cpp), and
// every file is written through a temporary file that is renamed into
// place, so an output is complete or absent.
#include "lsolid/mesh_io.hpp"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "atomic_write.hpp"
#include "formats.hpp"
#include "lsolid/errors.hpp"
#include "text_words.hpp"

namespace lsolid {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path,
                       const std::string& what) {
  throw IoError(path.string() + ": " + what);
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// Only regular files are read: a FIFO would block and a device such as
// /dev/zero never end.
void refuse_special_file(const std::filesystem::path& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!error && std::filesystem::exists(status) &&
      !std::filesystem::is_regular_file(status)) {
    fail(path, "cannot read: not a regular file");
  }
}

std::string read_file(const std::filesystem::path& path) {
  refuse_special_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot read: ") + std::strerror(errno));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

TriangleMesh merged(const std::vector<ColoredMesh>& volumes) {
  TriangleMesh mesh;
  for (const ColoredMesh& v : volumes) append(mesh, v.mesh);
  return mesh;
}

// One mesh in a format without colours.
std::string encode(const TriangleMesh& mesh, MeshFormat format,
                   const std::filesystem::path& path) {
  switch (format) {
    case MeshFormat::StlBinary:
      return encode_binary_stl(mesh);
    case MeshFormat::StlAscii:
      return encode_ascii_stl(mesh);
    case MeshFormat::Off:
      return encode_off(mesh);
    case MeshFormat::Scad:
      return encode_scad(mesh, path);
    case MeshFormat::ThreeMf:
    case MeshFormat::Obj:
      break;  // written by write_colored
  }
  return {};
}

}  // namespace

MeshFormat format_for(const std::filesystem::path& path, bool ascii) {
  const std::string ext = lower_extension(path);
  if (ext == ".stl")
    return ascii ? MeshFormat::StlAscii : MeshFormat::StlBinary;
  if (ext == ".off") return MeshFormat::Off;
  if (ext == ".scad") return MeshFormat::Scad;
  if (ext == ".3mf") return MeshFormat::ThreeMf;
  if (ext == ".obj") return MeshFormat::Obj;
  throw IoError(path.string() + ": unknown output format '" + ext +
                "' (use .stl, .off, .scad, .3mf or .obj)");
}

TriangleMesh read_mesh(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".3mf" || ext == ".obj") return merged(read_colored(path));
  const std::string data = read_file(path);
  if (data.starts_with("OFF") || ext == ".off") return decode_off(data, path);
  std::uint32_t count = 0;
  if (data.size() >= 84) {
    std::memcpy(&count, data.data() + 80, 4);
    if (data.size() == 84 + 50ULL * count) return decode_binary_stl(data, path);
  }
  // Binary STL headers often start with "solid" too, but hold NUL bytes.
  const bool is_text =
      data.substr(0, std::min<std::size_t>(data.size(), 1024)).find('\0') ==
      std::string::npos;
  if (data.starts_with("solid") && is_text) return decode_ascii_stl(data, path);
  if (data.size() >= 84 && !is_text) {
    malformed(path, "a damaged binary STL: its header counts " +
                        std::to_string(count) + " triangles (" +
                        std::to_string(84 + 50ULL * count) +
                        " bytes), the file has " + std::to_string(data.size()) +
                        " bytes");
  }
  malformed(path, "not an STL or OFF file");
}

std::vector<ColoredMesh> read_colored(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".3mf") {
    if (!std::filesystem::exists(path)) fail(path, "cannot read: no such file");
    refuse_special_file(path);
    return decode_3mf(path);
  }
  if (ext == ".obj") return decode_obj(read_file(path), path);
  TriangleMesh mesh = read_mesh(path);
  const std::size_t n = mesh.triangles.size();
  return {
      ColoredMesh{.mesh = std::move(mesh), .colors = std::vector<int>(n, 0)}};
}

void write_mesh(const TriangleMesh& mesh, const std::filesystem::path& path,
                MeshFormat format) {
  if (format == MeshFormat::ThreeMf || format == MeshFormat::Obj) {
    write_colored({ColoredMesh{.mesh = mesh, .colors = {}}}, path, format);
    return;
  }
  write_file_atomically(path, encode(mesh, format, path));
}

void write_colored(const std::vector<ColoredMesh>& volumes,
                   const std::filesystem::path& path, MeshFormat format,
                   const std::vector<Rgb>& colors) {
  switch (format) {
    case MeshFormat::ThreeMf:
      write_file_atomically(path, encode_3mf(volumes, colors));
      return;
    case MeshFormat::Obj: {
      std::filesystem::path mtl = path;
      mtl.replace_extension(".mtl");
      write_file_atomically(mtl, encode_mtl(volumes, colors));
      write_file_atomically(path, encode_obj(volumes, mtl));
      return;
    }
    default:
      write_file_atomically(path, encode(merged(volumes), format, path));
  }
}

}  // namespace lsolid
