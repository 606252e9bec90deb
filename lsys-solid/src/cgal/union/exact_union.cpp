// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The union of two closed meshes after Manifold's structure (J. M. Smith,
// "Robust geometric methods for surface modelling and manufacturing",
// Cambridge TR-766, 2009): every crossing of an edge of one operand with a
// face of the other is decided once, on input coordinates, and everything
// else is derived from those decisions. Unlike Manifold the decisions are
// exact (CGAL's filtered predicates on doubles), and unlike CGAL's
// corefinement no intersection point is ever constructed as a rational: it
// stays an implicit point (Attene 2020) whose predicates run in intervals,
// then in Mpzf. Points on one edge are ordered by their parameter and
// inserted into the cut face's triangulation where they are known to lie,
// so that no orientation test whose answer is known (collinear: exactly
// zero, which no filter can certify) is asked (docs/design.md, "The exact
// union engine").
#include "cgal/union/exact_union.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/intersections.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <memory>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "box_pairs.hpp"
#include "cgal/conversion.hpp"
#include "cgal/kernel.hpp"
#include "cgal/triangle_pair.hpp"
#include "cgal/union/implicit_point.hpp"
#include "cgal/union/ray_parity.hpp"
#include "shells.hpp"
#include "union_find.hpp"

namespace lsolid::exact_union {
namespace {

using K = Inexact;  // kernel.hpp
using Point3 = K::Point_3;
using Interval = CGAL::Interval_nt<false>;
using Sign = CGAL::Sign;

Point3 point3(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

// A degeneracy or a broken invariant: the union gives up, and the caller
// shifts an operand or falls back to the corefinement.
struct Failure {
  std::string what;
  bool degenerate = false;
  // Where the faces cross each other's planes (each has corners strictly
  // on both sides of the other's): a shift takes the coincidence away and
  // leaves any crossing of the faces, unlike one of faces that touch.
  bool transversal = false;
  // Among faces that touch, coplanar faces that face each other and
  // overlap in more than an edge or a point, or a face on the inner side of
  // the other's plane.
  bool face_on_face = false;
  // Among faces that touch, the pairs of coplanar faces that face the same
  // way, over the failures kept in one (keep_first).
  std::size_t alike_pairs = 0;
};

// Keeps the first failure of a kind in `first` and adds what any later one
// tells of the faces that touch.
void keep_first(std::optional<Failure>& first, const Failure& f) {
  if (!first) {
    first = f;
    return;
  }
  first->face_on_face = first->face_on_face || f.face_on_face;
  first->alike_pairs += f.alike_pairs;
}

// Orientations of points of one plane, in the projection along the largest
// coordinate of its normal `n`, which keeps every orientation there.
struct PlaneOrientation {
  explicit PlaneOrientation(const glm::dvec3& n) {
    const glm::dvec3 an = glm::abs(n);
    const int axis = an.x >= an.y && an.x >= an.z ? 0 : (an.y >= an.z ? 1 : 2);
    u = (axis + 1) % 3;
    v = (axis + 2) % 3;
  }
  CGAL::Orientation operator()(const glm::dvec3& p, const glm::dvec3& q,
                               const glm::dvec3& r) const {
    return CGAL::orientation(K::Point_2(p[u], p[v]), K::Point_2(q[u], q[v]),
                             K::Point_2(r[u], r[v]));
  }
  // Whether p lies inside the triangle t, not on its boundary.
  bool strictly_inside(const glm::dvec3& p,
                       const std::array<glm::dvec3, 3>& t) const {
    const CGAL::Orientation o = (*this)(t[0], t[1], t[2]);
    if (o == CGAL::COLLINEAR) return false;
    for (int i = 0; i < 3; ++i)
      if ((*this)(t[i], t[(i + 1) % 3], p) != o) return false;
    return true;
  }
  int u = 0;
  int v = 1;
};

// Whether two coplanar triangles overlap in more than an edge or a point:
// no edge of either leaves the other on its outer side or on its line
// (separating axes).
bool overlap_in_area(const std::array<std::array<glm::dvec3, 3>, 2>& corner,
                     const PlaneOrientation& orient) {
  for (int m = 0; m < 2; ++m) {
    const auto& t = corner[m];
    const CGAL::Orientation o = orient(t[0], t[1], t[2]);
    if (o == CGAL::COLLINEAR) return false;
    for (int i = 0; i < 3; ++i) {
      bool separates = true;
      for (const glm::dvec3& p : corner[1 - m]) {
        if (orient(t[i], t[(i + 1) % 3], p) == o) separates = false;
      }
      if (separates) return false;
    }
  }
  return true;
}

// Runs body(begin, end, chunk) over [0, n) in chunks of fixed size on
// oneTBB's threads, and rethrows the failure of the first chunk that failed:
// each chunk writes only its own results, and which failure is reported does
// not depend on how many threads ran, or in which order.
template <typename Body>
void for_each_chunk(std::size_t n, const Body& body) {
  constexpr std::size_t kChunk = 256;
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  std::vector<std::optional<Failure>> failed(chunks);
  tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
    try {
      body(c * kChunk, std::min(n, (c + 1) * kChunk), c);
    } catch (const Failure& f) {
      failed[c] = f;
    }
  });
  for (const std::optional<Failure>& f : failed)
    if (f) throw *f;
}

// An edge of one operand crossing a face of the other, in its canonical
// form: the edge's ends in increasing order.
struct Crossing {
  std::uint32_t mesh = 0;  // the edge's operand, 0 or 1
  std::uint32_t e0 = 0;
  std::uint32_t e1 = 0;
  std::uint32_t face = 0;  // in the other operand
  bool p_below = false;    // e0 lies on the face's negative side

  auto key() const { return std::tuple(mesh, e0, e1, face); }
  bool operator<(const Crossing& o) const { return key() < o.key(); }
  bool operator==(const Crossing& o) const { return key() == o.key(); }
};

// Where the faces a (of operand 0) and b (of operand 1) cross: from the
// crossing `from` to `to` along na × nb, which leaves the inside of operand
// 1 on its left in face a, and the outside of operand 0 on its left in b.
struct Segment {
  std::uint32_t face_a = 0;
  std::uint32_t face_b = 0;
  Crossing from;
  Crossing to;
};

struct Operand {
  const TriangleMesh* mesh;
  std::uint32_t offset;  // of its vertices among all points
};

Sign orient(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
            const glm::dvec3& d) {
  return CGAL::orientation(point3(a), point3(b), point3(c), point3(d));
}

// The segment of faces fa and fb, if they cross; nothing if they do not.
// @throws Failure on a degeneracy.
std::optional<Segment> cross_faces(const std::array<Operand, 2>& ops,
                                   std::uint32_t fa, std::uint32_t fb) {
  const std::array<std::uint32_t, 2> face{fa, fb};
  std::array<std::array<glm::dvec3, 3>, 2> corner;
  std::array<std::array<std::uint32_t, 3>, 2> index;
  for (int m = 0; m < 2; ++m) {
    index[m] = ops[m].mesh->triangles[face[m]];
    for (int i = 0; i < 3; ++i)
      corner[m][i] = ops[m].mesh->vertices[index[m][i]];
  }
  // side[m][i]: corner i of face m against the plane of the other face.
  std::array<std::array<Sign, 3>, 2> side;
  std::array<bool, 2> straddles{};
  bool zero = false;
  for (int m = 0; m < 2; ++m) {
    const auto& plane = corner[1 - m];
    bool pos = false;
    bool neg = false;
    for (int i = 0; i < 3; ++i) {
      side[m][i] = orient(plane[0], plane[1], plane[2], corner[m][i]);
      pos = pos || side[m][i] == CGAL::POSITIVE;
      neg = neg || side[m][i] == CGAL::NEGATIVE;
      zero = zero || side[m][i] == CGAL::ZERO;
    }
    if (!zero && (!pos || !neg)) return std::nullopt;
    straddles[m] = pos && neg;
  }
  if (zero) {
    // A corner on the other's plane is a degeneracy only where the faces
    // meet: faces that straddle each other's planes, one with a corner on
    // the other's, may still pass each other (a prism's cap whose centre
    // lies in the plane of a box's side beside the box, a finding of the
    // union fuzz target), and a shift for them would join solids that lie
    // apart.
    const K::Triangle_3 ta(point3(corner[0][0]), point3(corner[0][1]),
                           point3(corner[0][2]));
    const K::Triangle_3 tb(point3(corner[1][0]), point3(corner[1][1]),
                           point3(corner[1][2]));
    if (!CGAL::do_intersect(ta, tb)) return std::nullopt;
    if (!straddles[0] || !straddles[1]) {
      const auto flat = [&](int m) {
        return side[m][0] == CGAL::ZERO && side[m][1] == CGAL::ZERO &&
               side[m][2] == CGAL::ZERO;
      };
      const bool coplanar = flat(0) && flat(1);
      const glm::dvec3 na =
          glm::cross(corner[0][1] - corner[0][0], corner[0][2] - corner[0][0]);
      const glm::dvec3 nb =
          glm::cross(corner[1][1] - corner[1][0], corner[1][2] - corner[1][0]);
      // Facing the same way: the two triangles turn the same way in one
      // projection of their plane (exact; the normals' directions in
      // doubles decide only for a triangle that projects to a line).
      const bool alike = coplanar && [&] {
        const PlaneOrientation orient(na);
        const CGAL::Orientation oa =
            orient(corner[0][0], corner[0][1], corner[0][2]);
        const CGAL::Orientation ob =
            orient(corner[1][0], corner[1][1], corner[1][2]);
        if (oa == CGAL::COLLINEAR || ob == CGAL::COLLINEAR)
          return glm::dot(na, nb) > 0.0;
        return oa == ob;
      }();
      Failure touch{
          alike ? "coplanar faces that face the same way touch" : "faces touch",
          true, false};
      touch.alike_pairs = alike ? 1 : 0;
      // Or one face lies on the inner side of the other's plane with a
      // corner inside the other face: the solids overlap there already (a
      // face that an earlier growth tilted into the other solid). On the
      // inner side of a plane alone is not inside the solid: a tube's side
      // meets the plane of a box's side there, end to end with the box's
      // edge, at the box's corner only.
      const auto dips = [&](int m) {
        bool neg = false;
        for (const Sign s : side[m]) {
          if (s == CGAL::POSITIVE) return false;
          neg = neg || s == CGAL::NEGATIVE;
        }
        if (!neg) return false;
        const PlaneOrientation orient(m == 0 ? nb : na);
        for (int i = 0; i < 3; ++i) {
          if (side[m][i] == CGAL::ZERO &&
              orient.strictly_inside(corner[m][i], corner[1 - m])) {
            return true;
          }
        }
        return false;
      };
      touch.face_on_face = (coplanar && !alike &&
                            overlap_in_area(corner, PlaneOrientation(na))) ||
                           dips(0) || dips(1);
      throw touch;
    }
    throw Failure{"a vertex lies on a face's plane", true, true};
  }
  std::array<Crossing, 2> ends;
  std::array<bool, 2> is_forward{};
  int found = 0;
  for (int m = 0; m < 2; ++m) {
    const auto& plane = corner[1 - m];
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      if (side[m][i] == side[m][j]) continue;
      const glm::dvec3& u = corner[m][i];
      const glm::dvec3& v = corner[m][j];
      const Sign s0 = orient(u, v, plane[0], plane[1]);
      const Sign s1 = orient(u, v, plane[1], plane[2]);
      const Sign s2 = orient(u, v, plane[2], plane[0]);
      const bool any_pos =
          s0 == CGAL::POSITIVE || s1 == CGAL::POSITIVE || s2 == CGAL::POSITIVE;
      const bool any_neg =
          s0 == CGAL::NEGATIVE || s1 == CGAL::NEGATIVE || s2 == CGAL::NEGATIVE;
      if (any_pos && any_neg) continue;
      if (s0 == CGAL::ZERO || s1 == CGAL::ZERO || s2 == CGAL::ZERO)
        throw Failure{"an edge passes through an edge", true, true};
      if (found == 2) throw Failure{"faces cross in more than two points"};
      Crossing& c = ends[found];
      c.mesh = static_cast<std::uint32_t>(m);
      const bool ascending = index[m][i] < index[m][j];
      c.e0 = ascending ? index[m][i] : index[m][j];
      c.e1 = ascending ? index[m][j] : index[m][i];
      c.face = face[1 - m];
      c.p_below = (ascending ? side[m][i] : side[m][j]) == CGAL::NEGATIVE;
      // Walking the face's boundary counter-clockwise, the crossing at the
      // segment's forward end goes from above to below the other face in
      // face a, and from below to above in face b.
      is_forward[found] =
          m == 0 ? side[m][i] == CGAL::POSITIVE : side[m][i] == CGAL::NEGATIVE;
      ++found;
    }
  }
  if (found == 0) return std::nullopt;
  if (found != 2 || is_forward[0] == is_forward[1])
    throw Failure{"faces cross in one point"};
  Segment s{fa, fb, ends[0], ends[1]};
  if (is_forward[0]) std::swap(s.from, s.to);
  return s;
}

// The triangulation of a cut face, in the projection along its normal's
// largest coordinate, with the face's points as indices into a table.
struct FacePoint {
  const ImplicitPoint* def = nullptr;
  std::uint32_t id = 0;
  Homogeneous<Interval> approx;
  // The projected coordinates as intervals (x / w): a first filter of low
  // degree, tight where the point is well defined; the homogeneous form,
  // then Mpzf, decide what it cannot.
  std::array<Interval, 2> xy;
  // The exact homogeneous coordinates, once a predicate the intervals
  // could not decide needed them: a point near a degeneracy (a crossing on
  // the shared edge of two nearly coplanar faces) is mostly asked about
  // again, by orientations and incircle tests alike.
  mutable std::unique_ptr<Homogeneous<CGAL::Mpzf>> exact;
};

FacePoint face_point(const ImplicitPoint& def, std::uint32_t id,
                     const glm::dvec3& origin, int ax, int ay) {
  FacePoint p{&def, id, homogeneous<Interval>(def, origin), {}};
  if (def.is_vertex) {
    p.xy = {p.approx.xyz[ax], p.approx.xyz[ay]};
  } else if (CGAL::certainly(p.approx.w > 0)) {
    p.xy = {p.approx.xyz[ax] / p.approx.w, p.approx.xyz[ay] / p.approx.w};
  } else {
    p.xy = {Interval::largest(), Interval::largest()};
  }
  return p;
}

struct Projection {
  glm::dvec3 origin{};
  int ax = 0;
  int ay = 1;
  mutable std::uint64_t orient_calls = 0;
  mutable std::uint64_t orient_exact = 0;
};

template <typename NT>
NT det3(const Homogeneous<NT>& a, const Homogeneous<NT>& b,
        const Homogeneous<NT>& c, int ax, int ay) {
  const NT& xa = a.xyz[ax];
  const NT& ya = a.xyz[ay];
  const NT& xb = b.xyz[ax];
  const NT& yb = b.xyz[ay];
  const NT& xc = c.xyz[ax];
  const NT& yc = c.xyz[ay];
  return xa * (yb * c.w - b.w * yc) - ya * (xb * c.w - b.w * xc) +
         a.w * (xb * yc - yb * xc);
}

// The incircle determinant of four points in homogeneous coordinates, each
// row (x w, y w, x² + y², w²): Shewchuk's incircle with each row scaled by
// w² > 0, positive if d lies inside the circle through a, b, c (in
// counter-clockwise order).
template <typename NT>
NT incircle(const std::array<const Homogeneous<NT>*, 4>& p, int ax, int ay) {
  std::array<std::array<NT, 4>, 4> m;
  for (int i = 0; i < 4; ++i) {
    const NT& x = p[i]->xyz[ax];
    const NT& y = p[i]->xyz[ay];
    const NT& w = p[i]->w;
    m[i] = {x * w, y * w, x * x + y * y, w * w};
  }
  // Laplace expansion by the 2×2 minors of the first two rows.
  const auto minor = [&](int r0, int r1, int c0, int c1) {
    return m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0];
  };
  return minor(0, 1, 0, 1) * minor(2, 3, 2, 3) -
         minor(0, 1, 0, 2) * minor(2, 3, 1, 3) +
         minor(0, 1, 0, 3) * minor(2, 3, 1, 2) +
         minor(0, 1, 1, 2) * minor(2, 3, 0, 3) -
         minor(0, 1, 1, 3) * minor(2, 3, 0, 2) +
         minor(0, 1, 2, 3) * minor(2, 3, 0, 1);
}

// Shewchuk's incircle on Cartesian coordinates (intervals).
Interval incircle_cartesian(const std::array<Interval, 2>& a,
                            const std::array<Interval, 2>& b,
                            const std::array<Interval, 2>& c,
                            const std::array<Interval, 2>& d) {
  const Interval adx = a[0] - d[0];
  const Interval ady = a[1] - d[1];
  const Interval bdx = b[0] - d[0];
  const Interval bdy = b[1] - d[1];
  const Interval cdx = c[0] - d[0];
  const Interval cdy = c[1] - d[1];
  const Interval al = adx * adx + ady * ady;
  const Interval bl = bdx * bdx + bdy * bdy;
  const Interval cl = cdx * cdx + cdy * cdy;
  return adx * (bdy * cl - bl * cdy) - ady * (bdx * cl - bl * cdx) +
         al * (bdx * cdy - bdy * cdx);
}

template <typename NT>
NT cross_coordinate(const Homogeneous<NT>& a, const Homogeneous<NT>& b,
                    int axis) {
  return a.xyz[axis] * b.w - b.xyz[axis] * a.w;
}

Sign sign_of(const CGAL::Mpzf& x) { return CGAL::sign(x); }

struct Traits {
  struct Point_2 {
    const FacePoint* p = nullptr;
  };
  // A point's exact homogeneous coordinates, for what the intervals left.
  static const Homogeneous<CGAL::Mpzf>& exact(const Point_2& point,
                                              const Projection* proj) {
    if (!point.p->exact) {
      point.p->exact = std::make_unique<Homogeneous<CGAL::Mpzf>>(
          homogeneous<CGAL::Mpzf>(*point.p->def, proj->origin));
    }
    return *point.p->exact;
  }
  struct Segment_2 {
    Point_2 a;
    Point_2 b;
  };
  struct Triangle_2 {
    Point_2 a;
    Point_2 b;
    Point_2 c;
  };
  using Line_2 = Segment_2;

  struct Orientation_2 {
    const Projection* proj;
    CGAL::Orientation operator()(const Point_2& a, const Point_2& b,
                                 const Point_2& c) const {
      ++proj->orient_calls;
      {
        CGAL::Protect_FPU_rounding<true> guard;
        const auto& [ax, ay] = a.p->xy;
        const auto& [bx, by] = b.p->xy;
        const auto& [cx, cy] = c.p->xy;
        const CGAL::Uncertain<Sign> s0 =
            CGAL::sign((bx - ax) * (cy - ay) - (by - ay) * (cx - ax));
        if (s0.is_certain()) return s0.make_certain();
        const CGAL::Uncertain<Sign> s = CGAL::sign(
            det3(a.p->approx, b.p->approx, c.p->approx, proj->ax, proj->ay));
        if (s.is_certain()) return s.make_certain();
      }
      ++proj->orient_exact;
      return sign_of(det3(exact(a, proj), exact(b, proj), exact(c, proj),
                          proj->ax, proj->ay));
    }
  };
  // Compares the projected coordinate `axis` of two points.
  struct Compare_axis {
    const Projection* proj;
    int which;  // 0: x, 1: y
    CGAL::Comparison_result operator()(const Point_2& a,
                                       const Point_2& b) const {
      const int axis = which == 0 ? proj->ax : proj->ay;
      {
        CGAL::Protect_FPU_rounding<true> guard;
        const CGAL::Uncertain<Sign> s0 =
            CGAL::sign(a.p->xy[which] - b.p->xy[which]);
        if (s0.is_certain()) return s0.make_certain();
        const CGAL::Uncertain<Sign> s =
            CGAL::sign(cross_coordinate(a.p->approx, b.p->approx, axis));
        if (s.is_certain()) return s.make_certain();
      }
      return sign_of(cross_coordinate(exact(a, proj), exact(b, proj), axis));
    }
  };
  using Compare_x_2 = Compare_axis;
  using Compare_y_2 = Compare_axis;
  struct Less_axis {
    Compare_axis compare;
    bool operator()(const Point_2& a, const Point_2& b) const {
      return compare(a, b) == CGAL::SMALLER;
    }
  };
  using Less_x_2 = Less_axis;
  using Less_y_2 = Less_axis;
  struct Construct_segment_2 {
    Segment_2 operator()(const Point_2& a, const Point_2& b) const {
      return {a, b};
    }
  };
  struct Construct_triangle_2 {
    Triangle_2 operator()(const Point_2& a, const Point_2& b,
                          const Point_2& c) const {
      return {a, b, c};
    }
  };
  struct Side_of_oriented_circle_2 {
    const Projection* proj;
    CGAL::Oriented_side operator()(const Point_2& a, const Point_2& b,
                                   const Point_2& c, const Point_2& d) const {
      ++proj->orient_calls;
      {
        CGAL::Protect_FPU_rounding<true> guard;
        const CGAL::Uncertain<Sign> s0 =
            CGAL::sign(incircle_cartesian(a.p->xy, b.p->xy, c.p->xy, d.p->xy));
        if (s0.is_certain()) return s0.make_certain();
        const CGAL::Uncertain<Sign> s = CGAL::sign(incircle<Interval>(
            {&a.p->approx, &b.p->approx, &c.p->approx, &d.p->approx}, proj->ax,
            proj->ay));
        if (s.is_certain()) return s.make_certain();
      }
      ++proj->orient_exact;
      const auto& ea = exact(a, proj);
      const auto& eb = exact(b, proj);
      const auto& ec = exact(c, proj);
      const auto& ed = exact(d, proj);
      return sign_of(
          incircle<CGAL::Mpzf>({&ea, &eb, &ec, &ed}, proj->ax, proj->ay));
    }
  };
  // A constrained Delaunay triangulation asks none of these, but its base
  // class names them.
  struct Construct_circumcenter_2 {};
  struct Compute_squared_distance_2 {};
  struct Construct_point_2 {
    const Point_2& operator()(const Point_2& p) const { return p; }
  };

  explicit Traits(const Projection* proj = nullptr) : proj_(proj) {}
  Orientation_2 orientation_2_object() const { return {proj_}; }
  Compare_x_2 compare_x_2_object() const { return {proj_, 0}; }
  Compare_y_2 compare_y_2_object() const { return {proj_, 1}; }
  Less_x_2 less_x_2_object() const { return {{proj_, 0}}; }
  Less_y_2 less_y_2_object() const { return {{proj_, 1}}; }
  Construct_segment_2 construct_segment_2_object() const { return {}; }
  Construct_triangle_2 construct_triangle_2_object() const { return {}; }
  Construct_point_2 construct_point_2_object() const { return {}; }
  Side_of_oriented_circle_2 side_of_oriented_circle_2_object() const {
    return {proj_};
  }

 private:
  const Projection* proj_;
};

using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Traits>;
using Fb = CGAL::Triangulation_face_base_with_info_2<
    int, Traits, CGAL::Constrained_triangulation_face_base_2<Traits>>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Triangulation = CGAL::Constrained_Delaunay_triangulation_2<
    Traits, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag>;

// What a cut face keeps, and what it tells its uncut neighbours.
struct CutFaceResult {
  std::vector<std::array<std::uint32_t, 3>> kept;
  // For each corner edge that no crossing cuts: whether the piece along it
  // lies inside the other operand (-1: the edge is cut).
  std::array<int, 3> edge_inside{-1, -1, -1};
  std::uint64_t orient_calls = 0;
  std::uint64_t orient_exact = 0;
};

// A face of the union, and whether it lies where the operands meet (a piece
// of a cut face, or a face whose box meets the other operand's box): the
// only faces that rounding the new points can make intersect.
struct KeptFace {
  std::array<std::uint32_t, 3> corners;
  bool near_contact = false;
};

struct CutFace {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> segments;  // ids
  std::vector<std::uint32_t> interior;                            // ids
};

class Engine {
 public:
  Engine(const TriangleMesh& a, const TriangleMesh& b, FilterCounters& filters)
      : ops_{{{&a, 0}, {&b, static_cast<std::uint32_t>(a.vertices.size())}}},
        filters_(filters) {}

  PairUnion run() {
    PairUnion result;
    try {
      find_segments();
      number_crossings();
      make_vertex_points();
      std::array<std::vector<KeptFace>, 2> kept;
      for (int m = 0; m < 2; ++m) classify(m, kept[m]);
      result.mesh = assemble(kept, result.first_new, result.contact_faces);
    } catch (const Failure& f) {
      result.failure = f.what;
      result.degenerate = f.degenerate;
      result.transversal = f.transversal;
      result.face_on_face = f.face_on_face;
      result.alike_pairs = f.alike_pairs;
    } catch (const CGAL::Failure_exception& e) {
      // A violated precondition of CGAL's (on as exceptions): a bug here.
      result.failure = std::string("CGAL: ") + e.what();
    }
    result.counters = counters_;
    return result;
  }

 private:
  static CGAL::Bbox_3 box_of(const TriangleMesh& m,
                             const std::array<std::uint32_t, 3>& t) {
    CGAL::Bbox_3 b;
    for (const std::uint32_t v : t) b += point3(m.vertices[v]).bbox();
    return b;
  }

  static CGAL::Bbox_3 box_of(const TriangleMesh& m) {
    CGAL::Bbox_3 b;
    for (const glm::dvec3& v : m.vertices) b += point3(v).bbox();
    return b;
  }

  void find_segments() {
    for (int m = 0; m < 2; ++m) mesh_box_[m] = box_of(*ops_[m].mesh);
    std::array<std::vector<Box>, 2> boxes;
    std::array<std::vector<std::uint32_t>, 2> face;  // per box
    for (int m = 0; m < 2; ++m) {
      const TriangleMesh& mesh = *ops_[m].mesh;
      face_box_overlaps_[m].assign(mesh.triangles.size(), 0);
      for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f) {
        const CGAL::Bbox_3 b = box_of(mesh, mesh.triangles[f]);
        if (!CGAL::do_overlap(b, mesh_box_[1 - m])) continue;
        face_box_overlaps_[m][f] = 1;
        boxes[m].push_back(Box{.min = {b.xmin(), b.ymin(), b.zmin()},
                               .max = {b.xmax(), b.ymax(), b.zmax()}});
        face[m].push_back(f);
      }
    }
    // Each pair whose boxes meet is tested as the search meets it, on the
    // search's threads, and kept only if its faces cross or meet in a
    // degeneracy; the kept pairs are tested again below, in order, for
    // their segments and failures (the same whatever the threads). Listed
    // whole first, the 32.7 million pairs of blog tree B's last union took
    // 2.5-3.0 s to gather and sort and 1.5 s to test, twice (a transversal
    // degeneracy, then the shifted retry), for a few hundred thousand that
    // cross. The faces are listed in increasing order, so the pairs come
    // sorted.
    const auto crossing = [&](std::uint32_t x, std::uint32_t y) {
      try {
        return cross_faces(ops_, face[0][x], face[1][y]).has_value();
      } catch (const Failure&) {
        return true;
      }
    };
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs =
        meeting_box_pairs(boxes[0], boxes[1], crossing);
    for (auto& [x, y] : pairs) {
      x = face[0][x];
      y = face[1][y];
    }
    const std::size_t chunks = (pairs.size() + 255) / 256;
    std::vector<std::vector<Segment>> found(chunks);
    // A transversal degeneracy does not stop the search: if faces also
    // touch somewhere, that is the failure to report, since a shift could
    // part them.
    // Nor do faces that touch: the search goes on to learn whether any
    // coplanar faces that face the same way are among them, and how many
    // (PairUnion::alike_pairs).
    std::vector<std::optional<Failure>> transversal(chunks);
    std::vector<std::optional<Failure>> touching(chunks);
    for_each_chunk(pairs.size(), [&](std::size_t begin, std::size_t end,
                                     std::size_t chunk) {
      for (std::size_t i = begin; i < end; ++i) {
        try {
          if (std::optional<Segment> s =
                  cross_faces(ops_, pairs[i].first, pairs[i].second)) {
            found[chunk].push_back(*s);
          }
        } catch (const Failure& f) {
          if (!f.degenerate) throw;
          keep_first(f.transversal ? transversal[chunk] : touching[chunk], f);
        }
      }
    });
    std::optional<Failure> touch;
    for (const std::optional<Failure>& f : touching)
      if (f) keep_first(touch, *f);
    if (touch) throw *touch;
    for (const std::optional<Failure>& f : transversal)
      if (f) throw *f;
    for (const std::vector<Segment>& list : found)
      segments_.insert(segments_.end(), list.begin(), list.end());
  }

  void number_crossings() {
    for (const Segment& s : segments_) {
      crossings_.push_back(s.from);
      crossings_.push_back(s.to);
    }
    std::sort(crossings_.begin(), crossings_.end());
    crossings_.erase(std::unique(crossings_.begin(), crossings_.end()),
                     crossings_.end());
    counters_.crossings = crossings_.size();
    points_.reserve(crossings_.size());
    for (const Crossing& c : crossings_) {
      const TriangleMesh& edge_mesh = *ops_[c.mesh].mesh;
      const TriangleMesh& face_mesh = *ops_[1 - c.mesh].mesh;
      const auto& t = face_mesh.triangles[c.face];
      points_.push_back(ImplicitPoint{
          .p = edge_mesh.vertices[c.e0],
          .q = edge_mesh.vertices[c.e1],
          .plane = {face_mesh.vertices[t[0]], face_mesh.vertices[t[1]],
                    face_mesh.vertices[t[2]]},
          .is_vertex = false,
          .p_below = c.p_below});
    }
    first_new_ = ops_[1].offset +
                 static_cast<std::uint32_t>(ops_[1].mesh->vertices.size());
    // Points on one edge, ordered from e0 by their parameter: crossings of
    // one edge are neighbours in the sorted order.
    for (std::size_t i = 0; i < crossings_.size();) {
      std::size_t j = i + 1;
      while (j < crossings_.size() &&
             crossings_[j].mesh == crossings_[i].mesh &&
             crossings_[j].e0 == crossings_[i].e0 &&
             crossings_[j].e1 == crossings_[i].e1) {
        ++j;
      }
      std::vector<std::uint32_t> run;
      for (std::size_t k = i; k < j; ++k)
        run.push_back(static_cast<std::uint32_t>(k));
      if (run.size() > 1) {
        std::sort(run.begin(), run.end(),
                  [&](std::uint32_t x, std::uint32_t y) {
                    return along_edge(x, y) == CGAL::SMALLER;
                  });
      }
      const Crossing& c = crossings_[i];
      edge_points_[c.mesh][edge_key(c.e0, c.e1)] = std::move(run);
      i = j;
    }
  }

  std::uint32_t id_of(const Crossing& c) const {
    const auto it = std::lower_bound(crossings_.begin(), crossings_.end(), c);
    return first_new_ + static_cast<std::uint32_t>(it - crossings_.begin());
  }

  // Compares two points of one edge by their parameter from e0.
  Sign along_edge(std::uint32_t x, std::uint32_t y) {
    filters_.along_edge.fetch_add(1, std::memory_order_relaxed);
    {
      CGAL::Protect_FPU_rounding<true> guard;
      const auto [nx, dx] = edge_parameter<Interval>(points_[x]);
      const auto [ny, dy] = edge_parameter<Interval>(points_[y]);
      const CGAL::Uncertain<Sign> s = CGAL::sign(nx * dy - ny * dx);
      if (s.is_certain()) return s.make_certain();
    }
    filters_.along_edge_exact.fetch_add(1, std::memory_order_relaxed);
    const auto [nx, dx] = edge_parameter<CGAL::Mpzf>(points_[x]);
    const auto [ny, dy] = edge_parameter<CGAL::Mpzf>(points_[y]);
    const Sign s = sign_of(nx * dy - ny * dx);
    if (s == CGAL::ZERO)
      throw Failure{"two crossings of an edge coincide", true};
    return s;
  }

  // The operands' vertices as implicit points, for the triangulations.
  void make_vertex_points() {
    for (int m = 0; m < 2; ++m) {
      auto& table = vertex_points_[m];
      table.resize(ops_[m].mesh->vertices.size());
      for (std::size_t i = 0; i < table.size(); ++i)
        table[i].p = ops_[m].mesh->vertices[i];
    }
  }

  // Triangulates face f of operand m with its crossings, and keeps the
  // pieces outside the other operand.
  CutFaceResult triangulate(int m, std::uint32_t f, const CutFace& cut) {
    CutFaceResult out;
    const TriangleMesh& mesh = *ops_[m].mesh;
    const auto& t = mesh.triangles[f];
    const std::array<glm::dvec3, 3> c{mesh.vertices[t[0]], mesh.vertices[t[1]],
                                      mesh.vertices[t[2]]};
    Projection proj;
    proj.origin = c[0];
    const glm::dvec3 n = glm::cross(c[1] - c[0], c[2] - c[0]);
    const glm::dvec3 an = glm::abs(n);
    const int axis = an.x >= an.y && an.x >= an.z ? 0 : (an.y >= an.z ? 1 : 2);
    // The exact sign of the normal's coordinate along the axis, from the
    // projected triangle's orientation.
    const auto other = [&](int k) { return (axis + k) % 3; };
    const CGAL::Orientation o =
        CGAL::orientation(K::Point_2(c[0][other(1)], c[0][other(2)]),
                          K::Point_2(c[1][other(1)], c[1][other(2)]),
                          K::Point_2(c[2][other(1)], c[2][other(2)]));
    if (o == CGAL::COLLINEAR) throw Failure{"a degenerate face"};
    proj.ax = o == CGAL::POSITIVE ? other(1) : other(2);
    proj.ay = o == CGAL::POSITIVE ? other(2) : other(1);

    // The face's points: corners, then points on its edges, then inside.
    std::vector<FacePoint> pts;
    pts.reserve(3 + cut.interior.size() + 2 * cut.segments.size());
    const auto def_of = [&](std::uint32_t id) -> const ImplicitPoint& {
      if (id >= first_new_) return points_[id - first_new_];
      const int mm = id >= ops_[1].offset ? 1 : 0;
      return vertex_points_[mm][id - ops_[mm].offset];
    };
    {
      CGAL::Protect_FPU_rounding<true> guard;
      const auto add = [&](std::uint32_t id) {
        const ImplicitPoint& d = def_of(id);
        pts.push_back(face_point(d, id, proj.origin, proj.ax, proj.ay));
      };
      for (int i = 0; i < 3; ++i) add(ops_[m].offset + t[i]);
      for (int i = 0; i < 3; ++i) {
        const auto it = edge_points_[m].find(edge_key(t[i], t[(i + 1) % 3]));
        if (it == edge_points_[m].end()) continue;
        for (const std::uint32_t k : it->second) add(first_new_ + k);
      }
      for (const std::uint32_t id : cut.interior) add(id);
    }
    Triangulation tr{Traits(&proj)};
    std::unordered_map<std::uint32_t, Triangulation::Vertex_handle> handle;
    const auto insert_at = [&](std::size_t k, Triangulation::Locate_type lt,
                               Triangulation::Face_handle fh, int li) {
      const auto vh = tr.insert(Traits::Point_2{&pts[k]}, lt, fh, li);
      vh->info() = pts[k].id;
      handle[pts[k].id] = vh;
      return vh;
    };
    std::array<Triangulation::Vertex_handle, 3> corner;
    for (int i = 0; i < 3; ++i) {
      corner[i] = tr.insert(Traits::Point_2{&pts[i]});
      corner[i]->info() = pts[i].id;
      handle[pts[i].id] = corner[i];
    }
    // The face's edges are constraints, so that no flip asks about points
    // on one of them (collinear, a known answer) and points inserted on
    // them split them.
    for (int i = 0; i < 3; ++i)
      tr.insert_constraint(corner[i], corner[(i + 1) % 3]);
    std::size_t k = 3;
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t u = t[i];
      const std::uint32_t v = t[(i + 1) % 3];
      const auto it = edge_points_[m].find(edge_key(u, v));
      if (it == edge_points_[m].end()) continue;
      const std::size_t count = it->second.size();
      // The edge's points run from its smaller end; insert them from u.
      std::vector<std::size_t> order(count);
      for (std::size_t j = 0; j < count; ++j)
        order[j] = u < v ? k + j : k + count - 1 - j;
      Triangulation::Vertex_handle prev = corner[i];
      const Triangulation::Vertex_handle end = corner[(i + 1) % 3];
      for (const std::size_t at : order) {
        Triangulation::Face_handle fh;
        int li = 0;
        if (!tr.is_edge(prev, end, fh, li))
          throw Failure{"an edge point lost its edge"};
        prev = insert_at(at, Triangulation::EDGE, fh, li);
      }
      k += count;
    }
    for (; k < pts.size(); ++k) {
      Triangulation::Locate_type lt;
      int li = 0;
      const Traits::Point_2 p{&pts[k]};
      const Triangulation::Face_handle fh = tr.locate(p, lt, li);
      // On an edge of the triangulation so far is fine (an edge of this
      // face's plane crossing flat parts of the other operand puts several
      // crossings on one line); on a vertex, or outside, is not.
      if ((lt != Triangulation::FACE && lt != Triangulation::EDGE) ||
          tr.is_infinite(fh)) {
        throw Failure{"two crossings coincide in a face", true};
      }
      insert_at(k, lt, fh, li);
    }
    for (const auto& [from, to] : cut.segments)
      tr.insert_constraint(handle.at(from), handle.at(to));

    // Inside or outside, from the directed constraints, spread over the
    // face across edges that no constraint holds.
    const bool left_is_inside = m == 0;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> forward = cut.segments;
    std::sort(forward.begin(), forward.end());
    const auto directed = [&](std::uint32_t a, std::uint32_t b) {
      if (std::binary_search(forward.begin(), forward.end(), std::pair(a, b)))
        return 1;
      if (std::binary_search(forward.begin(), forward.end(), std::pair(b, a)))
        return -1;
      return 0;
    };
    const auto set_status = [](Triangulation::Face_handle fh, int inside) {
      if (fh->info() == inside) return false;
      if (fh->info() >= 0)
        throw Failure{"a piece of a cut face is both inside and outside"};
      fh->info() = inside;
      return true;
    };
    std::vector<Triangulation::Face_handle> queue;
    for (auto fh : tr.all_face_handles()) fh->info() = -1;
    for (auto fh : tr.finite_face_handles()) {
      for (int i = 0; i < 3; ++i) {
        if (!fh->is_constrained(i)) continue;
        const int d = directed(fh->vertex(tr.ccw(i))->info(),
                               fh->vertex(tr.cw(i))->info());
        if (d == 0) continue;
        if (set_status(fh, (d > 0) == left_is_inside ? 1 : 0))
          queue.push_back(fh);
      }
    }
    while (!queue.empty()) {
      const auto fh = queue.back();
      queue.pop_back();
      for (int i = 0; i < 3; ++i) {
        if (fh->is_constrained(i)) continue;
        const auto nb = fh->neighbor(i);
        if (tr.is_infinite(nb)) continue;
        if (set_status(nb, fh->info())) queue.push_back(nb);
      }
    }
    for (auto fh : tr.finite_face_handles()) {
      if (fh->info() < 0) throw Failure{"a piece of a cut face has no side"};
      if (fh->info() == 0) {
        out.kept.push_back({fh->vertex(0)->info(), fh->vertex(1)->info(),
                            fh->vertex(2)->info()});
      }
    }
    for (int i = 0; i < 3; ++i) {
      Triangulation::Face_handle fh;
      int li = 0;
      if (!tr.is_edge(corner[i], corner[(i + 1) % 3], fh, li)) continue;
      if (tr.is_infinite(fh)) fh = fh->neighbor(li);
      out.edge_inside[i] = fh->info();
    }
    out.orient_calls = proj.orient_calls;
    out.orient_exact = proj.orient_exact;
    return out;
  }

  void classify(int m, std::vector<KeptFace>& kept) {
    const TriangleMesh& mesh = *ops_[m].mesh;
    const auto nf = static_cast<std::uint32_t>(mesh.triangles.size());
    std::unordered_map<std::uint32_t, CutFace> cut;
    for (const Segment& s : segments_) {
      const std::uint32_t f = m == 0 ? s.face_a : s.face_b;
      cut[f].segments.emplace_back(id_of(s.from), id_of(s.to));
    }
    for (std::size_t i = 0; i < crossings_.size(); ++i) {
      const Crossing& c = crossings_[i];
      if (static_cast<int>(c.mesh) == m) continue;
      cut[c.face].interior.push_back(first_new_ +
                                     static_cast<std::uint32_t>(i));
    }
    counters_.cut_faces += cut.size();
    std::vector<std::uint32_t> cut_faces;
    for (const auto& [f, c] : cut) cut_faces.push_back(f);
    std::sort(cut_faces.begin(), cut_faces.end());

    // Neighbours across each edge.
    std::unordered_map<std::uint64_t, std::uint32_t> by_edge;
    by_edge.reserve(3 * nf);
    for (std::uint32_t f = 0; f < nf; ++f) {
      const auto& t = mesh.triangles[f];
      for (int i = 0; i < 3; ++i) {
        by_edge[(static_cast<std::uint64_t>(t[i]) << 32U) | t[(i + 1) % 3]] = f;
      }
    }
    const auto neighbour = [&](std::uint32_t f, int i) {
      const auto& t = mesh.triangles[f];
      const auto it = by_edge.find(
          (static_cast<std::uint64_t>(t[(i + 1) % 3]) << 32U) | t[i]);
      if (it == by_edge.end()) throw Failure{"an operand is not closed"};
      return it->second;
    };
    std::vector<std::uint8_t> is_cut(nf, 0);
    for (const std::uint32_t f : cut_faces) is_cut[f] = 1;
    // -1 unknown, 0 outside, 1 inside: for each uncut face, by its surface.
    std::vector<int> seed(nf, -1);
    UnionFind surfaces(nf);
    for (std::uint32_t f = 0; f < nf; ++f) {
      if (is_cut[f]) continue;
      if (!face_box_overlaps_[m][f]) seed[f] = 0;
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t g = neighbour(f, i);
        if (!is_cut[g]) surfaces.join(f, g);
      }
    }
    std::vector<CutFaceResult> results(cut_faces.size());
    for_each_chunk(cut_faces.size(), [&](std::size_t begin, std::size_t end,
                                         std::size_t) {
      for (std::size_t i = begin; i < end; ++i) {
        try {
          results[i] = triangulate(m, cut_faces[i], cut.at(cut_faces[i]));
        } catch (const Triangulation::Intersection_of_constraints_exception&) {
          // Two faces of one operand meet the other's face in segments that
          // cross: they touch there.
          throw Failure{"two cuts cross in a face", true};
        } catch (const CGAL::Failure_exception& e) {
          throw Failure{std::string("the triangulation of a cut face: ") +
                        e.what()};
        }
      }
    });
    for (std::size_t k = 0; k < cut_faces.size(); ++k) {
      const std::uint32_t f = cut_faces[k];
      const CutFaceResult& r = results[k];
      filters_.orient_2d.fetch_add(r.orient_calls, std::memory_order_relaxed);
      filters_.orient_2d_exact.fetch_add(r.orient_exact,
                                         std::memory_order_relaxed);
      for (const auto& tri : r.kept) kept.push_back({tri, true});
      for (int i = 0; i < 3; ++i) {
        if (r.edge_inside[i] < 0) continue;
        const std::uint32_t g = neighbour(f, i);
        if (is_cut[g]) continue;
        if (seed[g] >= 0 && seed[g] != r.edge_inside[i])
          throw Failure{"a surface is both inside and outside"};
        seed[g] = r.edge_inside[i];
      }
    }
    // One side per surface: its seeds agree, or one inside test decides.
    std::vector<int> side(nf, -1);
    for (std::uint32_t f = 0; f < nf; ++f) {
      if (is_cut[f] || seed[f] < 0) continue;
      const std::uint32_t r = surfaces.find(f);
      if (side[r] >= 0 && side[r] != seed[f])
        throw Failure{"a surface is both inside and outside"};
      side[r] = seed[f];
    }
    for (std::uint32_t f = 0; f < nf; ++f) {
      if (is_cut[f]) continue;
      const std::uint32_t r = surfaces.find(f);
      if (side[r] < 0) side[r] = inside_other(m, mesh.triangles[f][0]) ? 1 : 0;
      if (side[r] == 0) {
        const auto& t = mesh.triangles[f];
        kept.push_back({{ops_[m].offset + t[0], ops_[m].offset + t[1],
                         ops_[m].offset + t[2]},
                        face_box_overlaps_[m][f] != 0});
      }
    }
  }

  // Whether vertex v of operand m lies inside the other operand: for a
  // surface that no crossing touches (a part inside another, or beside it
  // within its box). By ray parity along an axis (ray_parity.hpp), and by
  // CGAL's random rays where a ray along each axis meets an edge.
  bool inside_other(int m, std::uint32_t v) {
    ++counters_.inside_tests;
    const int o = 1 - m;
    if (!rays_[o]) rays_[o] = ray_surface(*ops_[o].mesh);
    const glm::dvec3& p = ops_[m].mesh->vertices[v];
    for (int axis = 0; axis < 3; ++axis) {
      const std::optional<RaySide> side = side_by_ray(*rays_[o], p, axis);
      if (!side) continue;
      if (*side == RaySide::kOnSurface)
        throw Failure{"a vertex lies on the other operand", true};
      return *side == RaySide::kInside;
    }
    if (!side_of_[o]) {
      std::optional<InexactMesh> surface =
          to_surface_mesh<InexactMesh>(*ops_[o].mesh);
      if (!surface) throw Failure{"an operand is not a 2-manifold"};
      surface_[o] = std::make_unique<InexactMesh>(std::move(*surface));
      side_of_[o] =
          std::make_unique<CGAL::Side_of_triangle_mesh<InexactMesh, K>>(
              *surface_[o]);
    }
    const CGAL::Bounded_side s =
        (*side_of_[o])(point3(ops_[m].mesh->vertices[v]));
    if (s == CGAL::ON_BOUNDARY)
      throw Failure{"a vertex lies on the other operand", true};
    return s == CGAL::ON_BOUNDED_SIDE;
  }

  // The kept triangles over the points they use: first the operands'
  // vertices in order, then the new points, rounded to doubles.
  TriangleMesh assemble(const std::array<std::vector<KeptFace>, 2>& kept,
                        std::size_t& first_new,
                        std::vector<std::uint32_t>& contact_faces) {
    const std::uint32_t total =
        first_new_ + static_cast<std::uint32_t>(points_.size());
    std::vector<std::uint32_t> index(total, UINT32_MAX);
    for (const auto& list : kept)
      for (const KeptFace& k : list)
        for (const std::uint32_t v : k.corners) index[v] = 0;
    TriangleMesh out;
    bool any_new = false;
    for (std::uint32_t v = 0; v < total; ++v) {
      if (index[v] == UINT32_MAX) continue;
      index[v] = static_cast<std::uint32_t>(out.vertices.size());
      if (v < first_new_) {
        const int m = v >= ops_[1].offset ? 1 : 0;
        out.vertices.push_back(ops_[m].mesh->vertices[v - ops_[m].offset]);
      } else {
        if (!any_new) first_new = out.vertices.size();
        any_new = true;
        out.vertices.push_back(rounded(points_[v - first_new_]));
      }
    }
    if (!any_new) first_new = out.vertices.size();
    for (const auto& list : kept) {
      for (const KeptFace& k : list) {
        if (k.near_contact) {
          contact_faces.push_back(
              static_cast<std::uint32_t>(out.triangles.size()));
        }
        const auto& t = k.corners;
        out.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
      }
    }
    return out;
  }

  // The point rounded to doubles: from an interval around its offset from
  // the edge's first end, as tight as one unit in the last place, else from
  // its exact homogeneous coordinates (Mpzf), each as a tight interval: the
  // middle of their quotient, within two units in the last place. Rounding
  // to nearest through rationals (Gmpq, then MPFR) was a tenth of the
  // bush's union; what the rounding must keep, validity, is tested after.
  static glm::dvec3 rounded(const ImplicitPoint& point) {
    glm::dvec3 out;
    std::array<bool, 3> done{};
    {
      CGAL::Protect_FPU_rounding<true> guard;
      const Homogeneous<Interval> h = homogeneous<Interval>(point, point.p);
      for (int k = 0; k < 3; ++k) {
        const Interval x = h.xyz[k] / h.w + Interval(point.p[k]);
        if (x.inf() == x.sup() || std::nextafter(x.inf(), x.sup()) == x.sup()) {
          out[k] = x.inf();
          done[k] = true;
        }
      }
    }
    if (done[0] && done[1] && done[2]) return out;
    const Homogeneous<CGAL::Mpzf> h =
        homogeneous<CGAL::Mpzf>(point, glm::dvec3(0.0));
    std::array<Interval, 3> x;
    {
      CGAL::Protect_FPU_rounding<true> guard;
      const Interval w(h.w.to_interval());
      for (int k = 0; k < 3; ++k) x[k] = Interval(h.xyz[k].to_interval()) / w;
    }
    for (int k = 0; k < 3; ++k) {
      if (!done[k]) out[k] = x[k].inf() + (x[k].sup() - x[k].inf()) / 2.0;
    }
    return out;
  }

  std::array<Operand, 2> ops_;
  FilterCounters& filters_;
  PairCounters counters_;
  std::array<CGAL::Bbox_3, 2> mesh_box_;
  std::array<std::vector<std::uint8_t>, 2> face_box_overlaps_;
  std::vector<Segment> segments_;
  std::vector<Crossing> crossings_;
  std::vector<ImplicitPoint> points_;
  std::uint32_t first_new_ = 0;
  std::array<std::unordered_map<std::uint64_t, std::vector<std::uint32_t>>, 2>
      edge_points_;
  std::array<std::vector<ImplicitPoint>, 2> vertex_points_;
  std::array<std::optional<RaySurface>, 2> rays_;
  std::array<std::unique_ptr<InexactMesh>, 2> surface_;
  std::array<std::unique_ptr<CGAL::Side_of_triangle_mesh<InexactMesh, K>>, 2>
      side_of_;
};

}  // namespace

bool has_new_corner(const PairUnion& u, std::uint32_t face) {
  const auto& t = u.mesh.triangles[face];
  return std::any_of(t.begin(), t.end(),
                     [&](std::uint32_t v) { return v >= u.first_new; });
}

bool rounding_kept_valid(const PairUnion& u) {
  const TriangleMesh& mesh = u.mesh;
  const auto triangle = [&](std::uint32_t f) {
    IndexedTriangle t;
    t.ids = mesh.triangles[f];
    for (int i = 0; i < 3; ++i) t.points[i] = mesh.vertices[t.ids[i]];
    return t;
  };
  std::vector<Box> changed;
  std::vector<Box> unchanged;
  std::vector<std::uint32_t> changed_face;  // per box
  std::vector<std::uint32_t> unchanged_face;
  std::vector<char> unchanged_degenerate;
  for (const std::uint32_t f : u.contact_faces) {
    const IndexedTriangle t = triangle(f);
    Box b;
    for (const glm::dvec3& p : t.points) b.add(p);
    if (has_new_corner(u, f)) {
      if (is_degenerate(t)) return false;
      changed.push_back(b);
      changed_face.push_back(f);
    } else {
      unchanged.push_back(b);
      unchanged_face.push_back(f);
      unchanged_degenerate.push_back(is_degenerate(t) ? 1 : 0);
    }
  }
  // Each pair once: changed faces among themselves, then against the rest;
  // once one pair is found to meet, the others are no longer tested. Each
  // face's degeneracy is decided once above, not for every pair it is in
  // (triangles_intersect's two collinearity tests a pair).
  std::atomic<bool> ok{true};
  const auto meets = [&](std::uint32_t f, std::uint32_t g, bool degenerate) {
    if (ok &&
        (degenerate || proper_triangles_intersect(triangle(f), triangle(g)))) {
      ok = false;
    }
    return false;
  };
  (void)meeting_box_pairs(changed, [&](std::uint32_t i, std::uint32_t j) {
    return meets(changed_face[i], changed_face[j], false);
  });
  if (ok) {
    (void)meeting_box_pairs(changed, unchanged,
                            [&](std::uint32_t i, std::uint32_t j) {
                              return meets(changed_face[i], unchanged_face[j],
                                           unchanged_degenerate[j] != 0);
                            });
  }
  return ok;
}

PairUnion unite_pair(const TriangleMesh& a, const TriangleMesh& b,
                     FilterCounters& filters) {
  return Engine(a, b, filters).run();
}

}  // namespace lsolid::exact_union
