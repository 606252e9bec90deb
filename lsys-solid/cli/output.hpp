// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstdio>
#include <string>

namespace lsolid::cli {

/// Buffered text output to a C stream that reports write failures (a full
/// disk, a closed pipe) as IoError instead of losing them.
class Output {
 public:
  explicit Output(std::FILE* stream) : stream_(stream) {}
  /// Text appended here is written by the next flush.
  std::string& text() noexcept { return text_; }
  /// Writes the buffer when it has grown past a megabyte.
  /// @throws IoError.
  void flush_if_large() {
    if (text_.size() > (1U << 20U)) flush();
  }
  /// Writes the buffer and flushes the stream.
  /// @throws IoError.
  void flush();

 private:
  std::FILE* stream_;
  std::string text_;
};

}  // namespace lsolid::cli
