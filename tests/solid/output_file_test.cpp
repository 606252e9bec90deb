// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/output_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "lsolid/errors.hpp"
#include "lsolid/mesh_io.hpp"
#include "support/mesh_checks.hpp"
#include "support/test_dir.hpp"

namespace lsolid {
namespace {

namespace fs = std::filesystem;

class OutputFile : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::make_test_dir("lsolid_out_"); }
  void TearDown() override { fs::remove_all(dir_); }
  // The message output_target refuses `path` with, or "no error".
  static std::string refusal(const fs::path& path) {
    try {
      (void)output_target(path);
    } catch (const IoError& e) {
      return e.what();
    }
    return "no error";
  }
  fs::path dir_;
};

TEST_F(OutputFile, IsThePathItselfForARegularOrNewFile) {
  EXPECT_EQ(output_target(dir_ / "new.stl"), dir_ / "new.stl");
  { std::ofstream(dir_ / "old.stl") << "old"; }
  EXPECT_EQ(output_target(dir_ / "old.stl"), dir_ / "old.stl");
}

TEST_F(OutputFile, FollowsSymbolicLinksToTheirTarget) {
  { std::ofstream(dir_ / "real.stl") << "old"; }
  fs::create_symlink("real.stl", dir_ / "link.stl");
  fs::create_symlink(dir_ / "link.stl", dir_ / "chain.stl");
  EXPECT_EQ(output_target(dir_ / "link.stl"), dir_ / "real.stl");
  EXPECT_EQ(output_target(dir_ / "chain.stl"), dir_ / "real.stl");
  // A link to a file not yet there leads to where it will be.
  fs::create_symlink("later.stl", dir_ / "dangling.stl");
  EXPECT_EQ(output_target(dir_ / "dangling.stl"), dir_ / "later.stl");
}

TEST_F(OutputFile, RefusesEverythingButRegularFiles) {
  // Each was replaced by a regular file.
  ASSERT_EQ(::mkfifo((dir_ / "fifo.stl").c_str(), 0644), 0);
  fs::create_directory(dir_ / "folder.stl");
  fs::create_symlink("/dev/null", dir_ / "null.stl");
  fs::create_symlink("a.stl", dir_ / "b.stl");
  fs::create_symlink("b.stl", dir_ / "a.stl");
  EXPECT_EQ(refusal(dir_ / "fifo.stl"),
            "'" + (dir_ / "fifo.stl").string() +
                "' is a FIFO (named pipe); lsolid writes only regular files");
  EXPECT_EQ(refusal(dir_ / "folder.stl"),
            "'" + (dir_ / "folder.stl").string() +
                "' is a directory; lsolid writes only regular files");
  EXPECT_EQ(refusal(dir_ / "null.stl"),
            "'" + (dir_ / "null.stl").string() +
                "' is a link to a device; lsolid writes only regular files");
  EXPECT_EQ(refusal(dir_ / "a.stl"),
            "'" + (dir_ / "a.stl").string() +
                "' is a symbolic link in a loop; lsolid writes only regular "
                "files");
}

TEST_F(OutputFile, WritingThroughALinkKeepsTheLinkAndReplacesItsTarget) {
  { std::ofstream(dir_ / "real.stl") << "old"; }
  fs::create_symlink("real.stl", dir_ / "link.stl");
  write_mesh(testing::box_mesh({0, 0, 0}, {1, 1, 1}), dir_ / "link.stl",
             MeshFormat::StlBinary);
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.stl"));
  EXPECT_EQ(read_mesh(dir_ / "real.stl").triangles.size(), 12U);
  // A FIFO is refused by the write itself too, and left a FIFO.
  ASSERT_EQ(::mkfifo((dir_ / "fifo.stl").c_str(), 0644), 0);
  EXPECT_THROW(write_mesh(testing::box_mesh({0, 0, 0}, {1, 1, 1}),
                          dir_ / "fifo.stl", MeshFormat::StlBinary),
               IoError);
  EXPECT_TRUE(fs::is_fifo(dir_ / "fifo.stl"));
}

}  // namespace
}  // namespace lsolid
