// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

namespace lsolid::cli {

/// Sets glibc's allocator to keep the memory a build frees for the next
/// allocations rather than hand it back to the system and touch it afresh.
/// Called first thing in main; memory.cpp says why, with figures.
void keep_freed_memory();

}  // namespace lsolid::cli
