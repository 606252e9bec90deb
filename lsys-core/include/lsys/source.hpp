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

/// A run of a preprocessed text and where it came from: bytes
/// [text_begin, text_begin + length) of the text are bytes from
/// `original_begin` of the original when `verbatim`, or the expansion of
/// the macro written at `original_begin` when not.
struct SourceSpan {
  std::size_t text_begin = 0;
  std::size_t original_begin = 0;
  std::size_t length = 0;
  bool verbatim = true;
};

/// The text of one `.ls` file (or of a command-line value), indexed by line
/// so that byte offsets can be reported as line:column.
///
/// A file that a preprocessor rewrote (cpfg runs the C preprocessor) keeps
/// both texts: parsers read `text()`, and diagnostics report places in the
/// original, as the user wrote it.
class SourceFile {
 public:
  /// @param name what diagnostics print as the file name.
  SourceFile(std::string name, std::string text);
  /// A text that load_source read as Windows-1252 (Latin-1 and its
  /// kin), not being UTF-8, and turned into UTF-8.
  SourceFile(std::string name, std::string text, bool from_windows_1252);
  /// A preprocessed text: `spans` cover `text` in order, without gaps.
  /// @pre the spans start at 0, follow each other and end at text's end;
  ///   a verbatim span's bytes are the original's.
  SourceFile(std::string name, std::string original, std::string text,
             std::vector<SourceSpan> spans);

  /// The file name as given.
  [[nodiscard]] const std::string& name() const noexcept { return name_; }
  /// The whole text, byte for byte (after preprocessing, if any).
  [[nodiscard]] const std::string& text() const noexcept { return text_; }
  /// The text as written, before preprocessing.
  [[nodiscard]] const std::string& original() const noexcept {
    return spans_.empty() ? text_ : original_;
  }
  /// The byte offset in original() that a byte offset of text() comes from
  /// (for a byte of a macro's expansion, the place of the macro's name).
  /// @pre `offset <= text().size()`.
  [[nodiscard]] std::size_t original_offset(std::size_t offset) const;
  /// The line and column in original() of a byte offset of text().
  /// @pre `offset <= text().size()`.
  [[nodiscard]] SourceLocation location(std::size_t offset) const;
  /// True when the file was not UTF-8 and was read as Windows-1252.
  [[nodiscard]] bool from_windows_1252() const noexcept {
    return from_windows_1252_;
  }
  /// The text of a line of original() without its line break.
  /// @pre `1 <= line <= line_count()`.
  [[nodiscard]] std::string_view line_text(int line) const;
  /// The number of lines of original() (a final line without a break
  /// counts).
  [[nodiscard]] int line_count() const noexcept {
    return static_cast<int>(line_starts_.size());
  }

 private:
  std::string name_;
  std::string text_;
  std::string original_;
  std::vector<SourceSpan> spans_;
  std::vector<std::size_t> line_starts_;
  bool from_windows_1252_ = false;
};

/// The largest `.ls` file lsolid reads, 16 MiB: thousands of times the
/// largest L-system of the source documents, and small enough that reading
/// it takes a fraction of a second and well under a gigabyte.
inline constexpr std::size_t kMaxSourceBytes = std::size_t{16} << 20U;

/// Reads a file into a shared SourceFile named by its path, reading at most
/// `max_bytes + 1` bytes. Only a regular file is read: a FIFO, a device, a
/// socket or a folder is refused before it is opened (a FIFO would wait
/// for a writer for ever, a device such as /dev/zero never end).
/// @throws ParseError (line 0) when the file is missing, is not a regular
///   file (`cannot read file: it is a FIFO (named pipe), and lsolid reads
///   only regular files`) or cannot be read, and at the place of byte
///   `max_bytes` when the file is longer than that.
[[nodiscard]] std::shared_ptr<const SourceFile> load_source(
    const std::filesystem::path& path, std::size_t max_bytes = kMaxSourceBytes);

/// What a file of `type` is, for a refusal: "a FIFO (named pipe)", "a
/// device", "a directory", "a socket", "a regular file".
[[nodiscard]] std::string_view describe_file_type(
    std::filesystem::file_type type);

/// Checks that a source is UTF-8 text: well-formed UTF-8 (no overlong forms,
/// surrogates or code points above U+10FFFF) without control characters
/// other than tab and line breaks. A UTF-16 or UTF-32 file is named as such.
/// @throws ParseError at the first offending byte, naming it (`invalid
///   UTF-8 byte 0xFF`, `control character U+001B`, `the file is UTF-16
///   (little-endian); save it as UTF-8`).
void check_text(const SourceFile& source);

/// The text itself if it is UTF-8 (or UTF-16 or UTF-32, which check_text
/// names); otherwise the text read as Windows-1252, as older L-system files
/// of other programs were written (Latin-1 comments, box drawing), turned
/// into UTF-8 (SourceFile::from_windows_1252), an undefined byte becoming
/// U+FFFD.
[[nodiscard]] std::shared_ptr<const SourceFile> read_as_windows_1252(
    std::shared_ptr<const SourceFile> source);

}  // namespace lsys
