// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <glm/geometric.hpp>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lsys/derivation.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/interpretation.hpp"
#include "lsys/parser.hpp"

namespace lsys::testing {

/// The checkout's root, for printables/ and tests/data/.
inline std::filesystem::path source_dir() { return LSOLID_SOURCE_DIR; }

/// Parses `.ls` text named `test.ls`.
inline Grammar parse(std::string_view text, ParseOptions options = {}) {
  return parse_grammar_text(text, options, "test.ls");
}

/// Parses a file of the checkout (relative to its root).
inline Grammar parse_file(const std::string& relative,
                          ParseOptions options = {}) {
  return parse_grammar(load_source(source_dir() / relative), options);
}

/// The derived string of `.ls` text after n steps (the file's n if none).
inline std::string derived(std::string_view text,
                           std::optional<int> n = std::nullopt) {
  const Grammar g = parse(text);
  return to_string(derive(g, {.derivation_length = n}), g.alphabet);
}

/// The error message (without location) that parsing `.ls` text raises, or
/// "no error".
inline std::string parse_error(std::string_view text) {
  try {
    (void)parse(text);
  } catch (const ParseError& e) {
    return e.diagnostic().message;
  }
  return "no error";
}

/// `line:column: message` of what `work` raises, or "no error".
template <typename Work>
std::string located_error_of(const Work& work) {
  try {
    work();
  } catch (const ParseError& e) {
    const Diagnostic& d = e.diagnostic();
    return std::to_string(d.line) + ":" + std::to_string(d.column) + ": " +
           d.message;
  }
  return "no error";
}

/// The full diagnostic `line:column: message` that parsing raises.
inline std::string located_error(std::string_view text) {
  return located_error_of([&] { (void)parse(text); });
}

/// A notation lsolid reads, with the name its files carry, for the tests of
/// its front end: parse, derive and refuse text as that notation.
struct Notation {
  Dialect dialect = Dialect::Ls;
  const char* file = "test.ls";

  /// The text parsed as a file of this notation.
  [[nodiscard]] Grammar parse(std::string_view text,
                              ParseOptions options = {}) const {
    options.dialect = dialect;
    return parse_grammar_text(text, options, file);
  }
  /// The text's derived string (the file's n).
  [[nodiscard]] std::string derived(std::string_view text) const {
    const Grammar g = parse(text);
    return to_string(derive(g), g.alphabet);
  }
  /// `line:column: message` of the error parsing the text raises, or "no
  /// error".
  [[nodiscard]] std::string error(std::string_view text) const {
    return located_error_of([&] { (void)parse(text); });
  }
};

/// The numbers cpfg's `ran()`, L-Py's `random()` and lpfg's `ran()` draw in
/// lsolid, in order: POSIX's drand48 sequence from srand48(0) (the 48-bit
/// recurrence x ← 0x5DEECE66D·x + 11 mod 2⁴⁸ from x = 0x330E, x/2⁴⁸),
/// written here from the standard, apart from lsolid's own code, so that
/// counts of random outcomes can be checked against it.
inline std::vector<double> drand48_sequence(std::size_t count) {
  std::vector<double> out;
  std::uint64_t x = 0x330E;
  for (std::size_t i = 0; i < count; ++i) {
    x = (0x5DEECE66DULL * x + 0xBULL) % (std::uint64_t{1} << 48U);
    out.push_back(static_cast<double>(x) / static_cast<double>(1ULL << 48U));
  }
  return out;
}

/// Expects two points to agree to 10⁻⁹.
inline void expect_near(const glm::dvec3& actual, const glm::dvec3& expected) {
  EXPECT_LT(glm::length(actual - expected), 1e-9)
      << actual.x << ", " << actual.y << ", " << actual.z;
}

/// Expects `disc` to be the polygon of a disc of `diameter` about `center`
/// across `normal` (a unit vector): its corners in that plane, all at the
/// same distance, whose sides touch the circle.
inline void expect_disc(const Polygon& disc, const glm::dvec3& center,
                        const glm::dvec3& normal, double diameter) {
  ASSERT_GE(disc.points.size(), 3U);
  const double corner =
      diameter / 2.0 /
      std::cos(std::numbers::pi / static_cast<double>(disc.points.size()));
  for (const glm::dvec3& p : disc.points) {
    EXPECT_NEAR(glm::dot(p - center, normal), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(p - center), corner, 1e-12);
  }
}

}  // namespace lsys::testing
