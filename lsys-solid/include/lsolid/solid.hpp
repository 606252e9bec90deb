// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lsolid/boolean.hpp"
#include "lsolid/colors.hpp"
#include "lsolid/decimate.hpp"
#include "lsolid/mesh.hpp"
#include "lsolid/mesh_io.hpp"
#include "lsolid/placement.hpp"
#include "lsolid/print_settings.hpp"
#include "lsolid/rounding.hpp"
#include "lsolid/validate.hpp"
#include "lsys/derivation.hpp"
#include "lsys/grammar.hpp"
#include "lsys/interpretation.hpp"

namespace lsolid {

/// How to turn a grammar into a printable mesh.
struct SolidOptions {
  lsys::DerivationOptions derivation;
  lsys::InterpretOptions interpretation;
  PrintSettings print;
  /// False writes the overlapping parts without a union (`--no-union`).
  bool unite = true;
  /// The union's engine (`--union-engine`); the exact one falls back to the
  /// corefinement where it cannot finish, or its result fails a check.
  UnionEngine union_engine = UnionEngine::ExactCrossings;
  /// The threads the parts, the union and the decimation may use (`--threads`);
  /// 0: all the machine has. The model is the same, byte for byte, whatever the
  /// number.
  int threads = 0;
  /// The format the mesh is for: its coordinates are snapped to what that
  /// format keeps (precision_for) before the last check.
  MeshFormat format = MeshFormat::StlBinary;
  /// Decimate the union within `print.tolerance_mm` (needs `unite`).
  bool decimate = true;
  /// A cap on the triangles of the decimated mesh (`--max-triangles`).
  std::optional<std::size_t> max_triangles;
  /// Colour each triangle by the turtle's colour index (for 3MF and OBJ).
  /// Parts are then built one colour each (PartOptions::split_colors).
  bool colors = false;
  /// Colour each triangle by the turtle's colour index without building the
  /// united parts one colour each (for the preview and the viewer): the
  /// colours are looked up on parts built one colour each beside them, so
  /// the union keeps its long tubes and hull junctions and costs what an
  /// uncoloured one does. Where a colour changes along a tube the boundary
  /// follows the union's triangles nearest the change, not a tube's end.
  /// Ignored when `colors` is set.
  bool preview_colors = false;
  /// Also build one volume per colour, not overlapping (`--multi-material`;
  /// needs `unite`).
  bool multi_material = false;
  /// Told how far the build is: the stage ("skeleton", "parts", "union",
  /// "rounding", "decimation", "check", with multi_material "volumes") and
  /// the fraction of it done, 0 to 1,
  /// from the thread that builds. Empty: not told.
  std::function<void(std::string_view stage, double fraction)> progress;
  /// Told, as a stage begins, how many seconds it is expected to take on
  /// the project's 2-core machine, where that can be estimated before the
  /// work (the union: UnionStats::contacts), from the thread that builds.
  /// Empty: not told.
  std::function<void(std::string_view stage, double seconds)> expect;
};

/// Seconds spent in each stage.
struct StageSeconds {
  double skeleton = 0.0;  ///< parse is before; derivation and turtle
  double parts = 0.0;     ///< scaling and meshing the parts
  double unite = 0.0;     ///< the boolean union
  double round = 0.0;     ///< rounding, repair, and a planar model's cut
  /// Decimation and measuring its deviation, with the check of its result,
  /// which runs alongside the measurement.
  double decimate = 0.0;
  /// Validation of the mesh as it will be written: of a decimated mesh,
  /// the seconds its check took alongside the measurement, and those of
  /// the tests of the parts' witnesses after it.
  double check = 0.0;
  double volumes = 0.0;  ///< the volumes per colour (multi_material)
};

/// What was built.
struct SolidReport {
  Placement placement;
  std::size_t segments = 0;
  /// Segments that repeat an earlier one, left out before the parts
  /// (without_repeated_segments).
  std::size_t repeated_segments = 0;
  std::size_t polygons = 0;
  std::size_t tubes = 0;
  std::size_t junctions = 0;  ///< branch points meshed directly
  std::size_t joints = 0;
  std::size_t plates = 0;
  std::size_t spheres = 0;  ///< balls of `@O`
  std::size_t sheets = 0;   ///< predefined surfaces (`~l`), thickened
  std::size_t skipped_polygons = 0;
  lsys::Skeleton dropped;  ///< only the counts of what the turtle dropped
  double mm_per_unit = 1.0;
  /// A planar model lying flat built as its footprint extruded
  /// (Profile::Flat), with no 3D union (`union_stats` all zero): the
  /// outlines united in the plane and the rings of their union. Both 0
  /// otherwise.
  std::size_t flat_outlines = 0;
  std::size_t flat_rings = 0;
  UnionStats union_stats;
  std::size_t cavities_filled = 0;  ///< sealed voids the union left
  RoundingStats rounding;
  /// Whether the mesh returned is the decimated one; false when decimation
  /// was off, or its result failed validation and was thrown away (then
  /// `decimation` still says what it did).
  bool decimated = false;
  /// Why a decimated mesh was thrown away ("failed the check", "lost part
  /// of the model", "could not be made (the reason)"); empty when it was
  /// used or decimation was off.
  std::string decimation_discarded;
  DecimateStats decimation;
  /// Points deep inside the parts found inside the union (the union's
  /// invariant, containment.hpp); a point outside is an error.
  std::size_t witnesses_checked = 0;
  ValidationReport validation;  ///< of `Solid::mesh`, exactly as returned
  /// What a maker should know although the model was built: widths that
  /// dwarf lengths, a model that fills most of its box. One sentence each.
  std::vector<std::string> warnings;
  StageSeconds seconds;
};

/// A mesh ready to write and its report.
struct Solid {
  TriangleMesh mesh;
  SolidReport report;
  /// With SolidOptions::colors, the turtle's colour index of each triangle
  /// of `mesh`; otherwise empty.
  std::vector<int> colors;
  /// With SolidOptions::multi_material, one volume per colour, in order of
  /// colour; they meet on shared faces and together fill `mesh` (to the
  /// decimation tolerance). Otherwise, or when `mesh` is not printable,
  /// empty.
  std::vector<ColoredMesh> volumes;
};

/// Derives, interprets, scales, meshes, unites and validates. The mesh is
/// returned even when the validation fails; callers decide not to write it.
/// @throws lsys::ParseError for bad input, size limits, or a skeleton that
///   draws nothing (lsys::nothing_drawn_error), GeometryError when the union
///   fails.
[[nodiscard]] Solid build_solid(const lsys::Grammar& grammar,
                                const SolidOptions& options = {});

/// The same from a skeleton already drawn (the viewer shows it first):
/// `drawn` is what lsys::interpret returns for `grammar` with the options'
/// derivation and interpretation, which are not used again.
/// @throws as build_solid above.
[[nodiscard]] Solid build_solid(const lsys::Grammar& grammar,
                                const lsys::Skeleton& drawn,
                                const SolidOptions& options = {});

}  // namespace lsolid
