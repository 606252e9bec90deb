// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "cgal/union/exact_union.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <set>
#include <vector>

#include "lsolid/boolean.hpp"
#include "lsolid/mesh_io.hpp"
#include "lsolid/parts.hpp"
#include "lsolid/rounding.hpp"
#include "lsolid/validate.hpp"
#include "shells.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid::exact_union {
namespace {

using lsolid::testing::box_mesh;
using lsolid::testing::expect_printable;

TriangleMesh joined(const TriangleMesh& a, const TriangleMesh& b) {
  TriangleMesh out = a;
  append(out, b);
  return out;
}

// A closed prism of `sides` around the segment from a to b, its ring turned
// by `phase` radians.
TriangleMesh prism(const glm::dvec3& a, const glm::dvec3& b, double radius,
                   int sides, double phase) {
  const glm::dvec3 axis = glm::normalize(b - a);
  const glm::dvec3 helper =
      std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(axis, helper));
  const glm::dvec3 v = glm::cross(axis, u);
  TriangleMesh m;
  for (const glm::dvec3& c : {a, b}) {
    for (int i = 0; i < sides; ++i) {
      const double t = phase + 2 * std::numbers::pi * i / sides;
      m.vertices.push_back(c + radius * (std::cos(t) * u + std::sin(t) * v));
    }
  }
  m.vertices.push_back(a);
  m.vertices.push_back(b);
  const auto n = static_cast<std::uint32_t>(sides);
  const std::uint32_t ca = 2 * n;
  const std::uint32_t cb = 2 * n + 1;
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    m.triangles.push_back({i, j, n + i});
    m.triangles.push_back({j, n + j, n + i});
    m.triangles.push_back({ca, j, i});
    m.triangles.push_back({cb, n + i, n + j});
  }
  return m;
}

TEST(ExactUnion, UnitesTwoBoxesInGeneralPositionToTheirVolume) {
  FilterCounters filters;
  const PairUnion u =
      unite_pair(box_mesh({0, 0, 0}, {2, 2, 2}),
                 box_mesh({1.1, 1.2, 1.3}, {3, 3.5, 4}), filters);
  ASSERT_TRUE(u.failure.empty()) << u.failure;
  expect_printable(u.mesh);
  EXPECT_NEAR(signed_volume(u.mesh), 8.0 + 1.9 * 2.3 * 2.7 - 0.9 * 0.8 * 0.7,
              1e-12);
  EXPECT_GT(u.counters.crossings, 0U);
}

TEST(ExactUnion, KeepsAPartThatNoFaceCrossesOutsideAndDropsOneInside) {
  FilterCounters filters;
  const TriangleMesh big = box_mesh({0, 0, 0}, {4, 4, 4});
  const TriangleMesh inner = box_mesh({1, 1.1, 1.2}, {2, 2.1, 2.2});
  const TriangleMesh beside = box_mesh({5, 1, 1}, {6, 2, 2});
  const PairUnion u = unite_pair(big, joined(inner, beside), filters);
  ASSERT_TRUE(u.failure.empty()) << u.failure;
  expect_printable(u.mesh, 2);
  EXPECT_NEAR(signed_volume(u.mesh), 64.0 + 1.0, 1e-12);
}

TEST(ExactUnion, UnitesCrossingPrismsAsTheirVolumeSays) {
  FilterCounters filters;
  const TriangleMesh a =
      prism({-3, 0.01, 0.02}, {3, 0.03, -0.01}, 1.0, 12, 0.1);
  const TriangleMesh b =
      prism({0.02, -3, 0.01}, {-0.01, 3, 0.03}, 0.8, 10, 0.2);
  ASSERT_GT(signed_volume(a), 0.0);
  const PairUnion u = unite_pair(a, b, filters);
  ASSERT_TRUE(u.failure.empty()) << u.failure;
  expect_printable(u.mesh);
  EXPECT_GT(signed_volume(u.mesh), signed_volume(a));
  EXPECT_LT(signed_volume(u.mesh), signed_volume(a) + signed_volume(b));
}

// Random prisms in a 10 mm box, as the tubes of a tree meet: rings of 6 to
// 16 sides, radii 0.3 to 1.5 mm, turned at random.
std::vector<Part> random_tubes(unsigned seed, int count) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coordinate(0.0, 10.0);
  std::uniform_real_distribution<double> radius(0.3, 1.5);
  std::uniform_real_distribution<double> phase(0.0, 1.0);
  std::uniform_int_distribution<int> sides(6, 16);
  std::vector<Part> parts;
  for (int i = 0; i < count; ++i) {
    const glm::dvec3 a(coordinate(random), coordinate(random),
                       coordinate(random));
    glm::dvec3 b(coordinate(random), coordinate(random), coordinate(random));
    b = a + 0.5 * (b - a);
    std::string label = "tube ";
    label += std::to_string(i);
    parts.push_back(
        {prism(a, b, radius(random), sides(random), phase(random)), label});
  }
  return parts;
}

// The Euler characteristic of a closed triangle mesh, V − E + F.
long euler_characteristic(const TriangleMesh& m) {
  return static_cast<long>(m.vertices.size()) -
         static_cast<long>(m.triangles.size()) / 2;
}

TEST(ExactUnion, AgreesWithTheCorefinementOnRandomTubes) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const std::vector<Part> parts = random_tubes(seed, 40);
    const UnionResult exact =
        union_parts(parts, {.engine = UnionEngine::ExactCrossings});
    const UnionResult oracle =
        union_parts(parts, {.engine = UnionEngine::Corefinement});
    SCOPED_TRACE(seed);
    EXPECT_GT(exact.stats.exact_unions, 0U);
    EXPECT_EQ(exact.stats.fallbacks, 0U) << exact.stats.fallback_reason;
    EXPECT_EQ(exact.stats.degenerate_unions, 0U)
        << exact.stats.degenerate_reason;
    const double volume = signed_volume(oracle.mesh);
    EXPECT_NEAR(signed_volume(exact.mesh), volume, 1e-9 * volume);
    EXPECT_EQ(label_shells(exact.mesh).count, label_shells(oracle.mesh).count);
    EXPECT_EQ(euler_characteristic(exact.mesh),
              euler_characteristic(oracle.mesh));
    const ValidationReport check = validate(exact.mesh);
    EXPECT_EQ(check.boundary_edges, 0U);
    EXPECT_EQ(check.non_manifold_edges, 0U);
    EXPECT_EQ(check.non_manifold_vertices, 0U);
    EXPECT_EQ(check.genus, validate(oracle.mesh).genus);
  }
}

TEST(ExactUnion, CountsItsPredicatesAndDecidesMostInIntervals) {
  const UnionResult u = union_parts(random_tubes(7, 40));
  EXPECT_GT(u.stats.predicates, 1000U);
  EXPECT_LT(static_cast<double>(u.stats.filter_failures),
            0.1 * static_cast<double>(u.stats.predicates));
  EXPECT_GT(u.stats.crossings, 0U);
  EXPECT_GT(u.stats.cut_faces, 0U);
}

// Two cubes whose faces' diagonals cross exactly where the other's edges
// pass: a degeneracy where the faces cross each other's planes.
TEST(ExactUnion, SaysWhereFacesCrossAtACoincidence) {
  FilterCounters filters;
  const PairUnion u = unite_pair(box_mesh({0, 0, 0}, {2, 2, 2}),
                                 box_mesh({1, 1, 1}, {3, 3, 3}), filters);
  EXPECT_TRUE(u.degenerate);
  EXPECT_TRUE(u.transversal);
  EXPECT_EQ(u.failure, "an edge passes through an edge");
}

TEST(ExactUnion, ShiftsACoincidenceWhereFacesCrossAway) {
  std::vector<Part> parts{{box_mesh({0, 0, 0}, {2, 2, 2}), "a"},
                          {box_mesh({1, 1, 1}, {3, 3, 3}), "b"}};
  const UnionResult u = union_parts(std::move(parts));
  EXPECT_EQ(u.stats.degenerate_unions, 0U) << u.stats.degenerate_reason;
  EXPECT_EQ(u.stats.exact_unions, 1U);
  EXPECT_EQ(u.stats.retries, 1U);
  // One cube moved by 10⁻⁸ mm along (1, 0.618, 0.382): the overlap, a unit
  // cube, changes by about the sum of the shift's components.
  EXPECT_NEAR(std::abs(signed_volume(u.mesh) - 15.0), 2e-8, 1e-9);
  expect_printable(u.mesh);
}

// A box against another's face: the smaller grows by about 10⁻¹² mm (a
// thousand units in the last place at 3 mm), its face crosses into the
// larger box, and the exact engine joins them where they touched.
TEST(ExactUnion, GrowsAnOperandWhoseFacesTouchFaceOnAndUnitesItExactly) {
  std::vector<Part> parts{{box_mesh({0, 0, 0}, {2, 2, 2}), "a"},
                          {box_mesh({2, 0.5, 0.5}, {3, 1.5, 1.5}), "b"}};
  const UnionResult u = union_parts(parts);
  EXPECT_EQ(u.stats.degenerate_unions, 0U) << u.stats.degenerate_reason;
  EXPECT_EQ(u.stats.exact_unions, 1U);
  EXPECT_EQ(u.stats.grown, 1U);
  EXPECT_EQ(u.stats.retries, 0U);
  const UnionResult oracle =
      union_parts(parts, {.engine = UnionEngine::Corefinement});
  EXPECT_DOUBLE_EQ(signed_volume(oracle.mesh), 9.0);
  EXPECT_NEAR(signed_volume(u.mesh), 9.0, 1e-9 * 9.0);
  EXPECT_GT(signed_volume(u.mesh), 9.0);  // grown, not shrunk
  EXPECT_EQ(label_shells(u.mesh).count, 1U);
  EXPECT_EQ(euler_characteristic(u.mesh), euler_characteristic(oracle.mesh));
  expect_printable(u.mesh);
}

// A box on a slab, and a box against the first box's side: the two boxes
// (the fewest faces) are united first, one grown; their union, which holds
// that growth's steps, then lies on the slab (which three far cubes make
// the larger operand), and a second growth joins them.
TEST(ExactUnion, UnitesAChainOfFacesThatTouchGrowingEachTime) {
  TriangleMesh slab = box_mesh({0, 0, 0}, {2, 2, 1.5});
  for (const double x : {9.0, 11.0, 13.0})
    append(slab, box_mesh({x, 9, 9}, {x + 1, 10, 10}));
  std::vector<Part> parts{{slab, "slab"},
                          {box_mesh({0.2, 0.5, 1.5}, {1, 1.5, 3}), "b"},
                          {box_mesh({1, 0.6, 1.6}, {2.2, 1.4, 2.8}), "c"}};
  const UnionResult u = union_parts(parts);
  EXPECT_EQ(u.stats.degenerate_unions, 0U) << u.stats.degenerate_reason;
  EXPECT_EQ(u.stats.exact_unions, 2U);
  EXPECT_EQ(u.stats.grown, 2U);
  const UnionResult oracle =
      union_parts(parts, {.engine = UnionEngine::Corefinement});
  const double volume = 6.0 + 3.0 + 0.8 * 1.0 * 1.5 + 1.2 * 0.8 * 1.2;
  EXPECT_NEAR(signed_volume(oracle.mesh), volume, 1e-12 * volume);
  EXPECT_NEAR(signed_volume(u.mesh), volume, 1e-9 * volume);
  EXPECT_EQ(label_shells(u.mesh).count, 4U);
  EXPECT_EQ(euler_characteristic(u.mesh), euler_characteristic(oracle.mesh));
  // The steps the growths left are slivers 10⁻¹² mm wide: rounding to an
  // STL's floats mends them, as it mends the build's.
  const Rounded rounded = round_for(u.mesh, MeshFormat::StlBinary);
  EXPECT_TRUE(rounded.clean);
  EXPECT_NEAR(signed_volume(rounded.mesh), volume, 1e-6 * volume);
  expect_printable(rounded.mesh, 4);
}

// A box on a square prism's top, meeting it at a corner only, where an
// upright edge of each ends on the other's (a finding of the union fuzz
// target): a side of the prism lies on the inner side of the plane of a
// side of the box, but meets that side at its corner only. A growth would
// join the two by a neck 10⁻¹² mm wide; the corefinement unites them,
// parting or joining them as its shift does.
TEST(ExactUnion, LeavesSolidsThatTouchAtAPointToTheCorefinement) {
  // The square prism's corners exactly where its ring puts them roughly.
  TriangleMesh square =
      prism({0.5, 0.5, 0}, {0.5, 0.5, 3}, 1.0, 4, -std::numbers::pi / 2);
  for (glm::dvec3& p : square.vertices) p = glm::round(p * 2.0) / 2.0;
  ASSERT_EQ(square.vertices[0], glm::dvec3(1.5, 0.5, 0));
  std::vector<Part> parts{{box_mesh({1.5, 0, 3}, {3.5, 0.5, 5}), "box"},
                          {square, "prism"}};
  FilterCounters filters;
  const PairUnion pair = unite_pair(parts[0].mesh, parts[1].mesh, filters);
  EXPECT_TRUE(pair.degenerate);
  EXPECT_FALSE(pair.face_on_face);
  const UnionResult u = union_parts(parts);
  EXPECT_EQ(u.stats.grown, 0U);
  EXPECT_EQ(u.stats.degenerate_unions, 1U);
  const UnionResult oracle =
      union_parts(parts, {.engine = UnionEngine::Corefinement});
  EXPECT_EQ(label_shells(u.mesh).count, label_shells(oracle.mesh).count);
}

// Two cubes side by side: besides the faces against each other, their
// tops, bottoms and sides lie in one plane, facing the same way. A growth
// would leave a step between those along the whole seam: the corefinement
// unites them exactly instead.
TEST(ExactUnion, LeavesCoplanarFacesThatFaceAlikeToTheCorefinement) {
  std::vector<Part> parts{{box_mesh({0, 0, 0}, {1, 1, 1}), "a"},
                          {box_mesh({1, 0, 0}, {2, 1, 1}), "b"}};
  const UnionResult u = union_parts(std::move(parts));
  EXPECT_EQ(u.stats.degenerate_unions, 1U);
  EXPECT_EQ(u.stats.grown, 0U);
  EXPECT_EQ(u.stats.exact_unions, 0U);
  EXPECT_NE(u.stats.degenerate_reason.find(" with "), std::string::npos)
      << u.stats.degenerate_reason;
  EXPECT_DOUBLE_EQ(signed_volume(u.mesh), 2.0);
  EXPECT_EQ(label_shells(u.mesh).count, 1U);
  expect_printable(u.mesh);
}

// That `u` has the volume of the corefinement's union of `parts` (the
// oracle) to 10⁻⁹, `shells` shells and its Euler characteristic; returns
// that volume.
double expect_as_the_corefinement(const std::vector<Part>& parts,
                                  const UnionResult& u, std::size_t shells) {
  const UnionResult oracle =
      union_parts(parts, {.engine = UnionEngine::Corefinement});
  const double volume = signed_volume(oracle.mesh);
  EXPECT_NEAR(signed_volume(u.mesh), volume, 1e-9 * volume);
  EXPECT_EQ(label_shells(u.mesh).count, shells);
  EXPECT_EQ(label_shells(oracle.mesh).count, shells);
  EXPECT_EQ(euler_characteristic(u.mesh), euler_characteristic(oracle.mesh));
  return volume;
}

// A box against a larger box's side, their tops in one plane: a few
// coplanar faces that face the same way (where the tops meet), among
// hundreds of faces (each part holds a fine prism far away, as the touching
// Hilbert curve's tubes meet cap to cap in one plane now and then). The
// union is grown: the step it leaves along the tops' seam is mended by the
// rounding to an STL's floats, and the volume is the corefinement's.
TEST(ExactUnion, GrowsAnOperandWhereFewCoplanarFacesFaceAlike) {
  TriangleMesh big = box_mesh({0, 0, 0}, {2, 2, 2});
  append(big, prism({10, 10, 10}, {10, 10, 14}, 1.0, 150, 0.0));
  TriangleMesh small = box_mesh({2, 0.5, 1}, {3, 1.5, 2});
  append(small, prism({-10, 10, 10}, {-10, 10, 13}, 1.0, 150, 0.0));
  std::vector<Part> parts{{big, "big"}, {small, "small"}};
  FilterCounters filters;
  const PairUnion pair = unite_pair(parts[0].mesh, parts[1].mesh, filters);
  EXPECT_TRUE(pair.degenerate);
  EXPECT_TRUE(pair.face_on_face);
  EXPECT_GT(pair.alike_pairs, 0U);
  EXPECT_LE(100 * pair.alike_pairs, small.triangles.size());
  const UnionResult u = union_parts(parts);
  EXPECT_EQ(u.stats.degenerate_unions, 0U) << u.stats.degenerate_reason;
  EXPECT_EQ(u.stats.exact_unions, 1U);
  EXPECT_EQ(u.stats.grown, 1U);
  const double volume = expect_as_the_corefinement(parts, u, 3);
  const Rounded rounded = round_for(u.mesh, MeshFormat::StlBinary);
  EXPECT_TRUE(rounded.clean);
  EXPECT_NEAR(signed_volume(rounded.mesh), volume, 1e-6 * volume);
  expect_printable(rounded.mesh, 3);
}

// Two boxes side by side with coplanar bottoms are united first (the fewest
// faces), by the corefinement; the prism that crosses both is then united
// with their union by the exact engine again, as the union's points were
// all rounded.
TEST(ExactUnion, ReturnsToTheExactEngineAfterFacesThatTouch) {
  std::vector<Part> parts{
      {box_mesh({0, 0, 0}, {2, 2, 2}), "a"},
      {box_mesh({2, 0.5, 0}, {3, 1.5, 1.5}), "b"},
      {prism({1.3, -1, 1.1}, {2.7, 3, 1.2}, 0.3, 16, 0.1), "c"}};
  const UnionResult u = union_parts(parts);
  EXPECT_EQ(u.stats.degenerate_unions, 1U);
  EXPECT_EQ(u.stats.booleans, 2U);
  EXPECT_EQ(u.stats.exact_unions, 1U);
  expect_as_the_corefinement(parts, u, 1);
  expect_printable(u.mesh);
}

// A box against a cube's side, face on face; a cube on the cube's corner,
// meeting it at that point only; a cube beside it, their tops, bottoms and
// sides in one plane.
TEST(ExactUnion, RefusesFacesThatTouchAsADegeneracyAndSaysHow) {
  struct Case {
    TriangleMesh b;
    bool alike;
    bool face_on_face;
  };
  for (const Case& c :
       {Case{box_mesh({1, 0.2, 0.3}, {2, 0.7, 0.8}), false, true},
        Case{box_mesh({1, 1, 1}, {2, 2, 2}), false, false},
        Case{box_mesh({1, 0, 0}, {2, 1, 1}), true, true}}) {
    FilterCounters filters;
    const PairUnion u =
        unite_pair(box_mesh({0, 0, 0}, {1, 1, 1}), c.b, filters);
    SCOPED_TRACE(c.b.vertices.front().y);
    EXPECT_TRUE(u.degenerate);
    EXPECT_FALSE(u.transversal);
    EXPECT_EQ(u.alike_pairs > 0, c.alike);
    EXPECT_EQ(u.face_on_face, c.face_on_face);
    EXPECT_FALSE(u.failure.empty());
  }
}

// A box, and an octagonal prism beside it whose top cap's centre lies in the
// plane of the box's side (a finding of the union fuzz target): the cap and
// that side straddle each other's planes, and a corner of the cap lies in
// the side's plane, yet they miss each other, as do the solids, by 10⁻¹⁶.
// No degeneracy, no shift (which joined the two), and two shells as the
// corefinement has them.
TEST(ExactUnion, PartsSolidsWhoseFacesStraddleEachOthersPlanesAndMiss) {
  const TriangleMesh octagon = prism({0, 1.5, 0}, {0, 1.5, 1.5}, 1.0, 8, 0.0);
  ASSERT_EQ(octagon.vertices[16], glm::dvec3(0, 1.5, 0));
  ASSERT_EQ(octagon.vertices[4].y, 0.5);
  ASSERT_LT(octagon.vertices[4].x, 0.0);
  const std::vector<Part> parts{{box_mesh({0, 0, 0}, {3.5, 0.5, 3}), "box"},
                                {octagon, "prism"}};
  FilterCounters filters;
  const PairUnion pair = unite_pair(parts[0].mesh, parts[1].mesh, filters);
  EXPECT_FALSE(pair.degenerate) << pair.failure;
  const UnionResult u = union_parts(parts);
  EXPECT_EQ(u.stats.retries, 0U);
  EXPECT_EQ(u.stats.degenerate_unions, 0U) << u.stats.degenerate_reason;
  expect_as_the_corefinement(parts, u, 2);
  expect_printable(u.mesh, 2);
}

}  // namespace
}  // namespace lsolid::exact_union
