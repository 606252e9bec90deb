// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Sampling a contour as cpfg's general.c (MakeContour) does: a table of
// arc lengths along the uniform cubic B-spline, then points at equal steps
// of length. cpfg's table stops a tenth of a span short of an open
// contour's end (its last entry is at t = segments − 0.1), which leaves the
// last ring point short of the end the editor shows; this samples the
// whole curve, finer, as the contour is drawn in the editor.
#include "lsys/contour.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace lsys {
namespace {

// Arc-length samples per span of the spline: a span is at most a quarter
// turn of a leaf's cross-section, and 64 chords follow it to 10⁻⁴.
constexpr int kSamplesPerSpan = 64;

// The uniform cubic B-spline of the four control points from `first`, at
// u in [0, 1] (ABOP's and cpfg's basis matrix).
glm::dvec2 evaluate(const std::vector<glm::dvec2>& p, std::size_t first,
                    double u) {
  const double v = 1.0 - u;
  const double b0 = v * v * v / 6.0;
  const double b1 = (3.0 * u * u * u - 6.0 * u * u + 4.0) / 6.0;
  const double b2 = (-3.0 * u * u * u + 3.0 * u * u + 3.0 * u + 1.0) / 6.0;
  const double b3 = u * u * u / 6.0;
  return b0 * p[first] + b1 * p[first + 1] + b2 * p[first + 2] +
         b3 * p[first + 3];
}

// The curve at t in [0, segments].
glm::dvec2 at(const std::vector<glm::dvec2>& p, double t) {
  const std::size_t segments = p.size() - 3;
  const auto first =
      std::min(static_cast<std::size_t>(std::max(t, 0.0)), segments - 1);
  return evaluate(p, first, t - static_cast<double>(first));
}

}  // namespace

std::vector<glm::dvec2> sample_contour(const Contour& contour, int sides) {
  const std::vector<glm::dvec2>& p = contour.control_points;
  const std::size_t segments = p.size() - 3;
  const std::size_t samples = segments * kSamplesPerSpan;
  std::vector<double> length(samples + 1, 0.0);
  glm::dvec2 last = at(p, 0.0);
  for (std::size_t i = 1; i <= samples; ++i) {
    const glm::dvec2 next = at(p, static_cast<double>(i) / kSamplesPerSpan);
    length[i] = length[i - 1] + glm::length(next - last);
    last = next;
  }
  std::vector<glm::dvec2> out;
  out.reserve(static_cast<std::size_t>(sides) + 1);
  out.push_back(at(p, 0.0));
  std::size_t j = 1;
  for (int k = 1; k < sides; ++k) {
    const double target = length.back() * k / sides;
    while (j < samples && length[j] < target) ++j;
    const double span = length[j] - length[j - 1];
    const double f = span > 0.0 ? (target - length[j - 1]) / span : 0.0;
    out.push_back(at(p, (static_cast<double>(j - 1) + f) / kSamplesPerSpan));
  }
  out.push_back(at(p, static_cast<double>(segments)));
  return out;
}

}  // namespace lsys
