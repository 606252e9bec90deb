// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "surface_distance.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <bit>
#include <utility>

namespace lsolid {

SurfaceDistance::SurfaceDistance(const TriangleMesh& mesh, double min_cell_mm)
    : mesh_(mesh), seen_(mesh.triangles.size(), 0) {
  auto index = std::make_shared<Index>();
  // Summed in triangle order, on one thread, so that the cell width, and
  // with it every answer's order, is the same whatever the threads.
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    const glm::dvec3& a = mesh.vertices[t[0]];
    area += glm::length(
                glm::cross(mesh.vertices[t[1]] - a, mesh.vertices[t[2]] - a)) /
            2.0;
  }
  index->grid = CellGrid(std::max(
      {min_cell_mm,
       mesh.triangles.empty()
           ? 1.0
           : std::sqrt(area / static_cast<double>(mesh.triangles.size())),
       1e-6}));
  const CellGrid& grid = index->grid;
  const auto count = static_cast<std::uint32_t>(mesh.triangles.size());
  index->bounds.resize(count);
  std::vector<char> huge(count, 0);
  // The (cell, triangle) pairs are listed in chunks of triangles on the
  // threads, then counted into cells in triangle order on one: every cell
  // gets its triangles in triangle order, the same lists whatever the
  // threads. (Sorting the pairs instead, 3.2 million of them for the bush's
  // union at n = 7, took half the building.)
  using Entry = std::pair<std::uint64_t, std::uint32_t>;
  constexpr std::uint32_t kChunk = 2048;
  std::vector<std::vector<Entry>> listed((count + kChunk - 1) / kChunk);
  tbb::parallel_for(std::size_t{0}, listed.size(), [&](std::size_t chunk) {
    std::vector<Entry>& out = listed[chunk];
    const auto first = static_cast<std::uint32_t>(chunk * kChunk);
    const std::uint32_t last = std::min(count, first + kChunk);
    for (std::uint32_t i = first; i != last; ++i) {
      const auto& t = mesh.triangles[i];
      const glm::dvec3& a = mesh.vertices[t[0]];
      const glm::dvec3& b = mesh.vertices[t[1]];
      const glm::dvec3& c = mesh.vertices[t[2]];
      const glm::dvec3 lo = glm::min(glm::min(a, b), c);
      const glm::dvec3 hi = glm::max(glm::max(a, b), c);
      index->bounds[i] = bounds_of(a, b, c, lo, hi);
      const double cells = grid.count(lo, hi);
      if (cells > kHugeCells) {
        huge[i] = 1;  // tested by every query
      } else if (cells > kLargeCells) {
        // A long sliver across many cells, such as the flat underside's:
        // only the cells it passes through.
        for_each_cell_through(grid, a, b, c, [&](std::uint64_t key) {
          out.emplace_back(key, i);
        });
      } else {
        grid.for_each(lo, hi, [&](std::uint64_t key, const glm::dvec3&) {
          out.emplace_back(key, i);
        });
      }
    }
  });
  // Each entry's range (its cell's, numbered as first met), the ranges'
  // keys and sizes, and the table from key to range, kept at most half
  // full so that a miss ends within a few probes.
  std::size_t total = 0;
  for (const auto& part : listed) total += part.size();
  std::vector<std::uint32_t> range_of;
  range_of.reserve(total);
  std::vector<std::uint64_t> keys;
  std::vector<std::uint32_t> sizes;
  const auto make_table = [&](std::size_t slots) {
    index->slot_bits = std::countr_zero(slots);
    index->slots.assign(slots, Index::kEmpty);
    index->slot_range.assign(slots, 0);
    for (std::uint32_t r = 0; r < keys.size(); ++r) {
      std::size_t s = index->slot_of(keys[r]);
      while (index->slots[s] != Index::kEmpty) s = (s + 1) & (slots - 1);
      index->slots[s] = keys[r];
      index->slot_range[s] = r;
    }
  };
  make_table(std::bit_ceil(std::max<std::size_t>(total / 4, 2)));
  for (const auto& part : listed) {
    for (const auto& [key, i] : part) {
      std::size_t mask = index->slots.size() - 1;
      std::size_t s = index->slot_of(key);
      while (index->slots[s] != key && index->slots[s] != Index::kEmpty) {
        s = (s + 1) & mask;
      }
      if (index->slots[s] == Index::kEmpty) {
        if (2 * (keys.size() + 1) > index->slots.size()) {
          make_table(2 * index->slots.size());
          mask = index->slots.size() - 1;
          s = index->slot_of(key);
          while (index->slots[s] != Index::kEmpty) s = (s + 1) & mask;
        }
        index->slots[s] = key;
        index->slot_range[s] = static_cast<std::uint32_t>(keys.size());
        keys.push_back(key);
        sizes.push_back(0);
      }
      const std::uint32_t r = index->slot_range[s];
      ++sizes[r];
      range_of.push_back(r);
    }
  }
  index->starts.assign(keys.size() + 1, 0);
  for (std::size_t r = 0; r < keys.size(); ++r) {
    index->starts[r + 1] = index->starts[r] + sizes[r];
  }
  std::vector<std::uint32_t> next(index->starts.begin(),
                                  index->starts.end() - 1);
  index->members.resize(total);
  std::size_t k = 0;
  for (const auto& part : listed) {
    for (const auto& entry : part)
      index->members[next[range_of[k++]]++] = entry.second;
  }
  for (std::uint32_t i = 0; i < count; ++i) {
    if (huge[i] != 0) index->large.push_back(i);
  }
  index_ = std::move(index);
}

}  // namespace lsolid
