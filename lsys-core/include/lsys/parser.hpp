// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lsys/dialect.hpp"
#include "lsys/grammar.hpp"
#include "lsys/source.hpp"

namespace lsys {

/// What the caller adds to a file.
struct ParseOptions {
  /// `NAME=VALUE` texts, as `--define` gives them. They replace the file's
  /// `#define` of the same name and may add new names.
  std::vector<std::string> defines;
  /// Keys of settings that a client interprets itself (lsys-solid's print
  /// settings); they are returned in Grammar::extra_settings.
  std::vector<std::string> extra_settings;
  /// The notation; detected from the text (detect_dialect) when unset.
  std::optional<Dialect> dialect;
  /// In a file of several systems (Fractint), the one to read, by name
  /// without regard to case; empty reads the only one, or refuses to choose.
  std::string system;
  /// A cpfg view file (`.v`) to read with a cpfg `.l` file; empty looks
  /// beside it: the `.v` of the same name, else the folder's only one.
  std::string view_file;
  /// Folders besides the model's own (and the view file's) whose files a
  /// model may name (`--include-dir`): `#include "…"`, and a view file's
  /// function, surface and contour files. A model reads no other file.
  std::vector<std::string> include_dirs;
};

/// Reads an L-system file in any notation lsolid knows (docs/language.md,
/// docs/dialects/).
/// @throws ParseError with file, line and column for any malformed input.
[[nodiscard]] Grammar parse_grammar(std::shared_ptr<const SourceFile> source,
                                    const ParseOptions& options = {});

/// Reads `.ls` text held in memory, named `name` in diagnostics.
/// @throws ParseError as parse_grammar.
[[nodiscard]] Grammar parse_grammar_text(std::string_view text,
                                         const ParseOptions& options = {},
                                         std::string name = "<text>");

}  // namespace lsys
