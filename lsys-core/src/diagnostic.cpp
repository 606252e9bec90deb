// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/diagnostic.hpp"

#include "lsys/alphabet.hpp"

namespace lsys {
namespace {

std::string headline(const Diagnostic& d) {
  std::string out = d.file;
  if (d.line > 0) {
    out += ':' + std::to_string(d.line) + ':' + std::to_string(d.column);
  }
  return out + ": error: " + d.message;
}

}  // namespace

ParseError::ParseError(Diagnostic diagnostic)
    : std::runtime_error(headline(diagnostic)),
      diagnostic_(std::move(diagnostic)) {}

ParseError error_at(const SourceFile& source, std::size_t offset,
                    std::string message) {
  const SourceLocation where = source.location(offset);
  return ParseError(
      Diagnostic{.file = source.name(),
                 .line = where.line,
                 .column = where.column,
                 .message = std::move(message),
                 .source_line = std::string(source.line_text(where.line))});
}

std::string format_diagnostic(const Diagnostic& diagnostic) {
  std::string out = headline(diagnostic) + '\n';
  if (diagnostic.line <= 0) return out;
  out += diagnostic.source_line + '\n';
  // Tabs stay tabs so the caret lines up whatever the terminal's tab width.
  const std::string_view line(diagnostic.source_line);
  std::size_t i = 0;
  for (int column = 1; column < diagnostic.column && i < line.size();
       ++column) {
    out += line[i] == '\t' ? '\t' : ' ';
    i += code_point_length(line.substr(i));
  }
  return out + "^\n";
}

}  // namespace lsys
