// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// STL, binary and ASCII. Vertices with equal float coordinates are merged
// as they are read; facet normals are written as admesh recomputes them.
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/geometric.hpp>
#include <unordered_map>

#include "formats.hpp"
#include "text_words.hpp"
#include "vertex_key.hpp"

namespace lsolid {
namespace {

class SoupBuilder {
 public:
  void add(const std::array<glm::dvec3, 3>& corners) {
    std::array<std::uint32_t, 3> t{};
    for (int i = 0; i < 3; ++i) {
      const FloatKey key = float_key(corners[i]);
      const auto [it, inserted] = index_.emplace(
          key, static_cast<std::uint32_t>(mesh_.vertices.size()));
      if (inserted) mesh_.vertices.push_back(key_point(key));
      t[i] = it->second;
    }
    mesh_.triangles.push_back(t);
  }
  TriangleMesh take() { return std::move(mesh_); }

 private:
  TriangleMesh mesh_;
  std::unordered_map<FloatKey, std::uint32_t, FloatKeyHash> index_;
};

// The facet normal exactly as admesh recomputes it from the stored float
// corners (stl_calculate_normal and stl_normalize_vector in admesh's
// normals.c: float edge vectors, the first product of each component
// rounded to float), so that comparing the two finds nothing to "fix", even
// on thin facets where float arithmetic loses digits.
glm::vec3 facet_normal(const TriangleMesh& mesh,
                       const std::array<std::uint32_t, 3>& t) {
  std::array<float, 3> p0{};
  std::array<float, 3> v1{};
  std::array<float, 3> v2{};
  for (int k = 0; k < 3; ++k) {
    p0[static_cast<std::size_t>(k)] = to_float(mesh.vertices[t[0]][k]);
    v1[static_cast<std::size_t>(k)] =
        to_float(mesh.vertices[t[1]][k]) - p0[static_cast<std::size_t>(k)];
    v2[static_cast<std::size_t>(k)] =
        to_float(mesh.vertices[t[2]][k]) - p0[static_cast<std::size_t>(k)];
  }
  const auto component = [&](int a, int b) {
    const double first = static_cast<double>(static_cast<float>(
        static_cast<double>(v1[static_cast<std::size_t>(a)]) *
        static_cast<double>(v2[static_cast<std::size_t>(b)])));
    return static_cast<float>(
        first - static_cast<double>(v1[static_cast<std::size_t>(b)]) *
                    static_cast<double>(v2[static_cast<std::size_t>(a)]));
  };
  std::array<float, 3> n{component(1, 2), component(2, 0), component(0, 1)};
  const double length = std::sqrt(static_cast<double>(n[0]) * n[0] +
                                  static_cast<double>(n[1]) * n[1] +
                                  static_cast<double>(n[2]) * n[2]);
  if (length < 1e-12) return glm::vec3(0.0F);
  const double factor = 1.0 / length;
  for (float& c : n) c = static_cast<float>(c * factor);
  return {n[0], n[1], n[2]};
}

}  // namespace

TriangleMesh decode_binary_stl(const std::string& data,
                               const std::filesystem::path& path) {
  std::uint32_t count = 0;
  std::memcpy(&count, data.data() + 80, 4);
  if (data.size() != 84 + 50ULL * count)
    malformed(path, "truncated binary STL");
  SoupBuilder soup;
  for (std::uint32_t i = 0; i < count; ++i) {
    const char* record = data.data() + 84 + 50ULL * i;
    std::array<float, 9> xyz{};
    std::memcpy(xyz.data(), record + 12, sizeof(xyz));
    std::array<glm::dvec3, 3> corners;
    for (int k = 0; k < 3; ++k) {
      corners[k] = {xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]};
      if (!std::isfinite(corners[k].x) || !std::isfinite(corners[k].y) ||
          !std::isfinite(corners[k].z)) {
        malformed(path,
                  "triangle " + std::to_string(i) + " has a non-finite vertex");
      }
    }
    soup.add(corners);
  }
  return soup.take();
}

// ASCII STL word by word, as its grammar has it: `solid name`, then per
// facet `facet normal nx ny nz`, `outer loop`, three `vertex x y z`,
// `endloop`, `endfacet`, and `endsolid name` (several solids may follow
// one another). Anything else is refused at its place, rather than
// skipped: a file of nonsense after `solid` read as no triangles at all.
TriangleMesh decode_ascii_stl(const std::string& data,
                              const std::filesystem::path& path) {
  Words words(data, path);
  SoupBuilder soup;
  bool has_solid = false;
  for (std::string_view word = words.next(); !word.empty() || !has_solid;
       word = words.next()) {
    if (word != "solid") words.refuse("'solid'", word);
    has_solid = true;
    words.skip_line();  // the name
    for (;;) {
      word = words.next();
      if (word == "endsolid") break;
      if (word != "facet") words.refuse("'facet' or 'endsolid'", word);
      words.expect("normal");
      // Normals are recomputed; some exporters write nan there.
      for (int k = 0; k < 3; ++k) (void)words.number(false);
      words.expect("outer");
      words.expect("loop");
      std::array<glm::dvec3, 3> corners;
      for (glm::dvec3& p : corners) {
        words.expect("vertex");
        p = {words.number(true), words.number(true), words.number(true)};
      }
      words.expect("endloop");
      words.expect("endfacet");
      soup.add(corners);
    }
    words.skip_line();
  }
  return soup.take();
}

std::string encode_binary_stl(const TriangleMesh& mesh) {
  std::string out;
  out.assign(80, '\0');
  const char header[] = "lsolid binary STL, millimetres";
  std::memcpy(out.data(), header, sizeof(header) - 1);
  const auto count = static_cast<std::uint32_t>(mesh.triangles.size());
  out.append(reinterpret_cast<const char*>(&count), 4);
  out.reserve(84 + 50ULL * count);
  for (const auto& t : mesh.triangles) {
    std::array<float, 12> record{};
    const glm::vec3 n = facet_normal(mesh, t);
    record[0] = n.x;
    record[1] = n.y;
    record[2] = n.z;
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3& p = mesh.vertices[t[static_cast<std::size_t>(k)]];
      record[3 + 3 * k] = static_cast<float>(p.x);
      record[4 + 3 * k] = static_cast<float>(p.y);
      record[5 + 3 * k] = static_cast<float>(p.z);
    }
    out.append(reinterpret_cast<const char*>(record.data()), sizeof(record));
    out.append(2, '\0');
  }
  return out;
}

std::string encode_ascii_stl(const TriangleMesh& mesh) {
  std::string out;
  char line[160];
  out = "solid lsolid\n";
  for (const auto& t : mesh.triangles) {
    const glm::vec3 n = facet_normal(mesh, t);
    std::snprintf(line, sizeof(line),
                  " facet normal %.9g %.9g %.9g\n  outer loop\n", n.x, n.y,
                  n.z);
    out += line;
    for (const std::uint32_t v : t) {
      const glm::vec3 p(mesh.vertices[v]);
      std::snprintf(line, sizeof(line), "   vertex %.9g %.9g %.9g\n", p.x, p.y,
                    p.z);
      out += line;
    }
    out += "  endloop\n endfacet\n";
  }
  out += "endsolid lsolid\n";
  return out;
}

}  // namespace lsolid
