// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

namespace lsolid {

/// The golden ratio's conjugate, (√5 − 1) / 2. Its multiples modulo 1 never
/// repeat and spread evenly, so the ring phase of the n-th tube or sphere
/// (n · kGolden of a step) keeps neighbouring parts' seams apart; and a
/// shift along (1, kGolden, 1 − kGolden) lies along no axis or diagonal
/// (the union's retries, to three digits).
inline constexpr double kGolden = 0.6180339887498949;

}  // namespace lsolid
