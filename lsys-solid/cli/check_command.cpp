// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include <fmt/format.h>

#include <cstdio>

#include "commands.hpp"
#include "json.hpp"
#include "lsolid/errors.hpp"
#include "lsolid/mesh_io.hpp"
#include "lsolid/validate.hpp"

namespace lsolid::cli {
namespace {

std::string json_number(double v) { return fmt::format("{}", v); }

std::string json_report(const ValidationReport& r) {
  std::string problems;
  for (const std::string& p : r.problems()) {
    if (!problems.empty()) problems += ", ";
    append_json_string(problems, p);
  }
  const auto optional = [](bool known, const std::string& value) {
    return known ? value : std::string("null");
  };
  return fmt::format(
      "{{\"printable\": {}, \"triangles\": {}, \"vertices\": {}, \"closed\": "
      "{}, "
      "\"boundary_edges\": {}, \"non_manifold_edges\": {}, "
      "\"non_manifold_vertices\": {}, \"misoriented_edges\": {}, "
      "\"outward\": {}, \"degenerate_faces\": {}, \"self_intersecting_pairs\": "
      "{}, "
      "\"shells\": {}, \"genus\": {}, \"volume_mm3\": {}, "
      "\"bounds\": {{\"min\": {}, \"max\": {}}}, \"problems\": [{}]}}\n",
      r.is_printable(), r.triangles, r.vertices, r.boundary_edges == 0,
      r.boundary_edges, r.non_manifold_edges, r.non_manifold_vertices,
      r.misoriented_edges,
      optional(r.orientation_checked, r.is_outward ? "true" : "false"),
      r.degenerate_faces,
      optional(r.self_intersections_checked,
               std::to_string(r.self_intersecting_pairs)),
      r.shells, optional(r.genus >= 0, std::to_string(r.genus)),
      json_number(r.volume_mm3), json_point(r.bounds.min),
      json_point(r.bounds.max), problems);
}

std::string text_report(const std::string& file, const ValidationReport& r) {
  const auto yes = [](bool b) { return b ? "yes" : "no"; };
  std::string out = fmt::format("{}: {} triangles, {} vertices\n", file,
                                r.triangles, r.vertices);
  out += fmt::format("closed: {} ({} boundary edges)\n",
                     yes(r.boundary_edges == 0), r.boundary_edges);
  out += fmt::format(
      "manifold: {} ({} non-manifold edges, {} non-manifold vertices)\n",
      yes(r.non_manifold_edges == 0 && r.non_manifold_vertices == 0),
      r.non_manifold_edges, r.non_manifold_vertices);
  out += fmt::format(
      "oriented: {}\n",
      !r.orientation_checked
          ? (r.misoriented_edges > 0 ? "inconsistently" : "not checked")
      : r.is_outward ? "outward"
                     : "not outward");
  out += fmt::format("degenerate faces: {}\n", r.degenerate_faces);
  out += fmt::format(
      "self-intersections: {}\n",
      r.self_intersections_checked
          ? (r.self_intersecting_pairs == 0
                 ? std::string("none (exact test)")
                 : fmt::format("{} pairs", r.self_intersecting_pairs))
          : std::string("not checked (not edge-manifold)"));
  out += fmt::format(
      "shells: {}, genus: {}\n", r.shells,
      r.genus >= 0 ? std::to_string(r.genus) : std::string("unknown"));
  out += fmt::format("volume: {:.3f} mm³\n", r.volume_mm3);
  const glm::dvec3 size = r.bounds.size();
  out += fmt::format("size: {:.3f} x {:.3f} x {:.3f} mm\n", size.x, size.y,
                     size.z);
  out += fmt::format("verdict: {}\n",
                     r.is_printable() ? "printable" : "NOT printable");
  for (const std::string& p : r.problems()) out += "  " + p + "\n";
  return out;
}

}  // namespace

int run_check(const CheckCommand& command) {
  TriangleMesh mesh;
  try {
    mesh = read_mesh(command.file);
  } catch (const IoError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  const ValidationReport report = validate(mesh);
  const std::string text =
      command.json ? json_report(report) : text_report(command.file, report);
  std::fputs(text.c_str(), stdout);
  return report.is_printable() ? 0 : 1;
}

}  // namespace lsolid::cli
