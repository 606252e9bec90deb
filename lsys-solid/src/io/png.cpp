// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// PNG encoding with libpng's simplified API (libpng 1.6), into memory, then
// the same temporary-and-rename write as the meshes.
#include <png.h>

#include <string>

#include "atomic_write.hpp"
#include "lsolid/errors.hpp"
#include "lsolid/preview.hpp"

namespace lsolid {

void write_png(const Image& image, const std::filesystem::path& path) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGB;
  png_alloc_size_t size = 0;
  // The first call measures, the second encodes.
  if (!png_image_write_to_memory(&png, nullptr, &size, 0, image.rgb.data(), 0,
                                 nullptr)) {
    throw IoError(path.string() + ": cannot encode PNG: " + png.message);
  }
  std::string data(size, '\0');
  if (!png_image_write_to_memory(&png, data.data(), &size, 0, image.rgb.data(),
                                 0, nullptr)) {
    throw IoError(path.string() + ": cannot encode PNG: " + png.message);
  }
  data.resize(size);
  write_file_atomically(path, data);
}

}  // namespace lsolid
