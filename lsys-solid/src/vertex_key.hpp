// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <boost/container_hash/hash.hpp>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>

namespace lsolid {

/// A double rounded to the nearest float. Going through a volatile float
/// forces the rounding: GCC 12's SLP vectorizer (-O2 and up) was seen to
/// drop the pair of conversions in `(double)(float)x`, keeping x unrounded.
inline float to_float(double x) {
  volatile float f = static_cast<float>(x);
  return f;
}

/// A point rounded to floats, compared bit for bit: STL's vertex identity.
using FloatKey = std::array<std::uint32_t, 3>;

inline FloatKey float_key(const glm::dvec3& p) {
  const auto bits = [](double v) {
    float f = to_float(v);
    if (f == 0.0F) f = 0.0F;  // -0 and +0 are one vertex
    return std::bit_cast<std::uint32_t>(f);
  };
  return {bits(p.x), bits(p.y), bits(p.z)};
}

inline glm::dvec3 key_point(const FloatKey& k) {
  return {std::bit_cast<float>(k[0]), std::bit_cast<float>(k[1]),
          std::bit_cast<float>(k[2])};
}

/// A hash of float keys for unordered containers (Boost's hash_combine
/// over the three coordinates).
using FloatKeyHash = boost::hash<FloatKey>;

/// A triangle by its corners' bits, from its least corner on: the same key
/// whichever corner a face starts from, its orientation kept.
using TriangleKey = std::array<std::uint64_t, 9>;

inline TriangleKey triangle_key(const glm::dvec3& a, const glm::dvec3& b,
                                const glm::dvec3& c) {
  std::array<std::array<std::uint64_t, 3>, 3> corners{};
  const std::array<const glm::dvec3*, 3> points{&a, &b, &c};
  for (std::size_t k = 0; k < 3; ++k) {
    corners[k] = {std::bit_cast<std::uint64_t>(points[k]->x),
                  std::bit_cast<std::uint64_t>(points[k]->y),
                  std::bit_cast<std::uint64_t>(points[k]->z)};
  }
  const auto first = static_cast<std::size_t>(
      std::min_element(corners.begin(), corners.end()) - corners.begin());
  TriangleKey key{};
  for (std::size_t k = 0; k < 3; ++k) {
    const auto& q = corners[(first + k) % 3];
    std::copy(q.begin(), q.end(),
              key.begin() + static_cast<std::ptrdiff_t>(3 * k));
  }
  return key;
}

}  // namespace lsolid
