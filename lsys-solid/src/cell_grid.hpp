// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace lsolid {

/// The cells of a uniform grid of cubes `cell_mm` wide, for the spatial
/// indexes of the decimation (SurfaceDistance, ModIntersectionGuardT) and
/// of the tube mesher (a tube that comes back to itself). A cell's key
/// packs its integer coordinates, 21 bits each: cells 2²¹ apart share a
/// key, which only adds candidates that the exact tests reject. Cells are
/// counted from `origin`; a grid whose cells are fine beside the distance
/// of its points from the origin must set it, or cell coordinates leave
/// the range of int.
class CellGrid {
 public:
  explicit CellGrid(double cell_mm = 1.0, const glm::dvec3& origin = {})
      : cell_mm_(cell_mm), origin_(origin) {}

  [[nodiscard]] double cell_mm() const noexcept { return cell_mm_; }

  /// The cell of `p`; coordinates beyond ±2²⁹ are clamped there (cells
  /// that far out share keys anyway), so that they and their differences
  /// are ints however fine the cells.
  [[nodiscard]] glm::ivec3 cell_of(const glm::dvec3& p) const {
    constexpr double kFar = 0x1p29;
    return glm::ivec3(
        glm::clamp(glm::floor((p - origin_) / cell_mm_), -kFar, kFar));
  }

  [[nodiscard]] static std::uint64_t key(const glm::ivec3& c) noexcept {
    constexpr std::uint64_t mask = (1u << 21) - 1;
    return (std::uint64_t(c.x) & mask) | ((std::uint64_t(c.y) & mask) << 21) |
           ((std::uint64_t(c.z) & mask) << 42);
  }

  /// How many cells the box from `lo` to `hi` overlaps.
  [[nodiscard]] double count(const glm::dvec3& lo, const glm::dvec3& hi) const {
    const glm::ivec3 a = cell_of(lo);
    const glm::ivec3 b = cell_of(hi);
    return double(b.x - a.x + 1) * double(b.y - a.y + 1) *
           double(b.z - a.z + 1);
  }

  /// Calls visit(key, centre) for every cell the box overlaps.
  template <typename Visit>
  void for_each(const glm::dvec3& lo, const glm::dvec3& hi, Visit visit) const {
    const glm::ivec3 a = cell_of(lo);
    const glm::ivec3 b = cell_of(hi);
    for (int x = a.x; x <= b.x; ++x) {
      for (int y = a.y; y <= b.y; ++y) {
        for (int z = a.z; z <= b.z; ++z) {
          visit(key({x, y, z}),
                origin_ + (glm::dvec3(x, y, z) + 0.5) * cell_mm_);
        }
      }
    }
  }

 private:
  double cell_mm_;
  glm::dvec3 origin_;
};

}  // namespace lsolid
