// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "output.hpp"

#include <cerrno>
#include <cstring>

#include "lsolid/errors.hpp"

namespace lsolid::cli {

void Output::flush() {
  if (!text_.empty() &&
      std::fwrite(text_.data(), 1, text_.size(), stream_) != text_.size()) {
    throw IoError(std::string("cannot write to standard output: ") +
                  std::strerror(errno));
  }
  text_.clear();
  if (std::fflush(stream_) != 0) {
    throw IoError(std::string("cannot write to standard output: ") +
                  std::strerror(errno));
  }
}

}  // namespace lsolid::cli
