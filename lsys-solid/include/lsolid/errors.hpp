// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <stdexcept>
#include <string>

namespace lsolid {

/// A geometric operation could not deliver a valid result (for example a
/// boolean union that stays invalid after retries). The CLI exits with 3.
class GeometryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reading or writing a file failed. The CLI exits with 4.
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace lsolid
