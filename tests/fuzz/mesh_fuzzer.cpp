// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Fuzzes the readers of `lsolid check` (STL, OFF, OBJ, 3MF) and the check
// itself. The first byte chooses the format; the rest is the file. A file
// that cannot be read must end in IoError or lsys::ParseError; a mesh that
// was read must validate without a crash, and what validation says of it
// must hold when it is written and read back.
#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "lsolid/errors.hpp"
#include "lsolid/mesh_io.hpp"
#include "lsolid/validate.hpp"
#include "lsys/diagnostic.hpp"

namespace {

const std::filesystem::path& folder() {
  static const std::filesystem::path path = [] {
    auto p = std::filesystem::temp_directory_path() /
             ("lsolid_mesh_fuzzer_" + std::to_string(::getpid()));
    std::filesystem::create_directories(p);
    return p;
  }();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data,
                                      std::size_t size) {
  if (size < 1 || size > 65536) return 0;
  static constexpr std::array<const char*, 4> kExtensions{".stl", ".off",
                                                          ".obj", ".3mf"};
  const std::filesystem::path file =
      folder() / (std::string("in") + kExtensions[data[0] % 4]);
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1),
              static_cast<std::streamsize>(size - 1));
  }
  std::vector<lsolid::ColoredMesh> volumes;
  try {
    volumes = lsolid::read_colored(file);
  } catch (const lsolid::IoError&) {
    return 0;
  } catch (const lsys::ParseError& e) {
    (void)lsys::format_diagnostic(e.diagnostic());
    return 0;
  }
  for (const lsolid::ColoredMesh& v : volumes) {
    if (v.mesh.triangles.size() > 20'000) return 0;
    for (const auto& t : v.mesh.triangles) {
      for (const std::uint32_t i : t) {
        if (i >= v.mesh.vertices.size()) std::abort();
      }
    }
    const lsolid::ValidationReport report = lsolid::validate(v.mesh);
    if (!report.is_printable()) continue;
    // A printable mesh written as OFF (full precision) reads back printable.
    const std::filesystem::path copy = folder() / "copy.off";
    lsolid::write_mesh(v.mesh, copy, lsolid::MeshFormat::Off);
    const lsolid::ValidationReport again =
        lsolid::validate(lsolid::read_mesh(copy));
    if (!again.is_printable() || again.triangles != report.triangles) {
      std::abort();
    }
  }
  return 0;
}
