// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <vector>

#include "commands.hpp"
#include "json.hpp"
#include "lsolid/distance.hpp"
#include "lsolid/mesh_io.hpp"
#include "lsolid/validate.hpp"
#include "lsys/diagnostic.hpp"
#include "pieces.hpp"

namespace lsolid::cli {
namespace {

Json json_report(const ValidationReport& r) {
  const auto known = [](bool is_known, auto value) {
    return is_known ? Json(value) : Json(nullptr);
  };
  return Json{{"printable", r.is_printable()},
              {"triangles", r.triangles},
              {"vertices", r.vertices},
              {"closed", r.boundary_edges == 0},
              {"boundary_edges", r.boundary_edges},
              {"non_manifold_edges", r.non_manifold_edges},
              {"non_manifold_vertices", r.non_manifold_vertices},
              {"misoriented_edges", r.misoriented_edges},
              {"outward", known(r.orientation_checked, r.is_outward)},
              {"degenerate_faces", r.degenerate_faces},
              {"self_intersecting_pairs",
               known(r.self_intersections_checked, r.self_intersecting_pairs)},
              {"shells", r.shells},
              {"pieces", r.pieces()},
              {"loose_pieces", json_loose_pieces(r)},
              {"genus", known(r.genus >= 0, r.genus)},
              {"volume_mm3", r.volume_mm3},
              {"bounds", json_box(r.bounds)},
              {"problems", r.problems()}};
}

// `in_pieces`: --one-piece was asked for and the mesh is not one piece.
std::string text_report(const std::string& file, const ValidationReport& r,
                        bool in_pieces) {
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
  const std::string pieces = describe_pieces(r);
  out += fmt::format("pieces: {}\n",
                     pieces.empty() ? fmt::format("{}", r.pieces()) : pieces);
  out += fmt::format("volume: {:.3f} mm³\n", r.volume_mm3);
  const glm::dvec3 size = r.bounds.size();
  out += fmt::format("size: {:.3f} x {:.3f} x {:.3f} mm\n", size.x, size.y,
                     size.z);
  out +=
      fmt::format("verdict: {}\n", !r.is_printable() ? "NOT printable"
                                   : in_pieces ? "NOT one piece (--one-piece)"
                                               : "printable");
  for (const std::string& p : r.problems()) out += "  " + p + "\n";
  return out;
}

// A file of several volumes (a --multi-material 3MF or OBJ): each must be
// printable, and they must not overlap. A union of volumes that share
// faces, rounded to floats, took CGAL over 15 minutes on the bush at n = 3,
// so overlap is sampled (overlap_depth_mm).
bool check_volumes(const CheckCommand& command,
                   const std::vector<ColoredMesh>& volumes) {
  std::vector<ValidationReport> reports;
  bool printable = true;
  for (const ColoredMesh& v : volumes) {
    reports.push_back(validate(v.mesh));
    printable = printable && reports.back().is_printable();
  }
  // Volumes that share faces are written with their vertices rounded to
  // floats: points of one lie up to about 1e-5 mm inside the other.
  constexpr double kTouchMm = 1e-4;
  std::optional<double> overlap_mm;
  if (printable) {
    overlap_mm = 0.0;
    for (std::size_t i = 0; i < volumes.size(); ++i) {
      for (std::size_t j = 0; j < volumes.size(); ++j) {
        if (i != j) {
          overlap_mm = std::max(
              *overlap_mm, overlap_depth_mm(volumes[i].mesh, volumes[j].mesh));
        }
      }
    }
    printable = *overlap_mm <= kTouchMm;
  }
  const auto color = [&](std::size_t i) {
    return volumes[i].colors.empty() ? 0 : volumes[i].colors.front();
  };
  if (command.json) {
    Json items = Json::array();
    for (std::size_t i = 0; i < reports.size(); ++i) {
      Json one = json_report(reports[i]);
      one["color"] = color(i);
      items.push_back(std::move(one));
    }
    fmt::print("{}",
               json_line(Json{{"printable", printable},
                              {"volumes", std::move(items)},
                              {"overlap_mm", overlap_mm ? Json(*overlap_mm)
                                                        : Json(nullptr)}}));
  } else {
    fmt::print("{}: {} volumes\n", command.file, volumes.size());
    for (std::size_t i = 0; i < reports.size(); ++i) {
      const ValidationReport& r = reports[i];
      fmt::print("volume {} (colour {}): {} triangles, {:.3f} mm³, {}\n", i + 1,
                 color(i), r.triangles, r.volume_mm3,
                 r.is_printable() ? "printable" : "NOT printable");
      for (const std::string& p : r.problems()) fmt::print("  {}\n", p);
    }
    if (overlap_mm) {
      fmt::print(
          "overlap: {} (the deepest sampled point of one inside "
          "another, {:.6f} mm)\n",
          *overlap_mm <= kTouchMm ? "none, the volumes only touch"
                                  : "the volumes overlap",
          *overlap_mm);
    } else {
      fmt::print("overlap: not measured (a volume is not printable)\n");
    }
    fmt::print("verdict: {}\n", printable ? "printable" : "NOT printable");
  }
  return printable;
}

}  // namespace

bool run_check(const CheckCommand& command) {
  const std::vector<ColoredMesh> volumes = read_colored(command.file);
  // A file without a triangle is nothing to check, not a printable (or an
  // unprintable) mesh with empty bounds.
  std::size_t triangles = 0;
  for (const ColoredMesh& v : volumes) triangles += v.mesh.triangles.size();
  if (triangles == 0) {
    throw lsys::ParseError(lsys::Diagnostic{
        .file = command.file, .message = "the file holds no triangles"});
  }
  if (volumes.size() > 1) return check_volumes(command, volumes);
  const ValidationReport report =
      validate(volumes.empty() ? TriangleMesh() : volumes.front().mesh);
  const bool in_pieces = command.one_piece && report.pieces() > 1;
  const std::string text = command.json
                               ? json_line(json_report(report))
                               : text_report(command.file, report, in_pieces);
  std::fputs(text.c_str(), stdout);
  return report.is_printable() && !in_pieces;
}

}  // namespace lsolid::cli
