// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "text_words.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

#include "lsys/diagnostic.hpp"
#include "lsys/source.hpp"

namespace lsolid {

void malformed(const std::filesystem::path& path, const std::string& data,
               std::size_t offset, const std::string& message) {
  const lsys::SourceFile source(path.string(), data);
  // SourceFile drops a UTF-8 byte order mark.
  const std::size_t removed = data.size() - source.text().size();
  throw lsys::error_at(source, offset - std::min(offset, removed), message);
}

void malformed(const std::filesystem::path& path, const std::string& message) {
  throw lsys::ParseError(
      lsys::Diagnostic{.file = path.string(), .message = message});
}

std::string_view Words::next() {
  while (at_ < data_.size() &&
         std::isspace(static_cast<unsigned char>(data_[at_])) != 0) {
    ++at_;
  }
  begin_ = at_;
  while (at_ < data_.size() &&
         std::isspace(static_cast<unsigned char>(data_[at_])) == 0) {
    ++at_;
  }
  return std::string_view(data_).substr(begin_, at_ - begin_);
}

void Words::skip_line() {
  while (at_ < data_.size() && data_[at_] != '\n') ++at_;
}

void Words::refuse(const std::string& expected, std::string_view word) const {
  if (word.empty()) {
    malformed(path_, "the file ends where " + expected + " should follow");
  }
  // A word is shown up to 32 characters (a binary file may have none).
  std::string shown(word.substr(0, 32));
  if (word.size() > 32) shown += "...";
  malformed(path_, data_, begin_,
            "expected " + expected + ", not '" + shown + "'");
}

void Words::refuse_here(const std::string& message) const {
  malformed(path_, data_, begin_, message);
}

void Words::expect(std::string_view word) {
  const std::string_view got = next();
  // (Appending piecewise avoids a GCC 12 -Wrestrict false alarm.)
  if (got != word) refuse(std::string(1, '\'').append(word).append("'"), got);
}

double Words::number(bool must_be_finite) {
  const std::string_view word = next();
  double value = 0.0;
  const auto [end, error] =
      std::from_chars(word.data(), word.data() + word.size(), value);
  if (word.empty() || error != std::errc() ||
      end != word.data() + word.size() ||
      (must_be_finite && !std::isfinite(value))) {
    refuse(must_be_finite ? "a finite number" : "a number", word);
  }
  return value;
}

std::size_t Words::count(const std::string& expected, const std::string& things,
                         std::size_t most) {
  const std::string_view word = next();
  std::size_t value = 0;
  const auto [end, error] =
      std::from_chars(word.data(), word.data() + word.size(), value);
  if (word.empty() || error != std::errc() ||
      end != word.data() + word.size()) {
    refuse(expected, word);
  }
  if (value > most) {
    refuse_here(std::string(word) + " " + things + " do not fit in a file of " +
                std::to_string(data_.size()) + " bytes");
  }
  return value;
}

}  // namespace lsolid
