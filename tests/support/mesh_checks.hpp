// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <regex>
#include <string>

#include "lsolid/mesh.hpp"
#include "lsolid/validate.hpp"
#include "support/run_command.hpp"

namespace lsolid::testing {

/// An axis-aligned box as a closed, outward mesh.
inline TriangleMesh box_mesh(const glm::dvec3& lo, const glm::dvec3& hi) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) {
    m.vertices.push_back(
        {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
  }
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},
                 {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},
                 {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

/// A box from `lo` to `hi` with a sealed box-shaped cavity from `cavity_lo`
/// to `cavity_hi`: a second shell, facing inward.
inline TriangleMesh box_with_cavity(const glm::dvec3& lo, const glm::dvec3& hi,
                                    const glm::dvec3& cavity_lo,
                                    const glm::dvec3& cavity_hi) {
  TriangleMesh mesh = box_mesh(lo, hi);
  TriangleMesh cavity = box_mesh(cavity_lo, cavity_hi);
  for (auto& t : cavity.triangles) std::swap(t[1], t[2]);
  append(mesh, cavity);
  return mesh;
}

/// Asserts what a slicer needs: closed, manifold, outward, no
/// self-intersections, positive volume; and the number of shells.
inline void expect_printable(const TriangleMesh& mesh, std::size_t shells = 1) {
  const ValidationReport r = validate(mesh);
  EXPECT_TRUE(r.is_printable()) << [&] {
    std::string all;
    for (const std::string& p : r.problems()) all += p + "; ";
    return all;
  }();
  EXPECT_EQ(r.shells, shells);
}

/// What admesh (an independent checker) says of an STL file.
struct AdmeshOpinion {
  int parts = -1;
  int degenerate = -1;
  int edges_fixed = -1;
  int facets_removed = -1;
  int facets_added = -1;
  int facets_reversed = -1;
  int backwards_edges = -1;
  int normals_fixed = -1;
  double volume = 0.0;
};

inline AdmeshOpinion admesh(const std::filesystem::path& stl) {
  const CommandResult r = run_command("admesh '" + stl.string() + "'");
  AdmeshOpinion o;
  const auto number = [&](const char* label) {
    const std::regex pattern(std::string(label) + R"(\s*:\s*(-?[0-9.e+]+))");
    std::smatch m;
    return std::regex_search(r.out, m, pattern) ? std::stod(m[1]) : -1.0;
  };
  o.parts = static_cast<int>(number("Number of parts"));
  o.degenerate = static_cast<int>(number("Degenerate facets"));
  o.edges_fixed = static_cast<int>(number("Edges fixed"));
  o.facets_removed = static_cast<int>(number("Facets removed"));
  o.facets_added = static_cast<int>(number("Facets added"));
  o.facets_reversed = static_cast<int>(number("Facets reversed"));
  o.backwards_edges = static_cast<int>(number("Backwards edges"));
  o.normals_fixed = static_cast<int>(number("Normals fixed"));
  o.volume = number("Volume");
  return o;
}

/// admesh fixes nothing and counts one part.
inline void expect_admesh_agrees(const std::filesystem::path& stl,
                                 int parts = 1) {
  const AdmeshOpinion o = admesh(stl);
  EXPECT_EQ(o.parts, parts);
  EXPECT_EQ(o.degenerate, 0);
  EXPECT_EQ(o.edges_fixed, 0);
  EXPECT_EQ(o.facets_removed, 0);
  EXPECT_EQ(o.facets_added, 0);
  EXPECT_EQ(o.facets_reversed, 0);
  EXPECT_EQ(o.backwards_edges, 0);
  EXPECT_EQ(o.normals_fixed, 0);
}

}  // namespace lsolid::testing
