// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace lsys {

/// A position in a source text. Lines and columns count from 1; a column
/// counts Unicode code points, so `δ=90°` has `9` in column 3. Line 0 means
/// "the whole file".
struct SourceLocation {
  int line = 0;
  int column = 0;
};

/// The text of one `.ls` file (or of a command-line value), indexed by line
/// so that byte offsets can be reported as line:column.
class SourceFile {
 public:
  /// @param name what diagnostics print as the file name.
  SourceFile(std::string name, std::string text);

  /// The file name as given.
  [[nodiscard]] const std::string& name() const noexcept { return name_; }
  /// The whole text, byte for byte.
  [[nodiscard]] const std::string& text() const noexcept { return text_; }
  /// The line and column of a byte offset.
  /// @pre `offset <= text().size()`.
  [[nodiscard]] SourceLocation location(std::size_t offset) const;
  /// The text of a line without its line break.
  /// @pre `1 <= line <= line_count()`.
  [[nodiscard]] std::string_view line_text(int line) const;
  /// The number of lines (a final line without a break counts).
  [[nodiscard]] int line_count() const noexcept {
    return static_cast<int>(line_starts_.size());
  }

 private:
  std::string name_;
  std::string text_;
  std::vector<std::size_t> line_starts_;
};

/// The largest `.ls` file lsolid reads, 16 MiB: thousands of times the
/// largest L-system of the source documents, and small enough that reading
/// it takes a fraction of a second and well under a gigabyte.
inline constexpr std::size_t kMaxSourceBytes = std::size_t{16} << 20U;

/// Reads a file into a shared SourceFile named by its path, reading at most
/// `max_bytes + 1` bytes (so that a device such as /dev/zero ends too).
/// @throws ParseError (line 0) when the file cannot be read, and at the
///   place of byte `max_bytes` when the file is longer than that.
[[nodiscard]] std::shared_ptr<const SourceFile> load_source(
    const std::filesystem::path& path, std::size_t max_bytes = kMaxSourceBytes);

/// Checks that a source is UTF-8 text: well-formed UTF-8 (no overlong forms,
/// surrogates or code points above U+10FFFF) without control characters
/// other than tab and line breaks. A UTF-16 or UTF-32 file is named as such.
/// @throws ParseError at the first offending byte, naming it (`invalid
///   UTF-8 byte 0xFF`, `control character U+001B`, `the file is UTF-16
///   (little-endian); save it as UTF-8`).
void check_text(const SourceFile& source);

}  // namespace lsys
