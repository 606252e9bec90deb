// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "json.hpp"

#include <fmt/format.h>

namespace lsolid::cli {

void append_json_string(std::string& out, const std::string& text) {
  out += '"';
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20U) {
      static constexpr char kHex[] = "0123456789abcdef";
      out += "\\u00";
      out += kHex[(c >> 4) & 0xF];
      out += kHex[c & 0xF];
    } else {
      out += c;
    }
  }
  out += '"';
}

std::string json_string(const std::string& text) {
  std::string out;
  append_json_string(out, text);
  return out;
}

std::string json_point(const glm::dvec3& p) {
  return fmt::format("[{}, {}, {}]", p.x, p.y, p.z);
}

}  // namespace lsolid::cli
