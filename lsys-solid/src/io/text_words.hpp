// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace lsolid {

/// Refuses malformed content of a text format as bad input
/// (lsys::ParseError) at `offset` into `data`, shown with its line and a
/// caret; the text is copied into a SourceFile only then.
/// @throws lsys::ParseError always.
[[noreturn]] void malformed(const std::filesystem::path& path,
                            const std::string& data, std::size_t offset,
                            const std::string& message);

/// Refuses malformed content of a binary format, or of the file as a whole.
/// @throws lsys::ParseError always.
[[noreturn]] void malformed(const std::filesystem::path& path,
                            const std::string& message);

/// The words of a text format (ASCII STL, OFF), separated by white space,
/// read one by one with their places, for errors at the word.
class Words {
 public:
  /// @pre `data` and `path` outlive the reader.
  Words(const std::string& data, const std::filesystem::path& path)
      : data_(data), path_(path) {}

  /// The next word; empty at the end.
  std::string_view next();
  /// Skips the rest of the line.
  void skip_line();
  /// Refuses the word last read: `expected X, not 'word'`.
  [[noreturn]] void refuse(const std::string& expected,
                           std::string_view word) const;
  /// Refuses the word last read with `message`.
  [[noreturn]] void refuse_here(const std::string& message) const;
  /// Reads `word` or refuses what stands there.
  void expect(std::string_view word);
  /// Reads a number, finite if `must_be_finite`.
  double number(bool must_be_finite);
  /// Reads a whole number from 0 to `most` of `things`, where a count is
  /// `expected`.
  std::size_t count(const std::string& expected, const std::string& things,
                    std::size_t most);

 private:
  const std::string& data_;
  const std::filesystem::path& path_;
  std::size_t at_ = 0;
  std::size_t begin_ = 0;
};

}  // namespace lsolid
