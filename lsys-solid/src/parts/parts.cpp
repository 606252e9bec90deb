// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Meshing the skeleton into few, well-conditioned boolean operands
// (docs/design.md, "Parts"): the tubes and hull junctions planned by
// branch_graph.cpp and meshed by tube_mesher.cpp, round after round until
// no stitched part cuts itself; joints that enclose the end caps of tubes
// where a hull does not fit, so that no caps coincide; plates for leaves
// (plates.cpp); balls (balls.cpp) and thickened sheets
// (thickened_sheet.cpp).
#include "lsolid/parts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "parts/balls.hpp"
#include "parts/branch_graph.hpp"
#include "parts/geometry.hpp"
#include "parts/plates.hpp"
#include "parts/thickened_sheet.hpp"
#include "parts/tube_mesher.hpp"

namespace lsolid {
namespace {

constexpr int kMaxRounds = 8;
constexpr double kOnAxis = 0.1;  // of the stem radius: a leaf starts there
constexpr double kPlateMargin = 1.05;
// The least radius of a joint at a plate's corner, of the wall: it
// encloses the plate's edge there (half a plate's thickness from the
// corner, about 0.55 of the wall).
constexpr double kPlateJoint = 0.75;

// The largest side of the skeleton's box, at least 1 mm.
double size_of(const lsys::Skeleton& skeleton) {
  const lsys::Bounds box = lsys::bounds(skeleton);
  const glm::dvec3 extent = box.max - box.min;
  return std::max({1.0, extent.x, extent.y, extent.z});
}

// A plate that starts on its stem's axis, where the stem goes on, cuts
// through the tube and fuses with it in the union. At a tip the plate
// would meet the tube's cap face on: a joint encloses that corner.
void add_tip_joint(const lsys::Skeleton& skeleton, const BranchGraph& graph,
                   const PartOptions& options, const lsys::Polygon& polygon,
                   JointSet& joints) {
  if (polygon.parent < 0) return;
  const lsys::Segment& stem =
      skeleton.segments[static_cast<std::size_t>(polygon.parent)];
  const double stem_radius = node_radius(skeleton, graph, polygon.parent);
  const double from_end = glm::length(polygon.points.front() - stem.p1);
  const auto i = static_cast<std::size_t>(polygon.parent);
  const bool goes_on = graph.continuation[i] >= 0 || graph.end_junction[i] >= 0;
  if (from_end <= stem_radius &&
      !(goes_on && from_end <= kOnAxis * stem_radius)) {
    joints.add(stem.p1, std::max(stem_radius, kPlateJoint * options.wall_mm),
               stem.color);
  }
}

}  // namespace

int tube_sides(double radius_mm, double tolerance_mm) {
  // The flat sides touch the circle; the corners stand out by
  // r (1 / cos(π/m) - 1), which must stay within the tolerance. Clamped
  // before converting: a tolerance far below the radius makes the step 0
  // and the quotient infinite, which no int holds.
  const double step = std::acos(radius_mm / (radius_mm + tolerance_mm));
  if (!(step > 0.0)) return 128;
  return static_cast<int>(std::clamp(std::ceil(kPi / step), 6.0, 128.0));
}

double tube_corner_radius(double radius_mm, double tolerance_mm) {
  return radius_mm / std::cos(kPi / tube_sides(radius_mm, tolerance_mm));
}

double plate_thickness_mm(double wall_mm, double tolerance_mm) {
  return 2.0 * kPlateMargin * tube_corner_radius(wall_mm / 2.0, tolerance_mm);
}

PartSet build_parts(const lsys::Skeleton& skeleton,
                    const PartOptions& options) {
  BranchGraph graph = plan_branches(skeleton, options);
  TubeRound round;
  for (int attempt = 0;; ++attempt) {
    round = mesh_tubes(skeleton, graph, options);
    if (round.revert.empty()) break;
    for (const std::int32_t j : round.revert) {
      graph.junctions[static_cast<std::size_t>(j)].hull = false;
    }
    if (attempt + 1 >= kMaxRounds) {
      // Without hulls every part is a closed tube, sphere or plate.
      for (Junction& j : graph.junctions) j.hull = false;
    }
  }
  PartSet set{.parts = std::move(round.parts),
              .tubes = round.tubes,
              .junctions = round.junctions};
  Plates plates = build_plates(skeleton, options, size_of(skeleton));
  for (Part& plate : plates.parts) set.parts.push_back(std::move(plate));
  set.plates = plates.plates;
  set.skipped_polygons = plates.skipped;
  for (const std::size_t i : plates.tip_order) {
    add_tip_joint(skeleton, graph, options, skeleton.polygons[i], round.joints);
  }
  for (const auto& [corner, color] : plates.shared_corners) {
    round.joints.claim(corner, kPlateJoint * options.wall_mm, color);
  }
  std::size_t index = 0;
  for (const Joint& joint : round.joints.joints()) {
    set.parts.push_back(Part{
        joint_sphere(joint.center, joint.radius, index++, options.tolerance_mm),
        fmt::format("joint at ({:.3f}, {:.3f}, {:.3f}) mm", joint.center.x,
                    joint.center.y, joint.center.z),
        joint.color});
    ++set.joints;
  }
  // `@O` balls, each its own part of its own colour (scale_skeleton made
  // them a wall across at least).
  for (const lsys::Sphere& b : skeleton.spheres) {
    set.parts.push_back(
        Part{uv_ball(b.center, b.diameter / 2.0, index++, options.tolerance_mm),
             fmt::format("sphere at ({:.3f}, {:.3f}, {:.3f}) mm", b.center.x,
                         b.center.y, b.center.z),
             b.color});
    ++set.spheres;
  }
  const double thickness =
      plate_thickness_mm(options.wall_mm, options.tolerance_mm);
  for (std::size_t i = 0; i < skeleton.sheets.size(); ++i) {
    SheetPart sheet = sheet_part(skeleton.sheets[i], i, thickness);
    set.parts.push_back(std::move(sheet.part));
    ++set.sheets;
    if (sheet.kind == SheetKind::Hulled) ++set.hulled_sheets;
    if (sheet.kind == SheetKind::Thinned) {
      ++set.thinned_sheets;
      set.thinnest_sheet_mm =
          std::min(set.thinnest_sheet_mm, sheet.thinnest_mm);
    }
  }
  return set;
}

}  // namespace lsolid
