// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <string>

#include "lsolid/validate.hpp"

namespace lsolid::cli {

/// "3 separate pieces, which print as loose parts: ..." with the largest
/// loose ones and where they are; empty for a model in one piece.
[[nodiscard]] std::string describe_pieces(const ValidationReport& report);

/// The JSON members `"pieces": N, "loose_pieces": [...]` (the ten largest
/// loose pieces, each with `volume_mm3`, `min` and `max`).
[[nodiscard]] std::string json_pieces(const ValidationReport& report);

}  // namespace lsolid::cli
