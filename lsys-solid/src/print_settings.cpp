// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/print_settings.hpp"

#include <algorithm>
#include <charconv>

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

// The error for a word that is none of a setting's choices.
lsys::ParseError not_a_choice(const std::string& text, const std::string& what,
                              const std::string& must_be) {
  return lsys::ParseError(
      lsys::Diagnostic{.file = what,
                       .line = 1,
                       .column = 1,
                       .message = must_be + ", not '" + text + "'",
                       .source_line = text});
}

}  // namespace

Base parse_base(const std::string& text, const std::string& what) {
  if (text == "auto") return Base::Auto;
  if (text == "disc") return Base::Disc;
  if (text == "none") return Base::None;
  throw not_a_choice(text, what, "base must be auto, disc or none");
}

Profile parse_profile(const std::string& text, const std::string& what) {
  if (text == "flat") return Profile::Flat;
  if (text == "round") return Profile::Round;
  throw not_a_choice(text, what, "profile must be flat or round");
}

std::vector<Rgb> parse_colors(const std::string& text,
                              const std::string& what) {
  std::vector<Rgb> colors;
  std::size_t at = 0;
  while (at < text.size()) {
    if (text[at] == ' ' || text[at] == ',' || text[at] == '\t') {
      ++at;
      continue;
    }
    std::size_t end = at;
    while (end < text.size() && text[end] != ' ' && text[end] != ',' &&
           text[end] != '\t') {
      ++end;
    }
    const std::string word = text.substr(at, end - at);
    unsigned value = 0;
    const bool hex_digits =
        word.size() == 7 && word[0] == '#' &&
        std::from_chars(word.data() + 1, word.data() + 7, value, 16).ptr ==
            word.data() + 7;
    if (!hex_digits) {
      throw lsys::ParseError(
          lsys::Diagnostic{.file = what,
                           .line = 1,
                           .column = static_cast<int>(at) + 1,
                           .message = "a colour is #RRGGBB, not '" + word + "'",
                           .source_line = text});
    }
    colors.push_back(Rgb{static_cast<std::uint8_t>(value >> 16),
                         static_cast<std::uint8_t>((value >> 8) & 0xFF),
                         static_cast<std::uint8_t>(value & 0xFF)});
    at = end;
  }
  if (colors.empty()) {
    throw lsys::ParseError(lsys::Diagnostic{
        .file = what, .message = "no colour given: list #RRGGBB colours"});
  }
  return colors;
}

std::vector<std::string> print_setting_names() {
  return {"wall",      "height", "size",   "scale",
          "tolerance", "base",   "colors", "profile"};
}

PrintSettings resolve_print_settings(const lsys::Grammar& grammar,
                                     const PrintOverrides& command_line) {
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
    if (s.key == "base" || s.key == "profile") {
      try {
        if (s.key == "base") file.base = parse_base(s.value, s.key);
        if (s.key == "profile") file.profile = parse_profile(s.value, s.key);
      } catch (const lsys::ParseError& e) {
        throw lsys::error_at(*grammar.source, s.offset, e.diagnostic().message);
      }
      continue;
    }
    if (s.key == "colors") {
      try {
        file.colors = parse_colors(s.value, s.key);
      } catch (const lsys::ParseError& e) {
        throw lsys::error_at(*grammar.source,
                             s.offset + static_cast<std::size_t>(std::max(
                                            0, e.diagnostic().column - 1)),
                             e.diagnostic().message);
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
  const bool sets_size = command_line.height_mm || command_line.size_mm ||
                         command_line.scale_mm_per_unit;
  if (sizes > 1 && !sets_size) {
    throw lsys::error_at(*grammar.source, second_size,
                         "give one of height, size and scale, not several");
  }
  PrintSettings out = file;
  if (sets_size) {
    out.height_mm = command_line.height_mm;
    out.size_mm = command_line.size_mm;
    out.scale_mm_per_unit = command_line.scale_mm_per_unit;
  }
  out.wall_mm = command_line.wall_mm.value_or(out.wall_mm);
  out.tolerance_mm = command_line.tolerance_mm.value_or(out.tolerance_mm);
  out.base = command_line.base.value_or(out.base);
  out.profile = command_line.profile.value_or(out.profile);
  if (command_line.colors) out.colors = *command_line.colors;
  return out;
}

}  // namespace lsolid
