// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lsys/parser.hpp"
#include "lsys/source.hpp"

namespace lsys::dialects {

/// The files a model names besides itself (`#include "…"`, and a view
/// file's `function:`, `function set:`, `surface:` and `contour:` files),
/// and the one rule by which they are read: a model is a file people
/// download, so it reads nothing but its own folder's files.
///
/// The folders a model may read are the folder of its own file, the folder
/// of a view file the user named (`--view`) and the folders the user
/// allowed (`--include-dir`). A name resolves beside the file that writes
/// it, as C's `#include "…"` does, then in each allowed folder, and is
/// refused before anything is opened when it is absolute, holds a `..`
/// part, leads out of every allowed folder through a symbolic link, or is
/// not a regular file (docs/dialects/cpfg.md, "Files a model reads").
/// Each file is read once, however often it is named; the files read
/// together are bounded.
///
/// Invariant: every file in the cache is a regular file inside an allowed
/// folder, and the bytes named so far (each naming counted) are at most
/// kMaxSourceBytes.
class CompanionFiles {
 public:
  /// The folders a model read through `options` may read: the model's
  /// (`model_name`'s folder, the current one when it has none), the
  /// `--view` file's and `options.include_dirs`.
  CompanionFiles(const std::string& model_name, const ParseOptions& options);

  /// The file that `name` names, written in `naming` at byte `offset` of its
  /// text in a `what` (`#include`, `function:`).
  /// @throws ParseError at that place, quoting the name as written and never
  ///   the file's text, when the name is refused (above) or missing, when
  ///   the files named together pass kMaxSourceBytes, and as load_source.
  [[nodiscard]] std::shared_ptr<const SourceFile> load(const SourceFile& naming,
                                                       std::size_t offset,
                                                       std::string_view what,
                                                       const std::string& name);

  /// Whether a file found without being named (the `.v` beside the model,
  /// the folder's only `.fset`) may be read: a regular file inside an
  /// allowed folder. `std::nullopt` when it may; otherwise why not.
  [[nodiscard]] std::optional<std::string> refusal(
      const std::filesystem::path& path) const;

 private:
  // As refusal, for a path whose links are resolved already.
  [[nodiscard]] std::optional<std::string> refusal_of_canonical(
      const std::filesystem::path& canonical) const;

  std::vector<std::filesystem::path> roots_;  // canonical
  std::map<std::filesystem::path, std::shared_ptr<const SourceFile>> read_;
  std::size_t named_bytes_ = 0;
};

}  // namespace lsys::dialects
