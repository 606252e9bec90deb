// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <string_view>

namespace lsolid {

/// Reads a length such as `0.8mm`, `2 cm`, `1in` or a bare `12` (millimetres)
/// and returns it in millimetres.
/// @param what names the value in diagnostics, e.g. `--wall`.
/// @throws lsys::ParseError (file `what`, with the column) for a missing or
///   bad number, an unknown unit, or a value that is not positive.
[[nodiscard]] double parse_length_mm(std::string_view text,
                                     const std::string& what);

}  // namespace lsolid
