// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "lsys/bounds.hpp"

namespace lsolid::cli {

/// A JSON value whose objects keep their keys in the order they were set,
/// as docs/cli.md lists them (nlohmann-json).
using Json = nlohmann::ordered_json;

/// A point as `[x, y, z]`.
[[nodiscard]] Json json_point(const glm::dvec3& p);

/// A box as `{"min": [x, y, z], "max": [x, y, z]}`.
[[nodiscard]] Json json_box(const lsys::Bounds& box);

/// The value on one line, ended by a newline: the form every `--json`
/// prints. Bytes of a file name that are not UTF-8 become U+FFFD.
[[nodiscard]] std::string json_line(const Json& value);

}  // namespace lsolid::cli
