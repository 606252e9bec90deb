// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec3.hpp>

#include "lsolid/mesh.hpp"
#include "lsolid/mesh_io.hpp"
#include "lsolid/validate.hpp"

namespace lsolid {

/// What a file keeps of a coordinate as its usual readers read it. Every
/// coordinate of a mesh written to it is snapped to this before the last
/// check, so that the check judges the mesh every reader gets
/// (docs/design.md, "Precision of the files").
struct Precision {
  enum class Kind {
    /// Doubles as they are: OFF and OBJ are written with 17 digits.
    Double,
    /// float32, as binary STL stores it and slicers read it.
    Float,
    /// The six decimals lib3mf 1.8 writes of a coordinate's float32 (a 3MF
    /// holds text), as a reader of doubles gets them: a value that lib3mf,
    /// fed its float, writes again as itself. A reader of floats (slicers,
    /// lib3mf's own reader) gets that float, which is checked too
    /// (also_as_floats).
    SixDecimals,
    /// The float32 nearest to the coordinate's six significant digits:
    /// OpenSCAD reads a `.scad` as doubles (the float exactly), exports STL
    /// with six significant digits (the digits again), and a slicer reads
    /// that as the same float again. `step_mm` is the coarsest step at the
    /// model's reach (10⁻⁴ mm below 100 mm, 10⁻³ mm below 1 m).
    DecimalFloat,
  };
  Kind kind = Kind::Float;
  /// DecimalFloat's coarsest step; the mending after snapping treats
  /// edges and caps a few steps small as degenerate.
  double step_mm = 0.0;

  /// Whether the file's readers also read its coordinates as floats, so
  /// the mesh must be checked at both precisions (3MF).
  [[nodiscard]] bool also_as_floats() const noexcept {
    return kind == Kind::SixDecimals;
  }

  /// The coordinate a reader gets for `x`.
  [[nodiscard]] double snap(double x) const;
  /// The point a reader gets for `p`.
  [[nodiscard]] glm::dvec3 snap(const glm::dvec3& p) const {
    return {snap(p.x), snap(p.y), snap(p.z)};
  }
};

/// The precision of `format` for a model that reaches at most `reach_mm`
/// from the origin along any axis (DecimalFloat's step depends on it).
/// @pre 0 < reach_mm <= 1e6.
[[nodiscard]] Precision precision_for(MeshFormat format, double reach_mm);

/// The farthest any vertex lies from the origin along an axis, in mm.
[[nodiscard]] double reach_mm(const TriangleMesh& mesh);

/// The check of a mesh as every reader of a file of `precision` reads it:
/// as it stands (its coordinates are the file's), and, where the readers
/// also read floats (3MF), as floats; the report of the first reading
/// that is not printable, else of the mesh as it stands.
[[nodiscard]] ValidationReport validate_as_read(const TriangleMesh& mesh,
                                                const Precision& precision);

/// The mesh with every coordinate snapped, and vertices that become equal
/// merged.
[[nodiscard]] TriangleMesh snapped(const TriangleMesh& mesh,
                                   const Precision& precision);

}  // namespace lsolid
