// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/units.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "lsys/diagnostic.hpp"

namespace lsolid {

double parse_length_mm(std::string_view text, const std::string& what) {
  const lsys::SourceFile source(what, std::string(text));
  std::size_t begin = 0;
  while (begin < text.size() && text[begin] == ' ') ++begin;
  double value = 0.0;
  const auto [end, ec] =
      std::from_chars(text.data() + begin, text.data() + text.size(), value);
  if (ec != std::errc()) {
    throw lsys::error_at(source, begin, "expected a length such as 0.8mm");
  }
  auto unit_at = static_cast<std::size_t>(end - text.data());
  while (unit_at < text.size() && text[unit_at] == ' ') ++unit_at;
  std::string_view unit = text.substr(unit_at);
  while (!unit.empty() && unit.back() == ' ') unit.remove_suffix(1);
  static constexpr std::array<std::pair<std::string_view, double>, 4> kUnits{
      {{"", 1.0}, {"mm", 1.0}, {"cm", 10.0}, {"in", 25.4}}};
  for (const auto& [name, factor] : kUnits) {
    if (unit != name) continue;
    if (!(value > 0.0) || !std::isfinite(value)) {
      throw lsys::error_at(source, begin,
                           "a length must be a positive, finite number");
    }
    // No printer is a kilometre wide; `1e308in` would not even be finite.
    constexpr double kMostMm = 1e6;
    if (value * factor > kMostMm) {
      throw lsys::error_at(source, begin,
                           "a length must be at most 1000000 mm (1 km)");
    }
    return value * factor;
  }
  throw lsys::error_at(
      source, unit_at,
      "unknown unit '" + std::string(unit) + "': use mm, cm or in");
}

glm::dvec3 parse_bed_mm(std::string_view text, const std::string& what) {
  // Three lengths joined by `x`; a unit on the last one applies to those
  // without their own (`220x220x250mm`, `22cmx22cmx25cm`).
  std::vector<std::string> sides(1);
  for (const char c : text) {
    if (c == 'x' || c == 'X') {
      sides.emplace_back();
    } else {
      sides.back() += c;
    }
  }
  if (sides.size() != 3) {
    throw lsys::ParseError(lsys::Diagnostic{
        .file = what,
        .line = 1,
        .column = 1,
        .message = "a bed is WIDTHxDEPTHxHEIGHT, such as 220x220x250mm",
        .source_line = std::string(text)});
  }
  std::size_t unit_at = sides[2].size();
  while (unit_at > 0 &&
         std::isalpha(static_cast<unsigned char>(sides[2][unit_at - 1])) != 0) {
    --unit_at;
  }
  const std::string unit = sides[2].substr(unit_at);
  glm::dvec3 out(0.0);
  for (int i = 0; i < 3; ++i) {
    std::string side = sides[static_cast<std::size_t>(i)];
    if (side.empty() ||
        std::isalpha(static_cast<unsigned char>(side.back())) == 0) {
      side += unit;
    }
    out[i] = parse_length_mm(side, what);
  }
  return out;
}

}  // namespace lsolid
