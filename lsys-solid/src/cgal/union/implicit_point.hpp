// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>

namespace lsolid::exact_union {

/// A point of the union: an input vertex, or where an input edge crosses an
/// input face's plane (a line–plane intersection, "LPI"), kept as that
/// definition and never constructed (Attene 2020, "Indirect predicates for
/// geometric constructions").
struct ImplicitPoint {
  glm::dvec3 p{};                     ///< the vertex, or the edge's first end
  glm::dvec3 q{};                     ///< the edge's second end (an LPI)
  std::array<glm::dvec3, 3> plane{};  ///< the face (an LPI)
  bool is_vertex = true;
  /// p lies on the plane's negative side (an LPI): decided once, exactly,
  /// by the orientation test that found the crossing.
  bool p_below = false;
};

/// Homogeneous coordinates (x, y, z, w) relative to an origin; w > 0 (w = 1
/// for a vertex).
template <typename NT>
struct Homogeneous {
  std::array<NT, 3> xyz;
  NT w;
};

/// The orientation determinants of an LPI's edge ends against its plane,
/// dp = ((s − r) × (t − r))·(p − r) and dq likewise, in NT.
template <typename NT>
[[nodiscard]] std::array<NT, 2> plane_distances(const ImplicitPoint& point) {
  const auto& [r, s, t] = point.plane;
  std::array<NT, 3> u;
  std::array<NT, 3> v;
  std::array<NT, 3> pr;
  std::array<NT, 3> qr;
  for (int k = 0; k < 3; ++k) {
    u[k] = NT(s[k]) - NT(r[k]);
    v[k] = NT(t[k]) - NT(r[k]);
    pr[k] = NT(point.p[k]) - NT(r[k]);
    qr[k] = NT(point.q[k]) - NT(r[k]);
  }
  const std::array<NT, 3> n{u[1] * v[2] - u[2] * v[1],
                            u[2] * v[0] - u[0] * v[2],
                            u[0] * v[1] - u[1] * v[0]};
  return {n[0] * pr[0] + n[1] * pr[1] + n[2] * pr[2],
          n[0] * qr[0] + n[1] * qr[1] + n[2] * qr[2]};
}

/// The coordinates of `point` relative to `origin` in the number type NT:
/// for an LPI, x = (q − o)·dp − (p − o)·dq and w = dp − dq
/// (plane_distances), both negated when p lies below the plane, so that
/// w > 0. Exact for NT = Mpzf; an enclosure for Interval_nt (inside a
/// Protect_FPU_rounding scope).
template <typename NT>
[[nodiscard]] Homogeneous<NT> homogeneous(const ImplicitPoint& point,
                                          const glm::dvec3& origin) {
  Homogeneous<NT> h;
  if (point.is_vertex) {
    for (int k = 0; k < 3; ++k) h.xyz[k] = NT(point.p[k]) - NT(origin[k]);
    h.w = NT(1);
    return h;
  }
  auto [dp, dq] = plane_distances<NT>(point);
  if (point.p_below) {
    dp = -dp;
    dq = -dq;
  }
  for (int k = 0; k < 3; ++k) {
    const NT po = NT(point.p[k]) - NT(origin[k]);
    const NT qo = NT(point.q[k]) - NT(origin[k]);
    h.xyz[k] = qo * dp - po * dq;
  }
  h.w = dp - dq;
  return h;
}

/// The parameter of an LPI along its edge from p, as the fraction num / den
/// with den > 0: points on one edge are ordered by it, never by orientation
/// tests, whose answer (collinear) is known.
template <typename NT>
[[nodiscard]] std::array<NT, 2> edge_parameter(const ImplicitPoint& point) {
  auto [dp, dq] = plane_distances<NT>(point);
  if (point.p_below) return {-dp, dq - dp};
  return {dp, dp - dq};
}

}  // namespace lsolid::exact_union
