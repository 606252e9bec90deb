// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/solid.hpp"

#include <chrono>

#include "lsolid/parts.hpp"
#include "lsolid/rounding.hpp"
#include "lsolid/scale.hpp"

namespace lsolid {
namespace {

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

  const ScaledSkeleton scaled = scale_to_print(skeleton, options.print);
  report.mm_per_unit = scaled.mm_per_unit;
  PartSet parts = build_parts(scaled.skeleton,
                              {.wall_mm = options.print.wall_mm,
                               .tolerance_mm = options.print.tolerance_mm});
  report.tubes = parts.tubes;
  report.junctions = parts.junctions;
  report.joints = parts.joints;
  report.plates = parts.plates;
  report.skipped_polygons = parts.skipped_polygons;
  report.placement =
      place_on_bed(parts.parts, options.print.base, options.print.wall_mm,
                   options.print.tolerance_mm);
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
  tell("check", 0.0);

  report.validation = validate(solid.mesh);
  report.seconds.check = clock.lap();
  tell("check", 1.0);
  return solid;
}

}  // namespace lsolid
