// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <string_view>

namespace lsolid::cli::view {

/// The viewer's page, its script and its style sheet, built into lsolid
/// from lsys-solid/cli/view/assets/ (CMake writes assets.cpp from them), so
/// that the server reads no file of its own at run time.
extern const std::string_view kIndexHtml;
extern const std::string_view kViewerJs;
extern const std::string_view kViewerCss;

}  // namespace lsolid::cli::view
