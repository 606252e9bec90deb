// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>

#include "commands.hpp"
#include "lsolid/scale.hpp"
#include "lsys/module_string.hpp"
#include "output.hpp"

namespace lsolid::cli {
namespace {

void append_point(std::string& out, const glm::dvec3& p) {
  out += '[';
  lsys::append_number(out, p.x);
  out += ',';
  lsys::append_number(out, p.y);
  out += ',';
  lsys::append_number(out, p.z);
  out += ']';
}

// Written piece by piece rather than built as one nlohmann-json value, as
// the reports are: a skeleton may hold twenty million segments, which
// stream out in bounded memory here (Output flushes as it grows), where a
// document of them would take gigabytes.
void write_json(const lsys::Skeleton& skeleton, const char* units,
                Output& out) {
  std::string& text = out.text();
  text += "{\"units\": \"";
  text += units;
  text += "\", \"segments\": [";
  for (std::size_t i = 0; i < skeleton.segments.size(); ++i) {
    const lsys::Segment& s = skeleton.segments[i];
    text += i == 0 ? "\n" : ",\n";
    text += "{\"p0\": ";
    append_point(text, s.p0);
    text += ", \"p1\": ";
    append_point(text, s.p1);
    text += ", \"r0\": ";
    lsys::append_number(text, s.start_diameter / 2.0);
    text += ", \"r1\": ";
    lsys::append_number(text, s.end_diameter / 2.0);
    text += ", \"color\": " + std::to_string(s.color) + "}";
    out.flush_if_large();
  }
  text += "],\n\"polygons\": [";
  for (std::size_t i = 0; i < skeleton.polygons.size(); ++i) {
    const lsys::Polygon& polygon = skeleton.polygons[i];
    text += i == 0 ? "\n" : ",\n";
    text += "{\"points\": [";
    for (std::size_t k = 0; k < polygon.points.size(); ++k) {
      if (k > 0) text += ", ";
      append_point(text, polygon.points[k]);
    }
    text += "], \"color\": " + std::to_string(polygon.color) + "}";
    out.flush_if_large();
  }
  text += "]";
  if (!skeleton.spheres.empty()) {
    text += ",\n\"spheres\": [";
    for (std::size_t i = 0; i < skeleton.spheres.size(); ++i) {
      const lsys::Sphere& ball = skeleton.spheres[i];
      text += i == 0 ? "\n" : ",\n";
      text += "{\"center\": ";
      append_point(text, ball.center);
      text += ", \"r\": ";
      lsys::append_number(text, ball.diameter / 2.0);
      text += ", \"color\": " + std::to_string(ball.color) + "}";
      out.flush_if_large();
    }
    text += "]";
  }
  if (!skeleton.sheets.empty()) {
    text += ",\n\"surfaces\": [";
    for (std::size_t i = 0; i < skeleton.sheets.size(); ++i) {
      const lsys::Sheet& sheet = skeleton.sheets[i];
      text += i == 0 ? "\n" : ",\n";
      text += "{\"points\": [";
      for (std::size_t k = 0; k < sheet.points.size(); ++k) {
        if (k > 0) text += ", ";
        append_point(text, sheet.points[k]);
      }
      text += "], \"triangles\": [";
      for (std::size_t k = 0; k < sheet.triangles.size(); ++k) {
        const auto& t = sheet.triangles[k];
        text +=
            fmt::format("{}[{}, {}, {}]", k == 0 ? "" : ", ", t[0], t[1], t[2]);
      }
      text += "], \"color\": " + std::to_string(sheet.color) + "}";
      out.flush_if_large();
    }
    text += "]";
  }
  text += "}\n";
}

void write_summary(const lsys::Skeleton& skeleton, const char* units,
                   Output& out) {
  const lsys::Bounds box = lsys::bounds(skeleton);
  const glm::dvec3& low = box.min;
  const glm::dvec3& high = box.max;
  std::string& text = out.text();
  text += fmt::format("segments: {}\npolygons: {}\n", skeleton.segments.size(),
                      skeleton.polygons.size());
  if (!skeleton.spheres.empty()) {
    text += fmt::format("spheres: {}\n", skeleton.spheres.size());
  }
  if (!skeleton.sheets.empty()) {
    std::size_t triangles = 0;
    for (const lsys::Sheet& sheet : skeleton.sheets) {
      triangles += sheet.triangles.size();
    }
    text += fmt::format("surfaces: {} ({} triangles)\n", skeleton.sheets.size(),
                        triangles);
  }
  if (low.x > high.x) {
    text += "bounds: none (nothing is drawn)\n";
  } else {
    text += fmt::format(
        "bounds: [{:.6g}, {:.6g}, {:.6g}] to [{:.6g}, {:.6g}, {:.6g}] {}\n",
        low.x, low.y, low.z, high.x, high.y, high.z,
        std::string_view(units) == "mm" ? "mm" : "model units");
  }
}

}  // namespace

void warn_about_polygons(const lsys::Skeleton& skeleton) {
  const auto warn = [](std::size_t n, const char* what) {
    if (n > 0) std::fprintf(stderr, "warning: %zu %s\n", n, what);
  };
  warn(skeleton.unclosed_polygons,
       "polygons opened with '{' were never closed and are dropped");
  warn(skeleton.unmatched_polygon_ends,
       "'}' without an open polygon are ignored");
  warn(skeleton.degenerate_polygons,
       "polygons with fewer than 3 distinct points, or discs and surfaces "
       "without area, are dropped");
}

void run_skeleton(const SkeletonCommand& command) {
  const lsys::Grammar grammar = load_grammar(command.input);
  lsys::Skeleton skeleton =
      lsys::interpret(grammar, derivation_options(command.input),
                      interpret_options(command.input));
  warn_about_polygons(skeleton);
  const PrintInput& p = command.print;
  const bool in_mm = p.wall || p.height || p.size || p.scale;
  // Nothing drawn cannot be scaled: bad input, placed, as for a build.
  const bool nothing = lsys::draws_nothing(skeleton);
  if (in_mm && nothing) throw lsys::nothing_drawn_error(grammar, skeleton);
  if (nothing) {
    std::fputs(
        "warning: nothing is drawn; modules without a turtle meaning draw "
        "nothing (map them with an alias block, e.g. 'aliases: Fl=F Fr=F')\n",
        stderr);
  }
  if (in_mm) {
    skeleton = scale_to_print(skeleton, print_settings(grammar, p)).skeleton;
  }
  const char* units = in_mm ? "mm" : "model";
  Output out(stdout);
  if (command.json) {
    write_json(skeleton, units, out);
  } else {
    write_summary(skeleton, units, out);
  }
  out.flush();
}

}  // namespace lsolid::cli
