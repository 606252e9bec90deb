// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "report_json.hpp"

#include "pieces.hpp"

namespace lsolid::cli {

std::map<int, std::size_t> color_counts(const Solid& solid) {
  std::map<int, std::size_t> triangles;
  for (const ColoredMesh& v : solid.volumes) {
    for (const int c : v.colors) ++triangles[c];
  }
  if (solid.volumes.empty()) {
    for (const int c : solid.colors) ++triangles[c];
  }
  if (triangles.empty()) triangles[0] = solid.mesh.triangles.size();
  return triangles;
}

bool fits_bed(const Box& bounds, const glm::dvec3& bed_mm) {
  const glm::dvec3 size = bounds.size();
  constexpr double kSlack = 1e-3;
  return size.x <= bed_mm.x + kSlack && size.y <= bed_mm.y + kSlack &&
         size.z <= bed_mm.z + kSlack;
}

namespace {

// What the union engine did, as the text report's `union engine:` line.
Json union_engine_json(const UnionStats& u) {
  return Json{{"engine", engine_name(u.engine)},
              {"threads", u.threads},
              {"exact_unions", u.exact_unions},
              {"grown_unions", u.grown},
              {"degenerate_unions", u.degenerate_unions},
              {"degenerate_reason", u.degenerate_reason},
              {"fallbacks", u.fallbacks},
              {"fallback_reason", u.fallback_reason},
              {"crossings", u.crossings},
              {"cut_faces", u.cut_faces},
              {"predicates", u.predicates},
              {"filter_failures", u.filter_failures}};
}

}  // namespace

Json report_json(const Solid& solid, const OverhangReport& over,
                 const std::optional<glm::dvec3>& bed, bool fits,
                 const std::filesystem::path& output, bool written, bool united,
                 bool colored, const std::vector<Rgb>& palette) {
  const SolidReport& r = solid.report;
  const ValidationReport& v = r.validation;
  const Placement& p = r.placement;
  Json colors = nullptr;
  if (colored) {
    colors = Json::array();
    for (const auto& [color, count] : color_counts(solid)) {
      colors.push_back({{"color", color},
                        {"rgb", hex(palette_color(color, palette))},
                        {"triangles", count}});
    }
  }
  Json volumes = nullptr;
  for (const ColoredMesh& m : solid.volumes) {
    volumes.push_back({{"color", m.colors.empty() ? 0 : m.colors.front()},
                       {"triangles", m.mesh.triangles.size()},
                       {"volume_mm3", signed_volume(m.mesh)}});
  }
  Json decimation = nullptr;
  if (r.decimated) {
    const DecimateStats& d = r.decimation;
    decimation = {{"triangles_before", d.triangles_before},
                  {"triangles_after", d.triangles_after},
                  {"refused_intersections", d.refused_intersections},
                  {"max_deviation_mm", d.max_deviation_mm},
                  {"tolerance_mm", d.tolerance_mm},
                  {"within_tolerance", d.within_tolerance},
                  {"runs", d.attempts},
                  {"short_edges_left", d.short_edges_left},
                  {"reached_max_triangles", d.reached_max_triangles}};
  }
  Json base = nullptr;
  if (p.has_base) {
    base = {{"radius_mm", p.base_radius_mm},
            {"thickness_mm", p.base_thickness_mm}};
  }
  Json profile = nullptr;
  if (p.lies_flat) profile = r.flat_outlines > 0 ? "flat" : "round";
  return Json{{"output", output.string()},
              {"written", written},
              {"united", united},
              {"segments", r.segments},
              {"repeated_segments", r.repeated_segments},
              {"leaves", r.polygons},
              {"tubes", r.tubes},
              {"junction_hulls", r.junctions},
              {"joints", r.joints},
              {"leaf_plates", r.plates},
              {"spheres", r.spheres},
              {"surface_plates", r.sheets},
              {"contacts", r.union_stats.contacts},
              {"booleans", r.union_stats.booleans},
              {"union_engine", union_engine_json(r.union_stats)},
              {"mm_per_unit", r.mm_per_unit},
              {"base", std::move(base)},
              {"lies_flat", p.lies_flat},
              {"profile", std::move(profile)},
              {"underside_cut_mm", p.cut_depth_mm},
              {"decimation", std::move(decimation)},
              {"colors", std::move(colors)},
              {"volumes", std::move(volumes)},
              {"triangles", v.triangles},
              {"volume_mm3", v.volume_mm3},
              {"bounds", json_box(v.bounds)},
              {"printable", v.is_printable()},
              {"shells", v.shells},
              {"pieces", v.pieces()},
              {"loose_pieces", json_loose_pieces(v)},
              {"genus", v.genus},
              {"overhang_mm2", over.area_mm2},
              {"needs_supports", over.needs_supports},
              {"fits_bed", bed ? Json(fits) : Json(nullptr)},
              {"warnings", r.warnings},
              {"seconds",
               {{"skeleton", r.seconds.skeleton},
                {"parts", r.seconds.parts},
                {"union", r.seconds.unite},
                {"rounding", r.seconds.round},
                {"decimation", r.seconds.decimate},
                {"check", r.seconds.check},
                {"volumes", r.seconds.volumes}}}};
}

}  // namespace lsolid::cli
