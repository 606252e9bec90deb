// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "surface_distance.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

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
  // Each thread lists (cell, triangle) pairs for its triangles; sorted
  // together they give every cell its triangles in triangle order, the
  // same lists whatever the threads.
  using Entry = std::pair<std::uint64_t, std::uint32_t>;
  tbb::enumerable_thread_specific<std::vector<Entry>> listed;
  tbb::parallel_for(
      tbb::blocked_range<std::uint32_t>(0, count, 2048),
      [&](const tbb::blocked_range<std::uint32_t>& range) {
        std::vector<Entry>& out = listed.local();
        for (std::uint32_t i = range.begin(); i != range.end(); ++i) {
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
            // A long sliver across many cells, such as the flat
            // underside's: only the cells it passes through.
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
  std::vector<Entry> entries;
  std::size_t total = 0;
  for (const auto& part : listed) total += part.size();
  entries.reserve(total);
  for (auto& part : listed) {
    entries.insert(entries.end(), part.begin(), part.end());
    std::vector<Entry>().swap(part);
  }
  tbb::parallel_sort(entries.begin(), entries.end());
  index->members.reserve(entries.size());
  std::vector<std::uint64_t> keys;
  for (std::size_t k = 0; k < entries.size(); ++k) {
    if (k == 0 || entries[k].first != entries[k - 1].first) {
      keys.push_back(entries[k].first);
      index->starts.push_back(static_cast<std::uint32_t>(k));
    }
    index->members.push_back(entries[k].second);
  }
  index->starts.push_back(static_cast<std::uint32_t>(entries.size()));
  // At most half the slots filled: a miss ends within a few probes.
  const std::size_t slots =
      std::bit_ceil(std::max<std::size_t>(2 * keys.size(), 2));
  index->slot_bits = std::countr_zero(slots);
  index->slots.assign(slots, Index::kEmpty);
  index->slot_range.assign(slots, 0);
  for (std::size_t r = 0; r < keys.size(); ++r) {
    std::size_t s = index->slot_of(keys[r]);
    while (index->slots[s] != Index::kEmpty) s = (s + 1) & (slots - 1);
    index->slots[s] = keys[r];
    index->slot_range[s] = static_cast<std::uint32_t>(r);
  }
  for (std::uint32_t i = 0; i < count; ++i) {
    if (huge[i] != 0) index->large.push_back(i);
  }
  index_ = std::move(index);
}

}  // namespace lsolid
