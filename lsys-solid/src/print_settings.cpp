// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/print_settings.hpp"

#include <algorithm>

#include "lsolid/units.hpp"
#include "lsys/diagnostic.hpp"

namespace lsolid {
namespace {

// Reads a file's length, reporting errors at their place in the file.
double file_length(const lsys::Grammar& grammar,
                   const lsys::ExtraSetting& setting) {
  try {
    return parse_length_mm(setting.value, setting.key);
  } catch (const lsys::ParseError& e) {
    throw lsys::error_at(
        *grammar.source,
        setting.offset + static_cast<std::size_t>(e.diagnostic().column - 1),
        e.diagnostic().message);
  }
}

}  // namespace

Base parse_base(const std::string& text, const std::string& what) {
  if (text == "auto") return Base::Auto;
  if (text == "disc") return Base::Disc;
  if (text == "none") return Base::None;
  throw lsys::ParseError(lsys::Diagnostic{
      .file = what,
      .message = "base must be auto, disc or none, not '" + text + "'"});
}

std::vector<std::string> print_setting_names() {
  return {"wall", "height", "size", "scale", "tolerance", "base"};
}

PrintSettings resolve_print_settings(const lsys::Grammar& grammar,
                                     const PrintSettings& command_line,
                                     bool command_line_sets_size,
                                     bool command_line_sets_wall,
                                     bool command_line_sets_tolerance,
                                     bool command_line_sets_base) {
  PrintSettings file;
  int sizes = 0;
  std::size_t second_size = 0;
  std::vector<std::string> seen;
  for (const lsys::ExtraSetting& s : grammar.extra_settings) {
    if (std::find(seen.begin(), seen.end(), s.key) != seen.end()) {
      throw lsys::error_at(*grammar.source, s.offset,
                           "'" + s.key + "' is set twice");
    }
    seen.push_back(s.key);
    if (s.key == "base") {
      try {
        file.base = parse_base(s.value, s.key);
      } catch (const lsys::ParseError& e) {
        throw lsys::error_at(*grammar.source, s.offset, e.diagnostic().message);
      }
      continue;
    }
    const double mm = file_length(grammar, s);
    if (s.key == "wall") file.wall_mm = mm;
    if (s.key == "tolerance") file.tolerance_mm = mm;
    if (s.key == "height" || s.key == "size" || s.key == "scale") {
      if (++sizes == 2) second_size = s.offset;
      if (s.key == "height") file.height_mm = mm;
      if (s.key == "size") file.size_mm = mm;
      if (s.key == "scale") file.scale_mm_per_unit = mm;
    }
  }
  if (sizes > 1 && !command_line_sets_size) {
    throw lsys::error_at(*grammar.source, second_size,
                         "give one of height, size and scale, not several");
  }
  PrintSettings out = file;
  if (command_line_sets_size) {
    out.height_mm = command_line.height_mm;
    out.size_mm = command_line.size_mm;
    out.scale_mm_per_unit = command_line.scale_mm_per_unit;
  }
  if (command_line_sets_wall) out.wall_mm = command_line.wall_mm;
  if (command_line_sets_tolerance) out.tolerance_mm = command_line.tolerance_mm;
  if (command_line_sets_base) out.base = command_line.base;
  return out;
}

}  // namespace lsolid
