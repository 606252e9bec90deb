// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Fuzzes the readers of every notation with derivation and turtle under small
// limits. Bad input must end in lsys::ParseError; anything else (a crash, a
// sanitizer report, another exception, or a skeleton that breaks its
// invariants) is a finding.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "lsys/derivation.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/interpretation.hpp"
#include "lsys/module_string.hpp"
#include "lsys/parser.hpp"

namespace {

bool finite(const glm::dvec3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// The skeleton's documented invariants (skeleton.hpp).
void check(const lsys::Skeleton& skeleton) {
  for (const lsys::Segment& s : skeleton.segments) {
    if (!finite(s.p0) || !finite(s.p1) || !(s.start_diameter >= 0.0) ||
        !(s.end_diameter >= 0.0) || s.p0 == s.p1) {
      std::abort();
    }
    if (s.parent >= static_cast<std::int32_t>(skeleton.segments.size())) {
      std::abort();
    }
  }
  for (const lsys::Polygon& p : skeleton.polygons) {
    if (p.points.size() < 3) std::abort();
    for (const glm::dvec3& q : p.points) {
      if (!finite(q)) std::abort();
    }
  }
  for (const lsys::Sphere& b : skeleton.spheres) {
    if (!finite(b.center) || !(b.diameter >= 0.0)) std::abort();
  }
  for (const lsys::Sheet& sheet : skeleton.sheets) {
    if (sheet.triangles.empty()) std::abort();
    for (const glm::dvec3& q : sheet.points) {
      if (!finite(q)) std::abort();
    }
    for (const auto& t : sheet.triangles) {
      for (const std::uint32_t i : t) {
        if (i >= sheet.points.size()) std::abort();
      }
      if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) std::abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data,
                                      std::size_t size) {
  if (size > 8192) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const lsys::DerivationOptions limits{.max_segments = 20'000,
                                       .max_modules = 200'000,
                                       .max_memory_bytes = 64U << 20U};
  // The file's name decides some notations (a `.ls` is never cpfg or
  // Fractint, only a `.lpy` is L-Py): vary it so that every front end is
  // reached.
  static constexpr const char* kNames[] = {"fuzz.ls", "fuzz.l", "fuzz.lpy"};
  try {
    const lsys::Grammar grammar = lsys::parse_grammar_text(
        text,
        {.extra_settings = {"wall", "height", "size", "scale", "tolerance",
                            "base", "colors"}},
        kNames[size % 3]);
    lsys::DerivationOptions options = limits;
    // Deep derivations of tiny strings take long without finding more.
    options.derivation_length =
        std::min(grammar.settings.derivation_length, 12);
    const lsys::ModuleString derived = lsys::derive(grammar, options);
    (void)lsys::to_string(derived, grammar.alphabet);
    check(lsys::interpret(grammar, options, {}));
  } catch (const lsys::ParseError& e) {
    // The message is what a maker reads: it must format.
    (void)lsys::format_diagnostic(e.diagnostic());
  }
  return 0;
}
