// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec3.hpp>

namespace lsys {

/// The sine and cosine of an angle in degrees, exact for multiples of 90°
/// so that lattice figures such as the Hilbert curve land on integers.
struct SinCos {
  double sin;
  double cos;
};
[[nodiscard]] SinCos sin_cos_deg(double angle_deg) noexcept;

/// The turtle's position and frame (ABOP §1.5): heading H, left L and up U,
/// orthonormal and right-handed with H × L = U (seed 000). It starts at the
/// origin with H = +Z, L = −X, U = −Y, so 2D figures lie in the XZ plane and
/// read as in ABOP from the front (looking along +Y).
///
/// Every rotation is right-handed about its axis: a positive angle turns
/// counter-clockwise seen from the axis tip. docs/turtle.md relates this to
/// seed 000, ABOP, cpfg, L-Py and Houdini.
class Turtle {
 public:
  Turtle() = default;

  [[nodiscard]] const glm::dvec3& position() const noexcept {
    return position_;
  }
  [[nodiscard]] const glm::dvec3& heading() const noexcept { return heading_; }
  [[nodiscard]] const glm::dvec3& left() const noexcept { return left_; }
  [[nodiscard]] const glm::dvec3& up() const noexcept { return up_; }

  /// Puts the turtle at `position` without turning it (cpfg's surfaces
  /// move it to their end point).
  void set_position(const glm::dvec3& position) noexcept {
    position_ = position;
  }
  /// Moves along the heading (backwards for a negative distance).
  void move(double distance) noexcept { position_ += distance * heading_; }
  /// Rotates about U: positive turns H toward L (`+`).
  void turn(double angle_deg) noexcept { rotate(heading_, left_, angle_deg); }
  /// Rotates about L: positive turns H toward −U, pitching down (`&`).
  void pitch(double angle_deg) noexcept { rotate(heading_, up_, -angle_deg); }
  /// Rotates about H: positive turns L toward U (`/` in lpfg and L-Py).
  void roll(double angle_deg) noexcept { rotate(left_, up_, angle_deg); }
  /// Turns 180° about U (`|`).
  void turn_around() noexcept;
  /// Rolls about H so that L is horizontal: L = V × H / |V × H| with V = +Z,
  /// U = H × L (ABOP p. 57, `$`). Leaves the frame alone when H is vertical.
  void roll_to_vertical() noexcept;
  /// Heads along `heading`, turning the frame by the least rotation that
  /// takes H there (left and up follow). Does nothing for a zero vector.
  void set_heading(const glm::dvec3& heading) noexcept;
  /// Heads along `heading` with up along `up`'s part across it, left
  /// completing the frame. Falls back to set_heading when `up` has no such
  /// part.
  void set_heading_and_up(const glm::dvec3& heading,
                          const glm::dvec3& up) noexcept;
  /// Tropism (ABOP §2.2, p. 58): rotates the frame about H × T by
  /// e·|H × T| radians, bending the heading toward T.
  void bend(const glm::dvec3& tropism, double elasticity) noexcept;

 private:
  // Turns a toward b in their plane; inline because turtles turn often.
  void rotate(glm::dvec3& a, glm::dvec3& b, double angle_deg) noexcept {
    const double magnitude = angle_deg < 0.0 ? -angle_deg : angle_deg;
    if (magnitude != cached_angle_deg_) cache_angle(magnitude);
    const double s = angle_deg < 0.0 ? -cached_sin_ : cached_sin_;
    const double c = cached_cos_;
    const glm::dvec3 a2 = a * c + b * s;
    b = b * c - a * s;
    a = a2;
    if (++rotations_since_orthonormalize_ >= kRotationsPerOrthonormalize) {
      orthonormalize();
    }
  }
  void cache_angle(double magnitude_deg) noexcept;
  void orthonormalize() noexcept;

  static constexpr int kRotationsPerOrthonormalize = 64;

  // Most systems turn by one angle δ: keep its sine and cosine.
  double cached_angle_deg_ = 0.0;
  double cached_sin_ = 0.0;
  double cached_cos_ = 1.0;

  glm::dvec3 position_{0.0, 0.0, 0.0};
  glm::dvec3 heading_{0.0, 0.0, 1.0};
  glm::dvec3 left_{-1.0, 0.0, 0.0};
  glm::dvec3 up_{0.0, -1.0, 0.0};
  int rotations_since_orthonormalize_ = 0;
};

}  // namespace lsys
