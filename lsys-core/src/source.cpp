// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/source.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <system_error>

#include "lsys/alphabet.hpp"
#include "lsys/diagnostic.hpp"

namespace lsys {

namespace {

// A UTF-8 byte order mark is not part of the text; old Mac files end lines
// with a lone CR.
void normalise(std::string& text) {
  if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) {
      text[i] = '\n';
    }
  }
}

std::vector<std::size_t> line_starts(const std::string& text) {
  std::vector<std::size_t> starts{0};
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n' && i + 1 < text.size()) starts.push_back(i + 1);
  }
  return starts;
}

}  // namespace

SourceFile::SourceFile(std::string name, std::string text)
    : name_(std::move(name)), text_(std::move(text)) {
  normalise(text_);
  line_starts_ = line_starts(text_);
}

SourceFile::SourceFile(std::string name, std::string text,
                       bool from_windows_1252)
    : SourceFile(std::move(name), std::move(text)) {
  from_windows_1252_ = from_windows_1252;
}

SourceFile::SourceFile(std::string name, std::string original, std::string text,
                       std::vector<SourceSpan> spans)
    : name_(std::move(name)),
      text_(std::move(text)),
      original_(std::move(original)),
      spans_(std::move(spans)) {
  line_starts_ = line_starts(original_);
}

std::size_t SourceFile::original_offset(std::size_t offset) const {
  if (spans_.empty()) return offset;
  auto it = std::upper_bound(
      spans_.begin(), spans_.end(), offset,
      [](std::size_t o, const SourceSpan& s) { return o < s.text_begin; });
  if (it == spans_.begin()) return 0;
  const SourceSpan& span = *--it;
  if (!span.verbatim) return span.original_begin;
  return std::min(
      original_.size(),
      span.original_begin + std::min(offset - span.text_begin, span.length));
}

SourceLocation SourceFile::location(std::size_t text_offset) const {
  const std::size_t offset = original_offset(text_offset);
  const std::string& text = original();
  const auto it =
      std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const auto line = static_cast<int>(it - line_starts_.begin());
  const std::size_t start = line_starts_[static_cast<std::size_t>(line - 1)];
  int column = 1;
  const std::string_view view(text);
  for (std::size_t i = start; i < offset && i < view.size();
       i += code_point_length(view.substr(i))) {
    ++column;
  }
  return {line, column};
}

std::string_view SourceFile::line_text(int line) const {
  const std::string& text = original();
  const std::size_t start = line_starts_[static_cast<std::size_t>(line - 1)];
  std::size_t end = text.find('\n', start);
  if (end == std::string::npos) end = text.size();
  if (end > start && text[end - 1] == '\r') --end;
  return std::string_view(text).substr(start, end - start);
}

std::string_view describe_file_type(std::filesystem::file_type type) {
  switch (type) {
    case std::filesystem::file_type::regular:
      return "a regular file";
    case std::filesystem::file_type::directory:
      return "a directory";
    case std::filesystem::file_type::fifo:
      return "a FIFO (named pipe)";
    case std::filesystem::file_type::block:
    case std::filesystem::file_type::character:
      return "a device";
    case std::filesystem::file_type::socket:
      return "a socket";
    case std::filesystem::file_type::symlink:
      return "a symbolic link";
    default:
      return "not a regular file";
  }
}

namespace {

[[noreturn]] void refuse_file(const std::filesystem::path& path,
                              std::string message) {
  throw ParseError(
      Diagnostic{.file = path.string(), .message = std::move(message)});
}

void refuse_unless_regular(const std::filesystem::path& path,
                           std::filesystem::file_type type) {
  if (type == std::filesystem::file_type::regular) return;
  refuse_file(path, std::string("cannot read file: it is ") +
                        std::string(describe_file_type(type)) +
                        ", and lsolid reads only regular files");
}

// Closes a descriptor however the read ends.
struct Descriptor {
  int fd;
  ~Descriptor() { ::close(fd); }
};

}  // namespace

std::shared_ptr<const SourceFile> load_source(const std::filesystem::path& path,
                                              std::size_t max_bytes) {
  // The kind of file is known before it is opened: opening a FIFO waits
  // for a writer, and a device may never end or act on being opened. The
  // open itself does not wait (O_NONBLOCK), and the file opened is checked
  // again, in case it was replaced in between.
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error) refuse_file(path, "cannot read file: " + error.message());
  refuse_unless_regular(path, status.type());
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  struct stat opened {};
  if (fd < 0 || ::fstat(fd, &opened) != 0) {
    const int why = errno;
    if (fd >= 0) ::close(fd);
    refuse_file(path, std::string("cannot read file: ") + std::strerror(why));
  }
  const Descriptor descriptor{fd};
  if (!S_ISREG(opened.st_mode)) {
    refuse_file(path,
                "cannot read file: it was replaced by another kind of "
                "file as it was opened");
  }
  // Read in blocks up to one byte past the limit: a huge file is refused
  // without being held.
  std::string text;
  std::array<char, 1U << 16U> block{};
  while (text.size() <= max_bytes) {
    const ::ssize_t got = ::read(
        fd, block.data(), std::min(block.size(), max_bytes + 1 - text.size()));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      refuse_file(path,
                  std::string("cannot read file: ") + std::strerror(errno));
    }
    if (got == 0) break;
    text.append(block.data(), static_cast<std::size_t>(got));
  }
  const std::size_t read = text.size();
  auto source =
      std::make_shared<const SourceFile>(path.string(), std::move(text));
  if (read > max_bytes) {
    // The place where the limit falls, so that a runaway line is shown.
    const std::size_t removed = read - source->text().size();
    throw error_at(*source, max_bytes - std::min(max_bytes, removed),
                   "the file is larger than " + std::to_string(max_bytes) +
                       " bytes, the limit for a .ls file");
  }
  return source;
}

namespace {

// A UTF-16 or UTF-32 text's first line, as UTF-8, for showing it.
std::string first_line_of_wide_text(std::string_view text, std::size_t unit,
                                    bool is_big_endian) {
  std::string out;
  for (std::size_t i = 0; i + unit <= text.size() && out.size() < 400;
       i += unit) {
    std::uint32_t c = 0;
    for (std::size_t k = 0; k < unit; ++k) {
      const auto byte = static_cast<unsigned char>(
          text[is_big_endian ? i + k : i + unit - 1 - k]);
      c = (c << 8U) | byte;
    }
    if (unit == 2 && c >= 0xD800U && c < 0xDC00U &&
        i + 2 * unit <= text.size()) {
      std::uint32_t low = 0;
      for (std::size_t k = 0; k < unit; ++k) {
        const std::size_t at = i + unit + (is_big_endian ? k : unit - 1 - k);
        low = (low << 8U) | static_cast<unsigned char>(text[at]);
      }
      c = 0x10000U + ((c - 0xD800U) << 10U) + (low - 0xDC00U);
      i += unit;
    }
    if (c == 0xFEFFU) continue;
    if (c == '\n' || c == '\r') break;
    if (c >= 0x110000U) c = 0xFFFDU;
    if (c < 0x80U) {
      out += static_cast<char>(c);
    } else if (c < 0x800U) {
      out += static_cast<char>(0xC0U | (c >> 6U));
      out += static_cast<char>(0x80U | (c & 0x3FU));
    } else if (c < 0x10000U) {
      out += static_cast<char>(0xE0U | (c >> 12U));
      out += static_cast<char>(0x80U | ((c >> 6U) & 0x3FU));
      out += static_cast<char>(0x80U | (c & 0x3FU));
    } else {
      out += static_cast<char>(0xF0U | (c >> 18U));
      out += static_cast<char>(0x80U | ((c >> 12U) & 0x3FU));
      out += static_cast<char>(0x80U | ((c >> 6U) & 0x3FU));
      out += static_cast<char>(0x80U | (c & 0x3FU));
    }
  }
  return out;
}

// Names a wide encoding from its byte order mark or, without one, from the
// zero bytes that ASCII characters leave in it.
void refuse_wide_encoding(const SourceFile& source) {
  const std::string_view t = source.text();
  if (t.size() < 2) return;
  const auto at = [&](std::size_t i) {
    return i < t.size() ? static_cast<unsigned char>(t[i]) : 0xFFU;
  };
  std::size_t unit = 0;
  bool is_big_endian = false;
  if (at(0) == 0xFF && at(1) == 0xFE && at(2) == 0 && at(3) == 0) {
    unit = 4;
  } else if (at(0) == 0 && at(1) == 0 && at(2) == 0xFE && at(3) == 0xFF) {
    unit = 4;
    is_big_endian = true;
  } else if (at(0) == 0xFF && at(1) == 0xFE) {
    unit = 2;
  } else if (at(0) == 0xFE && at(1) == 0xFF) {
    unit = 2;
    is_big_endian = true;
  } else if (at(0) != 0 && at(1) == 0 && at(2) == 0 && at(3) == 0) {
    unit = 4;
  } else if (at(0) == 0 && at(1) == 0 && at(2) == 0 && at(3) != 0) {
    unit = 4;
    is_big_endian = true;
  } else if (at(0) != 0 && at(1) == 0) {
    unit = 2;
  } else if (at(0) == 0 && at(1) != 0) {
    unit = 2;
    is_big_endian = true;
  }
  if (unit == 0) return;
  throw ParseError(Diagnostic{
      .file = source.name(),
      .line = 1,
      .column = 1,
      .message = std::string("the file is UTF-") + (unit == 2 ? "16" : "32") +
                 (is_big_endian ? " (big-endian)" : " (little-endian)") +
                 "; save it as UTF-8",
      .source_line = first_line_of_wide_text(t, unit, is_big_endian)});
}

// The length of a well-formed UTF-8 sequence at `i` (Unicode's table 3-7),
// or 0.
std::size_t utf8_sequence_length(std::string_view t, std::size_t i) {
  const auto byte = [&](std::size_t k) {
    return i + k < t.size() ? static_cast<unsigned char>(t[i + k]) : 0U;
  };
  const unsigned lead = byte(0);
  const auto tail = [&](std::size_t k, unsigned low = 0x80U,
                        unsigned high = 0xBFU) {
    return byte(k) >= low && byte(k) <= high;
  };
  if (lead < 0x80U) return 1;
  if (lead >= 0xC2U && lead <= 0xDFU) return tail(1) ? 2 : 0;
  if (lead == 0xE0U) return tail(1, 0xA0U) && tail(2) ? 3 : 0;
  if (lead == 0xEDU) return tail(1, 0x80U, 0x9FU) && tail(2) ? 3 : 0;
  if (lead >= 0xE1U && lead <= 0xEFU) return tail(1) && tail(2) ? 3 : 0;
  if (lead == 0xF0U) return tail(1, 0x90U) && tail(2) && tail(3) ? 4 : 0;
  if (lead >= 0xF1U && lead <= 0xF3U) {
    return tail(1) && tail(2) && tail(3) ? 4 : 0;
  }
  if (lead == 0xF4U) return tail(1, 0x80U, 0x8FU) && tail(2) && tail(3) ? 4 : 0;
  return 0;
}

// Windows-1252's characters for bytes 0x80 to 0x9F (0: none there); the
// bytes from 0xA0 are Latin-1's, the code points of the same number.
constexpr std::array<char16_t, 32> kWindows1252{
    0x20AC, 0,      0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021,
    0x02C6, 0x2030, 0x0160, 0x2039, 0x0152, 0,      0x017D, 0,
    0,      0x2018, 0x2019, 0x201C, 0x201D, 0x2022, 0x2013, 0x2014,
    0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0,      0x017E, 0x0178};

// Turns a text that is not UTF-8 into UTF-8, reading it as Windows-1252
// (an undefined byte becomes U+FFFD); true if it did. UTF-16 and UTF-32
// are left for check_text to name.
bool transcode_windows_1252(std::string& text) {
  const std::string_view t = text;
  bool valid = true;
  for (std::size_t i = 0; i < t.size();) {
    const std::size_t length = utf8_sequence_length(t, i);
    if (length == 0) {
      valid = false;
      break;
    }
    i += length;
  }
  if (valid || t.find('\0') != std::string_view::npos) return false;
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  const auto put = [&](unsigned c) {
    if (c < 0x80U) {
      out += static_cast<char>(c);
    } else if (c < 0x800U) {
      out += static_cast<char>(0xC0U | (c >> 6U));
      out += static_cast<char>(0x80U | (c & 0x3FU));
    } else {
      out += static_cast<char>(0xE0U | (c >> 12U));
      out += static_cast<char>(0x80U | ((c >> 6U) & 0x3FU));
      out += static_cast<char>(0x80U | (c & 0x3FU));
    }
  };
  for (const char ch : text) {
    const auto b = static_cast<unsigned char>(ch);
    if (b >= 0x80U && b < 0xA0U) {
      const char16_t c = kWindows1252[b - 0x80U];
      put(c == 0 ? 0xFFFDU : static_cast<unsigned>(c));
    } else {
      put(b);
    }
  }
  text = std::move(out);
  return true;
}

// `value` in upper-case hexadecimal, `digits` wide.
std::string hex(unsigned value, int digits) {
  std::array<char, 16> text{};
  std::snprintf(text.data(), text.size(), "%0*X", digits, value);
  return text.data();
}

}  // namespace

void check_text(const SourceFile& source) {
  refuse_wide_encoding(source);
  const std::string_view t = source.text();
  for (std::size_t i = 0; i < t.size();) {
    const std::size_t length = utf8_sequence_length(t, i);
    if (length == 0) {
      throw error_at(source, i,
                     "invalid UTF-8 byte 0x" +
                         hex(static_cast<unsigned char>(t[i]), 2) +
                         ": save the file as UTF-8");
    }
    const auto c = static_cast<unsigned char>(t[i]);
    // C0 controls but tab and line breaks, DEL, and C1 (U+0080 to U+009F).
    const bool is_c1 = length == 2 && c == 0xC2U &&
                       static_cast<unsigned char>(t[i + 1]) < 0xA0U;
    if ((c < 0x20U && c != '\t' && c != '\n' && c != '\r') || c == 0x7FU ||
        is_c1) {
      const unsigned code = is_c1 ? static_cast<unsigned char>(t[i + 1])
                                  : static_cast<unsigned>(c);
      throw error_at(source, i,
                     "control character U+" + hex(code, 4) + " in the text");
    }
    i += length;
  }
}

std::shared_ptr<const SourceFile> read_as_windows_1252(
    std::shared_ptr<const SourceFile> source) {
  std::string text = source->text();
  if (!transcode_windows_1252(text)) return source;
  return std::make_shared<const SourceFile>(source->name(), std::move(text),
                                            true);
}

}  // namespace lsys
