// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// cpfg's view file, read as cpfg's ReadViewData reads it (interpret.c):
// each line a label ending at its first `:`, then values. The commands and
// their defaults are those of the CPFG Reference Manual §8.1; where the
// manual and cpfg's code differ (a width without a unit word), the code's
// behaviour is taken, as docs/dialects/cpfg.md says.
#include "dialects/cpfg_view.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <glm/geometric.hpp>
#include <string_view>

#include "dialects/c_preprocessor.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/module_string.hpp"

namespace lsys::dialects {
namespace {

// Commands about the camera, lights, rendering and animation: accepted
// and left out, as a solid has none of them.
constexpr std::array<std::string_view, 36> kViewOnly{{
    "viewpoint",
    "view reference point",
    "twist",
    "projection",
    "viewing angle",
    "front distance",
    "back distance",
    "scale factor",
    "box",
    "min zoom",
    "max zoom",
    "generate on view change",
    "z buffer",
    "render mode",
    "shadow map",
    "antialiasing",
    "concave polygons",
    "tapered lines",
    "polygonization level",
    "light direction",
    "diffuse reflection",
    "surface ambient",
    "surface diffuse",
    "light",
    "line",
    "tsurface",
    "texture",
    "background scene",
    "font",
    "winfont",
    "shade mode",
    "cue range",
    "background color",
    "ambient light",
    "interpretation step",
    "initial scale",
}};

class ViewReader {
 public:
  explicit ViewReader(const SourceFile& source)
      : source_(source), text_(source.text()) {}

  CpfgView run() {
    std::size_t start = 0;
    while (start < text_.size()) {
      std::size_t end = text_.find('\n', start);
      if (end == std::string_view::npos) end = text_.size();
      command(start, end);
      start = end + 1;
    }
    return std::move(view_);
  }

 private:
  [[noreturn]] void fail(std::size_t offset, std::string message) const {
    throw error_at(source_, offset, std::move(message));
  }

  void skip_blanks(std::size_t& i, std::size_t end) const {
    while (i < end && (text_[i] == ' ' || text_[i] == '\t' || text_[i] == '\r'))
      ++i;
  }

  // The next number at or after i, skipping blanks and commas (cpfg's
  // `%f,%f,%f` and `%f %f %f` both occur).
  double number(std::size_t& i, std::size_t end) const {
    while (i < end && (text_[i] == ' ' || text_[i] == '\t' || text_[i] == ',' ||
                       text_[i] == '\r')) {
      ++i;
    }
    const std::size_t at = i;
    double value = 0.0;
    const char* first = text_.data() + i;
    if (i < end && text_[i] == '+') ++first;
    const auto [ptr, ec] = std::from_chars(first, text_.data() + end, value);
    if (ec != std::errc() || ptr == first || !std::isfinite(value))
      fail(at, "expected a number");
    i = static_cast<std::size_t>(ptr - text_.data());
    return value;
  }

  std::string_view word(std::size_t& i, std::size_t end) const {
    skip_blanks(i, end);
    const std::size_t at = i;
    while (i < end && std::isalpha(static_cast<unsigned char>(text_[i])) != 0)
      ++i;
    return text_.substr(at, i - at);
  }

  ViewFileName file_name(std::size_t& i, std::size_t end) const {
    skip_blanks(i, end);
    const std::size_t at = i;
    while (i < end && text_[i] != ' ' && text_[i] != '\t' && text_[i] != '\r')
      ++i;
    return ViewFileName{.name = std::string(text_.substr(at, i - at)),
                        .offset = at};
  }

  // A `tropism:` or `torque:` line, read as cpfg's read_movement: letters
  // each followed by numbers, `T: x y z` the direction, `I: i` its
  // intensity (the direction becomes i / |T| times itself, that factor at
  // most 1 either way), `A: a` the angle to it in degrees, `E: e` the
  // elasticity, `S: s` its step. cpfg ignores a movement that it cannot
  // read, or of no direction or intensity; lsolid stops there.
  void movement(std::size_t i, std::size_t end, Movement::Kind kind) {
    const std::size_t start = i;
    Movement m{.kind = kind};
    bool has_direction = false;
    double scale = 0.0;
    for (;;) {
      while (i < end &&
             (text_[i] == ' ' || text_[i] == '\t' || text_[i] == ',' ||
              text_[i] == ':' || text_[i] == '\r')) {
        ++i;
      }
      if (i == end) break;
      const std::size_t at = i;
      const char letter = text_[i];
      while (i < end && std::isalpha(static_cast<unsigned char>(text_[i]))) ++i;
      const auto next = [&] {
        while (i < end && text_[i] == ':') ++i;
        return number(i, end);
      };
      switch (letter) {
        case 'T': {
          m.direction.x = next();
          m.direction.y = next();
          m.direction.z = next();
          const double length = std::sqrt(glm::dot(m.direction, m.direction));
          if (length == 0.0)
            fail(at, "a movement toward no direction (T: 0 0 0)");
          scale = 1.0 / length;
          has_direction = true;
          break;
        }
        case 'I':
          scale = std::clamp(scale * next(), -1.0, 1.0);
          if (scale == 0.0)
            fail(at, "a movement of intensity 0, or 'I' before 'T'");
          break;
        case 'A':
          m.angle_deg = next();
          break;
        case 'E':
          m.elasticity = next();
          break;
        case 'S':
          m.elasticity_step = next();
          break;
        default:
          fail(at, std::string("unknown part '") + letter +
                       "' of a movement: expected T, I, A, E or S");
      }
    }
    if (!has_direction)
      fail(start, "a movement without its direction (T: x y z)");
    m.direction *= scale;
    if (view_.movements.size() == kMaxMovements) {
      warn(start, "more than 10 movements: cpfg ignores the 11th and later");
      return;
    }
    view_.movements.push_back(m);
  }

  static std::optional<CpfgLineStyle> style_named(std::string_view w) {
    if (w.empty()) return std::nullopt;
    switch (std::tolower(static_cast<unsigned char>(w.front()))) {
      case 'p':
        return w.size() > 2 && (w[2] == 'l' || w[2] == 'L')
                   ? CpfgLineStyle::Polygon
                   : CpfgLineStyle::Pixel;
      case 'c':
        return CpfgLineStyle::Cylinder;
      default:
        return std::nullopt;
    }
  }

  void command(std::size_t begin, std::size_t end) {
    std::size_t i = begin;
    skip_blanks(i, end);
    if (i == end) return;
    const std::size_t colon = text_.find(':', i);
    if (colon == std::string_view::npos || colon >= end) {
      fail(i, "expected a command ending in ':'");
    }
    std::size_t label_end = colon;
    while (label_end > i &&
           (text_[label_end - 1] == ' ' || text_[label_end - 1] == '\t')) {
      --label_end;
    }
    const std::string_view label = text_.substr(i, label_end - i);
    std::size_t v = colon + 1;
    if (label == "angle factor") {
      const double n = number(v, end);
      if (n == 0.0) fail(colon + 1, "the angle factor cannot be 0");
      view_.angle_deg = 360.0 / n;
    } else if (label == "angle increment") {
      view_.angle_deg = number(v, end);
    } else if (label == "initial line width") {
      skip_blanks(v, end);
      view_.line_width_offset = v;
      view_.line_width = number(v, end);
      // cpfg's code: a unit word starting with p means pixels, with s
      // cylinders; no word means flat polygons in model units.
      const std::string_view unit = word(v, end);
      if (unit.empty()) {
        view_.line_style = CpfgLineStyle::Polygon;
      } else if (std::tolower(static_cast<unsigned char>(unit.front())) ==
                 's') {
        view_.line_style = CpfgLineStyle::Cylinder;
      } else if (std::tolower(static_cast<unsigned char>(unit.front())) ==
                 'p') {
        view_.line_style = CpfgLineStyle::Pixel;
      }
    } else if (label == "line style") {
      skip_blanks(v, end);
      if (v < end && text_[v] >= '1' && text_[v] <= '3') {
        view_.line_style = static_cast<CpfgLineStyle>(text_[v] - '1');
      } else if (const auto style = style_named(word(v, end))) {
        view_.line_style = *style;
      } else {
        // cpfg keeps its style for a word it does not know.
        warn(i, "line style other than pixel, polygon or cylinder");
      }
    } else if (label == "line width increment") {
      view_.width_increment = number(v, end);
    } else if (label == "initial color") {
      // Indices run 0 to 255 in cpfg (two maps: to 511); clamped before
      // the cast, which would be undefined for a huge number.
      view_.initial_color =
          static_cast<int>(std::clamp(number(v, end), 0.0, 511.0));
    } else if (label == "color increment") {
      view_.color_increment = number(v, end);
    } else if (label == "tropism direction") {
      const double x = number(v, end);
      const double y = number(v, end);
      const double z = number(v, end);
      view_.tropism_direction = glm::dvec3(x, y, z);
    } else if (label == "initial elasticity") {
      view_.elasticity = number(v, end);
    } else if (label == "elasticity increment") {
      view_.elasticity_increment = number(v, end);
    } else if (label == "surface") {
      // `surface: l leaf.s 1 8 4`, or `surface: leaf.s …`, whose id is the
      // file name's first letter.
      CpfgView::SurfaceLine line;
      ViewFileName first = file_name(v, end);
      if (first.name.size() == 1) {
        line.id = first.name.front();
        first = file_name(v, end);
      } else if (!first.name.empty()) {
        line.id = first.name.front();
      }
      if (first.name.empty()) fail(colon + 1, "expected a surface file");
      line.file = std::move(first);
      skip_blanks(v, end);
      if (v < end) line.size = number(v, end);
      skip_blanks(v, end);
      if (v < end) line.s = static_cast<int>(number(v, end));
      skip_blanks(v, end);
      if (v < end) line.t = static_cast<int>(number(v, end));
      // One number after the size is a texture, not a division.
      if (line.t == 0) line.s = 0;
      view_.surfaces.push_back(std::move(line));
    } else if (label == "contour") {
      // `contour: 1 leaf.con`: `@#(1)` sweeps the file's curve.
      CpfgView::ContourLine line;
      const std::size_t at = v;
      const double id = number(v, end);
      if (id != static_cast<int>(id)) fail(at, "expected a contour id");
      line.id = static_cast<int>(id);
      ViewFileName file = file_name(v, end);
      if (file.name.empty()) fail(v, "expected a contour file");
      line.file = std::move(file);
      view_.contours.push_back(std::move(line));
    } else if (label == "contour sides") {
      // cpfg draws at least 3 sides; lsolid at most kMostContourSides.
      const std::size_t at = v;
      const double sides = number(v, end);
      view_.contour_sides =
          static_cast<int>(std::clamp(sides, 3.0, double{kMostContourSides}));
      if (sides != *view_.contour_sides) {
        std::string what = "contour sides: ";
        append_number(what, sides);
        what += " is outside 3 to " + std::to_string(kMostContourSides) +
                ": taken as " + std::to_string(*view_.contour_sides);
        warn_plainly(at, what);
      }
    } else if (label == "twist of cylinders") {
      view_.twist_cylinders = word(v, end).starts_with("on");
    } else if (label == "function" || label == "function set") {
      std::size_t k = v;
      ViewFileName file = file_name(k, end);
      if (file.name.empty()) fail(v, "expected a file name");
      if (label == "function") {
        view_.functions.push_back(std::move(file));
      } else {
        view_.function_set = std::move(file);
      }
    } else if (label == "tropism" || label == "torque") {
      movement(v, end,
               label == "tropism" ? Movement::Kind::Tropism
                                  : Movement::Kind::Torque);
    } else if (label == "curve" || label == "scale multiplier" ||
               label == "interpretation past %") {
      // What uses them (curveX, `@Di`) is refused where the L-system
      // writes it.
    } else {
      for (std::string_view known : kViewOnly) {
        if (label == known) return;
      }
      std::string what = "unknown view command '";
      what += label;
      what += "'";
      warn(i, what);
    }
  }

  void warn(std::size_t at, std::string_view what) {
    warn_plainly(at, std::string(what) + " left out, as cpfg does");
  }

  void warn_plainly(std::size_t at, std::string_view what) {
    const SourceLocation where = source_.location(at);
    std::string warning = source_.name();
    warning += ':';
    warning += std::to_string(where.line);
    warning += ": ";
    warning += what;
    view_.warnings.push_back(std::move(warning));
  }

  const SourceFile& source_;
  std::string_view text_;
  CpfgView view_;
};

}  // namespace

CpfgView read_cpfg_view(const SourceFile& view, CompanionFiles& companions) {
  auto preprocessed = preprocess(
      view,
      PreprocessOptions{.keep_constants = false, .companions = &companions});
  CpfgView out = ViewReader(*preprocessed).run();
  out.source = std::move(preprocessed);
  return out;
}

}  // namespace lsys::dialects
