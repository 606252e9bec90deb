// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "surface_distance.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

double brute_distance(const TriangleMesh& mesh, const glm::dvec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 d =
        closest_point_on_triangle(p, mesh.vertices[t[0]], mesh.vertices[t[1]],
                                  mesh.vertices[t[2]]) -
        p;
    best = std::min(best, glm::length(d));
  }
  return best;
}

bool brute_covers(const TriangleMesh& mesh, const glm::dvec3& a,
                  const glm::dvec3& b, const glm::dvec3& c, double r) {
  for (const auto& t : mesh.triangles) {
    const auto near = [&](const glm::dvec3& p) {
      const glm::dvec3 d =
          closest_point_on_triangle(p, mesh.vertices[t[0]], mesh.vertices[t[1]],
                                    mesh.vertices[t[2]]) -
          p;
      return glm::dot(d, d) <= r * r;
    };
    if (near(a) && near(b) && near(c)) return true;
  }
  return false;
}

// A surface with the kinds of triangle the index files differently: small
// ones, filed by their box's cells; a box's sides and a long sliver, across
// many cells, filed by the cells they pass through; and a triangle nearly
// without area, which the plane tests leave out.
TriangleMesh mixed_surface() {
  TriangleMesh mesh = testing::box_mesh({0, 0, 0}, {3, 2, 1});
  const auto add = [&](const glm::dvec3& a, const glm::dvec3& b,
                       const glm::dvec3& c) {
    const auto n = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), {a, b, c});
    mesh.triangles.push_back({n, n + 1, n + 2});
  };
  for (int i = 0; i < 40; ++i) {
    const double x = 0.1 * i;
    add({x, 0, 1.5}, {x + 0.07, 0.05, 1.5}, {x + 0.02, 0.09, 1.52});
  }
  add({-1, -1, 2}, {4, -0.9, 2.01}, {-1, -0.95, 2});  // a long sliver
  add({0, 3, 0}, {2, 3 + 1e-9, 0}, {4, 3, 1e-12});    // nearly no area
  return mesh;
}

// What the index answers and a scan of every triangle answers, for one
// query of each kind.
struct Answers {
  int within = 0;   // points within r
  int covered = 0;  // triangles abc covered at r
};

// Expects `surface` (of `mesh`) to answer within(a, r) and covers(a, b, c, r)
// as a scan does; counts the answers that were true.
void expect_as_scan(SurfaceDistance& surface, const TriangleMesh& mesh,
                    const glm::dvec3& a, const glm::dvec3& b,
                    const glm::dvec3& c, double r, Answers& answers) {
  const bool within = brute_distance(mesh, a) <= r;
  answers.within += within ? 1 : 0;
  EXPECT_EQ(surface.within(a, r), within) << a.x << " " << r;
  const bool covered = brute_covers(mesh, a, b, c, r);
  answers.covered += covered ? 1 : 0;
  EXPECT_EQ(surface.covers(a, b, c, r), covered) << a.x << " " << r;
}

TEST(SurfaceDistance, AnswersAsAScanOfEveryTriangleDoes) {
  const TriangleMesh mesh = mixed_surface();
  SurfaceDistance surface(mesh);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> x(-1.5, 4.5);
  std::uniform_real_distribution<double> y(-1.5, 3.5);
  std::uniform_real_distribution<double> z(-1.5, 2.5);
  std::uniform_real_distribution<double> jitter(-0.08, 0.08);
  Answers answers;
  for (int i = 0; i < 4000; ++i) {
    const glm::dvec3 p(x(random), y(random), z(random));
    EXPECT_DOUBLE_EQ(surface.distance(p, 100.0),
                     std::min(brute_distance(mesh, p), 100.0));
    for (const double r : {0.05, 0.3, 1.0}) {
      const glm::dvec3 b = p + glm::dvec3(jitter(random), jitter(random), 0);
      const glm::dvec3 c = p + glm::dvec3(0, jitter(random), jitter(random));
      expect_as_scan(surface, mesh, p, b, c, r, answers);
    }
  }
  // The points were not all far from the surface, nor all near it.
  EXPECT_GT(answers.covered, 500);
  EXPECT_LT(answers.covered, 11000);
}

// Runs of nearby queries, as a decimation asks them: points that go back and
// forth over the row of small triangles, each answered by one of the last
// few triangles that answered or by a triangle of its cell.
TEST(SurfaceDistance, AnswersRunsOfNearbyQueriesAsAScanDoes) {
  const TriangleMesh mesh = mixed_surface();
  SurfaceDistance surface(mesh);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> step(-0.25, 0.3);
  std::uniform_real_distribution<double> off(-0.06, 0.06);
  double x = -0.2;
  Answers answers;
  for (int i = 0; i < 3000; ++i) {
    x = std::clamp(x + step(random), -0.3, 4.3);
    const glm::dvec3 p(x, 0.04 + off(random), 1.5 + off(random));
    for (const double r : {0.02, 0.06}) {
      const glm::dvec3 b = p + glm::dvec3(0.03, off(random), 0);
      const glm::dvec3 c = p + glm::dvec3(0, 0.03, off(random));
      expect_as_scan(surface, mesh, p, b, c, r, answers);
    }
  }
  // Both answers came often enough to matter.
  EXPECT_GT(answers.within, 600);
  EXPECT_LT(answers.within, 5400);
  EXPECT_GT(answers.covered, 100);
  EXPECT_LT(answers.covered, 5400);
}

// Triangles across the edges of a box, each first met point by point as a
// decimation meets them: covers_in_two proves some that no one triangle
// covers, and every point of each that it proves lies within the distance
// (a grid of 21 points a side, against a scan).
TEST(SurfaceDistance, CoversInTwoOnlyWhatLiesWithinAcrossACrease) {
  const TriangleMesh mesh = testing::box_mesh({0, 0, 0}, {3, 2, 1});
  SurfaceDistance surface(mesh);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> along(0.2, 2.8);
  std::uniform_real_distribution<double> spread(-0.3, 0.3);
  std::uniform_real_distribution<double> off(-0.04, 0.04);
  int proven = 0;
  int beyond_one = 0;
  for (int i = 0; i < 3000; ++i) {
    // About the box's edge along x at y = 2, z = 1, bent over it.
    const auto bent = [&](double x, double s) {
      return s < 0.0 ? glm::dvec3(x, 2.0 + s, 1.0 + off(random))
                     : glm::dvec3(x, 2.0 + off(random), 1.0 - s);
    };
    const double x = along(random);
    const glm::dvec3 a = bent(x + spread(random), spread(random));
    const glm::dvec3 b = bent(x + spread(random), spread(random));
    const glm::dvec3 c = bent(x + spread(random), spread(random));
    const double r = i % 2 == 0 ? 0.05 : 0.2;
    for (const glm::dvec3& p : {a, b, c}) (void)surface.within(p, r);
    if (!surface.covers_in_two(a, b, c, r)) continue;
    ++proven;
    beyond_one += brute_covers(mesh, a, b, c, r) ? 0 : 1;
    for (int u = 0; u <= 20; ++u) {
      for (int v = 0; u + v <= 20; ++v) {
        const glm::dvec3 p = a + (b - a) * (u / 20.0) + (c - a) * (v / 20.0);
        ASSERT_LE(brute_distance(mesh, p), r) << i << " " << u << " " << v;
      }
    }
  }
  EXPECT_GT(proven, 100);
  EXPECT_GT(beyond_one, 50);
}

TEST(SurfaceDistance, AQuerierSharingTheIndexAnswersTheSame) {
  const TriangleMesh mesh = mixed_surface();
  SurfaceDistance surface(mesh);
  SurfaceDistance other = surface.sharing();
  for (double t = -1.0; t < 4.0; t += 0.01) {
    const glm::dvec3 p(t, 0.5 * t, 1.0 + 0.1 * t);
    EXPECT_EQ(surface.distance(p, 10.0), other.distance(p, 10.0));
    EXPECT_EQ(surface.within(p, 0.05), other.within(p, 0.05));
  }
}

}  // namespace
}  // namespace lsolid
