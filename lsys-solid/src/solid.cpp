// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/solid.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "lsolid/cut.hpp"
#include "lsolid/decimate.hpp"
#include "lsolid/errors.hpp"
#include "lsolid/parts.hpp"
#include "lsolid/rounding.hpp"
#include "lsolid/scale.hpp"

namespace lsolid {
namespace {

constexpr int kSizePasses = 4;
constexpr double kSizeTolerance = 0.002;
constexpr double kDefaultSizeMm = 100.0;  // as scale_to_print's default

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

}  // namespace

Solid build_solid(const lsys::Grammar& grammar, const SolidOptions& options) {
  Solid solid;
  SolidReport& report = solid.report;
  Stopwatch clock;
  const auto tell = [&](std::string_view stage, double fraction) {
    if (options.progress) options.progress(stage, fraction);
  };
  tell("skeleton", 0.0);
  const lsys::Skeleton skeleton =
      lsys::interpret(grammar, options.derivation, options.interpretation);
  report.segments = skeleton.segments.size();
  report.polygons = skeleton.polygons.size();
  report.dropped.degenerate_polygons = skeleton.degenerate_polygons;
  report.dropped.unclosed_polygons = skeleton.unclosed_polygons;
  report.dropped.unmatched_polygon_ends = skeleton.unmatched_polygon_ends;
  report.seconds.skeleton = clock.lap();
  tell("parts", 0.0);

  // scale_to_print sizes the skeleton with round tubes; mitres, joints and
  // hulls reach a little beyond, so the parts are measured and the scale
  // corrected until the size asked for holds within 0.2%.
  PrintSettings print = options.print;
  ScaledSkeleton scaled;
  PartSet parts;
  for (int pass = 0; pass < kSizePasses; ++pass) {
    scaled = scale_to_print(skeleton, print);
    parts = build_parts(scaled.skeleton, {.wall_mm = print.wall_mm,
                                          .tolerance_mm = print.tolerance_mm});
    if (options.print.scale_mm_per_unit || parts.parts.empty()) break;
    const glm::dvec3 extent = bounds(parts.parts).size();
    const double actual = options.print.height_mm
                              ? extent.z
                              : std::max({extent.x, extent.y, extent.z});
    const double wanted = options.print.height_mm.value_or(
        options.print.size_mm.value_or(kDefaultSizeMm));
    if (std::fabs(actual - wanted) <= kSizeTolerance * wanted) break;
    print.scale_mm_per_unit = scaled.mm_per_unit * wanted / actual;
    print.height_mm.reset();
    print.size_mm.reset();
  }
  report.mm_per_unit = scaled.mm_per_unit;
  report.tubes = parts.tubes;
  report.junctions = parts.junctions;
  report.joints = parts.joints;
  report.plates = parts.plates;
  report.skipped_polygons = parts.skipped_polygons;
  report.placement = place_on_bed(
      parts.parts, options.print.base, options.print.wall_mm,
      options.print.tolerance_mm,
      options.unite ? skeleton_plane(scaled.skeleton, print.wall_mm)
                    : std::nullopt);
  if (report.placement.lies_flat && report.placement.cut_z_mm > 0.0) {
    const double z = report.placement.cut_z_mm;
    for (Part& part : parts.parts) {
      if (bounds(part.mesh).min.z < z) {
        // Rounding the cut's exact points to doubles can fold a cap that
        // had three points in a row; such a part stays uncut.
        TriangleMesh cut = cut_below(part.mesh, z);
        if (validate(cut).is_printable()) {
          part.mesh = std::move(cut);
        } else {
          ++report.placement.parts_left_uncut;
        }
      }
      for (glm::dvec3& p : part.mesh.vertices) p.z -= z;
    }
    std::erase_if(parts.parts,
                  [](const Part& part) { return part.mesh.triangles.empty(); });
    report.placement.moved_by_mm.z -= z;
  }
  report.seconds.parts = clock.lap();
  tell("union", 0.0);

  if (options.unite) {
    UnionResult united = union_parts(std::move(parts.parts),
                                     [&](double done) { tell("union", done); });
    solid.mesh = std::move(united.mesh);
    report.union_stats = united.stats;
    report.cavities_filled = remove_cavities(solid.mesh);
  } else {
    for (const Part& part : parts.parts) append(solid.mesh, part.mesh);
  }
  report.seconds.unite = clock.lap();
  tell("rounding", 0.0);
  if (options.unite) {
    solid.mesh = round_and_repair(solid.mesh, options.float_coordinates,
                                  report.rounding);
    report.cavities_filled += remove_cavities(solid.mesh);
  } else if (options.float_coordinates) {
    solid.mesh = round_to_float(solid.mesh);
  }
  report.seconds.round = clock.lap();

  if (options.unite && options.decimate) {
    tell("decimation", 0.0);
    Decimated decimated;
    try {
      decimated = lsolid::decimate(
          solid.mesh,
          {.tolerance_mm = options.print.tolerance_mm,
           .max_triangles = options.max_triangles,
           .progress = [&](double done) { tell("decimation", done); }});
    } catch (const GeometryError&) {
      // A union that is not a 2-manifold cannot be decimated; it is
      // written as it is and its check says why.
      decimated.mesh.triangles.clear();
    }
    report.decimation = decimated.stats;
    report.seconds.decimate = clock.lap();
    tell("check", 0.0);
    // The guard keeps every collapse valid; checking the result anyway
    // costs a second and means a failure ships the undecimated mesh, not a
    // broken one.
    if (!decimated.mesh.triangles.empty()) {
      report.validation = validate(decimated.mesh);
    }
    if (report.validation.is_printable()) {
      solid.mesh = std::move(decimated.mesh);
      report.decimated = true;
      report.seconds.check = clock.lap();
      tell("check", 1.0);
      return solid;
    }
  }
  tell("check", 0.0);
  report.validation = validate(solid.mesh);
  report.seconds.check = clock.lap();
  tell("check", 1.0);
  return solid;
}

}  // namespace lsolid
