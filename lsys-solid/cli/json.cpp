// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "json.hpp"

namespace lsolid::cli {

Json json_point(const glm::dvec3& p) { return Json::array({p.x, p.y, p.z}); }

Json json_box(const lsys::Bounds& box) {
  return {{"min", json_point(box.min)}, {"max", json_point(box.max)}};
}

std::string json_line(const Json& value) {
  // Linux file names may hold any bytes; strict UTF-8 would throw on them.
  return value.dump(-1, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace lsolid::cli
