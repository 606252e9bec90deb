// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/turtle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

namespace lsys {
namespace {

void expect_vec(const glm::dvec3& actual, const glm::dvec3& expected,
                double tolerance = 1e-12) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

void expect_right_handed(const Turtle& t) {
  expect_vec(glm::cross(t.heading(), t.left()), t.up(), 1e-12);
  EXPECT_NEAR(glm::length(t.heading()), 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(t.heading(), t.left()), 0.0, 1e-12);
}

TEST(Turtle, StartsHeadingUpWithLeftAlongMinusXAndUpAlongMinusY) {
  const Turtle t;
  EXPECT_EQ(t.heading(), glm::dvec3(0, 0, 1));
  EXPECT_EQ(t.left(), glm::dvec3(-1, 0, 0));
  EXPECT_EQ(t.up(), glm::dvec3(0, -1, 0));
  expect_right_handed(t);
}

TEST(Turtle, TurnMovesHeadingTowardLeft) {
  Turtle t;
  t.turn(90);
  EXPECT_EQ(t.heading(), glm::dvec3(-1, 0, 0));  // exactly: 90° is exact
  EXPECT_EQ(t.left(), glm::dvec3(0, 0, -1));
  EXPECT_EQ(t.up(), glm::dvec3(0, -1, 0));
  t.turn(-90);
  EXPECT_EQ(t.heading(), glm::dvec3(0, 0, 1));
}

TEST(Turtle, PitchDownMovesHeadingTowardMinusUp) {
  Turtle t;
  t.pitch(90);
  EXPECT_EQ(t.heading(), glm::dvec3(0, 1, 0));  // -U
  EXPECT_EQ(t.up(), glm::dvec3(0, 0, 1));
  EXPECT_EQ(t.left(), glm::dvec3(-1, 0, 0));
}

TEST(Turtle, RollMovesLeftTowardUp) {
  Turtle t;
  t.roll(90);
  EXPECT_EQ(t.left(), glm::dvec3(0, -1, 0));
  EXPECT_EQ(t.up(), glm::dvec3(1, 0, 0));
  EXPECT_EQ(t.heading(), glm::dvec3(0, 0, 1));
}

TEST(Turtle, TurnsAroundAboutUp) {
  Turtle t;
  t.turn_around();
  EXPECT_EQ(t.heading(), glm::dvec3(0, 0, -1));
  EXPECT_EQ(t.left(), glm::dvec3(1, 0, 0));
  EXPECT_EQ(t.up(), glm::dvec3(0, -1, 0));
}

TEST(Turtle, RollToVerticalMakesLeftHorizontal) {
  Turtle t;
  t.pitch(30);
  t.roll(40);
  t.roll_to_vertical();
  EXPECT_NEAR(t.left().z, 0.0, 1e-12);
  EXPECT_GT(t.up().z, 0.0);  // up points to the sky
  expect_right_handed(t);
  const glm::dvec3 heading = t.heading();
  t.roll_to_vertical();
  expect_vec(t.heading(), heading);
  Turtle vertical;  // heading along V: unchanged
  vertical.roll_to_vertical();
  EXPECT_EQ(vertical.left(), glm::dvec3(-1, 0, 0));
}

TEST(Turtle, BendsTowardTheTropismByElasticityTimesSine) {
  Turtle t;
  t.turn(90);  // heading -X, perpendicular to T = -Z
  t.bend(glm::dvec3(0, 0, -1), 0.25);
  // α = e·|H × T| = 0.25 rad toward -Z.
  expect_vec(t.heading(), glm::dvec3(-std::cos(0.25), 0, -std::sin(0.25)));
  expect_right_handed(t);
  Turtle parallel;
  parallel.bend(glm::dvec3(0, 0, 2), 0.5);
  EXPECT_EQ(parallel.heading(), glm::dvec3(0, 0, 1));
}

TEST(Turtle, StaysOrthonormalOverManyRotations) {
  Turtle t;
  for (int i = 0; i < 100000; ++i) {
    t.turn(17.3);
    t.pitch(-5.1);
    t.roll(33.3);
  }
  expect_right_handed(t);
}

TEST(Turtle, MovesAlongHeading) {
  Turtle t;
  t.move(2.5);
  t.turn(90);
  t.move(-1);
  EXPECT_EQ(t.position(), glm::dvec3(1, 0, 2.5));
}

TEST(SinCos, IsExactForQuarterTurns) {
  EXPECT_EQ(sin_cos_deg(90).cos, 0.0);
  EXPECT_EQ(sin_cos_deg(-90).sin, -1.0);
  EXPECT_EQ(sin_cos_deg(180).cos, -1.0);
  EXPECT_EQ(sin_cos_deg(720).sin, 0.0);
  EXPECT_NEAR(sin_cos_deg(30).sin, 0.5, 1e-16);
}

}  // namespace
}  // namespace lsys
