// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <string>

#include "json.hpp"
#include "lsolid/validate.hpp"

namespace lsolid::cli {

/// "3 separate pieces, which print as loose parts: ..." with the largest
/// loose ones and where they are; empty for a model in one piece.
[[nodiscard]] std::string describe_pieces(const ValidationReport& report);

/// The ten largest loose pieces (all but the largest piece), each as
/// `{"volume_mm3", "min", "max"}`: the report's `loose_pieces`.
[[nodiscard]] Json json_loose_pieces(const ValidationReport& report);

}  // namespace lsolid::cli
