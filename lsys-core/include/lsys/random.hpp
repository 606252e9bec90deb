// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

namespace lsys {

/// SplitMix64's output function (Steele, Lea, Flood 2014): a bijective
/// mix of 64 bits, written out so every compiler gives the same numbers.
[[nodiscard]] constexpr std::uint64_t splitmix64(std::uint64_t x) noexcept {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30U)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27U)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31U);
}

/// The random number in [0, 1) that decides the stochastic production of
/// the module at `position` (0-based) of the string of derivation step
/// `step`, for a given seed:
/// `splitmix64(splitmix64(splitmix64(seed) ^ step) ^ position) >> 11`,
/// times 2^-53. Keyed by place rather than drawn in sequence, it gives the
/// same string whether the derivation streams depth-first or rewrites
/// breadth-first.
[[nodiscard]] constexpr double stochastic_uniform(
    std::uint64_t seed, std::uint64_t step, std::uint64_t position) noexcept {
  const std::uint64_t h =
      splitmix64(splitmix64(splitmix64(seed) ^ step) ^ position);
  return static_cast<double>(h >> 11U) * 0x1.0p-53;
}

}  // namespace lsys
