// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/preview.hpp"

#include <gtest/gtest.h>
#include <png.h>

#include <filesystem>
#include <set>

#include "lsolid/errors.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::box_mesh;

bool is_background(const glm::ivec3& c) {
  return c == glm::ivec3(242, 242, 242);  // 0.95 of 255, rounded
}

TEST(Preview, DrawsTheModelShadedOnAPlainBackground) {
  const Image image = render_preview(box_mesh({0, 0, 0}, {10, 10, 10}),
                                     {.width_px = 160, .height_px = 120});
  ASSERT_EQ(image.width, 160);
  ASSERT_EQ(image.height, 120);
  ASSERT_EQ(image.rgb.size(), 160U * 120U * 3U);
  EXPECT_TRUE(is_background(image.at(0, 0)));
  EXPECT_TRUE(is_background(image.at(159, 119)));
  // The cube fills the middle; a three-quarter view from above shows the
  // top and two sides, each in its own shade.
  EXPECT_FALSE(is_background(image.at(80, 60)));
  const glm::ivec3 top = image.at(80, 25);
  const glm::ivec3 left = image.at(60, 80);
  const glm::ivec3 right = image.at(100, 80);
  std::set<int> reds{top.r, left.r, right.r};
  EXPECT_EQ(reds.size(), 3U) << top.r << " " << left.r << " " << right.r;
  for (const glm::ivec3& c : {top, left, right}) {
    EXPECT_FALSE(is_background(c));
    EXPECT_GT(c.r, c.b);  // the model's warm colour
  }
}

TEST(Preview, DrawsEachTriangleInItsColour) {
  const TriangleMesh box = box_mesh({0, 0, 0}, {10, 10, 10});
  // The box's lower half of triangles green, the others blue: both show,
  // shaded, and nothing of the single colour (warm: red above the rest)
  // does, not even where the edges blend into the background.
  PreviewOptions look{.width_px = 160, .height_px = 120};
  for (std::size_t i = 0; i < box.triangles.size(); ++i) {
    look.triangle_colors.emplace_back(i < box.triangles.size() / 2
                                          ? glm::dvec3(0.0, 0.8, 0.0)
                                          : glm::dvec3(0.0, 0.0, 0.8));
  }
  const Image image = render_preview(box, look);
  int green = 0;
  int blue = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const glm::ivec3 c = image.at(x, y);
      if (is_background(c)) continue;
      EXPECT_FALSE(c.r > c.g + 30 && c.r > c.b + 30) << x << "," << y;
      green += c.g > c.b + 40 ? 1 : 0;
      blue += c.b > c.g + 40 ? 1 : 0;
    }
  }
  EXPECT_GT(green, 500);
  EXPECT_GT(blue, 500);
  look.triangle_colors.pop_back();
  EXPECT_THROW((void)render_preview(box, look), std::logic_error);
}

TEST(Preview, FitsTheModelWhateverItsSize) {
  // A long thin bar, far from the origin: it still spans the picture.
  const Image image =
      render_preview(box_mesh({1000, 1000, 0}, {1001, 1001, 100}),
                     {.width_px = 100, .height_px = 100});
  int rows_with_model = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (!is_background(image.at(x, y))) {
        ++rows_with_model;
        break;
      }
    }
  }
  EXPECT_GT(rows_with_model, 85);  // 100 / 1.06 margin, less the slant
}

TEST(Preview, WritesAPngThatReadsBack) {
  const Image image = render_preview(box_mesh({0, 0, 0}, {1, 2, 3}),
                                     {.width_px = 64, .height_px = 48});
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "lsolid_preview_test.png";
  write_png(image, path);
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_file(&png, path.c_str()));
  png.format = PNG_FORMAT_RGB;
  std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(png));
  ASSERT_TRUE(png_image_finish_read(&png, nullptr, pixels.data(), 0, nullptr));
  EXPECT_EQ(png.width, 64U);
  EXPECT_EQ(png.height, 48U);
  EXPECT_EQ(pixels, image.rgb);
  std::filesystem::remove(path);
}

TEST(Preview, ReportsAFolderThatCannotBeWritten) {
  const Image image{2, 2, std::vector<std::uint8_t>(12, 0)};
  EXPECT_THROW(write_png(image, "/nonexistent-folder/x.png"), IoError);
}

}  // namespace
}  // namespace lsolid
