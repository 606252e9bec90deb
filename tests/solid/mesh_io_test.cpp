// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/mesh_io.hpp"

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "lsolid/errors.hpp"
#include "lsys/diagnostic.hpp"
#include "support/mesh_checks.hpp"
#include "support/test_dir.hpp"

namespace lsolid {
namespace {

namespace fs = std::filesystem;
using testing::box_mesh;

class MeshIo : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::make_test_dir("lsolid_io_"); }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(MeshIo, RoundTripsEveryFormat) {
  const TriangleMesh box = box_mesh({0, 0, 0}, {1, 2, 3.5});
  for (const auto& [name, format] : {std::pair{"b.stl", MeshFormat::StlBinary},
                                     std::pair{"a.stl", MeshFormat::StlAscii},
                                     std::pair{"o.off", MeshFormat::Off}}) {
    write_mesh(box, dir_ / name, format);
    const TriangleMesh back = read_mesh(dir_ / name);
    EXPECT_EQ(back.vertices.size(), 8U) << name;
    EXPECT_EQ(back.triangles.size(), 12U) << name;
    EXPECT_DOUBLE_EQ(signed_volume(back), 7.0) << name;
  }
  EXPECT_EQ(fs::file_size(dir_ / "b.stl"), 84U + 50U * 12U);
}

TEST_F(MeshIo, ChoosesTheFormatByExtension) {
  EXPECT_EQ(format_for("x.STL"), MeshFormat::StlBinary);
  EXPECT_EQ(format_for("x.stl", true), MeshFormat::StlAscii);
  EXPECT_EQ(format_for("x.off"), MeshFormat::Off);
  EXPECT_EQ(format_for("x.3MF"), MeshFormat::ThreeMf);
  EXPECT_EQ(format_for("x.obj"), MeshFormat::Obj);
  EXPECT_THROW((void)format_for("x.ply"), IoError);
}

TEST_F(MeshIo, WritesAnOpenScadModuleWithClockwiseFaces) {
  const TriangleMesh box = box_mesh({0, 0, 0}, {1, 2, 3.5});
  EXPECT_EQ(format_for("x.scad"), MeshFormat::Scad);
  write_mesh(box, dir_ / "3d-box.scad", MeshFormat::Scad);
  std::ifstream in(dir_ / "3d-box.scad");
  const std::string text((std::istreambuf_iterator<char>(in)),
                         std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("module lsolid_3d_box() {\n  polyhedron(points = [\n"),
            std::string::npos);
  EXPECT_NE(text.find("    [1, 0, 0],\n"), std::string::npos);
  EXPECT_NE(text.find("    [1, 2, 3.5]\n  ], faces"), std::string::npos);
  EXPECT_EQ(text.substr(text.size() - 17), "lsolid_3d_box();\n");
  // The faces, read back, are ours with the last two points swapped.
  const std::size_t faces = text.find("faces = [\n");
  ASSERT_NE(faces, std::string::npos);
  std::istringstream list(text.substr(faces + 10));
  for (const auto& t : box.triangles) {
    char open = 0, comma = 0;
    std::uint32_t a = 0, b = 0, c = 0;
    list >> open >> a >> comma >> b >> comma >> c;
    EXPECT_EQ(open, '[');
    EXPECT_EQ((std::array<std::uint32_t, 3>{a, c, b}), t);
    list.ignore(4, '\n');
  }
}

TEST_F(MeshIo, LeavesNothingBehindWhenWritingFails) {
  const fs::path target = dir_ / "missing-folder" / "x.stl";
  EXPECT_THROW(
      write_mesh(box_mesh({0, 0, 0}, {1, 1, 1}), target, MeshFormat::StlBinary),
      IoError);
  EXPECT_FALSE(fs::exists(target));
}

TEST_F(MeshIo, ReplacesAnExistingFileOnlyWhenComplete) {
  const fs::path target = dir_ / "x.off";
  { std::ofstream(target) << "old"; }
  write_mesh(box_mesh({0, 0, 0}, {1, 1, 1}), target, MeshFormat::Off);
  EXPECT_EQ(read_mesh(target).triangles.size(), 12U);
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir_)) ++entries;
  EXPECT_EQ(entries, 1U);  // no temporary left
}

TEST_F(MeshIo, RejectsTruncatedAndForeignFiles) {
  write_mesh(box_mesh({0, 0, 0}, {1, 1, 1}), dir_ / "b.stl",
             MeshFormat::StlBinary);
  fs::resize_file(dir_ / "b.stl", 100);
  // Malformed content is bad input; a file that cannot be read, I/O.
  EXPECT_THROW((void)read_mesh(dir_ / "b.stl"), lsys::ParseError);
  { std::ofstream(dir_ / "x.stl") << "hello"; }
  EXPECT_THROW((void)read_mesh(dir_ / "x.stl"), lsys::ParseError);
  EXPECT_THROW((void)read_mesh(dir_ / "absent.stl"), IoError);
}

// What read_mesh says of a file of this text: the formatted diagnostic of
// malformed content, the message of an I/O error, or "no error".
std::string read_error(const fs::path& path, const std::string& text) {
  { std::ofstream(path, std::ios::binary) << text; }
  try {
    (void)read_mesh(path);
  } catch (const lsys::ParseError& e) {
    return lsys::format_diagnostic(e.diagnostic());
  } catch (const IoError& e) {
    return e.what();
  }
  return "no error";
}

TEST_F(MeshIo, ReadsAsciiStlByItsGrammarAndPlacesAMistake) {
  const fs::path stl = dir_ / "a.stl";
  const std::string name = stl.string();
  const std::string facet =
      "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n"
      "  vertex 0 1 0\n endloop\nendfacet\n";
  // Nonsense after `solid` was read as a mesh of no triangles.
  EXPECT_EQ(read_error(stl, "solid x\nnonsense here\n"),
            name +
                ":2:1: error: expected 'facet' or 'endsolid', not "
                "'nonsense'\nnonsense here\n^\n");
  EXPECT_EQ(read_error(stl, "solid x\n" + facet),
            name +
                ": error: the file ends where 'facet' or 'endsolid' "
                "should follow\n");
  EXPECT_EQ(read_error(stl,
                       "solid x\nfacet normal 0 0 1\nouter loop\nvertex "
                       "0 nan 0\n"),
            name +
                ":4:10: error: expected a finite number, not 'nan'\n"
                "vertex 0 nan 0\n         ^\n");
  EXPECT_EQ(read_error(stl,
                       "solid x\nfacet normal 0 0 1\nouter loop\nvertex "
                       "0 0 0\nvertex 1 0 0\nendloop\n"),
            name +
                ":6:1: error: expected 'vertex', not 'endloop'\n"
                "endloop\n^\n");
  // Several solids, and normals some exporters write as nan, are fine.
  EXPECT_EQ(read_error(stl, "solid a\n" + facet + "endsolid a\nsolid b\n" +
                                facet + "endsolid\n"),
            "no error");
  EXPECT_EQ(read_mesh(stl).triangles.size(), 2U);
}

TEST_F(MeshIo, RefusesOffCountsTheFileCannotHold) {
  const fs::path off = dir_ / "x.off";
  const std::string name = off.string();
  // These allocated 10^11 vertices (bad_alloc) or wrapped -1 to 2^64-1.
  EXPECT_EQ(read_error(off, "OFF\n99999999999 1 0\n"),
            name +
                ":2:1: error: 99999999999 vertices do not fit in a file of "
                "20 bytes\n99999999999 1 0\n^\n");
  EXPECT_EQ(read_error(off, "OFF\n-1 1 0\n"),
            name +
                ":2:1: error: expected the number of vertices, not '-1'\n-1 1 "
                "0\n^\n");
  EXPECT_EQ(read_error(off, "COFF\n3 1 0\n"),
            name + ":1:1: error: expected 'OFF', not 'COFF'\nCOFF\n^\n");
  EXPECT_EQ(read_error(off, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
            name +
                ":6:7: error: no vertex 7: the file has 3\n3 0 1 7\n      "
                "^\n");
}

TEST_F(MeshIo, RefusesADamagedBinaryStlAndFilesThatAreNotRegular) {
  const fs::path stl = dir_ / "b.stl";
  std::string binary(84, '\0');
  binary.replace(0, 5, "solid");  // as many exporters write the header
  binary[80] = 2;
  binary += std::string(50, '\0');
  EXPECT_EQ(read_error(stl, binary),
            stl.string() +
                ": error: a damaged binary STL: its header counts 2 triangles "
                "(184 bytes), the file has 134 bytes\n");
  // A device would never end.
  try {
    (void)read_mesh("/dev/zero");
    ADD_FAILURE() << "no error";
  } catch (const IoError& e) {
    EXPECT_STREQ(e.what(), "/dev/zero: cannot read: not a regular file");
  }
}

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST_F(MeshIo, Writes3mfInMillimetresWithAColourPerTriangle) {
  ColoredMesh box{.mesh = box_mesh({0, 0, 0}, {1, 2, 3.5}), .colors = {}};
  for (std::size_t t = 0; t < 12; ++t) box.colors.push_back(t < 6 ? 0 : 3);
  write_colored({box}, dir_ / "box.3mf", MeshFormat::ThreeMf);
  const std::vector<ColoredMesh> back = read_colored(dir_ / "box.3mf");
  ASSERT_EQ(back.size(), 1U);
  EXPECT_EQ(back[0].mesh.vertices.size(), 8U);
  ASSERT_EQ(back[0].mesh.triangles.size(), 12U);
  EXPECT_EQ(back[0].colors, box.colors);
  EXPECT_EQ(back[0].mesh.triangles, box.mesh.triangles);
  EXPECT_DOUBLE_EQ(signed_volume(back[0].mesh), 7.0);
  EXPECT_DOUBLE_EQ(bounds(back[0].mesh).max.z, 3.5);  // millimetres
  EXPECT_DOUBLE_EQ(signed_volume(read_mesh(dir_ / "box.3mf")), 7.0);
  // The package is a ZIP.
  const std::string bytes = read_all(dir_ / "box.3mf");
  EXPECT_EQ(bytes.substr(0, 2), "PK");
}

TEST_F(MeshIo, Writes3mfVolumesThatReadBackApart) {
  const ColoredMesh stem{.mesh = box_mesh({0, 0, 0}, {1, 1, 4}),
                         .colors = std::vector<int>(12, 0)};
  const ColoredMesh leaf{.mesh = box_mesh({1, 0, 3}, {3, 1, 3.5}),
                         .colors = std::vector<int>(12, 4)};
  write_colored({stem, leaf}, dir_ / "two.3mf", MeshFormat::ThreeMf);
  const std::vector<ColoredMesh> back = read_colored(dir_ / "two.3mf");
  ASSERT_EQ(back.size(), 2U);
  EXPECT_EQ(back[0].colors, stem.colors);
  EXPECT_EQ(back[1].colors, leaf.colors);
  EXPECT_DOUBLE_EQ(signed_volume(back[0].mesh), 4.0);
  EXPECT_DOUBLE_EQ(signed_volume(back[1].mesh), 1.0);
  EXPECT_EQ(back[1].mesh.vertices.size(), 8U);
}

TEST_F(MeshIo, WritesObjWithAMaterialFileOfTheColours) {
  const ColoredMesh stem{.mesh = box_mesh({0, 0, 0}, {1, 1, 4}),
                         .colors = std::vector<int>(12, 0)};
  // 3.1 is no float: OBJ keeps doubles, as OFF does.
  const ColoredMesh leaf{.mesh = box_mesh({1, 0, 3}, {3, 1, 3.1}),
                         .colors = std::vector<int>(12, 3)};
  write_colored({stem, leaf}, dir_ / "two.obj", MeshFormat::Obj);
  const std::string obj = read_all(dir_ / "two.obj");
  EXPECT_NE(obj.find("mtllib two.mtl\n"), std::string::npos);
  EXPECT_NE(obj.find("usemtl colour_3\n"), std::string::npos);
  const std::string mtl = read_all(dir_ / "two.mtl");
  // #8CC63F, colour 3's leaf green, as fractions of 255.
  EXPECT_NE(mtl.find("newmtl colour_3\nKa 0 0 0\nKd 0.54902 0.776471 "
                     "0.247059\n"),
            std::string::npos)
      << mtl;
  const std::vector<ColoredMesh> back = read_colored(dir_ / "two.obj");
  ASSERT_EQ(back.size(), 2U);
  EXPECT_EQ(back[1].colors, leaf.colors);
  EXPECT_EQ(bounds(back[1].mesh).max.z, 3.1);
  EXPECT_NEAR(signed_volume(read_mesh(dir_ / "two.obj")), 4.2, 1e-12);
}

TEST_F(MeshIo, RefusesABrokenObjWithItsLine) {
  { std::ofstream(dir_ / "bad.obj") << "v 0 0 0\nv 1 0 0\nf 1 2 3\n"; }
  try {
    (void)read_mesh(dir_ / "bad.obj");
    FAIL() << "no error";
  } catch (const lsys::ParseError& e) {
    EXPECT_EQ(e.diagnostic().line, 3);
    EXPECT_EQ(e.diagnostic().column, 1);
    EXPECT_EQ(e.diagnostic().message, "a face names a missing vertex");
    EXPECT_EQ(e.diagnostic().source_line, "f 1 2 3");
  }
}

}  // namespace
}  // namespace lsolid
