// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include <cstdio>
#include <string>
#include <vector>

#include "formats.hpp"
#include "text_words.hpp"

namespace lsolid {

// OFF: `OFF`, the counts of vertices, faces and edges, the vertices, and
// each face as its corner count and corners (anything after them on its
// line, a colour, is skipped). Counts beyond what the file can hold (a
// vertex takes at least 6 bytes, a face 8) are refused before anything is
// allocated for them.
TriangleMesh decode_off(const std::string& data,
                        const std::filesystem::path& path) {
  Words words(data, path);
  const std::string_view header = words.next();
  if (header != "OFF") words.refuse("'OFF'", header);
  const std::size_t vertex_count =
      words.count("the number of vertices", "vertices", data.size() / 6);
  const std::size_t face_count =
      words.count("the number of faces", "faces", data.size() / 8);
  (void)words.count("the number of edges", "edges", data.size());
  TriangleMesh mesh;
  mesh.vertices.resize(vertex_count);
  for (glm::dvec3& p : mesh.vertices) {
    p = {words.number(true), words.number(true), words.number(true)};
  }
  for (std::size_t f = 0; f < face_count; ++f) {
    const std::size_t n =
        words.count("the number of corners", "corners", data.size() / 2);
    if (n < 3) words.refuse_here("a face needs at least 3 corners");
    std::vector<std::uint32_t> polygon(n);
    for (std::uint32_t& v : polygon) {
      v = static_cast<std::uint32_t>(
          words.count("a vertex index", "vertices", data.size()));
      if (v >= vertex_count) {
        words.refuse_here("no vertex " + std::to_string(v) + ": the file has " +
                          std::to_string(vertex_count));
      }
    }
    words.skip_line();
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {  // a convex fan
      mesh.triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
    }
  }
  return mesh;
}

std::string encode_off(const TriangleMesh& mesh) {
  std::string out;
  char line[160];
  out = "OFF\n" + std::to_string(mesh.vertices.size()) + " " +
        std::to_string(mesh.triangles.size()) + " 0\n";
  for (const glm::dvec3& p : mesh.vertices) {
    std::snprintf(line, sizeof(line), "%.17g %.17g %.17g\n", p.x, p.y, p.z);
    out += line;
  }
  for (const auto& t : mesh.triangles) {
    out += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " +
           std::to_string(t[2]) + "\n";
  }
  return out;
}

}  // namespace lsolid
