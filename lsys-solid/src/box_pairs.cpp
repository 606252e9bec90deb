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
#include <bit>
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

// Boxes over more cells than this are searched in a grid of their own,
// coarser (a leaf's face beside a dense seam, a tube's side along a
// branch): listed in each fine cell, the faces of blog tree B's leaves
// were 33 million entries.
constexpr double kMostCells = 64.0;

bool meet(const Box& a, const Box& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y &&
         b.min.y <= a.max.y && a.min.z <= b.max.z && b.min.z <= a.max.z;
}

// The median of the boxes' largest sides.
double median_side(const std::vector<Box>& boxes) {
  std::vector<double> sides(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const glm::dvec3 size = boxes[i].size();
    sides[i] = std::max({size.x, size.y, size.z});
  }
  const auto middle =
      sides.begin() + static_cast<std::ptrdiff_t>(sides.size() / 2);
  std::nth_element(sides.begin(), middle, sides.end());
  return *middle;
}

// Cells two median boxes wide, the larger median of the sets: a box of one
// then overlaps about eight, so at least half of each set is small. Never
// finer than 2⁻²⁰ of the boxes' span, counted from the lowest corner, so
// that cell coordinates fit the grid's 21 bits (and boxes of no size do not
// make cells of none, nor a few tiny boxes far from the origin coordinates
// beyond an int).
CellGrid grid_for(std::initializer_list<const std::vector<Box>*> sets) {
  double median = 0.0;
  Box all;
  for (const std::vector<Box>* boxes : sets) {
    median = std::max(median, median_side(*boxes));
    for (const Box& box : *boxes) {
      all.add(box.min);
      all.add(box.max);
    }
  }
  const glm::dvec3 span = all.size();
  const double widest = std::max({span.x, span.y, span.z});
  return CellGrid(std::max({2.0 * median, widest * 0x1p-20, 1e-300}), all.min);
}

// The boxes over at most kMostCells cells of a grid, and the others, each
// with its index in the set they came from.
struct Split {
  std::vector<Box> small;
  std::vector<std::uint32_t> small_id;
  std::vector<Box> large;
  std::vector<std::uint32_t> large_id;
};

Split split(const CellGrid& grid, const std::vector<Box>& boxes) {
  Split out;
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    if (grid.count(boxes[i].min, boxes[i].max) > kMostCells) {
      out.large.push_back(boxes[i]);
      out.large_id.push_back(i);
    } else {
      out.small.push_back(boxes[i]);
      out.small_id.push_back(i);
    }
  }
  return out;
}

using Entry = std::pair<std::uint64_t, std::uint32_t>;

// Boxes listed in the cells they overlap: (cell, box) for every cell of
// every box, sorted, so that the boxes of each cell are a run, in
// increasing order; and the runs by cell, in open addressing (a
// multiplicative hash, linear probing, at most half full). A binary search
// of the runs for each cell of each box (millions of runs on blog tree B,
// twenty-odd dependent reads a cell) was a sixth of the exact union's time.
struct Listed {
  std::vector<Entry> entries;
  std::vector<std::size_t> runs;  // where each cell's run starts, and the end
  std::vector<std::uint64_t> slot_key;  // a cell's key, or kEmpty
  std::vector<std::uint32_t> slot_run;  // its run
  int slot_bits = 1;

  // Keys use 63 bits (CellGrid::key), so this is none.
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

  [[nodiscard]] std::size_t slot_of(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ULL) >>
                                    (64 - slot_bits));
  }

  // Fills the table from the runs.
  void index_runs() {
    const std::size_t count = runs.size() - 1;
    slot_bits = std::max(1, static_cast<int>(std::bit_width(2 * count)));
    slot_key.assign(std::size_t{1} << slot_bits, kEmpty);
    slot_run.assign(slot_key.size(), 0);
    const std::size_t mask = slot_key.size() - 1;
    for (std::size_t r = 0; r < count; ++r) {
      const std::uint64_t key = entries[runs[r]].first;
      std::size_t s = slot_of(key);
      while (slot_key[s] != kEmpty) s = (s + 1) & mask;
      slot_key[s] = key;
      slot_run[s] = static_cast<std::uint32_t>(r);
    }
  }

  // The run of the cell `key`: [first, last) in entries, empty if none.
  // @pre index_runs() was called (the search of one set walks the runs and
  // needs no table).
  [[nodiscard]] std::pair<std::size_t, std::size_t> run(
      std::uint64_t key) const {
    const std::size_t mask = slot_key.size() - 1;
    for (std::size_t s = slot_of(key);; s = (s + 1) & mask) {
      if (slot_key[s] == key) {
        const std::uint32_t r = slot_run[s];
        return {runs[r], runs[r + 1]};
      }
      if (slot_key[s] == kEmpty) return {0, 0};
    }
  }
};

// @pre every box is over at most kMostCells cells.
Listed list_in_cells(const CellGrid& grid, const std::vector<Box>& boxes) {
  const std::size_t n = boxes.size();
  Listed out;
  std::vector<std::size_t> first(n + 1, 0);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
    first[i + 1] =
        static_cast<std::size_t>(grid.count(boxes[i].min, boxes[i].max));
  });
  std::partial_sum(first.begin(), first.end(), first.begin());
  out.entries.resize(first[n]);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
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
  return out;
}

// The cell of each box's lowest corner: a pair of boxes that meet is taken
// in the cell of the lowest corner of what they share, whose coordinates
// are the larger of the two boxes' lowest cells' (cells are monotone in x,
// y, z).
std::vector<glm::ivec3> lowest_cells(const CellGrid& grid,
                                     const std::vector<Box>& boxes) {
  std::vector<glm::ivec3> low(boxes.size());
  tbb::parallel_for(std::size_t{0}, boxes.size(), [&](std::size_t i) {
    low[i] = grid.cell_of(boxes[i].min);
  });
  return low;
}

// Whether boxes a and b, whose lowest cells are low_a and low_b, meet and
// their pair is taken in cell `key`, which holds them both: each pair in
// one cell alone.
bool taken_in(std::uint64_t key, const Box& a, const glm::ivec3& low_a,
              const Box& b, const glm::ivec3& low_b) {
  return meet(a, b) && CellGrid::key(glm::max(low_a, low_b)) == key;
}

// The pairs the threads found and `more`, sorted, each once: cells 2²¹
// apart share a key (CellGrid), so a pair may come twice.
std::vector<Pair> gathered(Found& found, std::vector<Pair> more) {
  std::vector<Pair> pairs = std::move(more);
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
  const Split parts = split(grid, boxes);
  const std::vector<Box>& small = parts.small;
  const std::vector<std::uint32_t>& id = parts.small_id;
  const Listed listed = list_in_cells(grid, small);
  const std::vector<Entry>& entries = listed.entries;
  const std::vector<std::size_t>& runs = listed.runs;
  const std::vector<glm::ivec3> low_cell = lowest_cells(grid, small);
  Found found;
  // A cell's boxes, copied side by side with their ids and lowest cells,
  // are swept along x, so that only those whose x ranges overlap are
  // compared (cells along a seam hold hundreds of small triangles).
  struct InCell {
    Box box;
    glm::ivec3 low;
    std::uint32_t id;
  };
  tbb::enumerable_thread_specific<std::vector<InCell>> scratch;
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, runs.size() - 1, 64),
      [&](const tbb::blocked_range<std::size_t>& range) {
        std::vector<Pair>& out = found.local();
        std::vector<InCell>& in_cell = scratch.local();
        for (std::size_t r = range.begin(); r < range.end(); ++r) {
          const std::uint64_t key = entries[runs[r]].first;
          in_cell.clear();
          for (std::size_t k = runs[r]; k < runs[r + 1]; ++k) {
            const std::uint32_t b = entries[k].second;
            in_cell.push_back({small[b], low_cell[b], id[b]});
          }
          std::sort(in_cell.begin(), in_cell.end(),
                    [](const InCell& a, const InCell& b) {
                      return a.box.min.x < b.box.min.x ||
                             (a.box.min.x == b.box.min.x && a.id < b.id);
                    });
          for (std::size_t a = 0; a < in_cell.size(); ++a) {
            const InCell& cell_a = in_cell[a];
            for (std::size_t b = a + 1; b < in_cell.size(); ++b) {
              const InCell& cell_b = in_cell[b];
              if (cell_b.box.min.x > cell_a.box.max.x) break;
              if (!taken_in(key, cell_a.box, cell_a.low, cell_b.box,
                            cell_b.low)) {
                continue;
              }
              const std::uint32_t i = std::min(cell_a.id, cell_b.id);
              const std::uint32_t j = std::max(cell_a.id, cell_b.id);
              if (keep(i, j)) out.emplace_back(i, j);
            }
          }
        }
      });
  // The large boxes against the small ones and among themselves, each in a
  // grid of their size.
  std::vector<Pair> more;
  const std::vector<std::uint32_t>& large_id = parts.large_id;
  const auto ordered = [](std::uint32_t i, std::uint32_t j) {
    return Pair{std::min(i, j), std::max(i, j)};
  };
  if (!parts.large.empty()) {
    for (const auto& [a, b] : meeting_box_pairs(
             parts.large, small, [&](std::uint32_t a, std::uint32_t b) {
               const Pair p = ordered(large_id[a], id[b]);
               return keep(p.first, p.second);
             })) {
      more.push_back(ordered(large_id[a], id[b]));
    }
    for (const auto& [a, b] :
         meeting_box_pairs(parts.large, [&](std::uint32_t a, std::uint32_t b) {
           const Pair p = ordered(large_id[a], large_id[b]);
           return keep(p.first, p.second);
         })) {
      more.push_back(ordered(large_id[a], large_id[b]));
    }
  }
  return gathered(found, std::move(more));
}

std::vector<Pair> meeting_box_pairs(const std::vector<Box>& first,
                                    const std::vector<Box>& second,
                                    const Keep& keep) {
  if (first.empty() || second.empty()) return {};
  const CellGrid grid = grid_for({&first, &second});
  const Split one = split(grid, first);
  const Split two = split(grid, second);
  // The small boxes of the second set listed in cells; each small box of
  // the first looks in its own. The pairs of each box of the first are
  // sorted on their own and the boxes taken in order, in fixed chunks, so
  // that the pairs come sorted without sorting them all (tens of millions
  // for the exact union's search on blog tree B, a seventh of its time).
  Listed listed = list_in_cells(grid, two.small);
  listed.index_runs();
  const std::vector<glm::ivec3> low_cell = lowest_cells(grid, two.small);
  constexpr std::size_t kChunk = 256;
  std::vector<std::vector<Pair>> chunks((one.small.size() + kChunk - 1) /
                                        kChunk);
  tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t chunk) {
    std::vector<Pair>& out = chunks[chunk];
    const std::size_t end = std::min(one.small.size(), (chunk + 1) * kChunk);
    for (std::size_t k = chunk * kChunk; k < end; ++k) {
      const Box& box = one.small[k];
      const std::uint32_t i = one.small_id[k];
      const std::size_t mine = out.size();
      const glm::ivec3 low = grid.cell_of(box.min);
      grid.for_each(
          box.min, box.max, [&](std::uint64_t key, const glm::dvec3&) {
            const auto [from, to] = listed.run(key);
            for (std::size_t e = from; e < to; ++e) {
              const std::uint32_t small = listed.entries[e].second;
              if (!taken_in(key, box, low, two.small[small], low_cell[small])) {
                continue;
              }
              const std::uint32_t j = two.small_id[small];
              if (keep(i, j)) out.emplace_back(i, j);
            }
          });
      // Cells 2²¹ apart share a key (CellGrid): a pair may come twice.
      const auto from = out.begin() + static_cast<std::ptrdiff_t>(mine);
      std::sort(from, out.end());
      out.erase(std::unique(from, out.end()), out.end());
    }
  });
  std::vector<Pair> pairs;
  std::size_t total = 0;
  for (const std::vector<Pair>& chunk : chunks) total += chunk.size();
  pairs.reserve(total);
  for (const std::vector<Pair>& chunk : chunks) {
    pairs.insert(pairs.end(), chunk.begin(), chunk.end());
  }
  // The large boxes of the first set against the whole second set, and the
  // large ones of the second against the small ones of the first, each in
  // a grid of their size.
  std::vector<Pair> more;
  if (!one.large.empty()) {
    for (const auto& [a, b] : meeting_box_pairs(
             one.large, second, [&](std::uint32_t a, std::uint32_t b) {
               return keep(one.large_id[a], b);
             })) {
      more.emplace_back(one.large_id[a], b);
    }
  }
  if (!two.large.empty() && !one.small.empty()) {
    for (const auto& [a, b] : meeting_box_pairs(
             two.large, one.small, [&](std::uint32_t a, std::uint32_t b) {
               return keep(one.small_id[b], two.large_id[a]);
             })) {
      more.emplace_back(one.small_id[b], two.large_id[a]);
    }
  }
  if (more.empty()) return pairs;
  // No pair of the small boxes has a large box: the two lists share none.
  std::sort(more.begin(), more.end());
  more.erase(std::unique(more.begin(), more.end()), more.end());
  const auto middle = static_cast<std::ptrdiff_t>(pairs.size());
  pairs.insert(pairs.end(), more.begin(), more.end());
  std::inplace_merge(pairs.begin(), pairs.begin() + middle, pairs.end());
  return pairs;
}

}  // namespace lsolid
