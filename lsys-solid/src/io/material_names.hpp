// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <string_view>

namespace lsolid {

/// The name of the material of a turtle colour index in the files lsolid
/// writes: `colour N` in 3MF, `colour_N` in OBJ and MTL (whose names are
/// single words).
[[nodiscard]] std::string material_name(int color, char separator);

/// The colour index a material name gives (`colour N` or `colour_N`), or 0
/// for a name lsolid did not write.
[[nodiscard]] int color_of_material(std::string_view name);

}  // namespace lsolid
