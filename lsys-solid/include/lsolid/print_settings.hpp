// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lsolid/colors.hpp"
#include "lsolid/defaults.hpp"
#include "lsys/grammar.hpp"

namespace lsolid {

/// What the model stands on (see placement.hpp).
enum class Base {
  Auto,  ///< a disc where the model would stand on a small footprint
  Disc,  ///< always a disc
  None,  ///< never
};

/// The section of a planar model's branches once it lies flat.
enum class Profile {
  /// The footprint of every branch and leaf, united in the plane and
  /// extruded: a flat top and square edges, as high as the round model.
  Flat,
  /// Round tubes united in 3D and cut flat underneath (far slower).
  Round,
};

/// How to print: sizes in millimetres. At most one of height, size and
/// scale is set; with none, the longest side becomes kDefaultSizeMm.
struct PrintSettings {
  /// Minimum wall: thinnest branch, leaf thickness.
  double wall_mm = kDefaultWallMm;
  std::optional<double> height_mm;            ///< model height along Z
  std::optional<double> size_mm;              ///< longest side
  std::optional<double> scale_mm_per_unit;    ///< millimetres per model unit
  double tolerance_mm = kDefaultToleranceMm;  ///< chord error of tubes
  Base base = Base::Auto;
  Profile profile = Profile::Flat;  ///< of a model that lies flat
  /// The colour of each turtle colour index for 3MF and OBJ (`colors:
  /// #7B4A2A #8CC63F`); empty: lsolid's palette (see palette_color).
  std::vector<Rgb> colors;
};

/// `auto`, `disc` or `none`.
/// @throws lsys::ParseError naming `what` for anything else.
[[nodiscard]] Base parse_base(const std::string& text, const std::string& what);

/// `flat` or `round`.
/// @throws lsys::ParseError naming `what` for anything else.
[[nodiscard]] Profile parse_profile(const std::string& text,
                                    const std::string& what);

/// `#RRGGBB` colours separated by spaces or commas.
/// @throws lsys::ParseError naming `what`, with the column of a bad colour.
[[nodiscard]] std::vector<Rgb> parse_colors(const std::string& text,
                                            const std::string& what);

/// The setting names a `.ls` file may use for print settings (`wall: 0.8mm`),
/// to pass as lsys::ParseOptions::extra_settings.
[[nodiscard]] std::vector<std::string> print_setting_names();

/// Print settings given on the command line: each one given overrides the
/// file's, and a height, size or scale replaces every size the file gives.
struct PrintOverrides {
  std::optional<double> wall_mm;
  /// At most one of the three.
  std::optional<double> height_mm;
  std::optional<double> size_mm;
  std::optional<double> scale_mm_per_unit;
  std::optional<double> tolerance_mm;
  std::optional<Base> base;
  std::optional<Profile> profile;
  std::optional<std::vector<Rgb>> colors;
};

/// The print settings a file states, then those of the command line, which
/// win.
/// @throws lsys::ParseError at the file's value for a bad setting, or at
///   its second size when the file gives several and the command line none.
[[nodiscard]] PrintSettings resolve_print_settings(
    const lsys::Grammar& grammar, const PrintOverrides& command_line = {});

}  // namespace lsolid
