// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>

namespace lsolid {

/// The file that writing to `path` replaces: `path` itself, or, when `path`
/// is a symbolic link, the file the link leads to (through any chain of
/// links), so that the link stays a link and its target gets the new
/// contents. The target need not exist yet.
/// @throws IoError when the target exists and is not a regular file (a
///   directory, FIFO, device or socket: `'x.stl' is a FIFO (named pipe);
///   lsolid writes only regular files`), or the links loop.
[[nodiscard]] std::filesystem::path output_target(
    const std::filesystem::path& path);

}  // namespace lsolid
