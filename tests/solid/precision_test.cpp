// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// What each file format keeps of a coordinate, and the mesh a reader of it
// gets: lsolid checks that mesh, so a file it calls printable stays
// printable as its readers read it (lib3mf writes six decimals, OpenSCAD
// exports six significant digits).
#include "lsolid/precision.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>

#include "lsolid/mesh_io.hpp"
#include "lsolid/rounding.hpp"
#include "lsolid/validate.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

// A number as a writer of `digits` significant digits (%g) or decimals
// (%f) writes it, read back as a double and as a float.
double written(double x, const char* format) {
  char text[64];
  std::snprintf(text, sizeof(text), format, x);
  return std::strtod(text, nullptr);
}
double as_float(double x) { return static_cast<double>(static_cast<float>(x)); }

TEST(Precision, RoundsToFloatsAndMergesVerticesThatMeet) {
  TriangleMesh m;
  m.vertices = {{0.1, 0, 0}, {0.1 + 1e-12, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 2, 3}, {1, 3, 2}};
  const TriangleMesh r = snapped(m, {.kind = Precision::Kind::Float});
  EXPECT_EQ(r.vertices.size(), 3U);
  EXPECT_EQ(r.vertices[0].x, static_cast<double>(0.1F));
  EXPECT_EQ(r.triangles[1][0], 0U);
}

TEST(Precision, ChoosesWhatEachFormatKeeps) {
  EXPECT_EQ(precision_for(MeshFormat::StlBinary, 100).kind,
            Precision::Kind::Float);
  EXPECT_EQ(precision_for(MeshFormat::StlAscii, 100).kind,
            Precision::Kind::Float);
  EXPECT_EQ(precision_for(MeshFormat::Off, 100).kind, Precision::Kind::Double);
  EXPECT_EQ(precision_for(MeshFormat::Obj, 100).kind, Precision::Kind::Double);
  const Precision threemf = precision_for(MeshFormat::ThreeMf, 100);
  EXPECT_EQ(threemf.kind, Precision::Kind::SixDecimals);
  EXPECT_TRUE(threemf.also_as_floats());
  EXPECT_FALSE(precision_for(MeshFormat::Scad, 100).also_as_floats());
  // Six significant digits: four decimals below 100 mm, three below 1 m.
  EXPECT_EQ(precision_for(MeshFormat::Scad, 99.9).step_mm, 1e-4);
  EXPECT_EQ(precision_for(MeshFormat::Scad, 100.0).step_mm, 1e-3);
  EXPECT_EQ(precision_for(MeshFormat::Scad, 999.0).step_mm, 1e-3);
  EXPECT_EQ(precision_for(MeshFormat::Scad, 1500.0).step_mm, 1e-2);
}

// A 3MF coordinate is six decimals that lib3mf, fed its float, writes as
// themselves: a reader of doubles gets them, one of floats their float.
TEST(Precision, A3mfCoordinateIsWhatLib3mfWritesOfItsFloat) {
  const Precision p = precision_for(MeshFormat::ThreeMf, 300.0);
  for (double x = -299.0; x < 299.0; x += 0.0731) {
    const double s = p.snap(x);
    EXPECT_LE(std::fabs(s - x), 1e-4) << x;
    EXPECT_EQ(p.snap(s), s);
    EXPECT_EQ(written(s, "%.6f"), s) << x;  // six decimals
  }
}

// What lib3mf writes of a mesh snapped for a 3MF is that mesh to the last
// digit (the emulation of its writer is checked against the writer).
TEST(Precision, Lib3mfWritesA3mfMeshAsItWasChecked) {
  TriangleMesh m;
  for (int i = 0; i < 3000; ++i) {
    const double t = 0.37 * i;
    m.vertices.push_back({-150.0 + 0.1 * t + 1e-7 * i, 17.3 * std::sin(t),
                          3.0 * std::cos(t) + 1.00000049});
  }
  for (std::uint32_t i = 0; i + 2 < 3000; i += 3) {
    m.triangles.push_back({i, i + 1, i + 2});
  }
  const Precision p = precision_for(MeshFormat::ThreeMf, 200.0);
  const TriangleMesh s = snapped(m, p);
  const auto dir = std::filesystem::temp_directory_path() /
                   ("lsolid_precision_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  write_mesh(s, dir / "m.3mf", MeshFormat::ThreeMf);
  const auto text =
      testing::run_command("unzip -p m.3mf 3D/3dmodel.model", dir).out;
  std::filesystem::remove_all(dir);
  const std::regex vertex(R"re(<vertex x="([^"]+)" y="([^"]+)" z="([^"]+)")re");
  std::size_t i = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), vertex);
       it != std::sregex_iterator(); ++it, ++i) {
    ASSERT_LT(i, s.vertices.size());
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(std::strtod((*it)[k + 1].str().c_str(), nullptr),
                s.vertices[i][k])
          << (*it)[k + 1].str();
    }
  }
  EXPECT_EQ(i, s.vertices.size());
}

// A `.scad` coordinate is a float that OpenSCAD reads exactly (as a
// double, from the shortest text), exports with six significant digits,
// and a slicer reads back as the same float.
TEST(Precision, AnOpenScadCoordinateSurvivesOpenScadsExport) {
  for (const double reach : {40.0, 300.0}) {
    const Precision p = precision_for(MeshFormat::Scad, reach);
    for (double x = -reach; x < reach; x += 0.3779) {
      const double s = p.snap(x);
      EXPECT_LE(std::fabs(s - x), p.step_mm) << x;
      EXPECT_EQ(p.snap(s), s);
      EXPECT_EQ(as_float(s), s);
      char shortest[32];
      *std::to_chars(shortest, shortest + 31, s).ptr = '\0';
      const double read = std::strtod(shortest, nullptr);
      EXPECT_EQ(read, s) << shortest;
      const double exported = written(read, "%.6g");
      EXPECT_NEAR(exported, s, p.step_mm / 20.0) << x;
      EXPECT_EQ(as_float(exported), s) << x;
    }
  }
}

TEST(Precision, RoundsForAFormatAndKeepsTheMeshPrintable) {
  // A box off every grid: snapped alone it stays printable, its triangles
  // in their order.
  const TriangleMesh box =
      testing::box_mesh({0.01, 0.02, 0.03}, {10.111, 20.222, 30.333});
  for (const MeshFormat format :
       {MeshFormat::StlBinary, MeshFormat::ThreeMf, MeshFormat::Scad}) {
    const auto rounded = rounded_for(box, format);
    ASSERT_TRUE(rounded);
    EXPECT_EQ(rounded->triangles, box.triangles);
    const Precision p = precision_for(format, 1.25 * reach_mm(box));
    for (const glm::dvec3& v : rounded->vertices) EXPECT_EQ(p.snap(v), v);
    EXPECT_TRUE(validate(*rounded).is_printable());
  }
  // Colours stay with their triangles.
  std::vector<int> colors(box.triangles.size());
  for (std::size_t t = 0; t < colors.size(); ++t) colors[t] = int(t % 3);
  const auto colored = rounded_for(ColoredMesh{.mesh = box, .colors = colors},
                                   MeshFormat::ThreeMf);
  ASSERT_TRUE(colored);
  EXPECT_EQ(colored->colors, colors);
  // A box thinner than six significant digits keep at 50 mm has no volume
  // left there: a `.scad` of it keeps floats; a 3MF (six decimals) keeps
  // it.
  const TriangleMesh sliver =
      testing::box_mesh({0.0, 0.0, 50.0}, {10.0, 10.0, 50.00004});
  const auto scad = rounded_for(sliver, MeshFormat::Scad);
  ASSERT_TRUE(scad);
  for (const glm::dvec3& v : scad->vertices) {
    EXPECT_EQ(precision_for(MeshFormat::StlBinary, 50).snap(v), v);
  }
  EXPECT_TRUE(validate(*scad).is_printable());
  EXPECT_TRUE(rounded_for(sliver, MeshFormat::ThreeMf));
}

}  // namespace
}  // namespace lsolid
