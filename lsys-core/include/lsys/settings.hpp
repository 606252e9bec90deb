// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lsys/alphabet.hpp"
#include "lsys/source.hpp"

namespace lsys {

/// Which way `/` and `\` roll. Lpfg (lpfg's default, L-Py, dotSCAD): `/`
/// rolls left toward up. Cpfg: the opposite, as cpfg computes it.
enum class RollConvention { Lpfg, Cpfg };

/// The coordinates in which the turtle answers queries (`?P`, `?H`, …)
/// and reads points (`@M`): cpfg's (Y up; its up is lsolid's −up),
/// PlantGL's, L-Py's turtle (Z up, starting with left (0, −1, 0) where
/// lsolid's is (−1, 0, 0)), or Babylon.js's, L-system Explorer's (Y up,
/// the turtle starting along +X with left +Z).
enum class QueryFrame { Cpfg, PlantGL, Babylon };

/// One of cpfg's movements (Mech's model, 1994: the view file's `tropism:`
/// and `torque:` lines), applied before each step `F`, `f`, `G`, `g`. A
/// tropism bends the heading toward the direction at `angle_deg` from it
/// (0: orthotropism, toward it; 90: plagiotropism, across it), by an angle
/// that grows with the elasticity; a torque rolls the turtle about its
/// heading, up toward the direction. docs/dialects/cpfg.md has the formulas.
struct Movement {
  enum class Kind { Tropism, Torque };
  Kind kind = Kind::Tropism;
  /// World coordinates (Z up), of length 1 unless an intensity scales it
  /// (docs/dialects/cpfg.md).
  glm::dvec3 direction{0.0, 0.0, 1.0};
  double angle_deg = 0.0;
  double elasticity = 0.0;       ///< at the start of each interpretation
  double elasticity_step = 0.0;  ///< what `@Ti(i)` adds and `@Td(i)` takes
};

/// The most movements a file may define, as cpfg (MAXMOVEMENTS).
inline constexpr std::size_t kMaxMovements = 10;

/// A setting that lsys-core does not interpret but accepts on behalf of a
/// client (the print settings of lsys-solid), with where its value stands.
struct ExtraSetting {
  std::string key;     ///< as the client named it
  std::string value;   ///< the text after `:` or `=`, trimmed
  std::size_t offset;  ///< byte offset of the value, for diagnostics
};

/// The most derivation steps a file or the command line may ask for: beyond
/// it a string that grows by one module a step is still modest, but every
/// model that grows cannot be derived anyway.
inline constexpr int kMaxDerivationLength = 10000;

/// The largest seed, and the largest limit on segments or modules: 2^53,
/// the whole numbers a double holds exactly, so that they compare exactly
/// with the size model's counts (which are doubles).
inline constexpr std::uint64_t kMaxWholeNumber = std::uint64_t{1} << 53U;

/// The largest colour index (the `colour` setting, `'(c)`, `;(c)`, `,(c)`).
inline constexpr int kMaxColorIndex = 1 << 20;

/// The settings of a `.ls` file (docs/language.md lists every one with its
/// spellings). Lengths are in model units; widths are diameters.
struct Settings {
  int derivation_length = 1;  ///< `n`
  double angle_deg = 45.0;    ///< δ, cpfg's default
  double step = 1.0;          ///< the length of `F` without a parameter
  /// Diameter: a tenth of a step, so that a file that sets no width prints
  /// as its figure looks, a line drawing (cpfg's default of 1 is a pixel;
  /// as a width it is a whole step, and neighbours fuse into a block).
  double initial_width = 0.1;
  /// Bare `!` subtracts this when set (cpfg's `line width increment`)...
  std::optional<double> width_increment;
  /// Bare `#` adds this when set (L-system Explorer adds 1 but takes 0.1
  /// away), else width_increment...
  std::optional<double> widen_increment;
  /// ...and otherwise multiplies by this (Houdini's thickness scale; the
  /// default is Honda's and da Vinci's 1/√2 ≈ 0.707).
  double width_factor = 0.707;
  /// The diameter of `@O(p)` per unit of p: 1 (cpfg's diameter), 2 for
  /// L-Py's radius.
  double sphere_diameter_per_parameter = 1.0;
  /// Multiplies every width, for files whose widths are in other units
  /// than their lengths (cpfg widths are pixels).
  double width_scale = 1.0;
  /// Diameter lost per derivation step that created a module (seed 001's
  /// "branch radius reduction", doubled).
  double width_decrement_per_generation = 0.0;
  /// Widths are fractions of each segment's own length (Lparser's
  /// thickness, a percentage of the length), not lengths.
  bool widths_relative_to_length = false;
  int initial_color = 0;
  glm::dvec3 tropism{0.0, 0.0, -1.0};  ///< T, world coordinates (Z up)
  double elasticity = 0.0;             ///< e; 0 turns tropism off
  /// What a bare cpfg `_` adds to e (cpfg's `elasticity increment`).
  double elasticity_increment = 0.0;
  /// Whether tropism also bends after `f` and `g`, as cpfg's does (ABOP
  /// bends after `F` only).
  bool bend_after_moves = false;
  /// cpfg's movements, at most kMaxMovements; `@Ts(i, e)`, `@Ti(i)` and
  /// `@Td(i)` change the elasticity of movement i, counted from 1.
  std::vector<Movement> movements;
  /// Points around a generalized cylinder's ring swept from a contour
  /// (cpfg's `contour sides`).
  int contour_sides = 8;
  /// Whether a generalized cylinder's rings turn smoothly from one control
  /// point's frame to the next (cpfg's `twist of cylinders: on`), or keep
  /// the first's, carried along the curve, until the last ring.
  bool twist_cylinders = false;
  std::uint64_t seed = 0;
  RollConvention roll = RollConvention::Lpfg;
  QueryFrame query_frame = QueryFrame::Cpfg;
  int maximum_depth = 1;  ///< of homomorphism and decomposition, as cpfg
  /// The homomorphism's own depth, where a notation gives each section
  /// one (lpfg's `maximum depth:` under `interpretation:`).
  std::optional<int> homomorphism_depth;
  std::vector<SymbolId> ignore;    ///< skipped when matching context
  std::vector<SymbolId> consider;  ///< if not empty, only these are seen

  /// Byte offset of the `n` setting, if the file has one.
  std::optional<std::size_t> derivation_length_offset;
  /// Byte offset of the `step` setting's value, if the file has one.
  std::optional<std::size_t> step_offset;
  /// Byte offset of the value that sets the initial width (`width:`,
  /// Lparser's thickness, L-system Explorer's `stemsize`, cpfg's `initial
  /// line width`), if the file has one.
  std::optional<std::size_t> width_offset;
  /// The file width_offset is in when it is not the grammar's own (cpfg's
  /// view file).
  std::shared_ptr<const SourceFile> width_source;
  /// Byte offset of the `seed` setting's value, if the file has one (cpfg
  /// makes an L-system stochastic only with it).
  std::optional<std::size_t> seed_offset;
};

}  // namespace lsys
