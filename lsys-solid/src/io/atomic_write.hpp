// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>

namespace lsolid {

/// Writes `data` so that the file is either complete or absent: it goes to
/// a hidden temporary file in the same folder, which is renamed over `path`
/// only when complete and synced. An existing file is untouched on failure.
/// A symbolic link is written through (output_target).
/// @throws IoError naming `path`, also when it is not a regular file.
void write_file_atomically(const std::filesystem::path& path,
                           const std::string& data);

}  // namespace lsolid
