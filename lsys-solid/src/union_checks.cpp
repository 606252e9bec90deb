// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "union_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <glm/vec3.hpp>

#include "lsolid/errors.hpp"
#include "lsolid/validate.hpp"

namespace lsolid {
namespace {

// How far below a part's surface a witness must lie to be required inside
// the rounded union: rounding moves points by far less (slivers under
// 1e-4 mm are collapsed).
constexpr double kRoundingDepthMm = 1e-3;
// The union's volume may fall short of its largest part's by rounding only.
constexpr double kVolumeSlack = 1e-5;

// The parts that `outside` names, for a message.
std::string lost_parts(const std::vector<Witness>& outside,
                       const PartsKept& kept) {
  std::vector<std::size_t> parts;
  for (const Witness& w : outside) {
    if (std::find(parts.begin(), parts.end(), w.part) == parts.end()) {
      parts.push_back(w.part);
    }
  }
  std::string out;
  const std::size_t shown = std::min<std::size_t>(parts.size(), 3);
  for (std::size_t i = 0; i < shown; ++i) {
    const auto w =
        std::find_if(outside.begin(), outside.end(),
                     [&](const Witness& x) { return x.part == parts[i]; });
    out += fmt::format(
        "{}{} (the point ({:.3f}, {:.3f}, {:.3f}) mm, {:.2f} mm "
        "inside it, is outside the result)",
        i == 0 ? "" : "; ", kept.labels[parts[i]], w->point.x, w->point.y,
        w->point.z, w->depth_mm);
  }
  if (parts.size() > shown) {
    out += fmt::format(" and {} more parts", parts.size() - shown);
  }
  return out;
}

}  // namespace

PartsKept parts_kept(const std::vector<Part>& parts) {
  PartsKept kept{.witnesses = witnesses(parts)};
  for (const Part& part : parts) {
    kept.labels.push_back(part.label);
    const double volume = signed_volume(part.mesh);
    if (volume > kept.largest_mm3) {
      kept.largest_mm3 = volume;
      kept.largest = part.label;
    }
  }
  return kept;
}

std::size_t check_witnesses(const TriangleMesh& mesh,
                            const std::vector<Witness>& witnesses,
                            const PartsKept& kept, std::string_view what,
                            std::string_view advice) {
  const std::vector<Witness> outside =
      witnesses_outside(mesh, witnesses, kRoundingDepthMm);
  const auto checked = static_cast<std::size_t>(std::count_if(
      witnesses.begin(), witnesses.end(),
      [](const Witness& w) { return w.depth_mm >= kRoundingDepthMm; }));
  if (!outside.empty()) {
    throw GeometryError(fmt::format(
        "{} lost part of the model (a bug in lsolid; please report it with "
        "this file{}): {}",
        what, advice, lost_parts(outside, kept)));
  }
  const std::vector<Shell> fragments =
      unaccounted_pieces(mesh, witnesses, kRoundingDepthMm);
  if (!fragments.empty()) {
    const glm::dvec3 at =
        (fragments.front().bounds.min + fragments.front().bounds.max) / 2.0;
    throw GeometryError(fmt::format(
        "the repair of {} left {} loose fragment{} that no part accounts for "
        "(a bug in lsolid; please report it with this file{}): the largest "
        "{:.3g} mm³ around ({:.3f}, {:.3f}, {:.3f}) mm",
        what, fragments.size(), fragments.size() == 1 ? "" : "s", advice,
        fragments.front().volume_mm3, at.x, at.y, at.z));
  }
  return checked;
}

std::size_t check_union_kept(const TriangleMesh& mesh, const PartsKept& kept) {
  const std::size_t checked =
      check_witnesses(mesh, kept.witnesses, kept, "the union", "");
  const double volume = signed_volume(mesh);
  if (volume < kept.largest_mm3 * (1.0 - kVolumeSlack)) {
    throw GeometryError(fmt::format(
        "the union lost part of the model (a bug in lsolid; please report it "
        "with this file): its volume, {:.3f} mm³, is less than that of {}, "
        "{:.3f} mm³",
        volume, kept.largest, kept.largest_mm3));
  }
  return checked;
}

std::vector<Witness> lowered(const std::vector<Witness>& witnesses,
                             double cut_z_mm) {
  std::vector<Witness> moved;
  for (Witness w : witnesses) {
    w.point.z -= cut_z_mm;
    w.depth_mm = std::min(w.depth_mm, w.point.z);
    if (w.depth_mm > 0.0) moved.push_back(w);
  }
  return moved;
}

bool lost_in_decimation(const Decimated& decimated, const PartsKept& kept,
                        double tolerance_mm, double cut_z_mm) {
  const std::vector<Witness> moved = lowered(kept.witnesses, cut_z_mm);
  const double moved_mm =
      std::max(tolerance_mm, decimated.stats.max_deviation_mm);
  return !witnesses_outside(decimated.mesh, moved, moved_mm + kRoundingDepthMm)
              .empty();
}

}  // namespace lsolid
