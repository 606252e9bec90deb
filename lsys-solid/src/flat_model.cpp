// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "flat_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <map>
#include <utility>

#include "lsolid/colors.hpp"
#include "lsolid/errors.hpp"
#include "lsolid/footprint.hpp"
#include "lsolid/parts.hpp"

namespace lsolid {
namespace {

// The plane union's invariant: it covers at least the largest outline's
// area (a union never has less), and its extrusion holds the volume of
// its area times its height.
// @throws GeometryError if either fails.
void check_footprint(const Footprint& footprint,
                     const std::vector<std::vector<glm::dvec2>>& outlines,
                     const TriangleMesh& solid, double height_mm) {
  double largest = 0.0;
  for (const std::vector<glm::dvec2>& outline : outlines) {
    largest = std::max(largest, std::fabs(area(Footprint{{outline}})));
  }
  const double covered = area(footprint);
  // Each point moves by at most half a grid step (2^-21 mm) onto the grid.
  if (covered < largest * (1.0 - 1e-6)) {
    throw GeometryError(fmt::format(
        "the union of the outlines in the plane lost part of the model (a bug "
        "in lsolid; please report it with this file): it covers {:.3f} mm², "
        "less than its largest outline, {:.3f} mm²",
        covered, largest));
  }
  const double volume = signed_volume(solid);
  if (std::fabs(volume - covered * height_mm) > 1e-9 * covered * height_mm) {
    throw GeometryError(fmt::format(
        "the footprint's extrusion holds {:.3f} mm³, not its area times its "
        "height, {:.3f} mm³ (a bug in lsolid; please report it with this "
        "file)",
        volume, covered * height_mm));
  }
}

}  // namespace

FlatModel flat_model(const lsys::Skeleton& skeleton, const Placement& placement,
                     const PrintSettings& print) {
  FlatModel flat;
  const auto add = [&](std::vector<glm::dvec2> outline, int color) {
    if (outline.empty()) return;
    flat.outlines.push_back(std::move(outline));
    flat.materials.push_back(material_index(color, print.colors));
  };
  const double tolerance = print.tolerance_mm;
  double plane_z = 0.0;
  double reach = 0.0;  // above the plane
  struct Node {
    glm::dvec2 at;
    double radius_mm = 0.0;
    int ends = 0;
    int color = 0;
  };
  // Ends meet where they fall on the same point of a 2^-20 mm grid.
  std::map<std::pair<double, double>, Node> nodes;
  const auto end_at = [&](const glm::dvec3& p, double r, int color) {
    const auto key = std::pair(std::round(p.x * kFootprintCellsPerMm),
                               std::round(p.y * kFootprintCellsPerMm));
    Node& node = nodes[key];
    if (node.ends++ == 0) {
      node.at = glm::dvec2(p);
      node.color = color;
    }
    node.radius_mm = std::max(node.radius_mm, r);
  };
  for (const lsys::Segment& s : skeleton.segments) {
    const glm::dvec3 p0 = on_bed(placement, s.p0);
    const glm::dvec3 p1 = on_bed(placement, s.p1);
    plane_z = p0.z;
    const double r0 = s.start_diameter / 2.0;
    const double r1 = s.end_diameter / 2.0;
    reach = std::max({reach, tube_corner_radius(r0, tolerance),
                      tube_corner_radius(r1, tolerance)});
    add(branch_outline(glm::dvec2(p0), r0, glm::dvec2(p1), r1, tolerance),
        s.color);
    end_at(p1, r1, s.color);
    end_at(p0, r0, s.color);
  }
  // A leaf or disc that starts at a branch's tip gets a joint there in the
  // round model (parts/parts.cpp's add_tip_joint), a wall and a half across at
  // least: the flat model gets a node as wide, so that the round model's
  // witnesses lie inside the footprint (a disc `@o` at each apex of vlab's
  // signal models was reported lost).
  for (const lsys::Polygon& polygon : skeleton.polygons) {
    if (polygon.parent < 0) continue;
    const lsys::Segment& stem =
        skeleton.segments[static_cast<std::size_t>(polygon.parent)];
    const glm::dvec3 tip = on_bed(placement, stem.p1);
    Node& node = nodes[std::pair(std::round(tip.x * kFootprintCellsPerMm),
                                 std::round(tip.y * kFootprintCellsPerMm))];
    if (glm::length(polygon.points.front() - stem.p1) > node.radius_mm) {
      continue;
    }
    node.radius_mm = std::max(node.radius_mm, 0.75 * print.wall_mm);
    node.ends = std::max(node.ends, 2);
    reach = std::max(reach, tube_corner_radius(node.radius_mm, tolerance));
  }
  for (const auto& [key, node] : nodes) {
    if (node.ends > 1) {
      add(node_outline(node.at, node.radius_mm, tolerance), node.color);
    }
  }
  for (const lsys::Polygon& polygon : skeleton.polygons) {
    std::vector<glm::dvec2> points;
    for (const glm::dvec3& p : polygon.points) {
      const glm::dvec3 q = on_bed(placement, p);
      plane_z = q.z;
      points.emplace_back(q);
    }
    if (is_simple_polygon(points)) {
      add(std::move(points), polygon.color);
      reach = std::max(reach, plate_thickness_mm(print.wall_mm, tolerance) / 2);
    }
  }
  flat.height_mm = plane_z + reach - placement.cut_z_mm;
  return flat;
}

glm::dvec3 extent(const FlatModel& flat) {
  glm::dvec2 lo(1e300);
  glm::dvec2 hi(-1e300);
  for (const std::vector<glm::dvec2>& outline : flat.outlines) {
    for (const glm::dvec2& p : outline) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  if (lo.x > hi.x) return glm::dvec3(0.0);
  return {hi.x - lo.x, hi.y - lo.y, flat.height_mm};
}

Extruded extrude_flat_model(const FlatModel& flat) {
  const Footprint footprint = footprint_union(flat.outlines);
  TriangleMesh solid = extrude(footprint, flat.height_mm);
  check_footprint(footprint, flat.outlines, solid, flat.height_mm);
  return Extruded{.mesh = std::move(solid),
                  .outlines = flat.outlines.size(),
                  .rings = footprint.rings.size()};
}

}  // namespace lsolid
