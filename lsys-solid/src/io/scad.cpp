// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include <cctype>
#include <charconv>
#include <cstdio>
#include <iterator>
#include <string>

#include "formats.hpp"

namespace lsolid {
namespace {

// An OpenSCAD identifier from a file name: `abop-1.25-bush` gives
// `lsolid_abop_1_25_bush`. The prefix keeps it clear of OpenSCAD's keywords
// (`for`, `module`) and built-in modules (`cube`, `polyhedron`).
std::string scad_module_name(const std::filesystem::path& path) {
  std::string name = "lsolid_" + path.stem().string();
  for (char& c : name) {
    if (std::isalnum(static_cast<unsigned char>(c)) == 0) c = '_';
  }
  return name;
}

}  // namespace

std::string encode_scad(const TriangleMesh& mesh,
                        const std::filesystem::path& path) {
  std::string out;
  // OpenSCAD wants each face's points clockwise seen from outside, the
  // opposite of our counter-clockwise triangles.
  const std::string name = scad_module_name(path);
  out =
      "// Written by lsolid: one closed, 2-manifold solid in millimetres.\n"
      "// `use <" +
      path.filename().string() + ">` and call " + name +
      "() to combine it with your own parts.\nmodule " + name +
      "() {\n  polyhedron(points = [\n";
  // The shortest text that reads back as the very double: OpenSCAD reads
  // doubles, and the mesh was checked at exactly these coordinates
  // (Precision::Kind::DecimalFloat).
  const auto number = [&](double x) {
    char text[32];
    const auto end = std::to_chars(std::begin(text), std::end(text), x).ptr;
    out.append(text, end);
  };
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const glm::dvec3& v = mesh.vertices[i];
    out += "    [";
    number(v.x);
    out += ", ";
    number(v.y);
    out += ", ";
    number(v.z);
    out += i + 1 < mesh.vertices.size() ? "],\n" : "]\n";
  }
  out += "  ], faces = [\n";
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    out += "    [" + std::to_string(t[0]) + ", " + std::to_string(t[2]) + ", " +
           std::to_string(t[1]) + "]" +
           (i + 1 < mesh.triangles.size() ? ",\n" : "\n");
  }
  out += "  ], convexity = 10);\n}\n\n" + name + "();\n";
  return out;
}

}  // namespace lsolid
