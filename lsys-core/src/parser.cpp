// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The front door: checks that a file is text lsolid can hold, finds its
// notation and hands it to that notation's front end (src/dialects/).
#include "lsys/parser.hpp"

#include <string>

#include "dialects/front_ends.hpp"
#include "lsys/diagnostic.hpp"

namespace lsys {

namespace {

Grammar read_in(Dialect dialect, std::shared_ptr<const SourceFile> source,
                const ParseOptions& options) {
  switch (dialect) {
    case Dialect::Lparser:
      return dialects::read_lparser(std::move(source), options);
    case Dialect::Fractint:
      return dialects::read_fractint(std::move(source), options);
    case Dialect::Lpy:
      return dialects::read_lpy(std::move(source), options);
    case Dialect::Cpfg:
      return dialects::read_cpfg(std::move(source), options);
    case Dialect::Lowclouds:
      return dialects::read_lowclouds(std::move(source), options);
    case Dialect::Lpfg:
      return dialects::read_lpfg(std::move(source), options);
    case Dialect::Ls:
      break;
  }
  return dialects::read_ls(std::move(source), options);
}

}  // namespace

Grammar parse_grammar(std::shared_ptr<const SourceFile> source,
                      const ParseOptions& options) {
  // Successors keep 32-bit source places; files are far smaller
  // (kMaxSourceBytes), texts given in memory must be too.
  if (source->text().size() > 0xFFFFFFFFU) {
    throw ParseError(Diagnostic{.file = source->name(),
                                .message = "the text is longer than 4 GiB"});
  }
  const Dialect dialect =
      options.dialect.value_or(detect_dialect(source->text(), source->name()));
  // Other programs' files predate UTF-8; lsolid's own notation is UTF-8.
  if (dialect != Dialect::Ls) source = read_as_windows_1252(std::move(source));
  check_text(*source);
  if (!options.system.empty() && dialect != Dialect::Fractint) {
    throw ParseError(Diagnostic{
        .file = source->name(),
        .message = "--system picks one system of a Fractint file; this file "
                   "is read as " +
                   std::string(dialect_name(dialect)) + " (--dialect)"});
  }
  if (!options.view_file.empty() && dialect != Dialect::Cpfg &&
      dialect != Dialect::Lpfg) {
    throw ParseError(Diagnostic{
        .file = source->name(),
        .message =
            "--view gives a cpfg or lpfg file its view file; this file is "
            "read as " +
            std::string(dialect_name(dialect)) + " (--dialect)"});
  }
  const bool transcoded = source->from_windows_1252();
  const std::string name = source->name();
  Grammar grammar = read_in(dialect, std::move(source), options);
  if (transcoded) {
    grammar.warnings.insert(
        grammar.warnings.begin(),
        name + " is not UTF-8: read as Windows-1252 (Latin-1)");
  }
  return grammar;
}

Grammar parse_grammar_text(std::string_view text, const ParseOptions& options,
                           std::string name) {
  return parse_grammar(
      std::make_shared<const SourceFile>(std::move(name), std::string(text)),
      options);
}

}  // namespace lsys
