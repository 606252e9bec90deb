// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// cpfg's surfaces (VLAB Tools Manual §5.4 for the file; cpfg's patches.c
// for how they are placed and meshed): a header that ties the surface to
// the turtle, then patches of 4 × 4 control points, each a bicubic Bézier
// patch S(u, v) = Σ Bᵢ(u) Bⱼ(v) Pᵢⱼ (i the row in the file, j the place
// in the row), evaluated on an s × t grid and cut into two triangles per
// cell, as cpfg draws them.
#include "dialects/cpfg_surface.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <map>
#include <string>
#include <string_view>

#include "dialects/word_scanner.hpp"
#include "lsys/diagnostic.hpp"

namespace lsys::dialects {
namespace {

constexpr int kMostPatches = 1000;
constexpr double kFarthest = 1e6;

class SurfaceReader : WordScanner {
 public:
  SurfaceReader(const SourceFile& file, const SurfaceOptions& options)
      : WordScanner(file), options_(options) {}

  Surface run() {
    for (int i = 0; i < 6; ++i) (void)number();  // the bounding box
    int precision_s = 0;
    int precision_t = 0;
    if (word_is("PRECISION")) {
      word();
      expect("S:");
      precision_s = static_cast<int>(number());
      expect("T:");
      precision_t = static_cast<int>(number());
    }
    expect("CONTACT");
    expect("POINT");
    const glm::dvec3 contact = point();
    expect("END");
    expect("POINT");
    const glm::dvec3 end = point();
    expect("HEADING");
    const glm::dvec3 heading = point();
    expect("UP");
    const glm::dvec3 up = point();
    expect("SIZE:");
    const double size = number();
    if (!(size > 0.0)) fail("SIZE must be positive");
    // The file's heading and up become the turtle's; cpfg makes them
    // orthonormal first.
    const double hl = glm::length(heading);
    const double ul = glm::length(up);
    if (!(hl > 0.0) || !(ul > 0.0)) fail("HEADING and UP must not be 0");
    const glm::dvec3 h = heading / hl;
    glm::dvec3 l = glm::cross(h, up / ul);
    if (!(glm::length(l) > 1e-12)) fail("HEADING and UP must not be parallel");
    l = glm::normalize(l);
    const glm::dvec3 u = glm::cross(l, h);
    const double k = options_.size / size;
    const auto local = [&](const glm::dvec3& p) {
      const glm::dvec3 q = (p - contact) * k;
      return glm::dvec3(glm::dot(q, l), glm::dot(q, h), glm::dot(q, u));
    };
    const auto divisions = [](int view, int file) {
      return std::clamp(view > 0 ? view : (file > 0 ? file : 5), 1, 10);
    };
    // cpfg takes t from the file's S precision too when the view gives
    // none (patches.c), so the file's T is read and left.
    const int s = divisions(options_.s_divisions, precision_s);
    const int t = divisions(options_.t_divisions, precision_s);
    (void)precision_t;
    Surface out;
    out.end_point = local(end);
    int patches = 0;
    while (skip_blanks(), pos_ < text_.size()) {
      if (++patches > kMostPatches) fail("too many patches");
      patch(out, local, s, t);
    }
    if (patches == 0) fail("expected a patch");
    if (out.triangles.empty()) fail("the surface's patches have no area");
    return out;
  }

 private:
  void expect(std::string_view w) {
    skip_blanks();
    if (!text_.substr(pos_).starts_with(w)) {
      fail("expected '" + std::string(w) + "'");
    }
    pos_ += w.size();
  }

  glm::dvec3 point() {
    expect("X:");
    const double x = number();
    expect("Y:");
    const double y = number();
    expect("Z:");
    const double z = number();
    return {x, y, z};
  }

  template <typename Local>
  void patch(Surface& out, const Local& local, int s, int t) {
    (void)word();  // the patch's name
    expect("TOP");
    expect("COLOR:");
    (void)number();
    expect("DIFFUSE:");
    (void)number();
    expect("BOTTOM");
    expect("COLOR:");
    (void)number();
    expect("DIFFUSE:");
    (void)number();
    // Neighbours, for cpfg's shading only.
    for (std::string_view label :
         {"AL:", "A:", "AR:", "L:", "R:", "BL:", "B:", "BR:"}) {
      expect(label);
      (void)word();
    }
    std::array<std::array<glm::dvec3, 4>, 4> p{};
    for (auto& row : p) {
      for (glm::dvec3& c : row) {
        const double x = number();
        const double y = number();
        const double z = number();
        c = local(glm::dvec3(x, y, z));
        // Far beyond any leaf; it keeps the welding grid in range.
        if (!(glm::length(c) < kFarthest)) {
          fail("a control point lies too far from the contact point");
        }
      }
    }
    const auto bernstein = [](double x) {
      const double y = 1.0 - x;
      return std::array<double, 4>{y * y * y, 3.0 * x * y * y, 3.0 * x * x * y,
                                   x * x * x};
    };
    std::vector<glm::dvec3> grid;
    for (int a = 0; a <= s; ++a) {
      const auto bu = bernstein(static_cast<double>(a) / s);
      for (int b = 0; b <= t; ++b) {
        const auto bv = bernstein(static_cast<double>(b) / t);
        glm::dvec3 q(0.0);
        for (std::size_t i = 0; i < 4; ++i) {
          for (std::size_t j = 0; j < 4; ++j) q += bu[i] * bv[j] * p[i][j];
        }
        grid.push_back(q);
      }
    }
    std::vector<std::uint32_t> index(grid.size());
    for (std::size_t k = 0; k < grid.size(); ++k) index[k] = weld(out, grid[k]);
    const auto at = [&](int a, int b) {
      return index[static_cast<std::size_t>(a * (t + 1) + b)];
    };
    const auto add = [&](std::uint32_t i, std::uint32_t j, std::uint32_t k) {
      if (i != j && j != k && k != i) out.triangles.push_back({i, j, k});
    };
    for (int a = 0; a < s; ++a) {
      for (int b = 0; b < t; ++b) {
        add(at(a, b), at(a + 1, b), at(a, b + 1));
        add(at(a + 1, b), at(a + 1, b + 1), at(a, b + 1));
      }
    }
  }

  // The index of `p` among the surface's points, added if no point lies
  // within kWeld of it. A row of equal control points (a leaf's tip) and
  // the edge two patches share evaluate to points some ulps apart; as one
  // point they make the surface one connected sheet, which lsys-solid
  // thickens without seams.
  std::uint32_t weld(Surface& out, const glm::dvec3& p) {
    const glm::dvec3 cell = glm::floor(p / kWeld);
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const auto found = cells_.find(key(cell + glm::dvec3(dx, dy, dz)));
          if (found == cells_.end()) continue;
          for (const std::uint32_t i : found->second) {
            if (glm::length(out.points[i] - p) <= kWeld) return i;
          }
        }
      }
    }
    const auto i = static_cast<std::uint32_t>(out.points.size());
    out.points.push_back(p);
    cells_[key(cell)].push_back(i);
    return i;
  }

  static std::array<std::int64_t, 3> key(const glm::dvec3& cell) {
    return {static_cast<std::int64_t>(cell.x),
            static_cast<std::int64_t>(cell.y),
            static_cast<std::int64_t>(cell.z)};
  }

  // Points closer than this (in the turtle's units for the file's SIZE)
  // are one: far below what a print resolves, far above rounding.
  static constexpr double kWeld = 1e-9;

  std::map<std::array<std::int64_t, 3>, std::vector<std::uint32_t>> cells_;
  const SurfaceOptions& options_;
};

}  // namespace

Surface read_cpfg_surface(const SourceFile& file,
                          const SurfaceOptions& options) {
  return SurfaceReader(file, options).run();
}

}  // namespace lsys::dialects
