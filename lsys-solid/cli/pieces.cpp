// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "pieces.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <vector>

#include "json.hpp"

namespace lsolid::cli {
namespace {

constexpr std::size_t kShownInText = 3;
constexpr std::size_t kShownInJson = 10;

// The loose pieces: every piece but the largest, largest first.
std::vector<Shell> loose(const ValidationReport& report) {
  std::vector<Shell> out;
  for (const Shell& s : report.shell_list) {
    if (s.volume_mm3 > 0.0) out.push_back(s);
  }
  if (!out.empty()) out.erase(out.begin());
  return out;
}

}  // namespace

std::string describe_pieces(const ValidationReport& report) {
  const std::size_t pieces = report.pieces();
  if (pieces <= 1) return {};
  std::vector<std::string> shown;
  const std::vector<Shell> rest = loose(report);
  for (std::size_t i = 0; i < std::min(rest.size(), kShownInText); ++i) {
    const glm::dvec3 c = (rest[i].bounds.min + rest[i].bounds.max) / 2.0;
    shown.push_back(fmt::format("{:.3g} mm³ around ({:.1f}, {:.1f}, {:.1f}) mm",
                                rest[i].volume_mm3, c.x, c.y, c.z));
  }
  return fmt::format(
      "{} separate pieces, which print as loose parts: the largest {:.1f} "
      "mm³; loose: {}{}",
      pieces, report.shell_list.front().volume_mm3, fmt::join(shown, ", "),
      rest.size() > kShownInText
          ? fmt::format(" and {} more", rest.size() - kShownInText)
          : std::string());
}

Json json_loose_pieces(const ValidationReport& report) {
  Json items = Json::array();
  const std::vector<Shell> rest = loose(report);
  for (std::size_t i = 0; i < std::min(rest.size(), kShownInJson); ++i) {
    items.push_back({{"volume_mm3", rest[i].volume_mm3},
                     {"min", json_point(rest[i].bounds.min)},
                     {"max", json_point(rest[i].bounds.max)}});
  }
  return items;
}

}  // namespace lsolid::cli
