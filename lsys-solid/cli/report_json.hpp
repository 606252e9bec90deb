// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <vector>

#include "json.hpp"
#include "lsolid/colors.hpp"
#include "lsolid/overhang.hpp"
#include "lsolid/solid.hpp"

namespace lsolid::cli {

/// How many triangles of each colour are written: those of the volumes with
/// --multi-material, else those of the one mesh.
[[nodiscard]] std::map<int, std::size_t> color_counts(const Solid& solid);

/// Whether a model of these bounds fits a printer's build volume
/// (`bed_mm`: width, depth, height), as the report prints sizes: to
/// 0.01 mm, so what fits as printed fits.
[[nodiscard]] bool fits_bed(const Box& bounds, const glm::dvec3& bed_mm);

/// A build's report as one JSON object, the build's `--json` and the
/// viewer's; docs/cli.md lists its members in this order.
[[nodiscard]] Json report_json(const Solid& solid, const OverhangReport& over,
                               const std::optional<glm::dvec3>& bed, bool fits,
                               const std::filesystem::path& output,
                               bool written, bool united, bool colored,
                               const std::vector<Rgb>& palette);

}  // namespace lsolid::cli
