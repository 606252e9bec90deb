// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/solid.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <map>
#include <optional>
#include <set>
#include <string_view>

#include "flat_model.hpp"
#include "lsolid/boolean.hpp"
#include "lsolid/colors.hpp"
#include "lsolid/containment.hpp"
#include "lsolid/cut.hpp"
#include "lsolid/decimate.hpp"
#include "lsolid/defaults.hpp"
#include "lsolid/errors.hpp"
#include "lsolid/footprint.hpp"
#include "lsolid/parts.hpp"
#include "lsolid/repeated_segments.hpp"
#include "lsolid/rounding.hpp"
#include "lsolid/scale.hpp"
#include "lsolid/units.hpp"
#include "lsolid/validate.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/interpretation.hpp"
#include "lsys/skeleton.hpp"
#include "union_checks.hpp"

namespace lsolid {
namespace {

// The size asked for is met to within 0.01% (0.01 mm at 100 mm) in at
// most this many passes; a size off by more than 1% cannot be met (walls
// too thick for it) and is refused.
constexpr int kSizePasses = 8;
constexpr double kSizeTolerance = 1e-4;
constexpr double kSizeRefused = 0.01;
// Lumps: a median segment wider than long, or a model standing up that
// fills more than half of its bounding box (of the printables, the Hilbert
// cube fills most, 13%, the bush 2%; the 3D Hilbert curve drawn a step
// wide, 73%).
// A segment as wide as it is long is a thick branch, not a lump (ABOP fig.
// 1.24c and d draw steps a width wide, and their pictures are branched
// plants); twice as wide, the tubes swallow the branching.
constexpr double kWideRatio = 2.0;
constexpr double kLumpFill = 0.5;

using Progress = std::function<void(std::string_view, double)>;

class Stopwatch {
 public:
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - start_).count();
    start_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point start_ =
      std::chrono::steady_clock::now();
};

// A cut height at least kCutClearanceMm from every vertex height, within
// a tenth of the cut depth of the wanted one. A tube lying along the plane
// has ring vertices at sin(angle) = -1/2, exactly where a cut half a radius
// deep falls; cutting a hair's breadth from them leaves slivers that fold
// when rounded to doubles.
constexpr double kCutClearanceMm = 1e-3;

double clear_cut_z(const TriangleMesh& mesh, double z, double depth) {
  std::vector<double> heights;
  const double reach = 0.1 * depth;
  for (const glm::dvec3& p : mesh.vertices) {
    if (std::fabs(p.z - z) <= reach) heights.push_back(p.z);
  }
  heights.push_back(z - reach);
  heights.push_back(z + reach);
  std::sort(heights.begin(), heights.end());
  const auto nearest = [&](double at) {
    const auto it = std::lower_bound(heights.begin(), heights.end(), at);
    double d = 1e300;
    if (it != heights.end()) d = *it - at;
    if (it != heights.begin()) d = std::min(d, at - *std::prev(it));
    return d;
  };
  if (nearest(z) >= kCutClearanceMm) return z;
  // The middle of the widest free interval, nearest to z among equals.
  double best = z;
  double best_gap = 0.0;
  for (std::size_t i = 1; i < heights.size(); ++i) {
    const double gap = heights[i] - heights[i - 1];
    const double mid = (heights[i] + heights[i - 1]) / 2.0;
    if (gap > best_gap ||
        (gap == best_gap && std::fabs(mid - z) < std::fabs(best - z))) {
      best_gap = gap;
      best = mid;
    }
  }
  return best;
}

// What the output format keeps of the coordinates of `mesh` (OpenSCAD's
// coarsest step depends on its reach).
Precision precision_of(const SolidOptions& options, const TriangleMesh& mesh) {
  return precision_for(options.format, std::max(reach_mm(mesh), 1.0));
}

// The mesh rounded to what its format keeps and mended (round_for), with a
// warning where a `.scad` had to keep floats.
Rounded round_for_output(const TriangleMesh& mesh, const SolidOptions& options,
                         std::vector<std::string>& warnings) {
  Rounded rounded = round_for(mesh, options.format);
  if (!rounded.as_floats) return rounded;
  const std::string warning =
      "the model has faces finer than OpenSCAD's STL export keeps (six "
      "significant digits): the .scad holds floats, which OpenSCAD reads as "
      "checked, but an STL exported from OpenSCAD may intersect itself; "
      "write the STL with lsolid";
  if (std::find(warnings.begin(), warnings.end(), warning) == warnings.end()) {
    warnings.push_back(warning);
  }
  return rounded;
}

// A mesh cut flat and moved down onto the bed, and what rounding it took.
struct Lowered {
  TriangleMesh mesh;
  RoundingStats rounding;
  std::size_t cavities_filled = 0;
};

// The mesh cut at z_mm, moved down onto z = 0, rounded and mended; nothing
// if CGAL cannot cut it.
std::optional<Lowered> cut_and_lower(const TriangleMesh& mesh, double z_mm,
                                     const SolidOptions& options,
                                     std::vector<std::string>& warnings) {
  std::optional<TriangleMesh> cut = cut_below(mesh, z_mm);
  if (!cut) return std::nullopt;
  for (glm::dvec3& p : cut->vertices) p.z -= z_mm;
  Rounded rounded = round_for_output(*cut, options, warnings);
  CavitiesFilled filled = fill_cavities(std::move(rounded.mesh));
  return Lowered{.mesh = std::move(filled.mesh),
                 .rounding = rounded.stats,
                 .cavities_filled = filled.removed};
}

// Cuts the united model's underside flat at the placement's height, moved
// clear of every vertex, and moves it down onto the bed. A cut that would
// not be printable is refused and the model left lying on its round
// undersides; the placement says which.
void cut_underside(TriangleMesh& mesh, Placement& placement,
                   const SolidOptions& options, SolidReport& report) {
  const double z =
      clear_cut_z(mesh, placement.cut_z_mm, placement.cut_depth_mm);
  std::optional<Lowered> cut = cut_and_lower(mesh, z, options, report.warnings);
  if (!cut || !validate_as_read(cut->mesh, precision_of(options, cut->mesh))
                   .is_printable()) {
    placement.cut_refused = true;
    placement.cut_z_mm = 0.0;
    placement.cut_depth_mm = 0.0;
    return;
  }
  placement.cut_depth_mm += placement.cut_z_mm - z;
  placement.cut_z_mm = z;
  placement.moved_by_mm.z -= z;
  mesh = std::move(cut->mesh);
  accumulate(report.rounding, cut->rounding);
  report.cavities_filled += cut->cavities_filled;
}

// Decimates the finished union where that keeps it printable and keeps
// every witness of `kept`, and checks the mesh as it will be written.
void decimate_and_check(TriangleMesh& mesh, const PartsKept& kept,
                        const SolidOptions& options, SolidReport& report,
                        Stopwatch& clock, const Progress& tell) {
  if (options.unite && options.decimate) {
    tell("decimation", 0.0);
    // The guard keeps every collapse valid; checking the result anyway
    // costs a second and means a failure ships the undecimated mesh, not a
    // broken one. The check runs alongside the measurement of the result's
    // deviation, so its seconds are also among the decimation's.
    ValidationReport checked;
    double check_seconds = 0.0;
    const auto check = [&](const TriangleMesh& result) {
      Stopwatch watch;
      checked = validate_as_read(result, precision_of(options, result));
      check_seconds = watch.lap();
    };
    // A union that cannot be decimated is checked and written as it is;
    // the report says why.
    Decimated decimated = lsolid::decimate(
        mesh, {.tolerance_mm = options.print.tolerance_mm,
               .max_triangles = options.max_triangles,
               .progress = [&](double done) { tell("decimation", done); },
               .alongside = check});
    report.decimation = decimated.stats;
    report.seconds.decimate = clock.lap();
    tell("check", 0.0);
    if (!decimated.refused.empty()) {
      report.decimation_discarded =
          "could not be made (" + decimated.refused + ")";
    } else {
      report.validation = std::move(checked);
      if (!report.validation.is_printable()) {
        report.decimation_discarded = "failed the check";
      } else if (lost_in_decimation(decimated, kept, options.print.tolerance_mm,
                                    report.placement.cut_z_mm)) {
        report.decimation_discarded = "lost part of the model";
        report.validation = ValidationReport{};
      }
    }
    if (report.validation.is_printable()) {
      mesh = std::move(decimated.mesh);
      report.decimated = true;
      report.seconds.check = check_seconds + clock.lap();
      tell("check", 1.0);
      return;
    }
  }
  tell("check", 0.0);
  report.validation = validate_as_read(mesh, precision_of(options, mesh));
  report.seconds.check = clock.lap();
  tell("check", 1.0);
}

// The union of the parts with `engine`, rounded to the file's precision,
// its cavities filled, and checked to keep the parts (check_union_kept).
// @throws GeometryError as union_parts and check_union_kept, and when the
//   exact engine's union does not round clean.
void unite_and_round(std::vector<Part> parts, UnionEngine engine,
                     const PartsKept& kept, const SolidOptions& options,
                     SolidReport& report, TriangleMesh& mesh, Stopwatch& clock,
                     const Progress& tell) {
  UnionResult united = union_parts(
      std::move(parts), {.progress = [&](double done) { tell("union", done); },
                         .expect =
                             [&](double seconds) {
                               if (options.expect)
                                 options.expect("union", seconds);
                             },
                         .engine = engine,
                         .threads = options.threads});
  CavitiesFilled filled = fill_cavities(std::move(united.mesh));
  report.union_stats = united.stats;
  report.cavities_filled = filled.removed;
  report.seconds.unite += clock.lap();
  tell("rounding", 0.0);
  Rounded rounded = round_for_output(filled.mesh, options, report.warnings);
  // The exact engine's union must round clean, or it is done again by the
  // corefinement (unite_and_finish): a result the repairs could not finish
  // is never handed on as the engine's.
  if (engine == UnionEngine::ExactCrossings && !rounded.clean) {
    throw GeometryError(
        "rounding left degenerate or intersecting faces it could not mend");
  }
  report.rounding = {};
  accumulate(report.rounding, rounded.stats);
  filled = fill_cavities(std::move(rounded.mesh));
  mesh = std::move(filled.mesh);
  report.cavities_filled += filled.removed;
  report.witnesses_checked = check_union_kept(mesh, kept);
}

// The union of the parts, rounded to the file's precision, its underside
// cut flat if it lies flat (the cut after the union: cut part by part, the
// coplanar caps made the union three times as slow on ABOP fig. 1.24a, and
// the union of the caps three times the triangles), decimated where that
// stays printable, and its check, into `mesh` and `report`. A union by the
// exact engine that fails its checks is done again by the corefinement
// (the safety net, docs/design.md), and the report says why.
void unite_and_finish(std::vector<Part> parts, const SolidOptions& options,
                      SolidReport& report, TriangleMesh& mesh, Stopwatch& clock,
                      const Progress& tell) {
  tell("union", 0.0);
  PartsKept kept;
  if (!options.unite) {
    for (const Part& part : parts) append(mesh, part.mesh);
    report.seconds.unite = clock.lap();
    tell("rounding", 0.0);
    mesh = snapped(mesh, precision_of(options, mesh));
    report.seconds.round = clock.lap();
    decimate_and_check(mesh, kept, options, report, clock, tell);
    return;
  }
  kept = parts_kept(parts);
  if (options.union_engine == UnionEngine::ExactCrossings) {
    std::vector<Part> spare = parts;
    try {
      unite_and_round(std::move(parts), options.union_engine, kept, options,
                      report, mesh, clock, tell);
    } catch (const GeometryError& e) {
      const std::size_t fallbacks = report.union_stats.fallbacks;
      const std::string reason =
          std::string("the exact engine's union failed its check: ") + e.what();
      mesh = {};
      unite_and_round(std::move(spare), UnionEngine::Corefinement, kept,
                      options, report, mesh, clock, tell);
      report.union_stats.engine = UnionEngine::ExactCrossings;
      report.union_stats.fallbacks += fallbacks + 1;
      report.union_stats.fallback_reason = reason;
      report.warnings.push_back(reason +
                                "; united again by CGAL's "
                                "corefinement");
    }
  } else {
    unite_and_round(std::move(parts), options.union_engine, kept, options,
                    report, mesh, clock, tell);
  }
  if (report.placement.lies_flat && report.placement.cut_z_mm > 0.0) {
    cut_underside(mesh, report.placement, options, report);
  }
  report.seconds.round = clock.lap();
  decimate_and_check(mesh, kept, options, report, clock, tell);
}

// A planar model lying flat, with the flat profile: the outlines of its
// branches and leaves united in the plane and extruded, as high as the
// round model stands once cut, in place of the 3D union and cut (ABOP
// fig. 1.24b: about 0.4 s against 300 s). The parts' witnesses above the
// cut must lie inside it, as they must inside the 3D union.
void extrude_and_finish(const FlatModel& flat, const std::vector<Part>& parts,
                        const SolidOptions& options, SolidReport& report,
                        TriangleMesh& mesh, Stopwatch& clock,
                        const Progress& tell) {
  tell("union", 0.0);
  const PartsKept kept = parts_kept(parts);
  Placement& placement = report.placement;
  Extruded extruded = extrude_flat_model(flat);
  mesh = std::move(extruded.mesh);
  report.flat_outlines = extruded.outlines;
  report.flat_rings = extruded.rings;
  report.seconds.unite = clock.lap();
  tell("union", 1.0);
  tell("rounding", 0.0);
  Rounded rounded = round_for_output(mesh, options, report.warnings);
  mesh = std::move(rounded.mesh);
  accumulate(report.rounding, rounded.stats);
  placement.moved_by_mm.z -= placement.cut_z_mm;
  report.witnesses_checked = check_witnesses(
      mesh, lowered(kept.witnesses, placement.cut_z_mm), kept, "the footprint",
      "; --profile round builds it as round tubes");
  report.seconds.round = clock.lap();
  decimate_and_check(mesh, kept, options, report, clock, tell);
}

// The whole model as the one volume of a model in one colour.
ColoredMesh one_volume(const Solid& whole, int color) {
  return ColoredMesh{
      .mesh = whole.mesh,
      .colors = std::vector<int>(whole.mesh.triangles.size(), color)};
}

// Appends the volume of `color` to `volumes`.
// @throws GeometryError if it is not printable.
void add_volume(std::vector<ColoredMesh>& volumes, TriangleMesh volume,
                int color, const SolidOptions& options) {
  const ValidationReport check =
      validate_as_read(volume, precision_of(options, volume));
  if (!check.is_printable()) {
    throw GeometryError(fmt::format(
        "the volume of colour {}, less the colours below it, is not "
        "printable: {}",
        color, fmt::join(check.problems(), "; ")));
  }
  const std::size_t n = volume.triangles.size();
  volumes.push_back(ColoredMesh{.mesh = std::move(volume),
                                .colors = std::vector<int>(n, color)});
}

// The flat profile's volumes per colour: each material's outlines less
// those of the materials below it, extruded like the whole model.
// @throws GeometryError if a volume is not printable.
std::vector<ColoredMesh> flat_color_volumes(const FlatModel& flat,
                                            const Solid& whole,
                                            const SolidOptions& options) {
  std::set<int> materials(flat.materials.begin(), flat.materials.end());
  if (materials.size() <= 1) {
    return {one_volume(whole, materials.empty() ? 0 : *materials.begin())};
  }
  std::vector<ColoredMesh> volumes;
  std::vector<std::vector<glm::dvec2>> below;
  for (const int material : materials) {
    std::vector<std::vector<glm::dvec2>> own = flat.of(material);
    const Footprint footprint = footprint_union(own, below);
    below.insert(below.end(), own.begin(), own.end());
    if (footprint.rings.empty()) continue;
    const TriangleMesh extruded = extrude(footprint, flat.height_mm);
    TriangleMesh volume =
        round_and_repair(extruded,
                         {.precision = precision_of(options, extruded)})
            .mesh;
    add_volume(volumes, std::move(volume), material, options);
  }
  return volumes;
}

// One volume per colour that do not overlap, for printers with an extruder
// per colour: the union of each colour's parts, finished like the whole
// model, less what the lower colours already fill (a leaf loses what lies
// inside its stem, colour 0 keeps all of its own). Volumes that nothing is
// left of are dropped.
// @throws GeometryError if a volume is not printable.
std::vector<ColoredMesh> color_volumes(std::vector<Part> parts,
                                       const Solid& whole,
                                       const SolidOptions& options,
                                       const Progress& tell) {
  std::map<int, std::vector<Part>> by_color;
  for (Part& part : parts) by_color[part.color].push_back(std::move(part));
  if (by_color.size() <= 1) {
    return {one_volume(whole, by_color.empty() ? 0 : by_color.begin()->first)};
  }
  std::vector<ColoredMesh> volumes;
  TriangleMesh filled;  // the union of the volumes so far
  std::size_t done = 0;
  // The estimate told is the whole model's union, not each colour's.
  SolidOptions per_color = options;
  per_color.expect = nullptr;
  for (auto& [color, group] : by_color) {
    // United uncut: cut volumes would meet on coplanar undersides, where
    // the subtraction's new points fold when rounded. Each volume is cut
    // at the end, at the whole model's height.
    SolidReport scratch;
    Stopwatch clock;
    TriangleMesh own;
    unite_and_finish(std::move(group), per_color, scratch, own, clock,
                     [](std::string_view, double) {});
    if (!scratch.validation.is_printable()) {
      throw GeometryError(
          fmt::format("the volume of colour {} is not printable: {}", color,
                      fmt::join(scratch.validation.problems(), "; ")));
    }
    const RoundingOptions rounding{.precision =
                                       precision_of(options, whole.mesh)};
    TriangleMesh volume =
        filled.triangles.empty()
            ? own
            : round_and_repair(subtract(own, filled), rounding).mesh;
    const Placement& placed = whole.report.placement;
    if (!volume.triangles.empty() && placed.lies_flat && placed.cut_z_mm > 0) {
      std::optional<Lowered> cut =
          cut_and_lower(volume, placed.cut_z_mm, options, scratch.warnings);
      if (!cut || cut->mesh.triangles.empty()) {
        throw GeometryError(fmt::format(
            "the volume of colour {} could not be cut flat", color));
      }
      volume = std::move(cut->mesh);
    }
    if (!volume.triangles.empty()) {
      add_volume(volumes, std::move(volume), color, options);
    }
    if (filled.triangles.empty()) {
      filled = std::move(own);
    } else {
      std::vector<Part> both;
      both.push_back(Part{.mesh = std::move(filled), .label = "lower colours"});
      both.push_back(Part{.mesh = std::move(own),
                          .label = fmt::format("colour {}", color)});
      filled =
          round_and_repair(union_parts(std::move(both)).mesh, rounding).mesh;
    }
    tell("volumes", double(++done) / double(by_color.size()));
  }
  return volumes;
}

// A file whose widths are in other units than its lengths (Honda's trees
// in ABOP Table 2.1: `A(1, 10)`, width 10 for length 1), or that sets no
// width in a dialect whose default is a whole step, prints as a lump. The
// segments' median width over length says the first.
std::optional<std::string> widths_dwarf_lengths(
    const lsys::Skeleton& skeleton) {
  std::vector<double> ratios;
  for (const lsys::Segment& s : skeleton.segments) {
    const double length = glm::length(s.p1 - s.p0);
    if (length <= 0.0) continue;
    ratios.push_back(std::max(s.start_diameter, s.end_diameter) / length);
  }
  if (ratios.empty()) return std::nullopt;
  auto middle = ratios.begin() + static_cast<std::ptrdiff_t>(ratios.size() / 2);
  std::nth_element(ratios.begin(), middle, ratios.end());
  if (*middle <= kWideRatio) return std::nullopt;
  return fmt::format(
      "the widths dwarf the lengths: the median segment is {:.3g} times as "
      "wide as it is long, so the branching is lost in the tubes; if the "
      "file's "
      "widths are in other units than its lengths, set `width scale:` (or a "
      "smaller `width:`)",
      *middle);
}

// The share of its bounding box a united model fills. Tubes a whole step
// wide (the 3D Hilbert curve with cpfg's default width) fill most of it.
std::optional<std::string> fills_its_box(const SolidReport& report,
                                         double wall_mm) {
  const ValidationReport& v = report.validation;
  const glm::dvec3 size = v.bounds.size();
  const double box = size.x * size.y * size.z;
  if (report.placement.lies_flat || !(box > 0.0)) return std::nullopt;
  const double fill = v.volume_mm3 / box;
  if (fill <= kLumpFill) return std::nullopt;
  return fmt::format(
      "the model fills {:.0f}% of its bounding box ({:.1f} cm³ of material): "
      "its tubes are as wide as their spacing; set a smaller `width:` or "
      "`width scale:` in the file, or a larger --size (the wall, {:.2g} mm, "
      "widens thinner lines)",
      100.0 * fill, v.volume_mm3 / 1000.0, wall_mm);
}

// The longest side of what the skeleton draws, tube widths not counted; not
// above 0 when it draws nothing or a point.
double drawing_extent(const lsys::Skeleton& skeleton) {
  const glm::dvec3 size = lsys::bounds(skeleton).size();
  return std::max({size.x, size.y, size.z});
}

// Fitting a model to its size shrinks its drawing with its widths: a width
// thousands of times the drawing's extent (`!(1e200)F`, a thickness of
// 1e308) shrinks the segments below what the tubes can be built from (at
// a ratio of a million a union lost a part; at 1e200 the tubes are no
// solids). Such a model is a lump at best: refuse the width at its place.
void refuse_widths_that_dwarf_the_drawing(const lsys::Grammar& grammar,
                                          const lsys::Skeleton& skeleton) {
  constexpr double kMostRatio = 1e4;
  double widest = 0.0;
  for (const lsys::Segment& s : skeleton.segments) {
    widest = std::max({widest, s.start_diameter, s.end_diameter});
  }
  const double extent = drawing_extent(skeleton);
  if (!(extent > 0.0) || widest <= kMostRatio * extent) return;
  throw lsys::width_error(
      grammar, widest,
      fmt::format("a width of {:g} units is more than {:g} times the "
                  "drawing's extent ({:g} unit{}): fitted to its size, the "
                  "drawing would shrink below what lsolid can build; set a "
                  "smaller width (or `width scale:`)",
                  widest, kMostRatio, extent, extent == 1.0 ? "" : "s"));
}

// A scale asked for (`--scale`, or the file's `scale:`) so small that the
// drawing shrinks below a micrometre, where tubes have no length: refused
// where it is given, as a size that cannot be met is.
void refuse_a_scale_below_a_micrometre(const lsys::Grammar& grammar,
                                       const lsys::Skeleton& skeleton,
                                       const PrintSettings& print) {
  constexpr double kFinestMm = 1e-3;
  if (!print.scale_mm_per_unit) return;
  const double mm_per_unit = *print.scale_mm_per_unit;
  const double extent = drawing_extent(skeleton);
  if (!(extent > 0.0) || extent * mm_per_unit >= kFinestMm) return;
  const std::string message = fmt::format(
      "at a scale of {:g} mm per unit the drawing spans {:g} mm, less than "
      "the {:g} mm lsolid builds to (choose a larger scale)",
      mm_per_unit, extent * mm_per_unit, kFinestMm);
  // The file's `scale:` when it is the scale used, else --scale.
  for (const lsys::ExtraSetting& s : grammar.extra_settings) {
    if (s.key == "scale" && parse_length_mm(s.value, s.key) == mm_per_unit) {
      throw lsys::error_at(*grammar.source, s.offset, message);
    }
  }
  throw lsys::ParseError(
      lsys::Diagnostic{.file = "--scale", .message = message});
}

// The scale asked for (`--scale`) may carry a huge drawing (`F(1e300)`)
// far past any printer, where grid keys and exact arithmetic overflow:
// refuse a model reaching beyond a kilometre as bad input.
void refuse_beyond_a_kilometre(const lsys::Grammar& grammar,
                               const ScaledSkeleton& scaled) {
  constexpr double kMostMm = 1e6;
  double reach = 0.0;
  const auto grow = [&](const glm::dvec3& p, double radius) {
    reach = std::max({reach, std::fabs(p.x) + radius, std::fabs(p.y) + radius,
                      std::fabs(p.z) + radius});
  };
  for (const lsys::Segment& s : scaled.skeleton.segments) {
    grow(s.p0, s.start_diameter / 2.0);
    grow(s.p1, s.end_diameter / 2.0);
  }
  for (const lsys::Polygon& polygon : scaled.skeleton.polygons) {
    for (const glm::dvec3& p : polygon.points) grow(p, 0.0);
  }
  for (const lsys::Sphere& s : scaled.skeleton.spheres) {
    grow(s.center, s.diameter / 2.0);
  }
  for (const lsys::Sheet& sheet : scaled.skeleton.sheets) {
    for (const glm::dvec3& p : sheet.points) grow(p, 0.0);
  }
  if (reach <= kMostMm) return;
  throw lsys::error_at(*grammar.source, grammar.axiom_offset,
                       fmt::format("at {:g} mm per unit the model reaches "
                                   "{:g} mm from its origin, more than the 1 "
                                   "km (1000000 mm) lsolid builds",
                                   scaled.mm_per_unit, reach));
}

// The whole build from the skeleton on; `clock` started before the skeleton
// was drawn, if it was drawn for this build.
Solid build_from_skeleton(const lsys::Grammar& grammar,
                          const lsys::Skeleton& drawn,
                          const SolidOptions& options, Stopwatch& clock) {
  // The part builder's tests, the union and the decimation run on oneTBB's
  // threads.
  std::optional<tbb::global_control> limit;
  if (options.threads > 0) {
    limit.emplace(tbb::global_control::max_allowed_parallelism,
                  static_cast<std::size_t>(options.threads));
  }
  Solid solid;
  SolidReport& report = solid.report;
  const auto tell = [&](std::string_view stage, double fraction) {
    if (options.progress) options.progress(stage, fraction);
  };
  // Drawing nothing is a mistake in the input, placed where it is made.
  if (lsys::draws_nothing(drawn)) {
    throw lsys::nothing_drawn_error(grammar, drawn);
  }
  refuse_widths_that_dwarf_the_drawing(grammar, drawn);
  // A segment drawn again over an earlier one adds nothing to the print,
  // only coincident tubes for the union to meet face on face.
  const WithoutRepeats unique = without_repeated_segments(drawn);
  const lsys::Skeleton& skeleton = unique.skeleton;
  report.repeated_segments = unique.dropped;
  report.segments = drawn.segments.size();
  report.polygons = skeleton.polygons.size();
  report.dropped.degenerate_polygons = skeleton.degenerate_polygons;
  report.dropped.unclosed_polygons = skeleton.unclosed_polygons;
  report.dropped.unmatched_polygon_ends = skeleton.unmatched_polygon_ends;
  report.seconds.skeleton = clock.lap();
  if (auto warning = widths_dwarf_lengths(skeleton)) {
    report.warnings.push_back(std::move(*warning));
  }
  tell("parts", 0.0);

  // estimate_scale sizes the skeleton with round tubes; mitres, joints,
  // hulls and a base disc reach beyond, so the placed parts are measured and
  // the scale corrected until the size asked for holds (the longest side,
  // or the height, of everything printed, base included).
  const PrintSettings& print = options.print;
  ScaledSkeleton scaled;
  PartSet parts;
  const bool sized = !options.print.scale_mm_per_unit.has_value();
  const double wanted = options.print.height_mm.value_or(
      options.print.size_mm.value_or(kDefaultSizeMm));
  double actual = 0.0;
  // A planar model lying flat with the flat profile is sized by what it
  // prints, its outlines and height, not by its round parts.
  FlatModel flat;
  bool is_flat = false;
  refuse_a_scale_below_a_micrometre(grammar, skeleton, print);
  double mm_per_unit = estimate_scale(skeleton, print);
  bool parts_tested = false;
  for (int pass = 0; pass < kSizePasses; ++pass) {
    // The first pass of a sized build only measures: its parts are not
    // tested for cutting themselves (most of their time), which leaves
    // their box as it is unless a hull junction at the very edge would be
    // left to the union; the pass that builds is always tested and always
    // measured again.
    const bool measuring = sized && pass == 0;
    scaled = scale_skeleton(skeleton, mm_per_unit, print.wall_mm);
    refuse_beyond_a_kilometre(grammar, scaled);
    const std::optional<SkeletonPlane> plane =
        options.unite ? skeleton_plane(scaled.skeleton, print.wall_mm)
                      : std::nullopt;
    // A planar model will most likely print as its footprint: its coplanar
    // polygons need not be united in 3D (minutes for 500 overlapping discs,
    // where the footprint takes a second). If it does not lie flat after
    // all, its parts are built again with them united.
    const auto build = [&](bool unite_coplanar) {
      return build_parts(
          scaled.skeleton,
          {.wall_mm = print.wall_mm,
           .tolerance_mm = print.tolerance_mm,
           .split_colors = options.colors || options.multi_material,
           .unite_coplanar_polygons = unite_coplanar,
           .check_self_intersections = !measuring});
    };
    const bool maybe_flat = plane && print.profile == Profile::Flat;
    const PlacementOptions placing{.base = print.base,
                                   .wall_mm = print.wall_mm,
                                   .tolerance_mm = print.tolerance_mm,
                                   .plane = plane};
    const auto place = [&](bool unite_coplanar) {
      parts = build(unite_coplanar);
      parts_tested = !measuring;
      Placed placed = place_on_bed(std::move(parts.parts), placing);
      parts.parts = std::move(placed.parts);
      report.placement = placed.placement;
    };
    place(!maybe_flat);
    is_flat = options.unite && report.placement.lies_flat &&
              print.profile == Profile::Flat;
    if (maybe_flat && !is_flat) place(true);
    if (is_flat) {
      flat = flat_model(scaled.skeleton, report.placement, print);
    }
    if (!sized || parts.parts.empty()) break;
    const glm::dvec3 size = is_flat ? extent(flat) : bounds(parts.parts).size();
    actual =
        options.print.height_mm ? size.z : std::max({size.x, size.y, size.z});
    if (std::fabs(actual - wanted) <= kSizeTolerance * wanted) {
      if (!measuring) break;
      continue;  // built again, tested, at the same scale
    }
    mm_per_unit = scaled.mm_per_unit * wanted / actual;
  }
  // Parts that may cut themselves are for measuring only; the union must
  // never get them.
  if (!parts.parts.empty() && !parts_tested) {
    throw GeometryError(
        "internal error: the parts to unite were built for measuring only "
        "(please report it with this file)");
  }
  if (sized && !parts.parts.empty() &&
      std::fabs(actual - wanted) > kSizeRefused * wanted) {
    const char* what = options.print.height_mm ? "height" : "size";
    throw lsys::ParseError(lsys::Diagnostic{
        .file = std::string("--") + what,
        .message = fmt::format(
            "a {} of {:.4g} mm cannot be met: with walls of {:.4g} mm the "
            "model comes out {:.4g} mm (choose a larger {} or a thinner "
            "--wall)",
            what, wanted, options.print.wall_mm, actual, what)});
  }
  // Indices of one colour are one material: one volume, one base material.
  for (Part& part : parts.parts) {
    part.color = material_index(part.color, options.print.colors);
  }
  report.mm_per_unit = scaled.mm_per_unit;
  report.tubes = parts.tubes;
  report.junctions = parts.junctions;
  report.joints = parts.joints;
  report.spheres = parts.spheres;
  report.sheets = parts.sheets;
  if (parts.hulled_sheets > 0) {
    report.warnings.push_back(fmt::format(
        "{} of {} surfaces, a few walls across, bend too sharply to thicken "
        "and are printed as the convex hull of their thickened points",
        parts.hulled_sheets, parts.sheets));
  }
  if (parts.thinned_sheets > 0) {
    report.warnings.push_back(fmt::format(
        "{} of {} surfaces fold more sharply than they are thick and are "
        "thinner there, down to {:.2f} mm (below the wall: a slicer may "
        "leave those spots out)",
        parts.thinned_sheets, parts.sheets, parts.thinnest_sheet_mm));
  }
  report.plates = parts.plates;
  report.skipped_polygons = parts.skipped_polygons;
  report.seconds.parts = clock.lap();
  std::vector<Part> colored;
  if (options.colors || options.multi_material) {
    colored = parts.parts;
  } else if (options.preview_colors) {
    // The colours are looked up on parts built one colour each, placed as
    // the united parts were, so a tube that changes colour shows both; the
    // union keeps its long tubes and hull junctions, which split colours
    // would cost it (twelve to fifteen times the union's time on the ABOP
    // bush at n = 4: 0.2 s against 2.6 to 3.3 s).
    PartSet split =
        build_parts(scaled.skeleton, {.wall_mm = print.wall_mm,
                                      .tolerance_mm = print.tolerance_mm,
                                      .split_colors = true,
                                      .unite_coplanar_polygons = false});
    for (Part& part : split.parts) {
      part.color = material_index(part.color, options.print.colors);
      for (glm::dvec3& p : part.mesh.vertices) p = on_bed(report.placement, p);
    }
    if (report.placement.has_base) split.parts.push_back(parts.parts.back());
    colored = std::move(split.parts);
  }
  if (is_flat) {
    extrude_and_finish(flat, parts.parts, options, report, solid.mesh, clock,
                       tell);
  } else {
    unite_and_finish(std::move(parts.parts), options, report, solid.mesh, clock,
                     tell);
  }
  // The united model was moved down by its cut, if any; its colours are
  // looked up on the parts moved alike.
  if (options.colors || options.preview_colors) {
    std::vector<Part> moved = colored;
    for (Part& part : moved) {
      for (glm::dvec3& p : part.mesh.vertices) p.z -= report.placement.cut_z_mm;
    }
    solid.colors = color_triangles(solid.mesh, moved);
  }
  if (options.multi_material && options.unite &&
      report.validation.is_printable()) {
    tell("volumes", 0.0);
    solid.volumes =
        is_flat ? flat_color_volumes(flat, solid, options)
                : color_volumes(std::move(colored), solid, options, tell);
    report.seconds.volumes = clock.lap();
    tell("volumes", 1.0);
  }
  if (options.unite && report.validation.is_printable()) {
    if (auto warning = fills_its_box(report, options.print.wall_mm)) {
      report.warnings.push_back(std::move(*warning));
    }
  }
  return solid;
}

}  // namespace

Solid build_solid(const lsys::Grammar& grammar, const SolidOptions& options) {
  Stopwatch clock;
  if (options.progress) options.progress("skeleton", 0.0);
  const lsys::Skeleton drawn =
      lsys::interpret(grammar, options.derivation, options.interpretation);
  return build_from_skeleton(grammar, drawn, options, clock);
}

Solid build_solid(const lsys::Grammar& grammar, const lsys::Skeleton& drawn,
                  const SolidOptions& options) {
  Stopwatch clock;
  return build_from_skeleton(grammar, drawn, options, clock);
}

}  // namespace lsolid
