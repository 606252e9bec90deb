// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <string_view>

namespace lsolid {

/// Reads a length such as `0.8mm`, `2 cm`, `1in` or a bare `12` (millimetres)
/// and returns it in millimetres.
/// @param what names the value in diagnostics, e.g. `--wall`.
/// @throws lsys::ParseError (file `what`, with the column) for a missing or
///   bad number, an unknown unit, a value that is not positive, or one
///   above 1000000 mm (1 km).
[[nodiscard]] double parse_length_mm(std::string_view text,
                                     const std::string& what);

/// Reads a printer's build volume such as `220x220x250mm` (width, depth,
/// height; one unit for all three, millimetres by default).
/// @throws lsys::ParseError (file `what`) for anything else.
[[nodiscard]] glm::dvec3 parse_bed_mm(std::string_view text,
                                      const std::string& what);

}  // namespace lsolid
