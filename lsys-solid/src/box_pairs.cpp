// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The broad phase of the self-intersection searches of rounding and of the
// exact union (docs/design.md, "Rounding"). CGAL's box_intersection_d
// (Zomorodian and Edelsbrunner's streamed segment tree) runs on one thread,
// and its Parallel_tag splits the boxes into sixteen pairs of quarters,
// four times the work, which two cores do not win back. The triangles of a
// mesh are boxes of about one size over a surface, which a uniform grid
// sorts in linear time, and its cells are searched on the threads: the
// self-intersection test of the bush's union at n = 7 (375,184 triangles,
// 5.6 million pairs of boxes) took 0.6 s against 1.2 s.
#include "box_pairs.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <initializer_list>
#include <numeric>

#include "cell_grid.hpp"

namespace lsolid {
namespace {

using Pair = std::pair<std::uint32_t, std::uint32_t>;
using Keep = std::function<bool(std::uint32_t, std::uint32_t)>;
using Found = tbb::enumerable_thread_specific<std::vector<Pair>>;

// Boxes over more cells than this are compared with every box rather than
// listed in each cell (a leaf's face beside a dense seam, the base's
// sectors): they are few, and listing them would fill the grid.
constexpr double kMostCells = 4096.0;

bool meet(const Box& a, const Box& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y &&
         b.min.y <= a.max.y && a.min.z <= b.max.z && b.min.z <= a.max.z;
}

// Cells about two median boxes wide: a box then overlaps about eight, and
// a cell holds a box's neighbours. Never finer than 2⁻²⁰ of the boxes'
// span, so that cell coordinates fit the grid's 21 bits (and boxes of no
// size do not make cells of none).
CellGrid grid_for(std::initializer_list<const std::vector<Box>*> sets) {
  std::vector<double> sides;
  Box all;
  for (const std::vector<Box>* boxes : sets) {
    for (const Box& box : *boxes) {
      const glm::dvec3 size = box.size();
      sides.push_back(std::max({size.x, size.y, size.z}));
      all.add(box.min);
      all.add(box.max);
    }
  }
  const auto middle =
      sides.begin() + static_cast<std::ptrdiff_t>(sides.size() / 2);
  std::nth_element(sides.begin(), middle, sides.end());
  const glm::dvec3 span = all.size();
  const double widest = std::max({span.x, span.y, span.z});
  return CellGrid(std::max({2.0 * *middle, widest * 0x1p-20, 1e-300}));
}

using Entry = std::pair<std::uint64_t, std::uint32_t>;

// Boxes listed in the cells they overlap.
struct Listed {
  // (cell, box) for every cell of every box but the large ones, sorted:
  // the boxes of each cell in a run, in increasing order.
  std::vector<Entry> entries;
  std::vector<std::size_t> runs;  // where each cell's run starts, and the end
  std::vector<char> large;        // per box: over more than kMostCells
  std::vector<std::uint32_t> large_ones;

  // The run of the cell `key`: [first, last) in entries, empty if none.
  [[nodiscard]] std::pair<std::size_t, std::size_t> run(
      std::uint64_t key) const {
    const auto it = std::lower_bound(
        runs.begin(), runs.end() - 1, key,
        [&](std::size_t at, std::uint64_t k) { return entries[at].first < k; });
    if (it == runs.end() - 1 || entries[*it].first != key) return {0, 0};
    return {*it, *(it + 1)};
  }
};

Listed list_in_cells(const CellGrid& grid, const std::vector<Box>& boxes) {
  const std::size_t n = boxes.size();
  Listed out;
  std::vector<std::size_t> first(n + 1, 0);
  out.large.assign(n, 0);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
    const double cells = grid.count(boxes[i].min, boxes[i].max);
    if (cells > kMostCells) {
      out.large[i] = 1;
    } else {
      first[i + 1] = static_cast<std::size_t>(cells);
    }
  });
  std::partial_sum(first.begin(), first.end(), first.begin());
  out.entries.resize(first[n]);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
    if (out.large[i] != 0) return;
    std::size_t at = first[i];
    grid.for_each(boxes[i].min, boxes[i].max,
                  [&](std::uint64_t key, const glm::dvec3&) {
                    out.entries[at++] = {key, static_cast<std::uint32_t>(i)};
                  });
  });
  tbb::parallel_sort(out.entries.begin(), out.entries.end());
  for (std::size_t k = 0; k < out.entries.size(); ++k) {
    if (k == 0 || out.entries[k].first != out.entries[k - 1].first) {
      out.runs.push_back(k);
    }
  }
  out.runs.push_back(out.entries.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    if (out.large[i] != 0) out.large_ones.push_back(i);
  }
  return out;
}

// Whether the pair is taken in cell `key`: two boxes that meet share every
// cell that holds the lowest corner of what they share, and the pair is
// taken in that cell alone.
bool taken_in(const CellGrid& grid, std::uint64_t key, const Box& a,
              const Box& b) {
  return meet(a, b) &&
         CellGrid::key(grid.cell_of(glm::max(a.min, b.min))) == key;
}

// The pairs the threads found, sorted, each once: cells 2²¹ apart share a
// key (CellGrid), so a pair may come twice.
std::vector<Pair> gathered(Found& found) {
  std::vector<Pair> pairs;
  for (const std::vector<Pair>& part : found) {
    pairs.insert(pairs.end(), part.begin(), part.end());
  }
  tbb::parallel_sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace

std::vector<Pair> meeting_box_pairs(const std::vector<Box>& boxes,
                                    const Keep& keep) {
  if (boxes.size() < 2) return {};
  const CellGrid grid = grid_for({&boxes});
  const Listed listed = list_in_cells(grid, boxes);
  const std::vector<Entry>& entries = listed.entries;
  const std::vector<std::size_t>& runs = listed.runs;
  Found found;
  tbb::enumerable_thread_specific<std::vector<std::uint32_t>> scratch;
  // A cell's boxes are swept along x, so that only those whose x ranges
  // overlap are compared (cells along a seam hold hundreds of small
  // triangles).
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, runs.size() - 1, 64),
      [&](const tbb::blocked_range<std::size_t>& range) {
        std::vector<Pair>& out = found.local();
        std::vector<std::uint32_t>& in_cell = scratch.local();
        for (std::size_t r = range.begin(); r < range.end(); ++r) {
          const std::uint64_t key = entries[runs[r]].first;
          in_cell.clear();
          for (std::size_t k = runs[r]; k < runs[r + 1]; ++k) {
            in_cell.push_back(entries[k].second);
          }
          std::sort(in_cell.begin(), in_cell.end(),
                    [&](std::uint32_t a, std::uint32_t b) {
                      return boxes[a].min.x < boxes[b].min.x ||
                             (boxes[a].min.x == boxes[b].min.x && a < b);
                    });
          for (std::size_t a = 0; a < in_cell.size(); ++a) {
            const Box& box_a = boxes[in_cell[a]];
            for (std::size_t b = a + 1; b < in_cell.size(); ++b) {
              const Box& box_b = boxes[in_cell[b]];
              if (box_b.min.x > box_a.max.x) break;
              if (!taken_in(grid, key, box_a, box_b)) continue;
              const std::uint32_t i = std::min(in_cell[a], in_cell[b]);
              const std::uint32_t j = std::max(in_cell[a], in_cell[b]);
              if (keep(i, j)) out.emplace_back(i, j);
            }
          }
        }
      });
  // The large boxes against every box; a pair of two large ones from the
  // first of them.
  const std::vector<std::uint32_t>& large_ones = listed.large_ones;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, large_ones.size(), 1),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      std::vector<Pair>& out = found.local();
                      for (std::size_t k = range.begin(); k < range.end();
                           ++k) {
                        const std::uint32_t i = large_ones[k];
                        for (std::uint32_t j = 0; j < boxes.size(); ++j) {
                          if (j == i || (listed.large[j] != 0 && j < i))
                            continue;
                          if (!meet(boxes[i], boxes[j])) continue;
                          if (keep(std::min(i, j), std::max(i, j))) {
                            out.emplace_back(std::min(i, j), std::max(i, j));
                          }
                        }
                      }
                    });
  return gathered(found);
}

std::vector<Pair> meeting_box_pairs(const std::vector<Box>& first,
                                    const std::vector<Box>& second,
                                    const Keep& keep) {
  if (first.empty() || second.empty()) return {};
  const CellGrid grid = grid_for({&first, &second});
  // The second set listed in cells; each box of the first looks in its own.
  const Listed listed = list_in_cells(grid, second);
  Found found;
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, first.size(), 256),
      [&](const tbb::blocked_range<std::size_t>& range) {
        std::vector<Pair>& out = found.local();
        for (std::size_t k = range.begin(); k < range.end(); ++k) {
          const auto i = static_cast<std::uint32_t>(k);
          const Box& box = first[i];
          if (grid.count(box.min, box.max) > kMostCells) {
            // Large: against every box of the second set.
            for (std::uint32_t j = 0; j < second.size(); ++j) {
              if (meet(box, second[j]) && keep(i, j)) out.emplace_back(i, j);
            }
            continue;
          }
          grid.for_each(
              box.min, box.max, [&](std::uint64_t key, const glm::dvec3&) {
                const auto [from, to] = listed.run(key);
                for (std::size_t e = from; e < to; ++e) {
                  const std::uint32_t j = listed.entries[e].second;
                  if (taken_in(grid, key, box, second[j]) && keep(i, j)) {
                    out.emplace_back(i, j);
                  }
                }
              });
        }
      });
  // The large boxes of the second set against the boxes of the first that
  // were not (those were compared with every box above).
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, listed.large_ones.size(), 1),
      [&](const tbb::blocked_range<std::size_t>& range) {
        std::vector<Pair>& out = found.local();
        for (std::size_t k = range.begin(); k < range.end(); ++k) {
          const std::uint32_t j = listed.large_ones[k];
          for (std::uint32_t i = 0; i < first.size(); ++i) {
            if (grid.count(first[i].min, first[i].max) > kMostCells) continue;
            if (meet(first[i], second[j]) && keep(i, j)) {
              out.emplace_back(i, j);
            }
          }
        }
      });
  return gathered(found);
}

}  // namespace lsolid
