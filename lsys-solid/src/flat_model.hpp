// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "lsolid/mesh.hpp"
#include "lsolid/placement.hpp"
#include "lsolid/print_settings.hpp"
#include "lsys/skeleton.hpp"

namespace lsolid {

/// A planar model lying flat, as the flat profile prints it: the outlines
/// seen from above of its branches, of the nodes where they meet and of the
/// leaves the parts print (those that do not cross themselves), placed as
/// the parts were, each with its material, and the height of the round
/// model once cut.
struct FlatModel {
  std::vector<std::vector<glm::dvec2>> outlines;
  std::vector<int> materials;  ///< of each outline
  double height_mm = 0.0;

  /// The outlines of one material.
  [[nodiscard]] std::vector<std::vector<glm::dvec2>> of(int material) const {
    std::vector<std::vector<glm::dvec2>> out;
    for (std::size_t i = 0; i < outlines.size(); ++i) {
      if (materials[i] == material) out.push_back(outlines[i]);
    }
    return out;
  }
};

/// The flat model of a millimetre skeleton placed flat on the bed.
/// Branches end square, as tubes do; where branch ends meet (a branch and
/// its continuation, the last branch of a closed curve and the first), a
/// polygon round the point, of the material of the branch that ends there
/// first (as a joint sphere takes its parent's), fills the notch outside a
/// bend (where tubes are mitred) and rounds the joint.
[[nodiscard]] FlatModel flat_model(const lsys::Skeleton& skeleton,
                                   const Placement& placement,
                                   const PrintSettings& print);

/// The flat model's size: its outlines' extent, and its height.
[[nodiscard]] glm::dvec3 extent(const FlatModel& flat);

/// A flat model united in the plane and extruded, standing on z = 0.
struct Extruded {
  TriangleMesh mesh;
  std::size_t outlines = 0;  ///< united in the plane
  std::size_t rings = 0;     ///< of their union
};

/// The outlines united in the plane (footprint_union) and extruded, with
/// the plane union's invariant checked: it covers at least the largest
/// outline's area (a union never has less), and its extrusion holds the
/// volume of its area times its height.
/// @throws GeometryError if either fails.
[[nodiscard]] Extruded extrude_flat_model(const FlatModel& flat);

}  // namespace lsolid
