// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The 3D turtle of ABOP §1.5 (p. 19) with ABOP's words, not its printed
// matrices, where the two disagree; docs/turtle.md has the comparison.
#include "lsys/turtle.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "lsys/rotation.hpp"

namespace lsys {
SinCos sin_cos_deg(double angle_deg) noexcept {
  const double quarter = angle_deg / 90.0;
  if (quarter == std::floor(quarter) && std::fabs(quarter) < 1e15) {
    switch (static_cast<long long>(std::fmod(quarter, 4.0) + 4.0) % 4) {
      case 0:
        return {0.0, 1.0};
      case 1:
        return {1.0, 0.0};
      case 2:
        return {0.0, -1.0};
      default:
        return {-1.0, 0.0};
    }
  }
  const double radians = angle_deg * std::numbers::pi / 180.0;
  return {std::sin(radians), std::cos(radians)};
}

void Turtle::cache_angle(double magnitude_deg) noexcept {
  const SinCos sc = sin_cos_deg(magnitude_deg);
  cached_angle_deg_ = magnitude_deg;
  cached_sin_ = sc.sin;
  cached_cos_ = sc.cos;
}

void Turtle::turn_around() noexcept {
  heading_ = -heading_;
  left_ = -left_;
}

void Turtle::roll_to_vertical() noexcept {
  const glm::dvec3 side = glm::cross(glm::dvec3(0.0, 0.0, 1.0), heading_);
  const double length = glm::length(side);
  if (length < 1e-12) return;
  left_ = side / length;
  up_ = glm::cross(heading_, left_);
}

void Turtle::bend(const glm::dvec3& tropism, double elasticity) noexcept {
  const glm::dvec3 axis = glm::cross(heading_, tropism);
  const double length = glm::length(axis);
  if (length < 1e-12) return;
  const double angle = elasticity * length;
  const glm::dvec3 k = axis / length;
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  heading_ = rotate_about(heading_, k, c, s);
  left_ = rotate_about(left_, k, c, s);
  up_ = rotate_about(up_, k, c, s);
  orthonormalize();
}

void Turtle::set_heading(const glm::dvec3& heading) noexcept {
  const double length = glm::length(heading);
  if (!(length > 0.0) || !std::isfinite(length)) return;
  const glm::dvec3 h = heading / length;
  const glm::dvec3 axis = glm::cross(heading_, h);
  const double s = glm::length(axis);
  const double c = glm::dot(heading_, h);
  if (s < 1e-12) {
    // Along H already, or against it: a half turn about up.
    if (c < 0.0) turn_around();
    return;
  }
  const glm::dvec3 k = axis / s;
  heading_ = h;
  left_ = rotate_about(left_, k, c, s);
  up_ = rotate_about(up_, k, c, s);
  orthonormalize();
}

void Turtle::set_heading_and_up(const glm::dvec3& heading,
                                const glm::dvec3& up) noexcept {
  const double length = glm::length(heading);
  if (!(length > 0.0) || !std::isfinite(length)) return;
  const glm::dvec3 h = heading / length;
  const glm::dvec3 across = up - glm::dot(up, h) * h;
  const double a = glm::length(across);
  if (!(a > 1e-12 * std::max(1.0, glm::length(up))) || !std::isfinite(a)) {
    set_heading(h);
    return;
  }
  heading_ = h;
  up_ = across / a;
  left_ = glm::cross(up_, heading_);  // so that H × L = U
  orthonormalize();
}

void Turtle::orthonormalize() noexcept {
  rotations_since_orthonormalize_ = 0;
  heading_ = glm::normalize(heading_);
  left_ = glm::normalize(left_ - glm::dot(left_, heading_) * heading_);
  up_ = glm::cross(heading_, left_);
}

}  // namespace lsys
