// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec3.hpp>
#include <string>

namespace lsolid::cli {

/// Appends `text` as a JSON string: quoted, with quotes, backslashes and
/// control characters escaped.
void append_json_string(std::string& out, const std::string& text);

/// `text` as a JSON string (see append_json_string).
[[nodiscard]] std::string json_string(const std::string& text);

/// `[x, y, z]`, numbers in shortest round-trip form.
[[nodiscard]] std::string json_point(const glm::dvec3& p);

}  // namespace lsolid::cli
