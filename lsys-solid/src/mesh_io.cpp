// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// STL (binary and ASCII), OFF, SCAD and OBJ, written through a temporary
// file that is renamed into place, so an output is complete or absent; 3MF
// is encoded by lib3mf in mesh_3mf.cpp.
#include "lsolid/mesh_io.hpp"

#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <sstream>
#include <unordered_map>

#include "atomic_write.hpp"
#include "lsolid/errors.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/source.hpp"
#include "mesh_3mf.hpp"
#include "vertex_key.hpp"

namespace lsolid {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path,
                       const std::string& what) {
  throw IoError(path.string() + ": " + what);
}

// Malformed content is bad input (lsys::ParseError): in a text format at
// its line and column, shown with the line and a caret; the text is copied
// into a SourceFile only then.
[[noreturn]] void malformed(const std::filesystem::path& path,
                            const std::string& data, std::size_t offset,
                            const std::string& message) {
  const lsys::SourceFile source(path.string(), data);
  // SourceFile drops a UTF-8 byte order mark.
  const std::size_t removed = data.size() - source.text().size();
  throw lsys::error_at(source, offset - std::min(offset, removed), message);
}

// Malformed content of a binary format, or of the file as a whole.
[[noreturn]] void malformed(const std::filesystem::path& path,
                            const std::string& message) {
  throw lsys::ParseError(
      lsys::Diagnostic{.file = path.string(), .message = message});
}

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

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

TriangleMesh read_binary_stl(const std::string& data,
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

// The words of a text format, separated by white space, with their places.
class Words {
 public:
  Words(const std::string& data, const std::filesystem::path& path)
      : data_(data), path_(path) {}

  std::string_view next() {
    while (at_ < data_.size() &&
           std::isspace(static_cast<unsigned char>(data_[at_])) != 0) {
      ++at_;
    }
    begin_ = at_;
    while (at_ < data_.size() &&
           std::isspace(static_cast<unsigned char>(data_[at_])) == 0) {
      ++at_;
    }
    return std::string_view(data_).substr(begin_, at_ - begin_);
  }
  void skip_line() {
    while (at_ < data_.size() && data_[at_] != '\n') ++at_;
  }
  // Refuses the word last read: `expected X, not 'word'`.
  [[noreturn]] void refuse(const std::string& expected,
                           std::string_view word) const {
    if (word.empty()) {
      malformed(path_, "the file ends where " + expected + " should follow");
    }
    // A word is shown up to 32 characters (a binary file may have none).
    std::string shown(word.substr(0, 32));
    if (word.size() > 32) shown += "...";
    malformed(path_, data_, begin_,
              "expected " + expected + ", not '" + shown + "'");
  }
  [[noreturn]] void refuse_here(const std::string& message) const {
    malformed(path_, data_, begin_, message);
  }
  void expect(std::string_view word) {
    const std::string_view got = next();
    // (Appending piecewise avoids a GCC 12 -Wrestrict false alarm.)
    if (got != word) refuse(std::string(1, '\'').append(word).append("'"), got);
  }
  double number(bool must_be_finite) {
    const std::string_view word = next();
    double value = 0.0;
    const auto [end, error] =
        std::from_chars(word.data(), word.data() + word.size(), value);
    if (word.empty() || error != std::errc() ||
        end != word.data() + word.size() ||
        (must_be_finite && !std::isfinite(value))) {
      refuse(must_be_finite ? "a finite number" : "a number", word);
    }
    return value;
  }
  // A whole number from 0 to `most` of `things`, where a count is
  // `expected`.
  std::size_t count(const std::string& expected, const std::string& things,
                    std::size_t most) {
    const std::string_view word = next();
    std::size_t value = 0;
    const auto [end, error] =
        std::from_chars(word.data(), word.data() + word.size(), value);
    if (word.empty() || error != std::errc() ||
        end != word.data() + word.size()) {
      refuse(expected, word);
    }
    if (value > most) {
      refuse_here(std::string(word) + " " + things +
                  " do not fit in a file of " + std::to_string(data_.size()) +
                  " bytes");
    }
    return value;
  }

 private:
  const std::string& data_;
  const std::filesystem::path& path_;
  std::size_t at_ = 0;
  std::size_t begin_ = 0;
};

// ASCII STL word by word, as its grammar has it: `solid name`, then per
// facet `facet normal nx ny nz`, `outer loop`, three `vertex x y z`,
// `endloop`, `endfacet`, and `endsolid name` (several solids may follow
// one another). Anything else is refused at its place, rather than
// skipped: a file of nonsense after `solid` read as no triangles at all.
TriangleMesh read_ascii_stl(const std::string& data,
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

// OFF: `OFF`, the counts of vertices, faces and edges, the vertices, and
// each face as its corner count and corners (anything after them on its
// line, a colour, is skipped). Counts beyond what the file can hold (a
// vertex takes at least 6 bytes, a face 8) are refused before anything is
// allocated for them.
TriangleMesh read_off(const std::string& data,
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

std::string encode(const TriangleMesh& mesh, MeshFormat format,
                   const std::filesystem::path& path) {
  std::string out;
  char line[160];
  switch (format) {
    case MeshFormat::StlBinary: {
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
        out.append(reinterpret_cast<const char*>(record.data()),
                   sizeof(record));
        out.append(2, '\0');
      }
      return out;
    }
    case MeshFormat::StlAscii:
      out = "solid lsolid\n";
      for (const auto& t : mesh.triangles) {
        const glm::vec3 n = facet_normal(mesh, t);
        std::snprintf(line, sizeof(line),
                      " facet normal %.9g %.9g %.9g\n  outer loop\n", n.x, n.y,
                      n.z);
        out += line;
        for (const std::uint32_t v : t) {
          const glm::vec3 p(mesh.vertices[v]);
          std::snprintf(line, sizeof(line), "   vertex %.9g %.9g %.9g\n", p.x,
                        p.y, p.z);
          out += line;
        }
        out += "  endloop\n endfacet\n";
      }
      out += "endsolid lsolid\n";
      return out;
    case MeshFormat::Off:
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
    case MeshFormat::Scad: {
      // OpenSCAD wants each face's points clockwise seen from outside, the
      // opposite of our counter-clockwise triangles.
      const std::string name = scad_module_name(path);
      out =
          "// Written by lsolid: one closed, 2-manifold solid in millimetres.\n"
          "// `use <" +
          path.filename().string() + ">` and call " + name +
          "() to combine it with your own parts.\nmodule " + name +
          "() {\n  polyhedron(points = [\n";
      for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
        const glm::dvec3& v = mesh.vertices[i];
        std::snprintf(line, sizeof(line), "    [%.9g, %.9g, %.9g]%s\n", v.x,
                      v.y, v.z, i + 1 < mesh.vertices.size() ? "," : "");
        out += line;
      }
      out += "  ], faces = [\n";
      for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const auto& t = mesh.triangles[i];
        out += "    [" + std::to_string(t[0]) + ", " + std::to_string(t[2]) +
               ", " + std::to_string(t[1]) + "]" +
               (i + 1 < mesh.triangles.size() ? ",\n" : "\n");
      }
      out += "  ], convexity = 10);\n}\n\n" + name + "();\n";
      return out;
    }
    case MeshFormat::ThreeMf:
    case MeshFormat::Obj:
      break;  // written by write_colored
  }
  return out;
}

// Wavefront OBJ: `v x y z` and `f a b c ...` (1-based, negative from the
// end, `a/t/n` forms), faces fanned; `o` starts a volume and `usemtl
// colour_N` sets the colour of the faces that follow.
std::vector<ColoredMesh> read_obj(const std::string& data,
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
      color = 0;
      if (name.starts_with("colour_")) {
        try {
          color = std::stoi(name.substr(7));
        } catch (const std::exception&) {
          color = 0;
        }
      }
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

std::string obj_material(int color) {
  return "colour_" + std::to_string(color);
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
                  obj_material(color).c_str(), rgb.r / 255.0, rgb.g / 255.0,
                  rgb.b / 255.0);
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
        out += "usemtl " + obj_material(color) + "\n";
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

// Only regular files are read: a FIFO would block and a device such as
// /dev/zero never end.
void refuse_special_file(const std::filesystem::path& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!error && std::filesystem::exists(status) &&
      !std::filesystem::is_regular_file(status)) {
    fail(path, "cannot read: not a regular file");
  }
}

std::string read_file(const std::filesystem::path& path) {
  refuse_special_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot read: ") + std::strerror(errno));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

TriangleMesh merged(const std::vector<ColoredMesh>& volumes) {
  TriangleMesh mesh;
  for (const ColoredMesh& v : volumes) append(mesh, v.mesh);
  return mesh;
}

}  // namespace

MeshFormat format_for(const std::filesystem::path& path, bool ascii) {
  const std::string ext = lower_extension(path);
  if (ext == ".stl")
    return ascii ? MeshFormat::StlAscii : MeshFormat::StlBinary;
  if (ext == ".off") return MeshFormat::Off;
  if (ext == ".scad") return MeshFormat::Scad;
  if (ext == ".3mf") return MeshFormat::ThreeMf;
  if (ext == ".obj") return MeshFormat::Obj;
  throw IoError(path.string() + ": unknown output format '" + ext +
                "' (use .stl, .off, .scad, .3mf or .obj)");
}

TriangleMesh read_mesh(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".3mf" || ext == ".obj") return merged(read_colored(path));
  const std::string data = read_file(path);
  if (data.starts_with("OFF") || ext == ".off") return read_off(data, path);
  std::uint32_t count = 0;
  if (data.size() >= 84) {
    std::memcpy(&count, data.data() + 80, 4);
    if (data.size() == 84 + 50ULL * count) return read_binary_stl(data, path);
  }
  // Binary STL headers often start with "solid" too, but hold NUL bytes.
  const bool is_text =
      data.substr(0, std::min<std::size_t>(data.size(), 1024)).find('\0') ==
      std::string::npos;
  if (data.starts_with("solid") && is_text) return read_ascii_stl(data, path);
  if (data.size() >= 84 && !is_text) {
    malformed(path, "a damaged binary STL: its header counts " +
                        std::to_string(count) + " triangles (" +
                        std::to_string(84 + 50ULL * count) +
                        " bytes), the file has " + std::to_string(data.size()) +
                        " bytes");
  }
  malformed(path, "not an STL or OFF file");
}

std::vector<ColoredMesh> read_colored(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".3mf") {
    if (!std::filesystem::exists(path)) fail(path, "cannot read: no such file");
    refuse_special_file(path);
    return decode_3mf(path);
  }
  if (ext == ".obj") return read_obj(read_file(path), path);
  TriangleMesh mesh = read_mesh(path);
  const std::size_t n = mesh.triangles.size();
  return {
      ColoredMesh{.mesh = std::move(mesh), .colors = std::vector<int>(n, 0)}};
}

void write_mesh(const TriangleMesh& mesh, const std::filesystem::path& path,
                MeshFormat format) {
  if (format == MeshFormat::ThreeMf || format == MeshFormat::Obj) {
    write_colored({ColoredMesh{.mesh = mesh, .colors = {}}}, path, format);
    return;
  }
  write_file_atomically(path, encode(mesh, format, path));
}

void write_colored(const std::vector<ColoredMesh>& volumes,
                   const std::filesystem::path& path, MeshFormat format,
                   const std::vector<Rgb>& colors) {
  switch (format) {
    case MeshFormat::ThreeMf:
      write_file_atomically(path, encode_3mf(volumes, colors));
      return;
    case MeshFormat::Obj: {
      std::filesystem::path mtl = path;
      mtl.replace_extension(".mtl");
      write_file_atomically(mtl, encode_mtl(volumes, colors));
      write_file_atomically(path, encode_obj(volumes, mtl));
      return;
    }
    default:
      write_file_atomically(path, encode(merged(volumes), format, path));
  }
}

}  // namespace lsolid
