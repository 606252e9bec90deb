// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// 3MF through lib3mf 1.8.1, the version Debian 12 packages: its C interface
// (NMR_DLLInterfaces.h; lib3mf 2.x's C++ bindings are not packaged). The
// only translation unit that includes lib3mf.
#include <Model/COM/NMR_DLLInterfaces.h>
#include <fmt/format.h>

#include <algorithm>
#include <boost/uuid/name_generator_sha1.hpp>
#include <boost/uuid/uuid_io.hpp>
#include <charconv>
#include <map>
#include <string_view>
#include <utility>

#include "formats.hpp"
#include "lsolid/errors.hpp"
#include "material_names.hpp"

namespace lsolid {
namespace {

using namespace NMR;

// Owns one lib3mf instance.
class Handle {
 public:
  Handle() = default;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() {
    if (p_ != nullptr) lib3mf_release(p_);
  }
  PLib3MFBase* get() const { return p_; }
  PLib3MFBase** out() { return &p_; }

 private:
  PLib3MFBase* p_ = nullptr;
};

void check(LIB3MFRESULT result, PLib3MFBase* instance, const char* what) {
  if (result == LIB3MF_OK) return;
  DWORD code = 0;
  LPCSTR message = nullptr;
  if (instance != nullptr) lib3mf_getlasterror(instance, &code, &message);
  throw IoError(std::string("3MF: ") + what + " failed" +
                (message != nullptr && *message != '\0'
                     ? std::string(": ") + message
                     : std::string()));
}

constexpr const char* kPrusaConfigPath = "/Metadata/Slic3r_PE_model.config";
constexpr const char* kPrusaConfigRelationship =
    "http://schemas.slic3r.org/3mf/2017/06/model-config";

// lib3mf gives the object, the build and its item random UUIDs (3MF's
// production extension), so two runs wrote different files. These are
// name-based UUIDs (RFC 4122 version 5, Boost.Uuid) of the role and the
// mesh's coordinates and triangles: the same mesh gives the same bytes,
// and different meshes different UUIDs.
std::string stable_uuid(const TriangleMesh& mesh, std::string_view role) {
  std::string name(role);
  const auto append = [&](const auto& values) {
    name.append(reinterpret_cast<const char*>(values.data()),
                values.size() * sizeof(values[0]));
  };
  append(mesh.vertices);
  append(mesh.triangles);
  const boost::uuids::name_generator_sha1 generate(boost::uuids::ns::oid());
  return boost::uuids::to_string(generate(name));
}

// Adds one mesh object with per-triangle base materials; the caller
// releases it.
PLib3MFModelMeshObject* add_mesh(PLib3MFModel* model, const ColoredMesh& volume,
                                 DWORD group_id,
                                 const std::map<int, DWORD>& material,
                                 const std::string& name) {
  PLib3MFModelMeshObject* object = nullptr;
  check(lib3mf_model_addmeshobject(model, &object), model, "adding a mesh");
  Handle owner;
  *owner.out() = object;
  std::vector<MODELMESHVERTEX> vertices(volume.mesh.vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const glm::dvec3& p = volume.mesh.vertices[i];
    vertices[i] = {{static_cast<FLOAT>(p.x), static_cast<FLOAT>(p.y),
                    static_cast<FLOAT>(p.z)}};
  }
  std::vector<MODELMESHTRIANGLE> triangles(volume.mesh.triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = volume.mesh.triangles[i];
    triangles[i] = {{t[0], t[1], t[2]}};
  }
  check(lib3mf_meshobject_setgeometry(
            object, vertices.data(), static_cast<DWORD>(vertices.size()),
            triangles.data(), static_cast<DWORD>(triangles.size())),
        object, "setting the geometry");
  check(lib3mf_object_setnameutf8(object, name.c_str()), object,
        "naming an object");
  check(lib3mf_object_setuuidutf8(object,
                                  stable_uuid(volume.mesh, "object").c_str()),
        object, "setting the object's UUID");
  check(lib3mf_object_settype(object, MODELOBJECTTYPE_MODEL), object,
        "setting the object type");
  const auto color_at = [&](std::size_t t) {
    return volume.colors.empty() ? 0 : volume.colors[t];
  };
  // The object's default material is its first triangle's: the 3MF core
  // wants a pid on the object when its triangles have one.
  Handle defaults;
  check(lib3mf_object_createdefaultpropertyhandler(
            object,
            reinterpret_cast<PLib3MFDefaultPropertyHandler**>(defaults.out())),
        object, "setting the default material");
  check(lib3mf_defaultpropertyhandler_setbasematerial(
            defaults.get(), group_id,
            material.at(triangles.empty() ? 0 : color_at(0))),
        defaults.get(), "setting the default material");
  if (!triangles.empty()) {
    Handle properties;
    check(lib3mf_meshobject_createpropertyhandler(
              object,
              reinterpret_cast<PLib3MFPropertyHandler**>(properties.out())),
          object, "setting the materials");
    std::vector<ModelResourceID> groups(triangles.size(), group_id);
    std::vector<DWORD> indices(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      indices[t] = material.at(color_at(t));
    }
    check(lib3mf_propertyhandler_setbasematerialarray(
              properties.get(), groups.data(), indices.data()),
          properties.get(), "setting the materials");
  }
  *owner.out() = nullptr;
  return object;
}

// The triangle ranges (first, last) of the volumes PrusaSlicer's metadata
// lists, in the order given; empty without that metadata. Only one object
// is expected, as lsolid writes.
std::vector<std::pair<std::size_t, std::size_t>> volume_ranges(
    PLib3MFModel* model) {
  std::vector<std::pair<std::size_t, std::size_t>> ranges;
  DWORD count = 0;
  if (lib3mf_model_getattachmentcount(model, &count) != LIB3MF_OK) return {};
  for (DWORD i = 0; i < count; ++i) {
    ULONG needed = 0;
    lib3mf_model_getattachmentpathutf8(model, i, nullptr, 0, &needed);
    std::string name(needed + 1, '\0');
    if (lib3mf_model_getattachmentpathutf8(model, i, name.data(), needed + 1,
                                           &needed) != LIB3MF_OK) {
      continue;
    }
    name.resize(needed);
    if (name != kPrusaConfigPath) continue;
    Handle attachment;
    if (lib3mf_model_getattachment(model, i, attachment.out()) != LIB3MF_OK) {
      continue;
    }
    ULONG64 size = 0;
    lib3mf_attachment_getstreamsize(attachment.get(), &size);
    std::string text(size, '\0');
    if (lib3mf_attachment_writetobuffer(attachment.get(),
                                        reinterpret_cast<BYTE*>(text.data()),
                                        size) != LIB3MF_OK) {
      continue;
    }
    const std::string first_key = "firstid=\"";
    const std::string last_key = "lastid=\"";
    for (std::size_t at = text.find(first_key); at != std::string::npos;
         at = text.find(first_key, at + 1)) {
      const std::size_t last_at = text.find(last_key, at);
      if (last_at == std::string::npos) break;
      std::size_t first = 0;
      std::size_t last = 0;
      const char* a = text.data() + at + first_key.size();
      const char* b = text.data() + last_at + last_key.size();
      if (std::from_chars(a, text.data() + text.size(), first).ec ==
              std::errc() &&
          std::from_chars(b, text.data() + text.size(), last).ec ==
              std::errc() &&
          first <= last) {
        ranges.emplace_back(first, last);
      }
    }
  }
  return ranges;
}

// The volumes of one mesh object: the triangle ranges, each on its own
// vertices, or the whole mesh if the ranges do not fit it.
std::vector<ColoredMesh> split(
    const ColoredMesh& mesh,
    const std::vector<std::pair<std::size_t, std::size_t>>& ranges) {
  if (ranges.empty() ||
      ranges.back().second + 1 != mesh.mesh.triangles.size()) {
    return {mesh};
  }
  std::vector<ColoredMesh> volumes;
  for (const auto& [first, last] : ranges) {
    ColoredMesh v;
    std::map<std::uint32_t, std::uint32_t> local;
    for (std::size_t t = first; t <= last; ++t) {
      std::array<std::uint32_t, 3> tri{};
      for (int c = 0; c < 3; ++c) {
        const std::uint32_t g = mesh.mesh.triangles[t][c];
        const auto [it, inserted] = local.try_emplace(
            g, static_cast<std::uint32_t>(v.mesh.vertices.size()));
        if (inserted) v.mesh.vertices.push_back(mesh.mesh.vertices[g]);
        tri[c] = it->second;
      }
      v.mesh.triangles.push_back(tri);
      if (!mesh.colors.empty()) v.colors.push_back(mesh.colors[t]);
    }
    volumes.push_back(std::move(v));
  }
  return volumes;
}

}  // namespace

std::string encode_3mf(const std::vector<ColoredMesh>& volumes,
                       const std::vector<Rgb>& colors) {
  Handle model;
  check(lib3mf_createmodel(model.out()), nullptr, "creating a model");
  check(lib3mf_model_setunit(model.get(), MODELUNIT_MILLIMETER), model.get(),
        "setting the unit");
  std::map<int, DWORD> material;
  for (const ColoredMesh& v : volumes) {
    if (v.colors.empty()) material.emplace(0, 0);
    for (const int c : v.colors) material.emplace(c, 0);
  }
  if (material.empty()) material.emplace(0, 0);
  Handle group;
  check(lib3mf_model_addbasematerialgroup(model.get(), group.out()),
        model.get(), "adding the materials");
  for (auto& [color, index] : material) {
    const Rgb rgb = palette_color(color, colors);
    check(lib3mf_basematerial_addmaterialutf8(group.get(),
                                              material_name(color, ' ').c_str(),
                                              rgb.r, rgb.g, rgb.b, &index),
          group.get(), "adding a material");
    // lib3mf 1.8.1 writes the colour added with the material with alpha 0,
    // transparent ("#7B4A2A00"); opaque is set explicitly.
    check(lib3mf_basematerial_setdisplaycolorrgba(group.get(), index, rgb.r,
                                                  rgb.g, rgb.b, 0xFF),
          group.get(), "setting a material's colour");
  }
  DWORD group_id = 0;
  check(lib3mf_resource_getresourceid(group.get(), &group_id), group.get(),
        "reading the material group's id");

  // Several volumes go into one mesh object, each a closed shell on its
  // own vertices, and PrusaSlicer's own metadata names their triangle
  // ranges as the parts of one object with an extruder each. PrusaSlicer
  // 2.5 (Debian 12) loads a components object as separate objects instead,
  // which it then moves apart (measured).
  ColoredMesh all;
  std::string config;
  for (std::size_t i = 0; i < volumes.size(); ++i) {
    const ColoredMesh& v = volumes[i];
    const std::size_t first = all.mesh.triangles.size();
    append(all.mesh, v.mesh);
    for (std::size_t t = 0; t < v.mesh.triangles.size(); ++t) {
      all.colors.push_back(v.colors.empty() ? 0 : v.colors[t]);
    }
    const int color = v.colors.empty() ? 0 : v.colors.front();
    config += fmt::format(
        "  <volume firstid=\"{}\" lastid=\"{}\">\n"
        "   <metadata type=\"volume\" key=\"name\" value=\"{}\"/>\n"
        "   <metadata type=\"volume\" key=\"volume_type\" "
        "value=\"ModelPart\"/>\n"
        "   <metadata type=\"volume\" key=\"extruder\" value=\"{}\"/>\n"
        "  </volume>\n",
        first, all.mesh.triangles.size() - 1, material_name(color, ' '), i + 1);
  }
  Handle mesh;
  *mesh.out() = add_mesh(model.get(), all, group_id, material, "lsolid model");
  // PrusaSlicer finds an object's volumes by its resource id.
  DWORD object_id = 0;
  check(lib3mf_resource_getresourceid(mesh.get(), &object_id), mesh.get(),
        "reading the object's id");
  config = fmt::format(
               "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<config>\n "
               "<object id=\"{}\" instances_count=\"1\">\n  <metadata "
               "type=\"object\" key=\"name\" value=\"lsolid model\"/>\n",
               object_id) +
           config + " </object>\n</config>\n";
  Handle item;
  check(lib3mf_model_addbuilditem(model.get(), mesh.get(), nullptr, item.out()),
        model.get(), "adding the build item");
  check(lib3mf_builditem_setuuidutf8(
            item.get(), stable_uuid(all.mesh, "build item").c_str()),
        item.get(), "setting the build item's UUID");
  check(lib3mf_model_setbuilduuidutf8(model.get(),
                                      stable_uuid(all.mesh, "build").c_str()),
        model.get(), "setting the build's UUID");
  if (volumes.size() > 1) {
    Handle attachment;
    check(lib3mf_model_addattachmentutf8(
              model.get(), const_cast<char*>(kPrusaConfigPath),
              const_cast<char*>(kPrusaConfigRelationship), attachment.out()),
          model.get(), "adding PrusaSlicer's volume list");
    check(lib3mf_attachment_readfrombuffer(
              attachment.get(), reinterpret_cast<BYTE*>(config.data()),
              config.size()),
          attachment.get(), "adding PrusaSlicer's volume list");
  }
  Handle writer;
  check(lib3mf_model_querywriter(model.get(), "3mf", writer.out()), model.get(),
        "creating the writer");
  ULONG64 size = 0;
  check(lib3mf_writer_getstreamsize(writer.get(), &size), writer.get(),
        "measuring the package");
  std::string bytes(size, '\0');
  check(lib3mf_writer_writetobuffer(
            writer.get(), reinterpret_cast<BYTE*>(bytes.data()), size),
        writer.get(), "writing the package");
  return bytes;
}

std::vector<ColoredMesh> decode_3mf(const std::filesystem::path& path) {
  Handle model;
  check(lib3mf_createmodel(model.out()), nullptr, "creating a model");
  Handle reader;
  check(lib3mf_model_queryreader(model.get(), "3mf", reader.out()), model.get(),
        "creating the reader");
  check(lib3mf_reader_addrelationtoreadutf8(reader.get(),
                                            kPrusaConfigRelationship),
        reader.get(), "creating the reader");
  check(lib3mf_reader_readfromfileutf8(reader.get(), path.string().c_str()),
        reader.get(), ("reading " + path.string()).c_str());
  DWORD unit = MODELUNIT_MILLIMETER;
  check(lib3mf_model_getunit(model.get(), &unit), model.get(),
        "reading the unit");
  double scale = 1.0;
  switch (unit) {
    case MODELUNIT_MICROMETER:
      scale = 0.001;
      break;
    case MODELUNIT_CENTIMETER:
      scale = 10.0;
      break;
    case MODELUNIT_INCH:
      scale = 25.4;
      break;
    case MODELUNIT_FOOT:
      scale = 304.8;
      break;
    case MODELUNIT_METER:
      scale = 1000.0;
      break;
    default:
      break;
  }
  const std::vector<std::pair<std::size_t, std::size_t>> ranges =
      volume_ranges(model.get());
  std::vector<ColoredMesh> out;
  Handle objects;
  check(lib3mf_model_getmeshobjects(model.get(), objects.out()), model.get(),
        "listing the meshes");
  std::map<std::pair<DWORD, DWORD>, int> colors;  // (group, index) → colour
  const auto color_of = [&](DWORD group_id, DWORD index) {
    const auto key = std::make_pair(group_id, index);
    if (const auto it = colors.find(key); it != colors.end()) return it->second;
    int color = 0;
    Handle group;
    if (lib3mf_model_getbasematerialbyid(model.get(), group_id, group.out()) ==
        LIB3MF_OK) {
      ULONG needed = 0;
      lib3mf_basematerial_getnameutf8(group.get(), index, nullptr, 0, &needed);
      std::string name(needed + 1, '\0');
      if (lib3mf_basematerial_getnameutf8(group.get(), index, name.data(),
                                          needed + 1, &needed) == LIB3MF_OK) {
        name.resize(needed);
        color = color_of_material(name);
      }
    }
    colors.emplace(key, color);
    return color;
  };
  for (;;) {
    BOOL more = 0;
    check(lib3mf_resourceiterator_movenext(objects.get(), &more), objects.get(),
          "listing the meshes");
    if (more == 0) break;
    Handle object;
    check(lib3mf_resourceiterator_getcurrent(objects.get(), object.out()),
          objects.get(), "listing the meshes");
    DWORD vertex_count = 0;
    DWORD triangle_count = 0;
    check(lib3mf_meshobject_getvertexcount(object.get(), &vertex_count),
          object.get(), "reading a mesh");
    check(lib3mf_meshobject_gettrianglecount(object.get(), &triangle_count),
          object.get(), "reading a mesh");
    std::vector<MODELMESHVERTEX> vertices(vertex_count);
    std::vector<MODELMESHTRIANGLE> triangles(triangle_count);
    if (vertex_count > 0) {
      check(lib3mf_meshobject_getvertices(object.get(), vertices.data(),
                                          vertex_count, nullptr),
            object.get(), "reading a mesh");
    }
    if (triangle_count > 0) {
      check(lib3mf_meshobject_gettriangleindices(object.get(), triangles.data(),
                                                 triangle_count, nullptr),
            object.get(), "reading a mesh");
    }
    ColoredMesh mesh;
    for (const MODELMESHVERTEX& v : vertices) {
      mesh.mesh.vertices.emplace_back(scale * v.m_fPosition[0],
                                      scale * v.m_fPosition[1],
                                      scale * v.m_fPosition[2]);
    }
    for (const MODELMESHTRIANGLE& t : triangles) {
      if (std::max({t.m_nIndices[0], t.m_nIndices[1], t.m_nIndices[2]}) >=
          vertex_count) {
        throw IoError(path.string() + ": a triangle names a missing vertex");
      }
      mesh.mesh.triangles.push_back(
          {t.m_nIndices[0], t.m_nIndices[1], t.m_nIndices[2]});
    }
    Handle properties;
    if (triangle_count > 0 &&
        lib3mf_meshobject_createpropertyhandler(
            object.get(), reinterpret_cast<PLib3MFPropertyHandler**>(
                              properties.out())) == LIB3MF_OK) {
      for (DWORD t = 0; t < triangle_count; ++t) {
        DWORD group_id = 0;
        DWORD index = 0;
        const bool has =
            lib3mf_propertyhandler_getbasematerial(
                properties.get(), t, &group_id, &index) == LIB3MF_OK &&
            group_id != 0;
        mesh.colors.push_back(has ? color_of(group_id, index) : 0);
      }
    }
    for (ColoredMesh& volume : split(mesh, ranges)) {
      out.push_back(std::move(volume));
    }
  }
  return out;
}

}  // namespace lsolid
