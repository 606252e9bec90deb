// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <bit>
#include <boost/container_hash/hash.hpp>
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

}  // namespace lsolid
