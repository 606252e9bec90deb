// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "material_names.hpp"

#include <charconv>

namespace lsolid {
namespace {

constexpr std::string_view kPrefix = "colour";

}  // namespace

std::string material_name(int color, char separator) {
  return std::string(kPrefix) + separator + std::to_string(color);
}

int color_of_material(std::string_view name) {
  if (name.size() <= kPrefix.size() + 1 || !name.starts_with(kPrefix) ||
      (name[kPrefix.size()] != ' ' && name[kPrefix.size()] != '_')) {
    return 0;
  }
  int color = 0;
  const char* first = name.data() + kPrefix.size() + 1;
  if (std::from_chars(first, name.data() + name.size(), color).ec !=
      std::errc()) {
    return 0;
  }
  return color;
}

}  // namespace lsolid
