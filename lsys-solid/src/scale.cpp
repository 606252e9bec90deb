// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/scale.hpp"

#include <algorithm>
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include "lsolid/defaults.hpp"
#include "lsolid/errors.hpp"
#include "lsolid/mesh.hpp"

namespace lsolid {
namespace {

// The box of the printed model at a given scale: tubes with clamped radii
// around the segments, plates of wall thickness around the polygons.
Box model_box(const lsys::Skeleton& s, double scale, double wall_mm) {
  Box box;
  const auto grow = [&](const glm::dvec3& p, const glm::dvec3& pad) {
    box.min = glm::min(box.min, p * scale - pad);
    box.max = glm::max(box.max, p * scale + pad);
  };
  for (const lsys::Segment& seg : s.segments) {
    // A disc of radius r across direction d reaches r·sqrt(1 - d_i²) along
    // axis i: a tube's flat end adds nothing along its own axis.
    const glm::dvec3 d = glm::normalize(seg.p1 - seg.p0);
    const glm::dvec3 across = glm::sqrt(glm::max(glm::dvec3(0.0), 1.0 - d * d));
    grow(seg.p0,
         across * (std::max(seg.start_diameter * scale, wall_mm) / 2.0));
    grow(seg.p1, across * (std::max(seg.end_diameter * scale, wall_mm) / 2.0));
  }
  for (const lsys::Polygon& polygon : s.polygons) {
    for (const glm::dvec3& p : polygon.points)
      grow(p, glm::dvec3(wall_mm / 2.0));
  }
  for (const lsys::Sphere& ball : s.spheres) {
    grow(ball.center, glm::dvec3(std::max(ball.diameter * scale, wall_mm) / 2));
  }
  for (const lsys::Sheet& sheet : s.sheets) {
    for (const glm::dvec3& p : sheet.points) grow(p, glm::dvec3(wall_mm / 2.0));
  }
  return box;
}

}  // namespace

double estimate_scale(const lsys::Skeleton& skeleton,
                      const PrintSettings& settings) {
  if (lsys::draws_nothing(skeleton)) {
    throw GeometryError(
        "nothing to build: the L-system draws no segment, polygon, sphere or "
        "surface");
  }
  double scale = 1.0;
  if (settings.scale_mm_per_unit) {
    scale = *settings.scale_mm_per_unit;
  } else {
    const bool by_height = settings.height_mm.has_value();
    const double target = by_height ? *settings.height_mm
                                    : settings.size_mm.value_or(kDefaultSizeMm);
    const auto extent = [&](double s) {
      const glm::dvec3 size = model_box(skeleton, s, 0.0).size();
      return by_height ? size.z : std::max({size.x, size.y, size.z});
    };
    // Radii grow with the scale but walls do not, so refine a few times.
    const double unit_extent = extent(1.0);
    if (!(unit_extent > 0.0)) {
      throw GeometryError(by_height ? "the model has no height to scale"
                                    : "the model has no extent to scale");
    }
    scale = target / unit_extent;
    for (int i = 0; i < 4; ++i) {
      const glm::dvec3 size =
          model_box(skeleton, scale, settings.wall_mm).size();
      const double actual =
          by_height ? size.z : std::max({size.x, size.y, size.z});
      if (actual <= 0.0) break;
      scale *= target / actual;
    }
  }
  return scale;
}

ScaledSkeleton scale_skeleton(const lsys::Skeleton& skeleton, double scale,
                              double wall_mm) {
  ScaledSkeleton out{skeleton, scale};
  for (lsys::Segment& seg : out.skeleton.segments) {
    seg.p0 *= scale;
    seg.p1 *= scale;
    seg.start_diameter = std::max(seg.start_diameter * scale, wall_mm);
    seg.end_diameter = std::max(seg.end_diameter * scale, wall_mm);
  }
  for (lsys::Polygon& polygon : out.skeleton.polygons) {
    for (glm::dvec3& p : polygon.points) p *= scale;
  }
  for (lsys::Sphere& ball : out.skeleton.spheres) {
    ball.center *= scale;
    ball.diameter = std::max(ball.diameter * scale, wall_mm);
  }
  for (lsys::Sheet& sheet : out.skeleton.sheets) {
    for (glm::dvec3& p : sheet.points) p *= scale;
  }
  return out;
}

ScaledSkeleton scale_to_print(const lsys::Skeleton& skeleton,
                              const PrintSettings& settings) {
  return scale_skeleton(skeleton, estimate_scale(skeleton, settings),
                        settings.wall_mm);
}

}  // namespace lsolid
