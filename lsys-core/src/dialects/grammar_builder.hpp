// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include "dialects/draft.hpp"
#include "dialects/text_scan.hpp"
#include "lsys/grammar.hpp"
#include "lsys/parser.hpp"

namespace lsys::dialects {

/// Builds the grammar from a front end's draft: constants, module names
/// (multi-character names first, so that text is split by longest match),
/// aliases, settings, axiom and productions, and each symbol's command.
/// @throws ParseError at the place of anything malformed.
[[nodiscard]] Grammar build_grammar(const TextScan& scan, Draft draft,
                                    const ParseOptions& options);

}  // namespace lsys::dialects
