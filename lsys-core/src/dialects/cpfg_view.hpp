// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lsys/contour.hpp"
#include "lsys/settings.hpp"
#include "lsys/source.hpp"

namespace lsys::dialects {

class CompanionFiles;

/// A file a view file names, and the byte of the view's text (`source`)
/// where the name is written.
struct ViewFileName {
  std::string name;
  std::size_t offset = 0;
};

/// How cpfg draws `F`: lines so many pixels wide, flat ribbons, or
/// cylinders; the last two in model units.
enum class CpfgLineStyle { Pixel, Polygon, Cylinder };

/// What lsolid takes from a cpfg view file (`.v`); the rest of it is about
/// the camera, lights and rendering, and has no bearing on a solid.
struct CpfgView {
  std::optional<double> angle_deg;   ///< `angle increment`, `angle factor`
  std::optional<double> line_width;  ///< `initial line width`
  /// Where its value stands in `source`.
  std::optional<std::size_t> line_width_offset;
  std::optional<CpfgLineStyle> line_style;
  std::optional<double> width_increment;  ///< `line width increment`
  std::optional<int> initial_color;
  std::optional<double> color_increment;
  std::optional<glm::dvec3> tropism_direction;  ///< in cpfg's frame, Y up
  std::optional<double> elasticity;             ///< `initial elasticity`
  std::optional<double> elasticity_increment;
  /// `tropism:` and `torque:` lines in order (`@Ts(1, e)` is the first);
  /// directions in cpfg's frame, Y up, scaled by their intensity.
  std::vector<Movement> movements;
  /// A `surface:` line: `~id` draws the file, `size` model units for its
  /// SIZE, meshed s × t per patch (0: the file's own).
  struct SurfaceLine {
    char id = 0;
    ViewFileName file;
    double size = 1.0;
    int s = 0;
    int t = 0;
  };
  std::vector<SurfaceLine> surfaces;
  /// A `contour:` line: `@#(id)` sweeps the contour in `file`.
  struct ContourLine {
    int id = 0;
    ViewFileName file;
  };
  std::vector<ContourLine> contours;
  /// `contour sides`: points around a generalized cylinder's ring (3 to
  /// kMostContourSides).
  std::optional<int> contour_sides;
  /// `twist of cylinders: on`: a generalized cylinder's rings turn
  /// smoothly from one control point's frame to the next.
  std::optional<bool> twist_cylinders;
  /// `function:` files in order (func's ids from 1), or a `function set:`.
  std::vector<ViewFileName> functions;
  std::optional<ViewFileName> function_set;
  std::vector<std::string> warnings;  ///< commands cpfg does not know
  /// The view's text once preprocessed, where the file names are.
  std::shared_ptr<const SourceFile> source;
};

/// Reads a view file, preprocessed as cpfg does (comments, `#define`,
/// `#include` of the files `companions` allows). A command is a label up
/// to the first `:` and values after it; later commands override earlier
/// ones (docs/dialects/cpfg.md).
/// @throws ParseError at a value that is not the number(s) its command
///   takes, and as preprocess.
[[nodiscard]] CpfgView read_cpfg_view(const SourceFile& view,
                                      CompanionFiles& companions);

}  // namespace lsys::dialects
