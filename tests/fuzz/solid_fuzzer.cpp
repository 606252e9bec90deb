// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Fuzzes the whole solid pipeline on tiny inputs: an .ls text whose model
// has at most a few segments and polygons is built, united, rounded,
// decimated and checked. Bad input must end in lsys::ParseError, a failed
// union in GeometryError; a model the build calls printable must be one
// when checked again on its own, also as an STL file reads it back.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "lsolid/errors.hpp"
#include "lsolid/mesh_io.hpp"
#include "lsolid/print_settings.hpp"
#include "lsolid/solid.hpp"
#include "lsolid/validate.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data,
                                      std::size_t size) {
  if (size > 2048) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  lsolid::Solid solid;
  try {
    const lsys::Grammar grammar = lsys::parse_grammar_text(
        text, {.extra_settings = lsolid::print_setting_names()}, "fuzz.ls");
    lsolid::SolidOptions options;
    options.derivation.derivation_length =
        std::min(grammar.settings.derivation_length, 4);
    options.derivation.max_segments = 12;
    options.derivation.max_modules = 2'000;
    options.derivation.max_memory_bytes = 16U << 20U;
    options.print.size_mm = 30.0;
    if (grammar.settings.derivation_length > 4) return 0;
    solid = lsolid::build_solid(grammar, options);
    if (solid.report.polygons > 6) return 0;
  } catch (const lsys::ParseError& e) {
    (void)lsys::format_diagnostic(e.diagnostic());
    return 0;
  } catch (const lsolid::GeometryError&) {
    return 0;
  }
  if (!solid.report.validation.is_printable()) return 0;
  if (!lsolid::validate(solid.mesh).is_printable()) std::abort();
  static const std::filesystem::path stl =
      std::filesystem::temp_directory_path() /
      ("lsolid_solid_fuzzer_" + std::to_string(::getpid()) + ".stl");
  lsolid::write_mesh(solid.mesh, stl, lsolid::MeshFormat::StlBinary);
  const lsolid::ValidationReport back =
      lsolid::validate(lsolid::read_mesh(stl));
  if (!back.is_printable() || back.triangles != solid.mesh.triangles.size()) {
    std::abort();
  }
  return 0;
}
