// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "lsolid/mesh.hpp"

namespace lsolid {

/// The pairs of boxes that meet, closed boxes (touching counts), for which
/// `keep` is true, each pair once as (i, j) with i < j, in increasing
/// order. The pairs whose boxes meet are those CGAL's
/// box_self_intersection_d finds over closed boxes; the answer depends on
/// nothing but the boxes and `keep`. Found on oneTBB's threads in a uniform
/// grid about two median boxes wide; the boxes over more than 64 of its
/// cells are searched, against the others and among themselves, in a grid
/// as coarse as they are. `keep` is called on those threads, once for each
/// pair that meets.
[[nodiscard]] std::vector<std::pair<std::uint32_t, std::uint32_t>>
meeting_box_pairs(
    const std::vector<Box>& boxes,
    const std::function<bool(std::uint32_t, std::uint32_t)>& keep);

/// The pairs (i, j) of a box of `first` and a box of `second` that meet,
/// closed boxes, for which `keep` is true, in increasing order: the pairs
/// CGAL's box_intersection_d finds over closed boxes, found as above.
/// @pre as above, for both sets.
[[nodiscard]] std::vector<std::pair<std::uint32_t, std::uint32_t>>
meeting_box_pairs(
    const std::vector<Box>& first, const std::vector<Box>& second,
    const std::function<bool(std::uint32_t, std::uint32_t)>& keep);

}  // namespace lsolid
