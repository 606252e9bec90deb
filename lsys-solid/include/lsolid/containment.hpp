// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <vector>

#include "lsolid/mesh.hpp"
#include "lsolid/validate.hpp"

namespace lsolid {

/// A point deep inside one part: the union of the parts must contain it.
struct Witness {
  std::size_t part = 0;   ///< index into the parts it was taken from
  glm::dvec3 point{0.0};  ///< in the parts' coordinates
  double depth_mm = 0.0;  ///< its distance to the part's surface
};

/// Points inside each part, spread over it: for every 64th face of a part
/// (at least one face per part), the midpoint of the ray from the face's
/// centre inward to where it leaves the part, with its distance to the
/// part's surface (CGAL's AABB tree). A part that is lost in a union, or a
/// branch of it, leaves some of these points outside the result.
/// @pre every part is closed and outward-oriented.
[[nodiscard]] std::vector<Witness> witnesses(const std::vector<Part>& parts);

/// The witnesses at least `min_depth_mm` deep that do not lie strictly
/// inside the solid bounded by `mesh`, decided with exact predicates on its
/// coordinates (CGAL's Side_of_triangle_mesh). `min_depth_mm` allows for
/// how far the surface may have moved since the parts were made (rounding,
/// decimation).
/// @pre `mesh` is closed and outward-oriented.
/// @throws GeometryError if `mesh` cannot be read as a surface.
[[nodiscard]] std::vector<Witness> witnesses_outside(
    const TriangleMesh& mesh, const std::vector<Witness>& witnesses,
    double min_depth_mm);

/// The pieces of `mesh` (edge-connected shells of positive volume) that
/// hold none of the witnesses at least `min_depth_mm` deep: fragments that
/// no part accounts for, which only a faulty repair can make. Largest
/// first.
/// @pre `mesh` is closed and outward-oriented.
[[nodiscard]] std::vector<Shell> unaccounted_pieces(
    const TriangleMesh& mesh, const std::vector<Witness>& witnesses,
    double min_depth_mm);

}  // namespace lsolid
