// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/random.hpp"

#include <gtest/gtest.h>

namespace lsys {
namespace {

TEST(Random, SplitMix64MatchesTheReferenceOutput) {
  // The first output of Vigna's splitmix64.c with state 0.
  EXPECT_EQ(splitmix64(0), 0xE220A8397B1DCDAFULL);
  static_assert(splitmix64(0) == 0xE220A8397B1DCDAFULL);
}

TEST(Random, UniformIsInTheUnitIntervalAndDependsOnEveryKey) {
  const double u = stochastic_uniform(1, 2, 3);
  EXPECT_GE(u, 0.0);
  EXPECT_LT(u, 1.0);
  EXPECT_NE(u, stochastic_uniform(2, 2, 3));
  EXPECT_NE(u, stochastic_uniform(1, 3, 3));
  EXPECT_NE(u, stochastic_uniform(1, 2, 4));
  EXPECT_EQ(u, stochastic_uniform(1, 2, 3));
}

TEST(Random, UniformHasTheMeanOfAUniformVariable) {
  double sum = 0.0;
  constexpr int kCount = 100000;
  for (int i = 0; i < kCount; ++i) sum += stochastic_uniform(42, 0, i);
  EXPECT_NEAR(sum / kCount, 0.5, 0.005);
}

}  // namespace
}  // namespace lsys
