// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <OpenMesh/Tools/Decimater/ModBaseT.hh>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "cell_grid.hpp"
#include "cgal/triangle_pair.hpp"
#include "surface_distance.hpp"

namespace lsolid {

/// An OpenMesh decimation module that refuses every collapse whose new
/// triangles would intersect the rest of the mesh, or each other, or be
/// degenerate. OpenMesh's own modules only compare normals locally, and on
/// a union of tubes they leave tens to thousands of intersecting pairs
/// (the bush at n = 4 capped at 800 triangles: 23 pairs; docs/design.md).
///
/// Faces are kept in a uniform grid of cells a few edges wide. A face that
/// changes is added to the cells it now covers; stale entries stay and are
/// skipped because every test reads the face's current corners. Once half
/// the faces indexed are gone, the faces are indexed again, the cells
/// sized to the edges then and the stale entries dropped (blog tree B's
/// peak 1.76 GiB against 1.89, its time the same within the noise; the
/// tests are exact, so the answers are the same).
template <typename MeshT>
class ModIntersectionGuardT : public OpenMesh::Decimater::ModBaseT<MeshT> {
 public:
  DECIMATING_MODULE(ModIntersectionGuardT, MeshT, IntersectionGuard);

  explicit ModIntersectionGuardT(MeshT& mesh) : Base(mesh, true) {}

  /// Indexes every face, with cells two median edge lengths wide. (Four
  /// mean edges, as before, were 4.7 mm on the bush at n = 6, where tube
  /// sides a branch long drive the mean up: hundreds of faces per cell, and
  /// each test of a collapse read them all.)
  void initialize() override {
    MeshT& m = Base::mesh();
    std::vector<double> lengths;
    lengths.reserve(m.n_edges());
    for (const auto e : m.edges()) {
      if (!m.status(e).deleted()) lengths.push_back(m.calc_edge_length(e));
    }
    double median = 1.0;
    if (!lengths.empty()) {
      auto middle =
          lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
      std::nth_element(lengths.begin(), middle, lengths.end());
      median = *middle;
    }
    grid_ = CellGrid(std::max(1e-6, 2.0 * median));
    cells_.clear();
    large_.clear();
    faces_.assign(m.n_faces(), FaceState{});
    changing_.assign(m.n_faces(), 0);
    corners_.assign(m.n_faces(), IndexedTriangle{});
    degenerate_.assign(m.n_faces(), 0);
    live_faces_ = 0;
    for (const auto f : m.faces()) {
      insert(f);
      ++live_faces_;
    }
    indexed_faces_ = live_faces_;
  }

  /// Legal unless a new triangle would be degenerate or intersect another.
  float collapse_priority(const CollapseInfo& ci) override {
    return would_intersect(ci) ? float(Base::ILLEGAL_COLLAPSE)
                               : float(Base::LEGAL_COLLAPSE);
  }

  /// Indexes the faces that moved; the entries of those it removed go
  /// stale, or all are indexed again once half the faces are gone.
  void postprocess_collapse(const CollapseInfo& ci) override {
    for (const auto f : {ci.fl, ci.fr}) {
      if (!f.is_valid()) continue;
      ++faces_[static_cast<std::size_t>(f.idx())].version;
      --live_faces_;
    }
    if (2 * live_faces_ <= indexed_faces_) {
      initialize();
      return;
    }
    for (const auto f : Base::mesh().vf_range(ci.v1)) insert(f);
  }

  /// Collapses refused so far.
  [[nodiscard]] std::size_t refused() const noexcept { return refused_; }

  /// The test behind collapse_priority, for a driver that asks only when
  /// it is about to collapse.
  [[nodiscard]] bool would_intersect(const CollapseInfo& ci) {
    MeshT& m = Base::mesh();
    ++collapse_stamp_;
    fresh_.clear();
    for (const auto f : m.vf_range(ci.v0)) {
      changing_[f.idx()] = collapse_stamp_;
      if (f == ci.fl || f == ci.fr) continue;
      IndexedTriangle t = triangle(f);
      for (int k = 0; k < 3; ++k) {
        if (t.ids[k] == static_cast<std::uint32_t>(ci.v0.idx())) {
          t.ids[k] = static_cast<std::uint32_t>(ci.v1.idx());
          t.points[k] = point(ci.p1);
        }
      }
      if (is_degenerate(t)) return refuse();
      fresh_.push_back(t);
    }
    for (std::size_t i = 0; i < fresh_.size(); ++i) {
      for (std::size_t j = i + 1; j < fresh_.size(); ++j) {
        if (proper_triangles_intersect(fresh_[i], fresh_[j])) return refuse();
      }
    }
    // One query for the whole fan: its triangles share v1 and their boxes
    // mostly overlap, so a query each visited most faces several times
    // (160 million visits for the bush at n = 7, five per face tested).
    if (fresh_.empty()) return false;
    glm::dvec3 lo = box(fresh_.front()).first;
    glm::dvec3 hi = box(fresh_.front()).second;
    fresh_lo_.clear();
    fresh_hi_.clear();
    for (const IndexedTriangle& t : fresh_) {
      const auto [t_lo, t_hi] = box(t);
      fresh_lo_.push_back(t_lo);
      fresh_hi_.push_back(t_hi);
      lo = glm::min(lo, t_lo);
      hi = glm::max(hi, t_hi);
    }
    ++query_stamp_;
    nearby_.clear();
    // Entries of faces deleted or moved since (a collapse adds a face's new
    // cells and leaves the old) are dropped as they are met.
    const auto visit = [&](std::vector<Entry>& cell) {
      std::size_t kept = 0;
      for (const Entry& entry : cell) {
        const int index = entry.face;
        const auto i = static_cast<std::size_t>(index);
        FaceState& face = faces_[i];
        if (entry.version != face.version) continue;
        cell[kept++] = entry;
        if (face.seen == query_stamp_) continue;
        face.seen = query_stamp_;
        // The box kept since the face last changed rejects most
        // candidates without walking the mesh for their corners.
        if (overlap(lo, hi, face) && changing_[i] != collapse_stamp_ &&
            !m.status(typename MeshT::FaceHandle(index)).deleted()) {
          nearby_.push_back(index);
        }
      }
      cell.resize(kept);
    };
    if (grid_.count(lo, hi) <= kBoxCells) {
      for_cells(lo, hi, visit);
    } else {
      // A fan over more than a few cells (a leaf's face across hundreds):
      // only the cells its triangles pass through, where any face that
      // meets one has an entry. Its box's cells were, past the number of
      // cells filled, all of them: most of the blog's tree B's decimation;
      // and past 3 × 3 × 3 cells, still 11% of it (69.7 s against 61.7 s,
      // the same bytes).
      visit(large_);
      for (const IndexedTriangle& t : fresh_) {
        for_each_cell_through(grid_, t.points[0], t.points[1], t.points[2],
                              [&](Cell key) {
                                if (auto* cell = cells_.find(key)) visit(*cell);
                              });
      }
    }
    for (const int index : nearby_) {
      const auto i = static_cast<std::size_t>(index);
      for (std::size_t k = 0; k < fresh_.size(); ++k) {
        if (overlap(fresh_lo_[k], fresh_hi_[k], faces_[i]) &&
            (degenerate_[i] != 0 ||
             proper_triangles_intersect(fresh_[k], corners_[i]))) {
          return refuse();
        }
      }
    }
    return false;
  }

 private:
  using Cell = std::uint64_t;

  static glm::dvec3 point(const typename MeshT::Point& p) {
    return {p[0], p[1], p[2]};
  }

  IndexedTriangle triangle(typename MeshT::FaceHandle f) {
    MeshT& m = Base::mesh();
    IndexedTriangle t;
    int k = 0;
    for (const auto v : m.fv_range(f)) {
      if (k == 3) break;
      t.ids[k] = static_cast<std::uint32_t>(v.idx());
      t.points[k] = point(m.point(v));
      ++k;
    }
    return t;
  }

  static std::pair<glm::dvec3, glm::dvec3> box(const IndexedTriangle& t) {
    return {glm::min(glm::min(t.points[0], t.points[1]), t.points[2]),
            glm::max(glm::max(t.points[0], t.points[1]), t.points[2])};
  }

  // Visits the cells that the box overlaps and the list of faces too large
  // for cells; a box over more cells than are filled visits every cell.
  template <typename Visit>
  void for_cells(const glm::dvec3& lo, const glm::dvec3& hi, Visit visit) {
    visit(large_);
    if (grid_.count(lo, hi) > double(cells_.size())) {
      cells_.for_each(visit);
      return;
    }
    grid_.for_each(lo, hi, [&](Cell key, const glm::dvec3&) {
      if (auto* cell = cells_.find(key)) visit(*cell);
    });
  }

  void insert(typename MeshT::FaceHandle f) {
    const IndexedTriangle t = triangle(f);
    const auto [lo, hi] = box(t);
    const auto i = static_cast<std::size_t>(f.idx());
    FaceState& face = faces_[i];
    for (int k = 0; k < 3; ++k) {
      face.lo[k] = std::nextafter(static_cast<float>(lo[k]), -HUGE_VALF);
      face.hi[k] = std::nextafter(static_cast<float>(hi[k]), HUGE_VALF);
    }
    corners_[i] = t;
    degenerate_[i] = is_degenerate(t) ? 1 : 0;
    const Entry entry{f.idx(), ++face.version};
    const auto add = [&](Cell key) {
      std::vector<Entry>& cell = cells_.at(key);
      if (cell.empty() || cell.back() != entry) cell.push_back(entry);
    };
    const double cells = grid_.count(lo, hi);
    if (cells <= kBoxCells) {
      grid_.for_each(lo, hi, [&](Cell key, const glm::dvec3&) { add(key); });
      return;
    }
    // A long face (a tube's side along a whole branch, a sliver of the flat
    // underside, a leaf's cut face) goes to the cells it passes through;
    // beyond kHugeCells, to the list every query visits. (Past 512 cells
    // only, as before, blog tree B's decimation took 59.4 s against 55.2 s,
    // the same bytes.)
    if (cells > kHugeCells) {
      large_.push_back(entry);
      return;
    }
    for_each_cell_through(grid_, t.points[0], t.points[1], t.points[2], add);
  }

  bool refuse() {
    ++refused_;
    return true;
  }

  // A face or a fan whose box spans more cells than this is indexed or
  // searched by the cells its triangles pass through, not all its box's.
  static constexpr double kBoxCells = 27.0;
  static constexpr double kHugeCells = double(1 << 16);
  CellGrid grid_;
  // A face in a cell, as it was when inserted: stale once the face's
  // version has moved on.
  struct Entry {
    int face = 0;
    std::uint32_t version = 0;
    bool operator==(const Entry&) const = default;
  };
  // The filled cells by key, in open addressing (a multiplicative hash and
  // linear probing): std::unordered_map's prime modulus and chains were a
  // fifth of the guard's time.
  class Cells {
   public:
    Cells() { clear(); }
    void clear() {
      keys_.assign(std::size_t{1} << kFirstBits, kEmpty);
      lists_.assign(keys_.size(), {});
      bits_ = kFirstBits;
      filled_ = 0;
    }
    [[nodiscard]] std::size_t size() const noexcept { return filled_; }
    // The cell's list, or null if it was never filled.
    [[nodiscard]] std::vector<Entry>* find(Cell key) {
      const std::size_t s = slot(key);
      return keys_[s] == key ? &lists_[s] : nullptr;
    }
    // The cell's list, made if need be.
    std::vector<Entry>& at(Cell key) {
      std::size_t s = slot(key);
      if (keys_[s] == key) return lists_[s];
      if (2 * (filled_ + 1) > keys_.size()) {
        grow();
        s = slot(key);
      }
      keys_[s] = key;
      ++filled_;
      return lists_[s];
    }
    template <typename Visit>
    void for_each(Visit visit) {
      for (std::size_t s = 0; s < keys_.size(); ++s) {
        if (keys_[s] != kEmpty) visit(lists_[s]);
      }
    }

   private:
    // Keys use 63 bits (CellGrid::key), so this is none.
    static constexpr Cell kEmpty = ~Cell{0};
    static constexpr int kFirstBits = 10;
    // Where `key` is or would go.
    [[nodiscard]] std::size_t slot(Cell key) const {
      const std::size_t mask = keys_.size() - 1;
      std::size_t s = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ULL) >>
                                               (64 - bits_));
      while (keys_[s] != key && keys_[s] != kEmpty) s = (s + 1) & mask;
      return s;
    }
    void grow() {
      std::vector<Cell> keys = std::move(keys_);
      std::vector<std::vector<Entry>> lists = std::move(lists_);
      ++bits_;
      keys_.assign(std::size_t{1} << bits_, kEmpty);
      lists_.assign(keys_.size(), {});
      for (std::size_t s = 0; s < keys.size(); ++s) {
        if (keys[s] == kEmpty) continue;
        const std::size_t to = slot(keys[s]);
        keys_[to] = keys[s];
        lists_[to] = std::move(lists[s]);
      }
    }
    std::vector<Cell> keys_;
    std::vector<std::vector<Entry>> lists_;
    int bits_ = kFirstBits;
    std::size_t filled_ = 0;
  };
  Cells cells_;
  std::vector<Entry> large_;
  // What a query reads of each face it meets in a cell, in one place
  // (from five arrays, up to five cache misses a face: the cell walk is
  // most of the guard's own time, and the guard a third of blog tree B's
  // decimation). The box is kept in floats rounded outwards, so that it
  // holds the true one: a box test then passes every face the exact tests
  // need, and a few more, which they reject. The bush at n = 7 on one
  // thread, decimation 9.25-9.45 s against 9.64-9.67 s, the same bytes.
  struct alignas(32) FaceState {
    glm::vec3 lo{0.0F};  // its box when inserted
    glm::vec3 hi{0.0F};
    std::uint32_t version = 0;  // inserts so far
    std::uint32_t seen = 0;     // last query
  };
  // Whether box lo-hi meets the face's box.
  static bool overlap(const glm::dvec3& lo, const glm::dvec3& hi,
                      const FaceState& face) {
    return lo.x <= face.hi.x && face.lo.x <= hi.x && lo.y <= face.hi.y &&
           face.lo.y <= hi.y && lo.z <= face.hi.z && face.lo.z <= hi.z;
  }
  std::vector<FaceState> faces_;
  std::vector<std::uint32_t> changing_;  // per face: last collapse tested
  // Per face: its corners when inserted, which stay while its version does
  // (a face's corners change only in a collapse at one of them, and
  // postprocess_collapse inserts it again). Read from the mesh, the
  // corners of the faces near each collapse were three dependent cache
  // misses a face, half of the guard's time on the bush at n = 7.
  std::vector<IndexedTriangle> corners_;
  // Per face: whether those corners are collinear, decided once (the fresh
  // triangles are tested on their own first, and the pair tests then need
  // neither again).
  std::vector<char> degenerate_;
  std::size_t live_faces_ = 0;     // faces not deleted
  std::size_t indexed_faces_ = 0;  // and as many at the last initialize()
  std::uint32_t query_stamp_ = 0;
  std::uint32_t collapse_stamp_ = 0;
  std::vector<IndexedTriangle> fresh_;
  std::vector<glm::dvec3> fresh_lo_;  // their boxes
  std::vector<glm::dvec3> fresh_hi_;
  std::vector<int> nearby_;  // faces whose boxes meet the fan's
  std::size_t refused_ = 0;
};

}  // namespace lsolid
