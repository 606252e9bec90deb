// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>

#include "formats.hpp"
#include "material_names.hpp"
#include "text_words.hpp"

namespace lsolid {

// Wavefront OBJ: `v x y z` and `f a b c ...` (1-based, negative from the
// end, `a/t/n` forms), faces fanned; `o` starts a volume and `usemtl
// colour_N` sets the colour of the faces that follow.
std::vector<ColoredMesh> decode_obj(const std::string& data,
                                    const std::filesystem::path& path) {
  std::istringstream in(data);
  std::string line;
  std::vector<glm::dvec3> points;
  std::vector<ColoredMesh> volumes(1);
  std::unordered_map<std::uint32_t, std::uint32_t> local;
  int color = 0;
  std::size_t next_line = 0;
  while (std::getline(in, line)) {
    const std::size_t start = next_line;
    next_line += line.size() + 1;
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    const auto bad = [&](const std::string& what) {
      const std::size_t tag_at = line.find_first_not_of(" \t");
      malformed(path, data, start + (tag_at == std::string::npos ? 0 : tag_at),
                what);
    };
    if (tag == "v") {
      glm::dvec3 p;
      if (!(words >> p.x >> p.y >> p.z)) bad("a vertex is 'v' and 3 numbers");
      points.push_back(p);
    } else if (tag == "o" || tag == "g") {
      if (!volumes.back().mesh.triangles.empty()) {
        volumes.emplace_back();
        local.clear();
      }
    } else if (tag == "usemtl") {
      std::string name;
      words >> name;
      color = color_of_material(name);
    } else if (tag == "f") {
      std::vector<std::uint32_t> polygon;
      std::string corner;
      while (words >> corner) {
        long index = 0;
        try {
          index = std::stol(corner.substr(0, corner.find('/')));
        } catch (const std::exception&) {
          bad("bad face");
        }
        if (index < 0) index += static_cast<long>(points.size()) + 1;
        if (index < 1 || index > static_cast<long>(points.size())) {
          bad("a face names a missing vertex");
        }
        const auto global = static_cast<std::uint32_t>(index - 1);
        ColoredMesh& v = volumes.back();
        const auto [it, inserted] = local.try_emplace(
            global, static_cast<std::uint32_t>(v.mesh.vertices.size()));
        if (inserted) v.mesh.vertices.push_back(points[global]);
        polygon.push_back(it->second);
      }
      if (polygon.size() < 3) bad("a face has fewer than 3 vertices");
      for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
        volumes.back().mesh.triangles.push_back(
            {polygon[0], polygon[k], polygon[k + 1]});
        volumes.back().colors.push_back(color);
      }
    }
  }
  if (volumes.back().mesh.triangles.empty() && volumes.size() > 1) {
    volumes.pop_back();
  }
  return volumes;
}

std::string encode_mtl(const std::vector<ColoredMesh>& volumes,
                       const std::vector<Rgb>& colors) {
  std::map<int, bool> used;
  for (const ColoredMesh& v : volumes) {
    if (v.colors.empty()) used[0] = true;
    for (const int c : v.colors) used[c] = true;
  }
  std::string out = "# lsolid: the turtle's colours (ABOP's ')\n";
  char line[160];
  for (const auto& [color, _] : used) {
    const Rgb rgb = palette_color(color, colors);
    std::snprintf(line, sizeof(line),
                  "\nnewmtl %s\nKa 0 0 0\nKd %.6g %.6g %.6g\nKs 0 0 0\nd 1\n"
                  "illum 1\n",
                  material_name(color, '_').c_str(), rgb.r / 255.0,
                  rgb.g / 255.0, rgb.b / 255.0);
    out += line;
  }
  return out;
}

std::string encode_obj(const std::vector<ColoredMesh>& volumes,
                       const std::filesystem::path& mtl) {
  std::string out =
      "# lsolid: closed 2-manifold volumes in millimetres\nmtllib " +
      mtl.filename().string() + "\n";
  char line[160];
  std::size_t base = 1;
  for (std::size_t i = 0; i < volumes.size(); ++i) {
    const ColoredMesh& v = volumes[i];
    out += volumes.size() == 1 ? std::string("o model\n")
                               : "o volume_" + std::to_string(i + 1) + "\n";
    for (const glm::dvec3& p : v.mesh.vertices) {
      std::snprintf(line, sizeof(line), "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
      out += line;
    }
    int current = -1;
    for (std::size_t t = 0; t < v.mesh.triangles.size(); ++t) {
      const int color = v.colors.empty() ? 0 : v.colors[t];
      if (color != current) {
        out += "usemtl " + material_name(color, '_') + "\n";
        current = color;
      }
      const auto& tri = v.mesh.triangles[t];
      out += "f " + std::to_string(base + tri[0]) + " " +
             std::to_string(base + tri[1]) + " " +
             std::to_string(base + tri[2]) + "\n";
    }
    base += v.mesh.vertices.size();
  }
  return out;
}

}  // namespace lsolid
