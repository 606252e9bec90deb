// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/source.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "lsys/diagnostic.hpp"
#include "lsys/parser.hpp"
#include "support/core_helpers.hpp"

namespace lsys {
namespace {

TEST(SourceFile, CountsColumnsInCodePointsNotBytes) {
  const SourceFile source("x.ls", "n=2\n\u03B4=90\u00B0, n=3\n");
  // `n` of the second line is its byte 9 but column 8.
  const std::size_t offset = source.text().find("n=3");
  EXPECT_EQ(source.location(offset).line, 2);
  EXPECT_EQ(source.location(offset).column, 8);
  EXPECT_EQ(source.location(0).column, 1);
}

TEST(SourceFile, ReportsPlacesOfAPreprocessedTextInTheOriginal) {
  // "A LONG B" with LONG expanded to "FF": "A FF B".
  const SourceFile source(
      "f.l", "x\nA LONG B\n", "x\nA FF B\n",
      {SourceSpan{.text_begin = 0, .original_begin = 0, .length = 4},
       SourceSpan{.text_begin = 4,
                  .original_begin = 4,
                  .length = 2,
                  .verbatim = false},
       SourceSpan{.text_begin = 6, .original_begin = 8, .length = 3}});
  EXPECT_EQ(source.text(), "x\nA FF B\n");
  EXPECT_EQ(source.original(), "x\nA LONG B\n");
  EXPECT_EQ(source.location(5).column, 3);  // inside the expansion: LONG
  EXPECT_EQ(source.location(7).line, 2);
  EXPECT_EQ(source.location(7).column, 8);  // B
  EXPECT_EQ(source.line_text(2), "A LONG B");
}

TEST(SourceFile, GivesLinesWithoutTheirBreaks) {
  const SourceFile source("x.ls", "first\r\nsecond\nthird");
  EXPECT_EQ(source.line_count(), 3);
  EXPECT_EQ(source.line_text(1), "first");
  EXPECT_EQ(source.line_text(2), "second");
  EXPECT_EQ(source.line_text(3), "third");
}

TEST(SourceFile, ReportsAMissingFileWithItsName) {
  try {
    (void)load_source("/nonexistent/tree.ls");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.diagnostic().file, "/nonexistent/tree.ls");
    EXPECT_EQ(e.diagnostic().line, 0);
    EXPECT_EQ(e.diagnostic().message,
              "cannot read file: No such file or directory");
  }
}

// `line:column: message` of check_text's error, or "no error".
std::string text_error(const std::string& text) {
  return testing::located_error_of(
      [&] { check_text(SourceFile("t.ls", text)); });
}

// Older L-system files are Latin-1 or Windows-1252 (comments with accents,
// box drawing): read so, turned into UTF-8, and said so.
TEST(SourceFile, ReadsATextThatIsNotUtf8AsWindows1252) {
  const auto path =
      std::filesystem::temp_directory_path() / "lsolid_latin1_test.ls";
  std::ofstream(path, std::ios::binary)
      << "Axiom: F\n# r\xE9sum\xE9 \x93quoted\x94 \x81\nderivation length: 1\n"
         "production:\nF --> FF\nendlsystem\n";
  const auto source = read_as_windows_1252(load_source(path));
  EXPECT_TRUE(source->from_windows_1252());
  EXPECT_EQ(source->line_text(2),
            "# r\u00E9sum\u00E9 \u201Cquoted\u201D \uFFFD");
  // Other notations' files are read so; lsolid's own must be UTF-8.
  const Grammar g = parse_grammar(load_source(path), {.dialect = Dialect::Lpy});
  ASSERT_FALSE(g.warnings.empty());
  EXPECT_EQ(g.warnings.front(), path.string() +
                                    " is not UTF-8: read as Windows-1252 "
                                    "(Latin-1)");
  EXPECT_THROW((void)parse_grammar(load_source(path), {}), ParseError);
  std::ofstream(path, std::ios::binary) << "axiom: F\n// r\u00E9sum\u00E9\n";
  EXPECT_FALSE(read_as_windows_1252(load_source(path))->from_windows_1252());
  std::filesystem::remove(path);
}

TEST(SourceFile, AcceptsUtf8TextWithOrWithoutAByteOrderMark) {
  EXPECT_EQ(text_error("n=2, \u03B4=90\u00B0\r\n\tF \u2192 F\U0001F33F\rX"),
            "no error");
  EXPECT_EQ(text_error("\xEF\xBB\xBF\u03C9: F\n"), "no error");
}

TEST(SourceFile, RefusesInvalidUtf8AtTheByteNamingIt) {
  EXPECT_EQ(text_error("axiom: F\xFF[F\n"),
            "1:9: invalid UTF-8 byte 0xFF: save the file as UTF-8");
  // Latin-1's degree sign, a truncated sequence, an overlong '/', a
  // surrogate and a code point above U+10FFFF.
  EXPECT_EQ(text_error("n=1\nangle: 90\xB0\n"),
            "2:10: invalid UTF-8 byte 0xB0: save the file as UTF-8");
  EXPECT_EQ(text_error("F\xC3"),
            "1:2: invalid UTF-8 byte 0xC3: save the file as UTF-8");
  EXPECT_EQ(text_error("F\xC0\xAF"),
            "1:2: invalid UTF-8 byte 0xC0: save the file as UTF-8");
  EXPECT_EQ(text_error("\xED\xA0\x80"),
            "1:1: invalid UTF-8 byte 0xED: save the file as UTF-8");
  EXPECT_EQ(text_error("\xF4\x90\x80\x80"),
            "1:1: invalid UTF-8 byte 0xF4: save the file as UTF-8");
}

TEST(SourceFile, RefusesControlCharactersButTabAndLineBreaks) {
  EXPECT_EQ(text_error(std::string("axiom: F\0F]\n", 13)),
            "1:9: control character U+0000 in the text");
  EXPECT_EQ(text_error("F -> F]\x1B]0;x\x07\n"),
            "1:8: control character U+001B in the text");
  EXPECT_EQ(text_error("F\x7F"), "1:2: control character U+007F in the text");
  EXPECT_EQ(text_error("F\xC2\x9B"),
            "1:2: control character U+009B in the text");
}

TEST(SourceFile, NamesUtf16AndUtf32AndShowsTheirFirstLine) {
  const std::string le16(
      "\xFF\xFEn\0=\0"
      "2\0\n\0F\0",
      12);
  try {
    check_text(SourceFile("w.ls", le16));
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(format_diagnostic(e.diagnostic()),
              "w.ls:1:1: error: the file is UTF-16 (little-endian); save it "
              "as UTF-8\nn=2\n^\n");
  }
  EXPECT_EQ(text_error(std::string("\0a\0x\0i", 6)),
            "1:1: the file is UTF-16 (big-endian); save it as UTF-8");
  EXPECT_EQ(text_error(std::string("F\0\0\0\n\0\0\0", 8)),
            "1:1: the file is UTF-32 (little-endian); save it as UTF-8");
  EXPECT_EQ(text_error(std::string("\0\0\xFE\xFF\0\0\0F", 8)),
            "1:1: the file is UTF-32 (big-endian); save it as UTF-8");
}

TEST(SourceFile, RefusesAFileLongerThanTheLimitWhereTheLimitFalls) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("lsolid_long_" + std::to_string(::getpid()) + ".ls");
  { std::ofstream(path) << "n=1\naxiom: " << std::string(200, 'F') << "\n"; }
  try {
    (void)load_source(path, 100);
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.diagnostic().line, 2);
    EXPECT_EQ(e.diagnostic().column, 97);
    EXPECT_EQ(e.diagnostic().message,
              "the file is larger than 100 bytes, the limit for a .ls file");
  }
  EXPECT_EQ(load_source(path, 300)->text().size(), 212U);
  std::filesystem::remove(path);
  EXPECT_EQ(kMaxSourceBytes, 16U * 1024U * 1024U);
}

TEST(SourceFile, RefusesADeviceAFifoOrAFolderBeforeOpeningIt) {
  // /dev/zero would never end, and opening a FIFO waits for a writer: a
  // FIFO that is opened hangs this test.
  const std::filesystem::path fifo =
      std::filesystem::temp_directory_path() /
      ("lsolid_source_fifo_" + std::to_string(::getpid()));
  std::filesystem::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  const std::vector<std::pair<std::filesystem::path, std::string>> cases{
      {"/dev/zero", "a device"},
      {fifo, "a FIFO (named pipe)"},
      {std::filesystem::temp_directory_path(), "a directory"}};
  for (const auto& [path, kind] : cases) {
    try {
      (void)load_source(path, 1000);
      ADD_FAILURE() << path << ": no error";
    } catch (const ParseError& e) {
      EXPECT_EQ(e.diagnostic().file, path.string());
      EXPECT_EQ(e.diagnostic().line, 0);
      EXPECT_EQ(e.diagnostic().message,
                "cannot read file: it is " + kind +
                    ", and lsolid reads only regular files");
    }
  }
  std::filesystem::remove(fifo);
}

}  // namespace
}  // namespace lsys
