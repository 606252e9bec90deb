// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/solid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <map>
#include <numbers>

#include "lsolid/distance.hpp"
#include "lsolid/errors.hpp"
#include "lsolid/mesh_io.hpp"
#include "lsolid/parts.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/parser.hpp"
#include "support/mesh_checks.hpp"

namespace lsolid {
namespace {

using testing::expect_admesh_agrees;
using testing::expect_printable;

lsys::Grammar parse(const std::string& text) {
  return lsys::parse_grammar_text(
      text, {.extra_settings = print_setting_names()}, "test.ls");
}

constexpr const char* kHilbert =
    "n=2, \u03B4=90\u00B0\nwidth: 0.3\nA\n"
    "A \u2192 B-F+CFC+F-D&F^D-F+&&CFC+F+B//\n"
    "B \u2192 A&F^CFB^F^D^^-F-D^|F^B|FC^F^A//\n"
    "C \u2192 |D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//\n"
    "D \u2192 |CFB-F+B|FA&F^A&&FB-F+B|FC//\n";

TEST(Solid, HilbertCubeIsOneGenusZeroShellOfTheExpectedVolume) {
  const Solid s =
      build_solid(parse(kHilbert), {.print = {.scale_mm_per_unit = 10.0}});
  const ValidationReport& r = s.report.validation;
  EXPECT_TRUE(r.is_printable());
  EXPECT_EQ(r.shells, 1U);
  EXPECT_EQ(r.genus, 0);
  EXPECT_EQ(s.report.segments, 63U);
  // One mitred tube of diameter 3 mm along 63 segments of 10 mm: its volume
  // is the cross-section times the axis length.
  const int m = tube_sides(1.5, 0.05);
  const double section = m * 1.5 * 1.5 * std::tan(std::numbers::pi / m);
  EXPECT_NEAR(r.volume_mm3, section * 630.0, 0.01 * section * 630.0);
}

TEST(Solid, FitsTheLongestSideAndClampsToTheWall) {
  const Solid s = build_solid(parse(kHilbert), {.print = {.wall_mm = 1.2}});
  EXPECT_FALSE(s.report.placement.has_base);  // it stands on a face
  EXPECT_EQ(s.report.validation.bounds.min.z, 0.0);
  const glm::dvec3 size = s.report.validation.bounds.size();
  EXPECT_NEAR(std::max({size.x, size.y, size.z}), 100.0, 0.5);
  const Solid thin = build_solid(
      parse("\u03C9: F\nwidth: 0.001\n"),
      {.print = {.wall_mm = 0.8, .size_mm = 50, .base = Base::None}});
  // A heptagon whose sides touch a circle of radius 0.4 mm: never thinner
  // than the wall, at most as wide as its corners.
  EXPECT_GE(thin.report.validation.bounds.size().x, 0.8 - 1e-6);
  EXPECT_LE(thin.report.validation.bounds.size().x,
            2 * tube_corner_radius(0.4, 0.05) + 1e-6);
  EXPECT_NEAR(thin.report.validation.bounds.size().z, 50.0, 0.01);
}

TEST(Solid, HoldsTheSizeAskedForWithJointsAndMitres) {
  // Koch's snowflake: sharp bends break chains and add joints, which reach
  // beyond the round tubes the skeleton is scaled with.
  const lsys::Grammar koch = parse(
      "n=2, \u03B4=60\u00B0\nwidth: 0.2\n\u03C9: F--F--F\nF \u2192 F+F--F+F\n");
  for (const double size : {40.0, 100.0}) {
    const Solid s =
        build_solid(koch, {.print = {.size_mm = size, .base = Base::None}});
    const glm::dvec3 extent = s.report.validation.bounds.size();
    EXPECT_NEAR(std::max({extent.x, extent.y, extent.z}), size, 0.002 * size);
  }
  const Solid tall =
      build_solid(koch, {.print = {.height_mm = 30.0, .base = Base::None}});
  EXPECT_NEAR(tall.report.validation.bounds.size().z, 30.0, 0.06);
}

TEST(Solid, TheSizeAskedForCountsTheBaseDisc) {
  // A thin tree whose disc is wider than the tree and lifts it by half
  // its thickness: the disc counts in the longest side and the height.
  const lsys::Grammar tree =
      parse("\u03B4=30\u00B0\nwidth: 0.1\n\u03C9: F[&F[+F]F]F[^F[-F]F]F\n");
  for (const double size : {40.0, 100.0}) {
    const Solid s = build_solid(tree, {.print = {.size_mm = size}});
    ASSERT_TRUE(s.report.placement.has_base);
    const glm::dvec3 extent = s.report.validation.bounds.size();
    EXPECT_NEAR(std::max({extent.x, extent.y, extent.z}), size, 1e-3 * size);
  }
  const Solid tall = build_solid(tree, {.print = {.height_mm = 30.0}});
  ASSERT_TRUE(tall.report.placement.has_base);
  EXPECT_NEAR(tall.report.validation.bounds.size().z, 30.0, 0.01);
}

TEST(Solid, RefusesASizeThatTheWallsCannotMeet) {
  try {
    (void)build_solid(parse("\u03C9: F\n"),
                      {.print = {.wall_mm = 200.0, .base = Base::None}});
    FAIL() << "no error";
  } catch (const lsys::ParseError& e) {
    EXPECT_EQ(e.diagnostic().file, "--size");
    EXPECT_NE(e.diagnostic().message.find("a size of 100 mm cannot be met"),
              std::string::npos)
        << e.diagnostic().message;
  }
}

TEST(Solid, APlanarFigureLiesFlatOnAFlatUnderside) {
  // ABOP fig. 1.7 b, quadratic Koch island, n = 1: every branch in one
  // plane.
  const lsys::Grammar koch = parse(
      "n=1, \u03B4=90\u00B0\nwidth: 1\nF-F-F-F\nF \u2192 F-F+F+FF-F-F+F\n");
  const Solid s = build_solid(koch, {.print = {.size_mm = 50.0}});
  expect_printable(s.mesh, 1);
  EXPECT_TRUE(s.report.placement.lies_flat);
  EXPECT_FALSE(s.report.placement.has_base);
  EXPECT_FALSE(s.report.placement.cut_refused);
  const Box box = s.report.validation.bounds;
  EXPECT_NEAR(box.min.z, 0.0, 1e-9);
  // Lying down it is as tall as its tubes less the cut, half a radius. All
  // tubes are of one thickness here: whole, at least two radii (four cut
  // depths) tall; cut, three and what the mitres and polygons reach beyond
  // the round radius.
  const double depth = s.report.placement.cut_depth_mm;
  EXPECT_GT(depth, 0.0);
  EXPECT_LT(box.size().z, 3.5 * depth);
  EXPECT_GT(box.size().z, 2.5 * depth);
  EXPECT_NEAR(std::max(box.size().x, box.size().y), 50.0, 0.1);
  // The underside: faces in z = 0 facing down, under every tube.
  double flat_mm2 = 0.0;
  for (const auto& t : s.mesh.triangles) {
    const glm::dvec3& a = s.mesh.vertices[t[0]];
    const glm::dvec3& b = s.mesh.vertices[t[1]];
    const glm::dvec3& c = s.mesh.vertices[t[2]];
    if (a.z == 0.0 && b.z == 0.0 && c.z == 0.0) {
      const glm::dvec3 n = glm::cross(b - a, c - a);
      EXPECT_LT(n.z, 0.0);
      flat_mm2 += glm::length(n) / 2.0;
    }
  }
  // 32 segments of 50/7 mm... at least half a tube width along all of them.
  EXPECT_GT(flat_mm2, 0.5 * 0.8 * 32 * (50.0 / 8.0) * 0.5);
}

TEST(Solid, APlanarFigureLyingFlatIsItsOutlineExtrudedUnlessRoundIsAsked) {
  const lsys::Grammar koch = parse(
      "n=1, \u03B4=90\u00B0\nwidth: 1\nF-F-F-F\nF \u2192 F-F+F+FF-F-F+F\n");
  const Solid flat = build_solid(koch, {.print = {.size_mm = 50.0}});
  const Solid round = build_solid(
      koch, {.print = {.size_mm = 50.0, .profile = Profile::Round}});
  expect_printable(flat.mesh, 1);
  expect_printable(round.mesh, 1);
  // 32 branches and a node at each of their 32 joins (the last branch
  // meets the first), united in the plane, no boolean in 3D; the round
  // profile needs booleans. One ring round the island, one round each hole.
  EXPECT_EQ(flat.report.flat_outlines, 64U);
  EXPECT_EQ(flat.report.flat_rings,
            static_cast<std::size_t>(flat.report.validation.genus) + 1);
  EXPECT_EQ(flat.report.union_stats.booleans, 0U);
  EXPECT_EQ(round.report.flat_outlines, 0U);
  EXPECT_GT(round.report.union_stats.booleans, 0U);
  // A flat top: every vertex on the bed or at the one top height, the top
  // of the round model's tubes (across their corners) above its cut.
  const double top = flat.report.validation.bounds.max.z;
  for (const glm::dvec3& p : flat.mesh.vertices) {
    EXPECT_TRUE(p.z == 0.0 || p.z == top) << p.z;
  }
  const double radius = flat.report.mm_per_unit / 2.0;
  EXPECT_NEAR(
      top,
      flat.report.placement.cut_depth_mm + tube_corner_radius(radius, 0.05),
      1e-6);
  EXPECT_LE(top, round.report.validation.bounds.max.z);
  // The size asked for holds for what is printed.
  const glm::dvec3 size = flat.report.validation.bounds.size();
  EXPECT_NEAR(std::max(size.x, size.y), 50.0, 50.0 * 1e-4 + 1e-5);
  // It holds the round model: more material, the same place.
  EXPECT_GT(flat.report.validation.volume_mm3,
            round.report.validation.volume_mm3);
  EXPECT_GT(flat.report.witnesses_checked, 0U);
}

TEST(Solid, AFlatModelKeepsTheJointOfALeafAtABranchTip) {
  // A leaf that starts at a branch's tip: the round model puts a joint
  // there, which the flat footprint must hold too. Without a node there
  // the footprint's rings crossed ("cannot wall the footprint"), and in
  // vlab's signal models the joint was reported lost.
  const Solid s = build_solid(parse("n=0, \u03B4=45\u00B0\nwidth: 0.2\n"
                                    "F[+F{.-f+f|-f+f}]F\n"),
                              {.print = {.size_mm = 40.0}});
  expect_printable(s.mesh, 1);
  EXPECT_TRUE(s.report.placement.lies_flat);
  EXPECT_GT(s.report.flat_outlines, 0U);
  EXPECT_GT(s.report.witnesses_checked, 0U);
}

TEST(Solid, TellsItsProgressStageByStage) {
  std::vector<std::string> stages;
  double last_union = -1.0;
  SolidOptions options;
  options.progress = [&](std::string_view stage, double fraction) {
    if (stages.empty() || stages.back() != stage) stages.emplace_back(stage);
    if (stage == "union") {
      EXPECT_GE(fraction, last_union);
      last_union = fraction;
    }
  };
  // The union's expected time is told as it begins, before it moves.
  std::vector<std::string> expected;
  options.expect = [&](std::string_view stage, double seconds) {
    expected.emplace_back(stage);
    EXPECT_EQ(last_union, 0.0);
    EXPECT_GT(seconds, 0.0);
  };
  // Not planar, so united in 3D.
  (void)build_solid(parse("\u03C9: F[+F][&F]\n\u03B4=30\u00B0\n"), options);
  EXPECT_EQ(stages,
            (std::vector<std::string>{"skeleton", "parts", "union", "rounding",
                                      "decimation", "check"}));
  EXPECT_EQ(last_union, 1.0);
  EXPECT_EQ(expected, std::vector<std::string>{"union"});
}

TEST(Solid, AbopBushWithLeavesIsOneValidShell) {
  const std::string bush =
      "n=3, \u03B4=22.5\u00B0\nwidth: 0.3\nwidth factor: 0.75\n\u03C9: A\n"
      "A \u2192 [&FL!A]/////'[&FL!A]///////'[&FL!A]\nF \u2192 S/////F\n"
      "S \u2192 FL\nL \u2192 ['''^^{-f+f+f-|-f+f+f}]\n";
  const Solid s = build_solid(parse(bush));
  expect_printable(s.mesh, 1);
  EXPECT_EQ(s.report.polygons, 12U);
  EXPECT_EQ(s.report.plates, 12U);
  const auto stl = std::filesystem::temp_directory_path() /
                   ("lsolid_bush_" + std::to_string(::getpid()) + ".stl");
  write_mesh(s.mesh, stl, MeshFormat::StlBinary);
  expect_admesh_agrees(stl);
  // What is read back is exactly what was checked.
  const TriangleMesh back = read_mesh(stl);
  expect_printable(back, 1);
  EXPECT_EQ(back.triangles.size(), s.mesh.triangles.size());
  std::filesystem::remove(stl);
}

// A stem (colour 0) with a branch of colour 1 and one of colour 2.
constexpr const char* kThreeColours =
    "n=0, \u03B4=45\u00B0\nwidth: 0.2\n\u03C9: FF[+'F][-''F]F\n";

TEST(Solid, ColoursEveryTriangleByTheTurtlesColourIndex) {
  const Solid plain = build_solid(parse(kThreeColours));
  EXPECT_TRUE(plain.colors.empty());
  EXPECT_TRUE(plain.volumes.empty());
  const Solid s = build_solid(parse(kThreeColours), {.colors = true});
  expect_printable(s.mesh, 1);
  ASSERT_EQ(s.colors.size(), s.mesh.triangles.size());
  std::map<int, std::size_t> count;
  for (const int c : s.colors) ++count[c];
  ASSERT_EQ(count.size(), 3U);
  EXPECT_GT(count[1], 10U);
  EXPECT_GT(count[2], 10U);
  // The branches are alike: their tubes get as many triangles, give or
  // take what the union and decimation cut differently at their feet.
  EXPECT_NEAR(double(count[1]), double(count[2]), 0.25 * double(count[1]));
  // A triangle at the branch tips' height is a branch's, not the stem's.
  for (std::size_t t = 0; t < s.mesh.triangles.size(); ++t) {
    const glm::dvec3 c = (s.mesh.vertices[s.mesh.triangles[t][0]] +
                          s.mesh.vertices[s.mesh.triangles[t][1]] +
                          s.mesh.vertices[s.mesh.triangles[t][2]]) /
                         3.0;
    if (std::fabs(c.x) > 0.3 * s.report.validation.bounds.size().x) {
      EXPECT_NE(s.colors[t], 0) << "triangle " << t;
    }
  }
}

TEST(Solid, EstimatesTheUnionOnceForAllItsVolumesPerColour) {
  // Not planar, so that the whole model and each colour are united in 3D.
  std::vector<std::string> estimated;
  SolidOptions options{.multi_material = true};
  options.expect = [&](std::string_view stage, double) {
    estimated.emplace_back(stage);
  };
  const Solid s = build_solid(
      parse("n=0, \u03B4=45\u00B0\nwidth: 0.2\n\u03C9: FF[+'F][&''F]F\n"),
      options);
  EXPECT_EQ(s.volumes.size(), 3U);
  EXPECT_EQ(estimated, std::vector<std::string>{"union"});
}

TEST(Solid, BuildsOneVolumePerColourThatDoNotOverlap) {
  const Solid s = build_solid(parse(kThreeColours), {.multi_material = true});
  expect_printable(s.mesh, 1);
  ASSERT_EQ(s.volumes.size(), 3U);
  double sum_mm3 = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    const ColoredMesh& v = s.volumes[i];
    expect_printable(v.mesh, 1);
    EXPECT_EQ(v.colors, std::vector<int>(v.mesh.triangles.size(), int(i)));
    sum_mm3 += signed_volume(v.mesh);
    for (std::size_t j = 0; j < 3; ++j) {
      if (i != j) {
        EXPECT_LE(overlap_depth_mm(v.mesh, s.volumes[j].mesh), 1e-4)
            << i << " in " << j;
      }
    }
  }
  // Together they fill the model, to within what decimating each volume
  // on its own moves (0.05 mm on a surface of some 10^4 mm²).
  EXPECT_NEAR(sum_mm3, s.report.validation.volume_mm3,
              0.01 * s.report.validation.volume_mm3);
}

TEST(Solid, ReadsColoursFromTheFileAndRefusesBadOnes) {
  const lsys::Grammar g = parse("colors: #7B4A2A, #8cc63f\nF\n");
  const PrintSettings s = resolve_print_settings(g);
  ASSERT_EQ(s.colors.size(), 2U);
  EXPECT_EQ(hex(s.colors[1]), "#8CC63F");
  try {
    (void)resolve_print_settings(parse("colors: #7B4A2A #12345\nF\n"));
    FAIL() << "no error";
  } catch (const lsys::ParseError& e) {
    EXPECT_EQ(e.diagnostic().line, 1);
    EXPECT_EQ(e.diagnostic().column, 17);
    EXPECT_EQ(e.diagnostic().message, "a colour is #RRGGBB, not '#12345'");
  }
  EXPECT_THROW((void)parse_colors(" , ", "--colors"), lsys::ParseError);
}

TEST(Solid, ReadsPrintSettingsFromTheFileUnlessTheCommandLineGivesThem) {
  const lsys::Grammar g = parse("wall: 1.5mm\nheight: 4cm\n\u03C9: F\n");
  const PrintSettings file = resolve_print_settings(g);
  EXPECT_EQ(file.wall_mm, 1.5);
  EXPECT_EQ(file.height_mm, 40.0);
  const PrintSettings cli =
      resolve_print_settings(g, {.wall_mm = 0.4, .size_mm = 10.0});
  EXPECT_EQ(cli.wall_mm, 0.4);
  EXPECT_FALSE(cli.height_mm.has_value());
  EXPECT_EQ(cli.size_mm, 10.0);
  const lsys::Grammar bad = parse("wall: 2 furlongs\n\u03C9: F\n");
  try {
    (void)resolve_print_settings(bad);
    FAIL() << "no error";
  } catch (const lsys::ParseError& e) {
    EXPECT_EQ(e.diagnostic().line, 1);
    EXPECT_EQ(e.diagnostic().column, 9);
    EXPECT_EQ(e.diagnostic().message,
              "unknown unit 'furlongs': use mm, cm or in");
  }
}

// ABOP fig. 5.5's cordate leaf as a published file draws it: a fan of 22
// coplanar triangles on shared edges. Once the plates vanished in the
// union (530 mm³ left, "printable", 8 shells).
constexpr const char* kCordateFan =
    "delta=10\nwidth: 0.5\nderivation length: 12\n"
    "axiom: !(0.05)F(0.1)\\(30)&(30)FFFFF!(0.045)[A][B]\n"
    "p1: A -> [[+A{.C.]GC.}]\np2: B -> [[-B{.C.]GC.}]\np3: C -> GC\n";

// Lparser's cordate leaf (its header as settings, its ' dropped): four
// leaves of 14 overlapping coplanar polygons each.
constexpr const char* kLparserLeaf =
    "n = 10\nangle: 10\nwidth: 0.1\n"
    "[|FFFFFFFFFFF]P>(90)P>(90)P>(90)P\nP=[&(10)G[ccA][ccB][a][b]]\n"
    "G=tFtFtFtFtFtFtFtFtFtFtFtFtF\nA=[+A{.].C.}\nB=[-B{.].C.}\nC=tfC\n"
    "a=[+a]d\nb=[-b]d\nd=tFd\naliases: > = /  < = \\  c = '\n";

TEST(Solid, KeepsALeafDrawnAsAFanOfCoplanarTriangles) {
  // Undecimated, to compare volumes: decimation may move the surface of
  // this thin leaf by its tolerance, about 0.6% of its volume.
  const Solid s = build_solid(
      parse(kCordateFan), {.print = {.base = Base::None}, .decimate = false});
  expect_printable(s.mesh, 1);
  EXPECT_EQ(s.report.polygons, 22U);
  EXPECT_EQ(s.report.plates, 1U);  // the fan, united in its plane
  EXPECT_GT(s.report.witnesses_checked, 40U);
  // manifold-3d 3.5.4 unites the same parts (`lsolid --no-union`) into
  // 4219.3 mm³.
  EXPECT_NEAR(s.report.validation.volume_mm3, 4219.3, 0.001 * 4219.3);
}

TEST(Solid, BuildsLeavesOfOverlappingCoplanarPolygons) {
  const Solid s =
      build_solid(parse(kLparserLeaf), {.print = {.base = Base::None}});
  const Solid whole = build_solid(
      parse(kLparserLeaf), {.print = {.base = Base::None}, .decimate = false});
  expect_printable(s.mesh, 1);
  EXPECT_EQ(s.report.segments, 351U);
  EXPECT_EQ(s.report.plates, 4U);
  EXPECT_TRUE(s.report.decimated);
  // manifold-3d 3.5.4: 1199.0 mm³ for the same parts.
  EXPECT_NEAR(whole.report.validation.volume_mm3, 1199.0, 0.001 * 1199.0);
  EXPECT_NEAR(s.report.validation.volume_mm3, 1199.0, 0.01 * 1199.0);
}

TEST(Solid, AFileWithoutWidthsPrintsAsALineDrawing) {
  // The lecture's 3D Hilbert curve typed verbatim: no width. A tenth of a
  // step wide, it keeps its shape; a step wide (cpfg's default, once ours)
  // it filled 73% of its cube and is warned about.
  const std::string verbatim =
      "n=2, \u03B4=90\u00B0\nA\n"
      "A \u2192 B-F+CFC+F-D&F^D-F+&&CFC+F+B//\n"
      "B \u2192 A&F^CFB^F^D^^-F-D^|F^B|FC^F^A//\n"
      "C \u2192 |D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//\n"
      "D \u2192 |CFB-F+B|FA&F^A&&FB-F+B|FC//\n";
  const Solid thin = build_solid(parse(verbatim));
  EXPECT_TRUE(thin.report.warnings.empty());
  const glm::dvec3 size = thin.report.validation.bounds.size();
  EXPECT_LT(thin.report.validation.volume_mm3, 0.05 * size.x * size.y * size.z);
  const Solid lump = build_solid(parse(verbatim + "width: 1\n"));
  ASSERT_EQ(lump.report.warnings.size(), 1U);
  EXPECT_EQ(lump.report.warnings[0].rfind("the model fills 7", 0), 0U)
      << lump.report.warnings[0];
  EXPECT_NE(lump.report.warnings[0].find("`width scale:`"), std::string::npos);
}

TEST(Solid, WarnsWhenWidthsDwarfLengths) {
  // Honda's tree as ABOP Table 2.1 prints it: width 10 for length 1.
  const Solid s = build_solid(parse(
      "n=3, \u03B4=137.5\n\u03C9 : A(1, 10)\n"
      "A(l,w) \u2192 !(w)F(l)[&(45)B(l*0.6,w*0.707)]/(137.5)A(l*0.9,w*0.707)\n"
      "B(l,w) \u2192 !(w)F(l)[-(45)$C(l*0.6,w*0.707)]C(l*0.9,w*0.707)\n"
      "C(l,w) \u2192 !(w)F(l)[+(45)$B(l*0.6,w*0.707)]B(l*0.9,w*0.707)\n"));
  ASSERT_GE(s.report.warnings.size(), 1U);
  EXPECT_EQ(s.report.warnings[0].rfind(
                "the widths dwarf the lengths: the median segment is ", 0),
            0U)
      << s.report.warnings[0];
}

// A plant drawn with steps as wide as they are long (ABOP fig. 1.24c at its
// own settings) is branched, not a lump: no warning (one came from a
// median ratio of 1 + 7·10⁻¹⁶).
TEST(Solid, DoesNotCallAPlantOfStepsAsWideAsLongALump) {
  const Solid s =
      build_solid(parse("n=2, \u03B4=22.5\nwidth: 1\n\u03C9: F\n"
                        "F \u2192 FF-[-F+F+F]+[+F-F-F]\n"));
  EXPECT_TRUE(s.report.validation.is_printable());
  for (const std::string& warning : s.report.warnings) {
    EXPECT_EQ(warning.find("dwarf"), std::string::npos) << warning;
  }
}

TEST(Solid, BuildsABallWhereTheTurtleStandsAndNeverLaysItFlat) {
  // A stem of 10 mm and 2 mm across with a berry of 6 mm on top, and a
  // lone ball: balls of `@O` are parts of their own colour.
  const Solid s =
      build_solid(parse("\u03C9: F@O(0.6)[f(2);@O(0.6)]\nwidth: 0.2\n"),
                  {.print = {.scale_mm_per_unit = 10.0, .base = Base::None}});
  const ValidationReport& r = s.report.validation;
  EXPECT_TRUE(r.is_printable());
  EXPECT_EQ(s.report.spheres, 2U);
  EXPECT_EQ(r.shells, 2U);  // the second ball stands apart
  // Each ball's faces lie at 3 mm or farther from its centre, its corners
  // within a few tolerances (0.05 mm) of it: the volume lies between two
  // true balls and that plus the stem's tube.
  const auto ball = [](double radius) {
    return 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  };
  EXPECT_GT(r.volume_mm3, 2.0 * ball(3.0));
  EXPECT_LT(r.volume_mm3,
            2.0 * ball(3.15) + std::numbers::pi * 1.05 * 1.05 * 10.0);
  EXPECT_GE(r.bounds.max.z, 10.0 + 20.0 + 3.0);
  EXPECT_LE(r.bounds.max.z, 10.0 + 20.0 + 3.15);
  EXPECT_FALSE(s.report.placement.lies_flat);
}

TEST(Solid, RefusesAModelThatDrawsNothingAsBadInputAtItsPlace) {
  // It was a GeometryError (exit 3); F(0) draws nothing either.
  try {
    (void)build_solid(parse("n=1\n\u03C9: A\nA \u2192 F(0)+F(0)\n"));
    FAIL() << "no error";
  } catch (const lsys::ParseError& e) {
    EXPECT_EQ(e.diagnostic().line, 3);
    EXPECT_EQ(e.diagnostic().column, 5);
    EXPECT_EQ(e.diagnostic().message,
              "nothing to build: every segment has length 0");
  }
  EXPECT_THROW((void)build_solid(parse("\u03C9: A+B")), lsys::ParseError);
}

TEST(Solid, RefusesAModelReachingBeyondAKilometre) {
  // F(1e300) at 1 mm a unit failed as geometry (exit 3), through integer
  // grid keys that could not hold its coordinates.
  SolidOptions options;
  options.print.scale_mm_per_unit = 1.0;
  options.print.size_mm.reset();
  try {
    (void)build_solid(parse("\u03C9: F(1e300)\n"), options);
    FAIL() << "no error";
  } catch (const lsys::ParseError& e) {
    EXPECT_EQ(e.diagnostic().column, 4);
    EXPECT_EQ(e.diagnostic().message,
              "at 1 mm per unit the model reaches 1e+300 mm from its origin, "
              "more than the 1 km (1000000 mm) lsolid builds");
  }
}

TEST(Solid, WritesOverlappingPartsWhenAskedNotToUnite) {
  const Solid s = build_solid(parse("\u03C9: F[+F]F\n\u03B4=45\nwidth: 1"),
                              {.unite = false});
  EXPECT_EQ(s.report.tubes, 2U);
  EXPECT_GT(s.report.validation.self_intersecting_pairs, 0U);
}

}  // namespace
}  // namespace lsolid
