// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>

#include "commands.hpp"
#include "json.hpp"
#include "lsolid/colors.hpp"
#include "lsolid/errors.hpp"
#include "lsolid/mesh_io.hpp"
#include "lsolid/output_file.hpp"
#include "lsolid/overhang.hpp"
#include "lsolid/preview.hpp"
#include "lsolid/solid.hpp"
#include "lsolid/units.hpp"
#include "lsys/diagnostic.hpp"
#include "pieces.hpp"
#include "report_json.hpp"

namespace lsolid::cli {
namespace {

void print_report(const SolidReport& r, bool united) {
  const ValidationReport& v = r.validation;
  fmt::print("segments: {}{}, leaves: {}\n", r.segments,
             r.repeated_segments == 0
                 ? std::string()
                 : fmt::format(" ({} drawn again over another, left out)",
                               r.repeated_segments),
             r.polygons);
  fmt::print(
      "parts: {} tubes, {} junction hulls, {} joints, {} leaf plates{}{}; "
      "scale {:.4g} mm per unit\n",
      r.tubes, r.junctions, r.joints, r.plates,
      r.spheres == 0 ? std::string() : fmt::format(", {} spheres", r.spheres),
      r.sheets == 0 ? std::string()
                    : fmt::format(", {} surface plates", r.sheets),
      r.mm_per_unit);
  if (r.skipped_polygons > 0) {
    fmt::print("skipped: {} polygons without area or crossing themselves\n",
               r.skipped_polygons);
  }
  if (united && r.flat_outlines > 0) {
    fmt::print(
        "union: in the plane (flat profile): {} outlines, {} rings; {} points "
        "inside the parts found inside it\n",
        r.flat_outlines, r.flat_rings, r.witnesses_checked);
  } else if (united) {
    const UnionStats& u = r.union_stats;
    fmt::print(
        "union: {} contacts, {} booleans ({} rounded to doubles), {} joined "
        "without a boolean, {} retried, {} cavities filled; {} points inside "
        "the parts found inside it\n",
        u.contacts, u.booleans, u.rounded, u.concatenations, u.retries,
        r.cavities_filled, r.witnesses_checked);
    if (u.engine == UnionEngine::ExactCrossings) {
      fmt::print(
          "union engine: exact, {} threads, {} unions ({} with an operand "
          "grown where faces touch), {} where parts touch "
          "and {} fallbacks left to the corefinement; {} crossings, {} faces "
          "cut; {} predicates on implicit points, {} ({:.2f}%) evaluated "
          "exactly\n",
          u.threads, u.exact_unions, u.grown, u.degenerate_unions, u.fallbacks,
          u.crossings, u.cut_faces, u.predicates, u.filter_failures,
          u.predicates == 0 ? 0.0
                            : 100.0 * static_cast<double>(u.filter_failures) /
                                  static_cast<double>(u.predicates));
      if (!u.degenerate_reason.empty())
        fmt::print("union engine: parts touch: {}\n", u.degenerate_reason);
      if (!u.fallback_reason.empty())
        fmt::print("union engine: fell back: {}\n", u.fallback_reason);
    } else {
      fmt::print("union engine: corefine (CGAL's corefinement)\n");
    }
  }
  if (r.placement.lies_flat && r.placement.cut_refused) {
    fmt::print(
        "placement: planar, lying flat on round undersides; not cut flat, "
        "as the cut model would not be printable\n");
  } else if (r.placement.lies_flat && r.flat_outlines > 0) {
    fmt::print(
        "placement: planar, lying flat; its outline extruded from {:.2f} mm "
        "below the branches' centre plane (--profile round for round "
        "tubes)\n",
        r.placement.cut_depth_mm);
  } else if (r.placement.lies_flat) {
    fmt::print(
        "placement: planar, lying flat; underside cut flat {:.2f} mm below "
        "the branches' centre plane\n",
        r.placement.cut_depth_mm);
  }
  if (r.placement.has_base) {
    fmt::print(
        "base: a disc of {:.1f} mm radius, {:.1f} mm thick, under a foot "
        "{:.1f} "
        "mm wide\n",
        r.placement.base_radius_mm, r.placement.base_thickness_mm,
        r.placement.footprint_mm);
  }
  const DecimateStats& d = r.decimation;
  if (r.decimated) {
    fmt::print(
        "decimation: {} -> {} triangles, {} collapses refused as they would "
        "cut the mesh; deviation {:.3f} mm (Hausdorff, sampled), {} the "
        "tolerance of {:.3g} mm{}\n",
        d.triangles_before, d.triangles_after, d.refused_intersections,
        d.max_deviation_mm, d.within_tolerance ? "within" : "BEYOND",
        d.tolerance_mm,
        d.attempts > 1 ? fmt::format(" ({} runs, aiming lower)", d.attempts)
                       : std::string());
    if (d.short_edges_left > 0) {
      fmt::print(
          "decimation: {} edges shorter than 0.03 mm left (no collapse could "
          "remove them within the tolerance)\n",
          d.short_edges_left);
    }
    if (!d.reached_max_triangles) {
      fmt::print(
          "decimation: could not reach --max-triangles without breaking the "
          "mesh\n");
    }
  } else if (!r.decimation_discarded.empty()) {
    fmt::print(
        "decimation: its result {} and was not used (please report this)\n",
        r.decimation_discarded);
  }
  fmt::print("triangles: {}\n", v.triangles);
  fmt::print("volume: {:.1f} mm³\n", v.volume_mm3);
  const glm::dvec3 size = v.bounds.size();
  // A coordinate that rounds to zero prints as 0.00, not -0.00: the union's
  // growth where faces touch (10⁻¹¹ mm) can leave the lowest point that far
  // below the bed.
  const auto shown = [](double mm) { return std::abs(mm) < 0.005 ? 0.0 : mm; };
  fmt::print(
      "size: {:.2f} x {:.2f} x {:.2f} mm, from ({:.2f}, {:.2f}, {:.2f})\n",
      size.x, size.y, size.z, shown(v.bounds.min.x), shown(v.bounds.min.y),
      shown(v.bounds.min.z));
  if (united) {
    fmt::print(
        "rounding: {} pass{}, {} slivers removed, {} intersecting faces "
        "rebuilt{}; volume changed by {:+.4f} mm³\n",
        r.rounding.passes, r.rounding.passes == 1 ? "" : "es",
        r.rounding.slivers_removed, r.rounding.faces_rebuilt,
        r.rounding.slivers_kept
            ? " (slivers kept but where faces met: collapsing them all "
              "left faces that meet)"
            : "",
        r.rounding.volume_change_mm3);
  }
  fmt::print(
      "time: skeleton {:.2f} s, parts {:.2f} s, union {:.2f} s, rounding "
      "{:.2f} s, decimation {:.2f} s, check {:.2f} s\n",
      r.seconds.skeleton, r.seconds.parts, r.seconds.unite, r.seconds.round,
      r.seconds.decimate, r.seconds.check);
  if (v.is_printable()) {
    fmt::print(
        "check: printable: closed, manifold, outward, no self-intersections; "
        "{} shell{}, genus {}\n",
        v.shells, v.shells == 1 ? "" : "s", v.genus);
    const std::string pieces = describe_pieces(v);
    if (!pieces.empty()) fmt::print("pieces: {}\n", pieces);
  } else {
    fmt::print("check: NOT printable\n");
    for (const std::string& problem : v.problems())
      fmt::print("  {}\n", problem);
  }
}

// The colours written, and with --multi-material the volumes.
void print_colors(const Solid& solid, const std::vector<Rgb>& palette) {
  std::vector<std::string> names;
  for (const auto& [color, count] : color_counts(solid)) {
    names.push_back(fmt::format("{} {} ({} triangles)", color,
                                hex(palette_color(color, palette)), count));
  }
  fmt::print("colours: {}\n", fmt::join(names, ", "));
  if (solid.volumes.empty()) return;
  std::vector<std::string> volumes;
  std::size_t written = 0;
  for (const ColoredMesh& v : solid.volumes) {
    volumes.push_back(fmt::format("colour {} {:.1f} mm³",
                                  v.colors.empty() ? 0 : v.colors.front(),
                                  signed_volume(v.mesh)));
    written += v.mesh.triangles.size();
  }
  // The report's other lines describe the whole model as one union.
  fmt::print(
      "volumes: {} for {} extruders, not overlapping, {} triangles written: "
      "{}\n",
      solid.volumes.size(), solid.volumes.size(), written,
      fmt::join(volumes, ", "));
}

}  // namespace

namespace {

// The file a build writes: -o, else the input's name with .stl.
std::filesystem::path output_of(const BuildCommand& command) {
  if (!command.output.empty()) return command.output;
  return std::filesystem::path(command.input.file).replace_extension(".stl");
}

}  // namespace

std::string failed_build_json(const BuildCommand& command, int exit_code,
                              const lsys::Diagnostic& error) {
  Json where = nullptr;
  if (!error.file.empty()) {
    where = Json{
        {"file", error.file}, {"line", error.line}, {"column", error.column}};
  }
  return json_line(Json{{"output", output_of(command).string()},
                        {"written", false},
                        {"exit_code", exit_code},
                        {"error", Json{{"message", error.message},
                                       {"place", std::move(where)}}}});
}

void run_build(const BuildCommand& command) {
  const std::filesystem::path output = output_of(command);
  MeshFormat format = MeshFormat::StlBinary;
  try {
    format = format_for(output, command.ascii);
  } catch (const IoError& e) {
    // A name we cannot write is a usage error, found before any work.
    throw lsys::ParseError(lsys::Diagnostic{
        .file = "--output",
        .message = "unknown output format '" + output.extension().string() +
                   "': use .stl, .off, .scad, .3mf or .obj"});
  }
  if (command.ascii && format != MeshFormat::StlAscii) {
    throw lsys::ParseError(lsys::Diagnostic{
        .file = "--ascii",
        .message = "--ascii is for STL; '" + output.filename().string() +
                   "' is not an STL file"});
  }
  const bool colored =
      format == MeshFormat::ThreeMf || format == MeshFormat::Obj;
  if (command.print.colors && !colored) {
    std::fprintf(stderr,
                 "warning: --colors is for .3mf and .obj output; %s is "
                 "written without colour\n",
                 output.filename().string().c_str());
  }
  if (command.multi_material && !colored) {
    throw lsys::ParseError(lsys::Diagnostic{
        .file = "--multi-material",
        .message = "volumes per colour need a .3mf or .obj output, not '" +
                   output.filename().string() + "'"});
  }
  const std::filesystem::path preview = command.preview;
  std::string preview_ext = preview.extension().string();
  for (char& c : preview_ext) {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  if (!preview.empty() && preview_ext != ".png") {
    throw lsys::ParseError(lsys::Diagnostic{
        .file = "--preview",
        .message = "a preview is a PNG: name it FILE.png, not '" +
                   preview.string() + "'"});
  }
  // Outputs are regular files (or links to them, written through) in
  // folders that exist, checked before the long work: a FIFO or a device
  // must not be replaced by a file, nor a directory be refused at the end.
  std::filesystem::path mtl;
  if (format == MeshFormat::Obj)
    mtl = std::filesystem::path(output).replace_extension(".mtl");
  for (const auto& [given, option] :
       {std::pair{output, "--output"}, std::pair{mtl, "--output"},
        std::pair{preview, "--preview"}}) {
    if (given.empty()) continue;
    std::filesystem::path target;
    try {
      target = output_target(given);
    } catch (const IoError& e) {
      throw lsys::ParseError(
          lsys::Diagnostic{.file = option, .message = e.what()});
    }
    const std::filesystem::path folder =
        target.has_parent_path() ? target.parent_path() : ".";
    if (!std::filesystem::is_directory(folder)) {
      throw IoError(given.string() + ": no folder " + folder.string());
    }
  }
  std::optional<glm::dvec3> bed;
  if (command.bed) bed = parse_bed_mm(*command.bed, "--bed");
  const lsys::Grammar grammar = load_grammar(command.input);
  SolidOptions options;
  options.derivation = derivation_options(command.input);
  options.interpretation = interpret_options(command.input);
  options.print = print_settings(grammar, command.print);
  options.unite = !command.no_union;
  if (command.threads) {
    options.threads = static_cast<int>(
        parse_whole_number(*command.threads, "--threads", 1, 256));
  }
  options.union_engine = command.union_engine == "corefine"
                             ? UnionEngine::Corefinement
                             : UnionEngine::ExactCrossings;
  options.decimate = !command.no_decimate;
  if (command.max_triangles) {
    // A closed mesh has at least 4 triangles; indices are 32 bits.
    options.max_triangles = static_cast<std::size_t>(parse_whole_number(
        *command.max_triangles, "--max-triangles", 4, 4294967295U));
  }
  // Snapped to what the format keeps (floats for STL, doubles for OFF and
  // OBJ, grids for 3MF and OpenSCAD) before the last check.
  options.format = format;
  options.colors = colored && options.unite;
  options.preview_colors = !preview.empty();
  options.multi_material = command.multi_material;
  const bool text = !command.quiet && !command.json;
  // A progress bar on a terminal only: redrawn in place on standard error,
  // and wiped before the report. A stage expected to take 10 s or more says
  // so from its start, so that a long build is known to be one early.
  const bool bar = text && ::isatty(STDERR_FILENO) != 0;
  // The stage whose time was estimated, and the estimate; both lambdas
  // live in `options`, which build_solid uses only within this function.
  std::pair<std::string, double> expected;
  if (bar) {
    options.expect = [&expected](std::string_view stage, double seconds) {
      expected = {std::string(stage), seconds};
    };
    options.progress = [&expected](std::string_view stage, double fraction) {
      constexpr int kWidth = 30;
      const int filled = static_cast<int>(fraction * kWidth);
      std::string note;
      if (expected.first == stage && expected.second >= 10.0) {
        note = expected.second < 90.0
                   ? fmt::format("  about {:.0f} s", expected.second)
                   : fmt::format("  about {:.0f} min", expected.second / 60.0);
      }
      std::fprintf(
          stderr, "\r%-10.*s [%s%s] %3d%%%-16s", static_cast<int>(stage.size()),
          stage.data(),
          std::string(static_cast<std::size_t>(filled), '#').c_str(),
          std::string(static_cast<std::size_t>(kWidth - filled), ' ').c_str(),
          static_cast<int>(fraction * 100.0), note.c_str());
      std::fflush(stderr);
    };
  }
  const Solid solid = build_solid(grammar, options);
  if (bar) std::fprintf(stderr, "\r%66s\r", "");
  warn_about_polygons(solid.report.dropped);
  for (const std::string& warning : solid.report.warnings) {
    std::fprintf(stderr, "warning: %s\n", warning.c_str());
  }
  const DecimateStats& decimation = solid.report.decimation;
  if (solid.report.decimated && !decimation.within_tolerance) {
    std::fprintf(stderr,
                 "warning: decimation moved the surface by up to %.3f mm, "
                 "more than the tolerance of %.3g mm%s\n",
                 decimation.max_deviation_mm, decimation.tolerance_mm,
                 decimation.beyond_tolerance_for_cap
                     ? ", to reach --max-triangles"
                     : " (--no-decimate keeps every triangle)");
  }
  if (text) print_report(solid.report, options.unite);
  if (text && colored) print_colors(solid, options.print.colors);
  const OverhangReport over = overhang(solid.mesh);
  if (text) {
    fmt::print("overhang: {:.1f} mm² faces down more steeply than 45°: {}\n",
               over.area_mm2,
               over.needs_supports ? "supports needed" : "no supports needed");
  }
  const bool fits = !bed || fits_bed(solid.report.validation.bounds, *bed);
  if (text && bed) {
    if (fits) {
      fmt::print("bed: fits {} x {} x {} mm\n", bed->x, bed->y, bed->z);
    } else {
      const glm::dvec3 size = solid.report.validation.bounds.size();
      fmt::print(
          "bed: {:.1f} x {:.1f} x {:.1f} mm does not fit {} x {} x {} mm\n",
          size.x, size.y, size.z, bed->x, bed->y, bed->z);
    }
  }
  const auto finish = [&](bool written) {
    if (command.json) {
      fmt::print("{}", json_line(report_json(solid, over, bed, fits, output,
                                             written, options.unite, colored,
                                             options.print.colors)));
    }
    // The report goes out before any error on standard error; a report
    // that cannot be written is an error of its own.
    if (std::fflush(stdout) != 0) {
      throw IoError(std::string("cannot write to standard output: ") +
                    std::strerror(errno));
    }
  };
  if (!fits && !command.force) {
    finish(false);
    throw Refused(fmt::format(
        "the model does not fit the bed; {} was not written (--force writes "
        "it anyway)",
        output.string()));
  }
  const std::size_t pieces = solid.report.validation.pieces();
  if (pieces > 1 && options.unite) {
    if (command.one_piece) {
      finish(false);
      throw Refused(
          fmt::format("the model is in {} separate pieces; {} was not written "
                      "(--one-piece)",
                      pieces, output.string()));
    }
    std::fprintf(stderr,
                 "warning: the model is in %zu separate pieces, which print "
                 "as loose parts (--one-piece refuses such a model)\n",
                 pieces);
  }
  if (!solid.report.validation.is_printable() && options.unite) {
    finish(false);
    throw Refused(fmt::format("the mesh is not printable; {} was not written",
                              output.string()));
  }
  if (!solid.volumes.empty()) {
    write_colored(solid.volumes, output, format, options.print.colors);
  } else if (colored) {
    write_colored({ColoredMesh{.mesh = solid.mesh, .colors = solid.colors}},
                  output, format, options.print.colors);
  } else {
    write_mesh(solid.mesh, output, format);
  }
  if (text) {
    fmt::print(
        "wrote {}{}\n", output.string(),
        options.unite ? "" : " (overlapping parts, not united: --no-union)");
  }
  if (!preview.empty()) {
    PreviewOptions look;
    look.triangle_colors.reserve(solid.colors.size());
    for (const int color : solid.colors) {
      const Rgb rgb = palette_color(color, options.print.colors);
      look.triangle_colors.emplace_back(rgb.r / 255.0, rgb.g / 255.0,
                                        rgb.b / 255.0);
    }
    write_png(render_preview(solid.mesh, look), preview);
    if (text) fmt::print("rendered {}\n", preview.string());
  }
  finish(true);
}

}  // namespace lsolid::cli
