// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The decimation guard's pair test. The cases follow CGAL's own
// self-intersection test (Polygon_mesh_processing/self_intersections.h,
// Strict_intersect_faces): triangles sharing an edge meet beyond it only
// when they are coplanar and fold onto each other; triangles sharing one
// vertex meet beyond it exactly when the edge opposite that vertex in one
// crosses the other. Coordinates are doubles and every predicate of EPICK is
// exact, so the answer is the one `lsolid check` gives.
#include "kernel.hpp"

#include "triangle_pair.hpp"

#include <CGAL/intersections.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "box_pairs.hpp"

namespace lsolid {
namespace {

using Point = Inexact::Point_3;
using Segment = Inexact::Segment_3;
using Triangle = Inexact::Triangle_3;

Point point(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

// The triangle's corners reordered so that the first `count` are those it
// shares with `other`.
std::array<Point, 3> shared_first(const IndexedTriangle& t,
                                  const IndexedTriangle& other, int& count) {
  std::array<int, 3> order{0, 1, 2};
  count = 0;
  std::array<bool, 3> used{};
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      if (!used[i] && t.ids[i] == other.ids[j]) {
        order[count++] = i;
        used[i] = true;
        break;
      }
    }
  }
  for (int i = 0, k = count; i < 3; ++i) {
    if (!used[i]) order[k++] = i;
  }
  return {point(t.points[order[0]]), point(t.points[order[1]]),
          point(t.points[order[2]])};
}

// The projection of triangle p's space along the axis p faces most (its
// normal's largest coordinate), which keeps p a triangle unless it has
// almost no area.
struct FacingProjection {
  int axis = 2;

  explicit FacingProjection(const std::array<Point, 3>& p) {
    const auto n = CGAL::cross_product(p[1] - p[0], p[2] - p[0]);
    const double ax = std::abs(n.x());
    const double ay = std::abs(n.y());
    const double az = std::abs(n.z());
    axis = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
  }

  [[nodiscard]] Inexact::Point_2 operator()(const Point& x) const {
    return {x[(axis + 1) % 3], x[(axis + 2) % 3]};
  }
};

// Whether triangles p and q, sharing their first corner and no other, meet
// only there as seen along the axis p faces most: a line through the corner
// along one of the four sides from it leaves the one triangle's other
// corner strictly on one side and both of the other's strictly on the
// other. Exact (EPICK's 2D orientation on the coordinates as they are); a
// projection of p without area answers false, and the 3D tests decide.
bool apart_round_corner(const std::array<Point, 3>& p,
                        const std::array<Point, 3>& q) {
  const FacingProjection project(p);
  const Inexact::Point_2 o = project(p[0]);
  const std::array<Inexact::Point_2, 2> a{project(p[1]), project(p[2])};
  const std::array<Inexact::Point_2, 2> b{project(q[1]), project(q[2])};
  const CGAL::Orientation own = CGAL::orientation(o, a[0], a[1]);
  if (own == CGAL::COLLINEAR) return false;
  const auto parts = [&](const Inexact::Point_2& along,
                         const Inexact::Point_2& mine,
                         const std::array<Inexact::Point_2, 2>& theirs) {
    const CGAL::Orientation s = CGAL::orientation(o, along, mine);
    return s != CGAL::COLLINEAR &&
           CGAL::orientation(o, along, theirs[0]) == -s &&
           CGAL::orientation(o, along, theirs[1]) == -s;
  };
  return parts(a[0], a[1], b) || parts(a[1], a[0], b) || parts(b[0], b[1], a) ||
         parts(b[1], b[0], a);
}

// Whether every corner of `other` that `t` does not share lies strictly on
// one side of the plane of `t`, as far as double arithmetic shows it: each
// corner's orientation determinant is taken against Shewchuk's error bound
// for orient3d ("Adaptive precision floating-point arithmetic and fast
// robust geometric predicates", 1997: (7 + 56 eps) eps times the
// permanent; 1e-15 here, for some margin), the plane's minors formed once.
// Then `other` meets the plane of `t` only at the corners they share, so
// the two meet nowhere else. False when the bound cannot show it; the exact
// tests decide. Most pairs whose boxes meet are shown apart like this, and
// reordering both triangles' corners and CGAL's orientations for each pair
// were a fifth of the decimation guard's time on blog tree B.
bool beside_but_shared(const IndexedTriangle& t, const IndexedTriangle& other) {
  constexpr double kBound = 1e-15;
  const glm::dvec3& o = t.points[0];
  const glm::dvec3 a = t.points[1] - o;
  const glm::dvec3 b = t.points[2] - o;
  const glm::dvec3 minor(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
                         a.x * b.y - a.y * b.x);
  const glm::dvec3 size(std::abs(a.y * b.z) + std::abs(a.z * b.y),
                        std::abs(a.z * b.x) + std::abs(a.x * b.z),
                        std::abs(a.x * b.y) + std::abs(a.y * b.x));
  int side = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    const std::uint32_t id = other.ids[k];
    if (id == t.ids[0] || id == t.ids[1] || id == t.ids[2]) continue;
    const glm::dvec3 c = other.points[k] - o;
    const double det = minor.x * c.x + minor.y * c.y + minor.z * c.z;
    const double bound =
        kBound * (size.x * std::abs(c.x) + size.y * std::abs(c.y) +
                  size.z * std::abs(c.z));
    const int s = det > bound ? 1 : (det < -bound ? -1 : 0);
    if (s == 0 || (side != 0 && s != side)) return false;
    side = s;
  }
  return side != 0;
}

}  // namespace

bool proper_triangles_intersect(const IndexedTriangle& a,
                                const IndexedTriangle& b) {
  if (beside_but_shared(a, b) || beside_but_shared(b, a)) return false;
  int count = 0;
  const std::array<Point, 3> p = shared_first(a, b, count);
  int count_b = 0;
  const std::array<Point, 3> q = shared_first(b, a, count_b);
  // Most pairs whose boxes meet lie strictly on one side of the other's
  // plane, which four to six orientations (EPICK's static filter) show;
  // CGAL's do_intersect checks both triangles for degeneracy first, exactly,
  // and that was a tenth of the blog's tree B build in the decimation's
  // guard.
  const auto beside = [](const std::array<Point, 3>& plane, const Point& u,
                         const Point& v) {
    const CGAL::Orientation sa =
        CGAL::orientation(plane[0], plane[1], plane[2], u);
    return sa != CGAL::COPLANAR &&
           sa == CGAL::orientation(plane[0], plane[1], plane[2], v);
  };
  switch (count) {
    case 0:
      if ((beside(p, q[0], q[1]) && beside(p, q[1], q[2])) ||
          (beside(q, p[0], p[1]) && beside(q, p[1], p[2]))) {
        return false;
      }
      return CGAL::do_intersect(Triangle(p[0], p[1], p[2]),
                                Triangle(q[0], q[1], q[2]));
    case 1:
      // Triangles round one vertex of a flat region are nearly coplanar,
      // where the plane tests below need exact arithmetic. Seen along the
      // axis that p faces most, p's projection is a triangle (p[2] off the
      // line p[0] p[1]) and the projection is one to one on p: if a line
      // through the shared corner parts the two projections, they meet only
      // there, and so do the triangles.
      if (apart_round_corner(p, q)) return false;
      // Beyond the shared corner, one triangle's opposite side must meet
      // the other triangle, so cross its plane.
      return (!beside(q, p[1], p[2]) &&
              CGAL::do_intersect(Segment(p[1], p[2]),
                                 Triangle(q[0], q[1], q[2]))) ||
             (!beside(p, q[1], q[2]) &&
              CGAL::do_intersect(Segment(q[1], q[2]),
                                 Triangle(p[0], p[1], p[2])));
    case 2: {
      // p[0], p[1] are the shared edge's ends; p[2] and q[2] the corners
      // opposite. Only a fold onto each other overlaps. Neighbours in one
      // flat region are nearly coplanar, where the coplanarity test needs
      // exact arithmetic: first, if the corners lie strictly on opposite
      // sides of the edge seen along the axis the triangle faces most, the
      // two cannot fold onto each other (coplanar or not).
      const FacingProjection project(p);
      const auto side = [&](const Point& c) {
        return CGAL::orientation(project(p[0]), project(p[1]), project(c));
      };
      const CGAL::Orientation sp = side(p[2]);
      const CGAL::Orientation sq = side(q[2]);
      if (sp != CGAL::COLLINEAR && sq != CGAL::COLLINEAR && sp != sq) {
        return false;
      }
      return CGAL::coplanar(p[0], p[1], p[2], q[2]) &&
             CGAL::coplanar_orientation(p[0], p[1], p[2], q[2]) ==
                 CGAL::POSITIVE;
    }
    default:
      return true;
  }
}

bool is_degenerate(const IndexedTriangle& t) {
  return CGAL::collinear(point(t.points[0]), point(t.points[1]),
                         point(t.points[2]));
}

bool triangles_intersect(const IndexedTriangle& a, const IndexedTriangle& b) {
  return is_degenerate(a) || is_degenerate(b) ||
         proper_triangles_intersect(a, b);
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> intersecting_pairs(
    const std::vector<IndexedTriangle>& triangles) {
  return intersecting_pairs(triangles, std::vector<char>(triangles.size(), 0));
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> intersecting_pairs(
    const std::vector<IndexedTriangle>& triangles,
    const std::vector<char>& settled) {
  using Pair = std::pair<std::uint32_t, std::uint32_t>;
  std::vector<Pair> out;
  // As CGAL's test does: a degenerate triangle is reported alone and left
  // out of the search.
  std::vector<char> degenerate(triangles.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, triangles.size(), 4096),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i < range.end();
                           ++i) {
                        degenerate[i] = is_degenerate(triangles[i]) ? 1 : 0;
                      }
                    });
  // The boxes of the triangles to search from, and of the settled ones.
  std::array<std::vector<Box>, 2> boxes;
  std::array<std::vector<std::uint32_t>, 2> id;  // per box: its triangle
  for (std::uint32_t i = 0; i < triangles.size(); ++i) {
    if (degenerate[i] != 0) {
      out.emplace_back(i, i);
      continue;
    }
    Box b;
    for (const glm::dvec3& p : triangles[i].points) b.add(p);
    const std::size_t set = settled[i] != 0 ? 1 : 0;
    boxes[set].push_back(b);
    id[set].push_back(i);
  }
  // The pairs whose boxes meet, tested on the threads, neither triangle
  // degenerate (decided once above): CGAL's own test walks the halfedges
  // round both faces and checks each triangle for degeneracy, exactly, for
  // every pair (a third of blog tree B's rounding and check at n = 9).
  const auto meets = [&](std::uint32_t f, std::uint32_t g) {
    return proper_triangles_intersect(triangles[f], triangles[g]);
  };
  std::vector<Pair> found;
  for (const auto& [a, b] :
       meeting_box_pairs(boxes[0], [&](std::uint32_t a, std::uint32_t b) {
         return meets(id[0][a], id[0][b]);
       })) {
    found.emplace_back(id[0][a], id[0][b]);
  }
  for (const auto& [a, b] : meeting_box_pairs(
           boxes[0], boxes[1], [&](std::uint32_t a, std::uint32_t b) {
             return meets(id[0][a], id[1][b]);
           })) {
    found.emplace_back(std::min(id[0][a], id[1][b]),
                       std::max(id[0][a], id[1][b]));
  }
  std::sort(found.begin(), found.end());
  out.insert(out.end(), found.begin(), found.end());
  return out;
}

}  // namespace lsolid
