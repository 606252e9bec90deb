// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/mesh_io.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lsolid/errors.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

namespace fs = std::filesystem;
using testing::box_mesh;

class MeshIo : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("lsolid_io_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
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
  EXPECT_THROW((void)format_for("x.obj"), IoError);
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
  EXPECT_THROW((void)read_mesh(dir_ / "b.stl"), IoError);
  { std::ofstream(dir_ / "x.stl") << "hello"; }
  EXPECT_THROW((void)read_mesh(dir_ / "x.stl"), IoError);
  EXPECT_THROW((void)read_mesh(dir_ / "absent.stl"), IoError);
}

}  // namespace
}  // namespace lsolid
