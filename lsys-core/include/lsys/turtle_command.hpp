// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string_view>

namespace lsys {

/// What the turtle does with a module (docs/turtle.md has the exact effect
/// of each, with its source).
enum class TurtleCommand {
  None,            ///< any other module: kept in the string, no action
  Draw,            ///< `F`: move, draw a segment; a vertex inside `{ }`
  Move,            ///< `f`: move without drawing; a vertex inside `{ }`
  DrawNoVertex,    ///< `G`: move and draw, never a polygon vertex
  MoveNoVertex,    ///< `g`: move, never a polygon vertex
  TurnLeft,        ///< `+`: about up, heading toward left
  TurnRight,       ///< `-`
  PitchDown,       ///< `&`: about left, heading toward -up
  PitchUp,         ///< `^` (also `∧`)
  RollRight,       ///< `/`: about heading, left toward up
  RollLeft,        ///< `\`
  TurnAround,      ///< `|`: 180 degrees about up
  RollToVertical,  ///< `$` (also `@v`): left made horizontal, ABOP p. 57
  Push,            ///< `[`
  Pop,             ///< `]`
  PolygonBegin,    ///< `{`
  PolygonVertex,   ///< `.`
  PolygonEnd,      ///< `}`
  Width,           ///< `!`: set the width, or apply the width rule
  Widen,           ///< L-Py `_`: set the width, or add the increment
  ColorNext,       ///< `'` and `;`: next colour index, or set it
  ColorPrevious,   ///< `,`: previous colour index, or set it
  Cut,             ///< `%`: cut the rest of the branch (while deriving)
  SetTropism,      ///< `@Tp(x,y,z)`: the tropism vector
  SetElasticity,   ///< `@Ts(e)`: the elasticity
  MultiplyStep,    ///< Lparser `"` `'`, Fractint `@`: step length × p
  MultiplyAngle,   ///< Lparser `;` `:`: δ × p
  MultiplyWidth,   ///< Lparser `?` `!`: width × p
  SwapTurns,       ///< Fractint `!`: `+` and `-` trade meanings
  TurnRightFixed,  ///< Fractint `|`: right by p degrees, whatever `!` says
  ColorAdd,        ///< Fractint `<nn` `>nn`: colour index + p, at least 0
  DrawHalf,        ///< Lparser `Z`: draw half a step, never a vertex
  MoveHalf,        ///< Lparser `z`: move half a step; a vertex in `{ }`
  RandomTurn,      ///< Lparser `~`: turn, pitch, roll at random, ±p degrees
  Gravity,         ///< Lparser `t`: pitch down by p × |horizontal heading|
  RollToVerticalSwappingTurns,  ///< Lparser `$`: `$`, then `+` `-` swapped
  ElasticityChange,  ///< cpfg `_`: set the elasticity, or add its increment
  /// cpfg's movements (Settings::movements): `@Ts(i, e)` sets movement i's
  /// elasticity to e (to 0 without e), `@Ti(i, d)` adds d (its step
  /// without d), `@Td(i, d)` takes it away; without i, nothing.
  MovementElasticity,
  MovementElasticityUp,
  MovementElasticityDown,
  /// cpfg's `@R(hx, hy[, hz[, ux, uy, uz]])`, L-Py's `@R` and `SetHead`:
  /// heads along h (up along u when given), in the notation's coordinates
  /// (Settings::query_frame).
  SetHeading,
  /// cpfg's `@M(x, y[, z])`, L-Py's `@M` and `MoveTo`: moves to the point,
  /// drawing nothing.
  MoveTo,
  /// L-Py's `LineTo(x, y, z[, r])`: draws a segment to the point (of end
  /// radius r), the frame unchanged.
  LineTo,
  Sphere,   ///< cpfg `@O(d)`: a ball of diameter d, or of the width, here
  Surface,  ///< cpfg `~l(s)`: draw a predefined surface (Grammar::surfaces)
  /// A disc of diameter d (or of the width) centred on the turtle, a leaf
  /// polygon: cpfg's `@c` across up (in the heading–left plane)...
  DiscAcrossUp,
  DiscAcrossHeading,  ///< ...L-Py's `@o(r)`, across the heading...
  DiscAcrossLeft,     ///< ...L-system Explorer's `@o(d)`, across left...
  /// ...and cpfg's `@o`, a "two-dimensional" circle that faces cpfg's
  /// viewer on its z axis: across lsolid's y.
  DiscFacingViewer,
  /// cpfg's generalized cylinder: `@Gs` starts a smooth tube at the turtle,
  /// `@Gc(n)` adds a control point and draws the span to it in n pieces
  /// along a Hermite curve, `@Ge(n)` adds the last; `F` between them moves
  /// without drawing. `@Gt(a, b)` sets the tangents' factors.
  CylinderStart,
  CylinderPoint,
  CylinderEnd,
  CylinderTangents,
  /// cpfg's `@Gr(a1, l1, a2, l2)`: the tangents of the radius along the
  /// spans to come, at angle a (degrees) and length l in the plane of
  /// (curve parameter, radius); `@Gr(s)` scales them by each span's chord
  /// when s is not 0.
  CylinderRadiusTangents,
  /// cpfg's `@#(id)`: the cross-section of the generalized cylinders to
  /// come is contour id (Grammar::contours); `@#` alone, the circle.
  SelectContour,
  /// cpfg's `@!(n)`: n points around the rings swept from a contour
  /// (`contour sides` without n).
  ContourSides,
  /// cpfg's queries `?P(x, y, z)`, `?H`, `?L` and `?U`: before each
  /// derivation step the turtle walks the string and writes its position,
  /// heading, left or up where the module stands into the module's
  /// parameters, in cpfg's coordinates (Y up, U = −H × L).
  QueryPosition,
  QueryHeading,
  QueryLeft,
  QueryUp,
};

/// True for the query commands, whose parameters the turtle writes.
[[nodiscard]] constexpr bool is_query(TurtleCommand command) noexcept {
  return command == TurtleCommand::QueryPosition ||
         command == TurtleCommand::QueryHeading ||
         command == TurtleCommand::QueryLeft ||
         command == TurtleCommand::QueryUp;
}

/// The command a module name has without aliases, if it has one.
[[nodiscard]] std::optional<TurtleCommand> builtin_command(
    std::string_view name) noexcept;

/// The most parameters a command accepts (`F(l, w)` takes two).
[[nodiscard]] int max_parameters(TurtleCommand command) noexcept;
/// The fewest parameters a command needs (`@Tp` needs three).
[[nodiscard]] int min_parameters(TurtleCommand command) noexcept;

}  // namespace lsys
