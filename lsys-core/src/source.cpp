// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/source.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "lsys/alphabet.hpp"
#include "lsys/diagnostic.hpp"

namespace lsys {

SourceFile::SourceFile(std::string name, std::string text)
    : name_(std::move(name)), text_(std::move(text)) {
  // A UTF-8 byte order mark is not part of the text; old Mac files end
  // lines with a lone CR.
  if (text_.starts_with("\xEF\xBB\xBF")) text_.erase(0, 3);
  for (std::size_t i = 0; i < text_.size(); ++i) {
    if (text_[i] == '\r' && (i + 1 == text_.size() || text_[i + 1] != '\n')) {
      text_[i] = '\n';
    }
  }
  line_starts_.push_back(0);
  for (std::size_t i = 0; i < text_.size(); ++i) {
    if (text_[i] == '\n' && i + 1 < text_.size()) line_starts_.push_back(i + 1);
  }
}

SourceLocation SourceFile::location(std::size_t offset) const {
  const auto it =
      std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const auto line = static_cast<int>(it - line_starts_.begin());
  const std::size_t start = line_starts_[static_cast<std::size_t>(line - 1)];
  int column = 1;
  const std::string_view text(text_);
  for (std::size_t i = start; i < offset && i < text.size();
       i += code_point_length(text.substr(i))) {
    ++column;
  }
  return {line, column};
}

std::string_view SourceFile::line_text(int line) const {
  const std::size_t start = line_starts_[static_cast<std::size_t>(line - 1)];
  std::size_t end = text_.find('\n', start);
  if (end == std::string::npos) end = text_.size();
  if (end > start && text_[end - 1] == '\r') --end;
  return std::string_view(text_).substr(start, end - start);
}

std::shared_ptr<const SourceFile> load_source(
    const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw ParseError(Diagnostic{
        .file = path.string(),
        .message = std::string("cannot read file: ") + std::strerror(errno)});
  }
  std::ostringstream text;
  text << in.rdbuf();
  return std::make_shared<const SourceFile>(path.string(), text.str());
}

}  // namespace lsys
