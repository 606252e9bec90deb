// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>
#include <png.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "support/hostile_models.hpp"
#include "support/run_command.hpp"
#include "support/test_dir.hpp"

namespace lsolid {
namespace {

using testing::lsolid;
using testing::read_text;
using testing::run_command;
using Json = nlohmann::ordered_json;

// The command succeeded, printing exactly `out`.
void expect_output(const testing::CommandResult& r, const std::string& out) {
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, out);
}

// The command failed with `exit_code`, saying exactly `err` on standard
// error.
void expect_failure(const testing::CommandResult& r, int exit_code,
                    const std::string& err) {
  EXPECT_EQ(r.exit_code, exit_code) << r.out;
  EXPECT_EQ(r.err, err);
}

const std::filesystem::path kSource = LSOLID_SOURCE_DIR;
const std::filesystem::path kDiagnostics = kSource / "tests/data/diagnostics";

TEST(Cli, DerivePrintsTheString) {
  const auto r = run_command(lsolid() + " derive hilbert-cube.ls -n 1",
                             kSource / "printables");
  expect_output(r, "B-F+CFC+F-D&F^D-F+&&CFC+F+B//\n");
}

TEST(Cli, DerivePrintsParametersInShortestForm) {
  const auto r = run_command(lsolid() + " derive honda-2.1a.ls -n 1",
                             kSource / "printables");
  expect_output(r,
                "!(10)F(1)[&(45)B(0.6,7.069999999999999)]/(137.5)"
                "A(0.9,7.069999999999999)\n");
}

TEST(Cli, DeriveStatsPrintsLengthCountsAndDepth) {
  const auto r = run_command(lsolid() + " derive abop-1.25-bush.ls --stats",
                             kSource / "printables");
  expect_output(r,
                "{\"length\":77399,\"modules\":{\"!\":3279,\"&\":3279,"
                "\"'\":6038,\"+\":5136,\"-\":3852,\"/\":22596,\"A\":2187,"
                "\"F\":3891,\"L\":2607,\"S\":1284,\"[\":4563,\"]\":4563,"
                "\"^\":2568,\"f\":7704,\"{\":1284,\"|\":1284,\"}\":1284},"
                "\"max_depth\":7}\n");
}

TEST(Cli, DefinesAndSeedsComeFromTheCommandLine) {
  const auto r = run_command(lsolid() +
                                 " derive honda-2.1a.ls -n 1 --define wr=0.5 "
                                 "--define r2=0.5",
                             kSource / "printables");
  expect_output(r, "!(10)F(1)[&(45)B(0.5,5)]/(137.5)A(0.9,5)\n");
}

TEST(Cli, SkeletonJsonHasPointsRadiiAndColours) {
  const auto r = run_command(lsolid() + " skeleton hilbert-cube.ls -n 1 --json",
                             kSource / "printables");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::string head =
      "{\"units\": \"model\", \"segments\": [\n"
      "{\"p0\": [0,0,0], \"p1\": [1,0,0], \"r0\": 0.15, \"r1\": 0.15, "
      "\"color\": 0},\n";
  EXPECT_EQ(r.out.substr(0, head.size()), head);
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 9);
  EXPECT_NE(r.out.find("\"polygons\": []}"), std::string::npos);
  EXPECT_EQ(r.out.find("NaN"), std::string::npos);
}

TEST(Cli, SkeletonSummarisesWithoutJson) {
  const auto r = run_command(lsolid() + " skeleton hilbert-cube.ls",
                             kSource / "printables");
  expect_output(
      r,
      "segments: 63\npolygons: 0\nbounds: [0, 0, 0] to [3, 3, 3] model "
      "units\n");
}

TEST(Cli, HelpShowsExamplesAndVersionShowsTheVersion) {
  const auto help = run_command(lsolid() + " --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("Examples:"), std::string::npos);
  EXPECT_NE(help.out.find("lsolid derive"), std::string::npos);
  const auto version = run_command(lsolid() + " --version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_EQ(version.out, "lsolid 0.1.0\n");
}

TEST(Cli, BadUsageExitsWithTwo) {
  EXPECT_EQ(run_command(lsolid() + " derive").exit_code, 2);
  EXPECT_EQ(run_command(lsolid() + " derive nonexistent.ls").exit_code, 2);
  EXPECT_EQ(run_command(lsolid() + " frobnicate").exit_code, 2);
  const auto r = run_command(lsolid() + " derive hilbert-cube.ls -n -3",
                             kSource / "printables");
  EXPECT_EQ(r.exit_code, 2);
}

TEST(Cli, ReportsABadDefineWithACaret) {
  const auto r =
      run_command(lsolid() + " derive honda-2.1a.ls --define r2=0.5.5",
                  kSource / "printables");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "--define:1:4: error: bad number '0.5.5'\nr2=0.5.5\n   ^\n");
}

TEST(Cli, RefusesAnyNumericOptionOutOfItsRangeWithAPlainMessage) {
  // `-1` wrapped to 1.8e19 and disabled the limit; `--max-triangles 0`
  // printed a 300-digit range.
  struct Case {
    std::string args;
    std::string option;
    std::string range;
    std::string value;
  };
  const std::string most = "9007199254740992";
  for (const Case& c : std::vector<Case>{
           {"derive --max-segments -1", "--max-segments", "1 to " + most, "-1"},
           {"derive --max-modules -1", "--max-modules", "1 to " + most, "-1"},
           {"skeleton --max-segments 0", "--max-segments", "1 to " + most, "0"},
           {"derive --max-modules 18446744073709551616", "--max-modules",
            "1 to " + most, "18446744073709551616"},
           {"derive -n 1e300", "--derivation-length", "0 to 10000", "1e300"},
           {"skeleton -n 3.5", "--derivation-length", "0 to 10000", "3.5"},
           {"derive --seed -1", "--seed", "0 to " + most, "-1"},
           {"derive --seed 9007199254740993", "--seed", "0 to " + most,
            "9007199254740993"},
           {"derive --max-memory 0", "--max-memory", "1 to 1073741824", "0"},
           {"--max-triangles 0", "--max-triangles", "4 to 4294967295", "0"},
           {"--max-triangles 1e3", "--max-triangles", "4 to 4294967295",
            "1e3"}}) {
    const std::string command = c.args.starts_with("-")
                                    ? "hilbert-cube.ls " + c.args + " -o x.stl"
                                    : c.args.substr(0, c.args.find(' ')) +
                                          " hilbert-cube.ls" +
                                          c.args.substr(c.args.find(' '));
    const auto r =
        run_command(lsolid() + " " + command, kSource / "printables");
    EXPECT_EQ(r.exit_code, 2) << command;
    EXPECT_EQ(r.err, c.option + ":1:1: error: expected a whole number from " +
                         c.range + ", not '" + c.value + "'\n" + c.value +
                         "\n^\n")
        << command;
    EXPECT_EQ(r.out, "") << command;
  }
  EXPECT_FALSE(std::filesystem::exists(kSource / "printables/x.stl"));
  const auto wall =
      run_command(lsolid() + " skeleton hilbert-cube.ls --wall 1e308in",
                  kSource / "printables");
  EXPECT_EQ(wall.exit_code, 2);
  EXPECT_EQ(wall.err,
            "--wall:1:1: error: a length must be at most 1000000 mm (1 km)\n"
            "1e308in\n^\n");
}

TEST(Cli, ReadsALongAxiomInLittleMemoryAndRefusesAFileOverTheLimit) {
#ifdef LSOLID_SANITIZED
  GTEST_SKIP() << "AddressSanitizer's shadow memory is not lsolid's";
#endif
  const auto dir = std::filesystem::temp_directory_path() /
                   ("lsolid_long_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  { std::ofstream(dir / "tiny.ls") << "axiom: F\n"; }
  {
    std::ofstream out(dir / "long.ls");
    out << "axiom: " << std::string(10'000'000, 'F') << "\n";
  }
  // A 10 MB axiom took 1.1 GB (110 bytes a byte); now under 25 a byte.
  const long tiny = testing::peak_rss_kib(
      lsolid() + " derive tiny.ls --stats > /dev/null", dir);
  const long peak = testing::peak_rss_kib(
      lsolid() + " derive long.ls --stats > /dev/null", dir);
  ASSERT_GT(tiny, 0);
  EXPECT_LT(peak - tiny, 25L * 10'000'000L / 1024L) << peak << " " << tiny;
  {
    std::ofstream out(dir / "huge.ls");
    out << "n=1\naxiom: " << std::string(17U << 20U, 'F') << "\n";
  }
  const auto huge = run_command(lsolid() + " huge.ls -o out.stl", dir);
  EXPECT_EQ(huge.exit_code, 2);
  EXPECT_EQ(huge.err,
            "huge.ls:2:16777213: error: the file is larger than 16777216 "
            "bytes, the limit for a .ls file\n\u2026" +
                std::string(51, 'F') + "\n" + std::string(51, ' ') + "^\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.stl"));
  std::filesystem::remove_all(dir);
}

class Build : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("lsolid_cli_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  // Copies printables/NAME.ls into the test's folder as AS.
  void use_printable(const std::string& name, const std::string& as) const {
    std::filesystem::copy_file(kSource / "printables" / (name + ".ls"),
                               dir_ / as);
  }
  std::filesystem::path dir_;
};

// The volume a build's report gives, as printed; empty if it gives none.
std::string reported_volume(const std::string& out) {
  static const std::regex volume(R"(\nvolume: ([\d.]+) mm³)");
  std::smatch m;
  return std::regex_search(out, m, volume) ? m[1].str() : std::string();
}

// An OFF of the vertices (each as `read` makes of the three numbers the
// regex `vertex` matches in `points`) and triangles (the regex `face` in
// `triangles`, whose groups are 0-based indices, turned by `flip`).
std::string off_of(const std::string& points, const std::string& triangles,
                   const std::regex& vertex, const std::regex& face,
                   const std::function<double(const std::string&)>& read,
                   bool flip) {
  std::vector<std::string> vertices;
  std::vector<std::string> faces;
  char line[128];
  for (auto it = std::sregex_iterator(points.begin(), points.end(), vertex);
       it != std::sregex_iterator(); ++it) {
    std::snprintf(line, sizeof(line), "%.17g %.17g %.17g\n",
                  read((*it)[1].str()), read((*it)[2].str()),
                  read((*it)[3].str()));
    vertices.emplace_back(line);
  }
  for (auto it = std::sregex_iterator(triangles.begin(), triangles.end(), face);
       it != std::sregex_iterator(); ++it) {
    faces.push_back("3 " + (*it)[1].str() + " " + (*it)[flip ? 3 : 2].str() +
                    " " + (*it)[flip ? 2 : 3].str() + "\n");
  }
  std::string off = "OFF\n" + std::to_string(vertices.size()) + " " +
                    std::to_string(faces.size()) + " 0\n";
  for (const std::string& v : vertices) off += v;
  for (const std::string& f : faces) off += f;
  return off;
}

// A file lsolid calls printable stays printable as its readers read it: a
// 3MF's six decimals read as doubles and as floats, a `.scad` as OpenSCAD
// exports it (six significant digits) and a slicer reads that (floats).
// The monopodial tree's 3MF once had 6 pairs of intersecting faces read as
// doubles; OpenSCAD broke the `.scad` of ABOP fig. 1.26's plant.
TEST_F(Build, WritesFilesThatStayPrintableAsTheirReadersReadThem) {
  use_printable("lparser-monopodial-tree", "tree.ls");
  const auto as_double = [](const std::string& s) {
    return std::strtod(s.c_str(), nullptr);
  };
  const auto as_float = [](const std::string& s) {
    return static_cast<double>(std::strtof(s.c_str(), nullptr));
  };
  const auto openscad_export = [](const std::string& s) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", std::strtod(s.c_str(), nullptr));
    return static_cast<double>(std::strtof(text, nullptr));
  };
  for (const char* output : {"tree.3mf", "tree.scad"}) {
    const auto built = run_command(lsolid() + " tree.ls -q -o " + output, dir_);
    ASSERT_EQ(built.exit_code, 0) << built.err;
  }
  const std::string model =
      run_command("unzip -p tree.3mf 3D/3dmodel.model", dir_).out;
  const std::regex vertex3mf(
      R"re(<vertex x="([^"]+)" y="([^"]+)" z="([^"]+)")re");
  const std::regex triangle3mf(
      R"re(<triangle v1="(\d+)" v2="(\d+)" v3="(\d+)")re");
  const std::string scad = read_text(dir_ / "tree.scad");
  const std::size_t faces_at = scad.find("faces = [");
  ASSERT_NE(faces_at, std::string::npos);
  const std::string scad_points = scad.substr(0, faces_at);
  const std::string scad_faces = scad.substr(faces_at);
  const std::string number = R"re(\s*(-?[0-9.e+-]+)\s*)re";
  const std::regex vertex_scad("\\[" + number + "," + number + "," + number +
                               "\\]");
  const std::regex face_scad(R"re(\[(\d+), (\d+), (\d+)\])re");
  const std::vector<std::pair<std::string, std::string>> readings{
      {"3mf-doubles.off",
       off_of(model, model, vertex3mf, triangle3mf, as_double, false)},
      {"3mf-floats.off",
       off_of(model, model, vertex3mf, triangle3mf, as_float, false)},
      {"scad-export.off", off_of(scad_points, scad_faces, vertex_scad,
                                 face_scad, openscad_export, true)}};
  for (const auto& [name, off] : readings) {
    { std::ofstream(dir_ / name) << off; }
    const auto check = run_command(lsolid() + " check " + name, dir_);
    EXPECT_EQ(check.exit_code, 0) << name << "\n" << check.out;
    EXPECT_NE(check.out.find("triangles, "), std::string::npos) << name;
  }
}

TEST_F(Build, WritesAPrintableStlAndReports) {
  const auto out = dir_ / "hilbert.stl";
  const auto r = run_command(lsolid() + " " +
                             (kSource / "printables/hilbert-cube.ls").string() +
                             " --size 60mm -o " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  for (const char* line : {"segments: 63, leaves: 0\n", "triangles: ",
                           "volume: ", "size: ", "time: skeleton ",
                           "check: printable: closed, manifold, outward, no "
                           "self-intersections; 1 shell, genus 0\n"}) {
    EXPECT_NE(r.out.find(line), std::string::npos) << line;
  }
  EXPECT_TRUE(std::filesystem::exists(out));
  const auto check = run_command(lsolid() + " check " + out.string());
  EXPECT_EQ(check.exit_code, 0) << check.out;
  EXPECT_NE(check.out.find("verdict: printable\n"), std::string::npos);
  EXPECT_NE(check.out.find(" x 60.000 x 60.000 mm"), std::string::npos)
      << check.out;
}

TEST_F(Build, DecimatesTheBushWithinToleranceAndItStillPassesCheck) {
  use_printable("abop-1.25-bush", "bush.ls");
  const auto r = run_command(
      lsolid() + " bush.ls -n 4 --tolerance 0.05mm -o bush.stl", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::regex line(
      "decimation: ([0-9]+) -> ([0-9]+) triangles, [0-9]+ collapses refused "
      "as they would cut the mesh; deviation ([0-9.]+) mm");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, line)) << r.out;
  EXPECT_LT(std::stoul(m[2]), std::stoul(m[1]));
  EXPECT_LE(std::stod(m[3]), 0.05);
  EXPECT_NE(r.out.find(" mm (Hausdorff, sampled), within the tolerance of "
                       "0.05 mm"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.err.find("warning: decimation"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("triangles: " + m[2].str() + "\n"), std::string::npos);
  const auto check = run_command(lsolid() + " check bush.stl", dir_);
  EXPECT_EQ(check.exit_code, 0) << check.out;
  const auto capped = run_command(
      lsolid() + " bush.ls -n 4 --max-triangles 1500 -o capped.stl", dir_);
  ASSERT_EQ(capped.exit_code, 0) << capped.err;
  EXPECT_NE(capped.out.find("-> 1500 triangles"), std::string::npos)
      << capped.out;
  // Beyond the tolerance: said in the report and warned about.
  EXPECT_NE(capped.out.find("BEYOND the tolerance of 0.05 mm"),
            std::string::npos)
      << capped.out;
  EXPECT_NE(capped.err.find("warning: decimation moved the surface by up to "),
            std::string::npos)
      << capped.err;
  EXPECT_NE(capped.err.find("more than the tolerance of 0.05 mm, to reach "
                            "--max-triangles\n"),
            std::string::npos)
      << capped.err;
  EXPECT_EQ(run_command(lsolid() + " check capped.stl", dir_).exit_code, 0);
  const auto raw =
      run_command(lsolid() + " bush.ls -n 4 --no-decimate -o raw.stl", dir_);
  EXPECT_EQ(raw.out.find("decimation:"), std::string::npos);
  EXPECT_EQ(
      run_command(lsolid() + " bush.ls --no-decimate --max-triangles 9", dir_)
          .exit_code,
      2);
}

TEST_F(Build, WritesBesideTheInputByDefaultAndTakesOff) {
  use_printable("branches-90", "b.ls");
  EXPECT_EQ(run_command(lsolid() + " b.ls", dir_).exit_code, 0);
  EXPECT_TRUE(std::filesystem::exists(dir_ / "b.stl"));
  EXPECT_EQ(run_command(lsolid() + " b.ls -o b.off", dir_).exit_code, 0);
  EXPECT_EQ(read_text(dir_ / "b.off").substr(0, 4), "OFF\n");
  EXPECT_EQ(run_command(lsolid() + " b.ls --ascii -o a.stl", dir_).exit_code,
            0);
  EXPECT_EQ(read_text(dir_ / "a.stl").substr(0, 12), "solid lsolid");
}

TEST_F(Build, RendersAPreviewBesideTheMesh) {
  use_printable("branches-90", "b.ls");
  const auto r = run_command(lsolid() + " b.ls --preview b.png", dir_);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("rendered b.png\n"), std::string::npos);
  EXPECT_EQ(read_text(dir_ / "b.png").substr(0, 8), "\x89PNG\r\n\x1a\n");
  const auto bad = run_command(lsolid() + " b.ls --preview b.jpg", dir_);
  expect_failure(bad, 2,
                 "--preview: error: a preview is a PNG: name it FILE.png, not "
                 "'b.jpg'\n");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "b.jpg"));
}

// The preview's pixels that are clearly brown (the palette's colour 0,
// #7B4A2A) and clearly green (colour 1, #2E6B2E).
std::pair<int, int> brown_and_green(const std::filesystem::path& png_file) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, png_file.string().c_str())) {
    ADD_FAILURE() << "cannot read " << png_file;
    return {0, 0};
  }
  png.format = PNG_FORMAT_RGB;
  std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(png));
  EXPECT_TRUE(png_image_finish_read(&png, nullptr, pixels.data(), 0, nullptr));
  int brown = 0;
  int green = 0;
  for (std::size_t i = 0; i + 2 < pixels.size(); i += 3) {
    const int red = pixels[i];
    const int g = pixels[i + 1];
    const int blue = pixels[i + 2];
    brown += red > g + 20 && g > blue ? 1 : 0;
    green += g > red + 20 && g > blue + 20 ? 1 : 0;
  }
  return {brown, green};
}

TEST_F(Build, PreviewsTheModelInItsColours) {
  // A brown stem (colour 0) with a green leaf (colour 1): a plate of its
  // own, coloured as it is in a 3MF even when the output is an STL.
  {
    std::ofstream(dir_ / "leaf.ls")
        << "n = 0\nwidth: 0.2\nscale: 8mm\nbase: none\n"
           "\u03C9: F[&'{+f-ff-f+|+f-ff-f}]F\n";
  }
  ASSERT_EQ(
      run_command(lsolid() + " leaf.ls --preview leaf.png", dir_).exit_code, 0);
  const auto [brown, green] = brown_and_green(dir_ / "leaf.png");
  EXPECT_GT(brown, 1000);
  EXPECT_GT(green, 1000);
  // A stem that turns green halfway: one tube for an STL, two for a 3MF,
  // and both drawn brown, then green.
  {
    std::ofstream(dir_ / "two.ls")
        << "n = 0\nwidth: 0.2\nscale: 8mm\nbase: none\n\u03C9: F'F\n";
  }
  ASSERT_EQ(run_command(lsolid() + " two.ls --preview stl.png", dir_).exit_code,
            0);
  const auto [brown_stl, green_stl] = brown_and_green(dir_ / "stl.png");
  EXPECT_GT(brown_stl, 1000);
  EXPECT_GT(green_stl, 1000);
  ASSERT_EQ(run_command(lsolid() + " two.ls -o two.3mf --preview 3mf.png", dir_)
                .exit_code,
            0);
  const auto [brown_3mf, green_3mf] = brown_and_green(dir_ / "3mf.png");
  EXPECT_GT(brown_3mf, 1000);
  EXPECT_GT(green_3mf, 1000);
}

TEST_F(Build, RefusesAnUnknownBase) {
  use_printable("branches-90", "b.ls");
  const auto r = run_command(lsolid() + " b.ls --base wobbly", dir_);
  expect_failure(r, 2,
                 "--base:1:1: error: base must be auto, disc or none, not "
                 "'wobbly'\nwobbly\n^\n");
  { std::ofstream(dir_ / "c.ls") << "base: tripod\n\u03C9: F\n"; }
  const auto file = run_command(lsolid() + " c.ls", dir_);
  expect_failure(
      file, 2,
      "c.ls:1:7: error: base must be auto, disc or none, not 'tripod'\n"
      "base: tripod\n"
      "      ^\n");
}

TEST_F(Build, ChoosesTheProfileOfAFlatModelAndRefusesAnUnknownOne) {
  use_printable("branches-90", "b.ls");
  const auto r = run_command(lsolid() + " b.ls --profile square", dir_);
  expect_failure(r, 2,
                 "--profile:1:1: error: profile must be flat or round, not "
                 "'square'\nsquare\n^\n");
  const auto flat = run_command(lsolid() + " b.ls --json -o f.stl", dir_);
  EXPECT_EQ(flat.exit_code, 0) << flat.err;
  EXPECT_EQ(Json::parse(flat.out)["profile"], "flat") << flat.out;
  const auto round =
      run_command(lsolid() + " b.ls --profile round -o r.stl", dir_);
  EXPECT_EQ(round.exit_code, 0) << round.err;
  EXPECT_NE(round.out.find("placement: planar, lying flat; underside cut"),
            std::string::npos)
      << round.out;
  { std::ofstream(dir_ / "c.ls") << "profile: round\n\u03C9: F+F+F\n"; }
  const auto file = run_command(lsolid() + " c.ls --json -o c.stl", dir_);
  EXPECT_EQ(file.exit_code, 0) << file.err;
  EXPECT_EQ(Json::parse(file.out)["profile"], "round") << file.out;
}

TEST_F(Build, RefusesAModelThatDoesNotFitTheBedUnlessForced) {
  use_printable("hilbert-cube", "h.ls");  // 60 mm on each side
  const auto small = run_command(lsolid() + " h.ls --bed 50x50x50mm", dir_);
  EXPECT_EQ(small.exit_code, 3);
  EXPECT_NE(small.out.find("bed: 60.0 x 60.0 x 60.0 mm does not fit 50 x 50 x "
                           "50 mm\n"),
            std::string::npos)
      << small.out;
  EXPECT_EQ(small.err,
            "error: the model does not fit the bed; h.stl was not written "
            "(--force writes it anyway)\n");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "h.stl"));
  EXPECT_EQ(
      run_command(lsolid() + " h.ls --bed 50x50x50mm --force", dir_).exit_code,
      0);
  EXPECT_TRUE(std::filesystem::exists(dir_ / "h.stl"));
  const auto fits = run_command(lsolid() + " h.ls --bed 22x22x25cm", dir_);
  EXPECT_NE(fits.out.find("bed: fits 220 x 220 x 250 mm\n"), std::string::npos);
  EXPECT_NE(fits.out.find("overhang: "), std::string::npos);
}

TEST_F(Build, SaysPlainlyWhenTheModelFallsApartAndCanRefuseIt) {
  // A stem and, 3 units beside it, a loose twig: two pieces.
  {
    std::ofstream(dir_ / "apart.ls")
        << "\u03B4=90\u00B0\nwidth: 0.5\nbase: none\nsize: 50mm\n"
           "\u03C9: FF[+fff-F]\n";
  }
  const auto built = run_command(lsolid() + " apart.ls", dir_);
  EXPECT_EQ(built.exit_code, 0) << built.err;
  EXPECT_NE(built.out.find("pieces: 2 separate pieces, which print as loose "
                           "parts: the largest "),
            std::string::npos)
      << built.out;
  EXPECT_NE(built.out.find(" mm³ around ("), std::string::npos) << built.out;
  EXPECT_EQ(built.err,
            "warning: the model is in 2 separate pieces, which print as "
            "loose parts (--one-piece refuses such a model)\n");
  const auto check = run_command(lsolid() + " check apart.stl", dir_);
  EXPECT_EQ(check.exit_code, 0);
  EXPECT_NE(check.out.find("pieces: 2 separate pieces"), std::string::npos);
  const auto strict =
      run_command(lsolid() + " check apart.stl --one-piece", dir_);
  EXPECT_EQ(strict.exit_code, 1);
  EXPECT_NE(strict.out.find("verdict: NOT one piece (--one-piece)\n"),
            std::string::npos)
      << strict.out;
  const auto json =
      run_command(lsolid() + " check apart.stl --json --one-piece", dir_);
  EXPECT_EQ(json.exit_code, 1);
  const Json pieces = Json::parse(json.out);
  EXPECT_EQ(pieces["pieces"], 2) << json.out;
  ASSERT_EQ(pieces["loose_pieces"].size(), 1U) << json.out;
  EXPECT_GT(pieces["loose_pieces"][0]["volume_mm3"].get<double>(), 0.0);
  // Refused at build time: exit 3, nothing written over what was there.
  const auto refused =
      run_command(lsolid() + " apart.ls --one-piece -o again.stl", dir_);
  EXPECT_EQ(refused.exit_code, 3);
  EXPECT_EQ(refused.err,
            "error: the model is in 2 separate pieces; again.stl was not "
            "written (--one-piece)\n");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "again.stl"));
  // One piece passes.
  use_printable("hilbert-cube", "h.ls");
  EXPECT_EQ(run_command(lsolid() + " h.ls --one-piece", dir_).exit_code, 0);
  const auto whole = run_command(lsolid() + " check h.stl --one-piece", dir_);
  EXPECT_EQ(whole.exit_code, 0);
  EXPECT_NE(whole.out.find("pieces: 1\n"), std::string::npos);
}

TEST_F(Build, WritesTheSameBytesEveryRun) {
  // Two runs of one binary on one input, on one thread and on two:
  // byte-identical STL, OFF, OBJ (and its MTL) and 3MF, whose UUIDs lib3mf
  // would otherwise draw at random.
  // A planar figure (cut flat), a tree with leaves, and a Koch curve whose
  // mitres break chains into joints left to the union.
  use_printable("abop-1.25-bush", "bush.ls");
  use_printable("abop-1.24a", "plant.ls");
  {
    std::ofstream(dir_ / "koch.ls")
        << "n=2, \u03B4=60\u00B0\nwidth: 0.2\n\u03C9: F--F--F\n"
           "F \u2192 F+F--F+F\n";
  }
  for (const char* run : {"first", "second"}) {
    std::filesystem::create_directory(dir_ / run);
  }
  const std::vector<std::pair<std::string, std::string>> builds = {
      {"bush.ls -n 3", "bush"},
      {"plant.ls -n 2", "plant"},
      {"koch.ls -n 1", "koch"},
      {"bush.ls -n 1 --multi-material", "volumes"}};
  for (const auto& [input, name] : builds) {
    for (const char* ext : {".stl", ".off", ".obj", ".3mf"}) {
      const bool multi = name == "volumes";
      if (multi && std::string(ext) != ".3mf" && std::string(ext) != ".obj")
        continue;
      // The first run on one thread, the second on two: the union's
      // threads must not change a byte.
      for (const char* run : {"first", "second"}) {
        std::string command = lsolid();
        command += " ";
        command += input;
        command +=
            std::string(run) == "first" ? " --threads 1" : " --threads 2";
        command += " -q -o ";
        command += run;
        command += "/" + name + ext;
        const auto r = run_command(command, dir_);
        ASSERT_EQ(r.exit_code, 0) << input << ext << ": " << r.err;
      }
      std::vector<std::string> files{name + ext};
      if (std::string(ext) == ".obj") files.push_back(name + ".mtl");
      for (const std::string& file : files) {
        const std::string first = testing::read_text(dir_ / "first" / file);
        EXPECT_FALSE(first.empty()) << file;
        EXPECT_TRUE(first == testing::read_text(dir_ / "second" / file))
            << input << ": " << file << " differs between runs";
      }
    }
  }
}

TEST_F(Build, UnitesWithTheEngineAskedAndSaysWhatItDid) {
  use_printable("abop-1.25-bush", "bush.ls");
  const auto exact =
      run_command(lsolid() + " bush.ls -n 3 --no-decimate -o e.off", dir_);
  ASSERT_EQ(exact.exit_code, 0) << exact.err;
  const std::regex line(
      R"(\nunion engine: exact, \d+ threads, (\d+) unions \((\d+) with an )"
      R"(operand grown where faces touch\), (\d+) where )"
      R"(parts touch and 0 fallbacks left to the )"
      R"(corefinement; (\d+) crossings)");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(exact.out, m, line)) << exact.out;
  EXPECT_GT(std::stoi(m[1]), 0);
  EXPECT_EQ(std::stoi(m[2]), 0);
  EXPECT_GT(std::stoi(m[4]), 0);
  const auto oracle = run_command(
      lsolid() + " bush.ls -n 3 --no-decimate --union-engine corefine -o c.off",
      dir_);
  ASSERT_EQ(oracle.exit_code, 0) << oracle.err;
  EXPECT_NE(oracle.out.find("\nunion engine: corefine (CGAL's corefinement)\n"),
            std::string::npos)
      << oracle.out;
  ASSERT_FALSE(reported_volume(exact.out).empty()) << exact.out;
  EXPECT_EQ(reported_volume(exact.out), reported_volume(oracle.out));
  const auto json = run_command(
      lsolid() + " bush.ls -n 3 --no-decimate --json -o j.off", dir_);
  EXPECT_NE(json.out.find(R"("union_engine":{)"), std::string::npos);
  EXPECT_NE(json.out.find(R"("engine":"exact")"), std::string::npos);
  EXPECT_NE(json.out.find(R"("grown_unions":0)"), std::string::npos);
  const auto bad =
      run_command(lsolid() + " bush.ls --union-engine fast -o b.off", dir_);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--union-engine"), std::string::npos) << bad.err;
}

TEST_F(Build, FusesTubesThatTouch) {
  // Width 1 and a sideways step of 1: the circles of the two tubes touch.
  {
    std::ofstream(dir_ / "touch.ls")
        << "\u03B4=90\u00B0\nwidth: 1\nbase: none\n\u03C9: F[+f-F]\n";
  }
  const auto built = run_command(lsolid() + " touch.ls --one-piece", dir_);
  EXPECT_EQ(built.exit_code, 0) << built.err;
  EXPECT_NE(built.out.find("1 shell, genus 0"), std::string::npos) << built.out;
  // Their flats lie face on face: the exact engine grows one tube by a
  // thousand units in the last place and unites them itself.
  EXPECT_NE(built.out.find(" 1 unions (1 with an operand grown where faces "
                           "touch), 0 where parts touch and 0 fallbacks"),
            std::string::npos)
      << built.out;
  const auto oracle = run_command(
      lsolid() + " touch.ls --union-engine corefine -o c.stl", dir_);
  ASSERT_EQ(oracle.exit_code, 0) << oracle.err;
  ASSERT_FALSE(reported_volume(built.out).empty()) << built.out;
  EXPECT_EQ(reported_volume(built.out), reported_volume(oracle.out));
}

TEST_F(Build, LeavesOutSegmentsDrawnAgainAndSaysHowMany) {
  { std::ofstream(dir_ / "again.ls") << "base: none\n\u03C9: F[F][F]F\n"; }
  const auto built = run_command(lsolid() + " again.ls", dir_);
  EXPECT_EQ(built.exit_code, 0) << built.err;
  EXPECT_NE(built.out.find("segments: 4 (2 drawn again over another, left "
                           "out), leaves: 0\n"),
            std::string::npos)
      << built.out;
  // One straight tube: nothing is left for a union to do.
  EXPECT_NE(built.out.find("parts: 1 tubes, 0 junction hulls, 0 joints"),
            std::string::npos)
      << built.out;
  EXPECT_NE(built.out.find("union: 0 contacts, 0 booleans"), std::string::npos)
      << built.out;
}

// --json prints one JSON object whatever happens: a build that fails
// before its report says what failed, where, and with which exit code
// (it once printed nothing).
TEST_F(Build, SpeaksJsonWhenItFails) {
  { std::ofstream(dir_ / "wide.ls") << "n=0\naxiom: F!(1e200)F\n"; }
  const auto bad = run_command(lsolid() + " wide.ls --json -o w.stl", dir_);
  EXPECT_EQ(bad.exit_code, 2);
  const Json refused = Json::parse(bad.out);
  EXPECT_EQ(refused["output"], "w.stl");
  EXPECT_EQ(refused["written"], false);
  EXPECT_EQ(refused["exit_code"], 2);
  EXPECT_EQ(refused["error"]["place"],
            Json::parse(R"({"file": "wide.ls", "line": 2, "column": 9})"));
  EXPECT_NE(bad.err.find(refused["error"]["message"].get<std::string>()),
            std::string::npos);
  // An output in a folder that is not there: an I/O failure, without a
  // place.
  { std::ofstream(dir_ / "f.ls") << "\u03C9: F\n"; }
  const auto io = run_command(lsolid() + " f.ls --json -o nowhere/f.stl", dir_);
  EXPECT_EQ(io.exit_code, 4);
  const Json lost = Json::parse(io.out);
  EXPECT_EQ(lost["written"], false);
  EXPECT_EQ(lost["exit_code"], 4);
  EXPECT_TRUE(lost["error"]["place"].is_null());
  EXPECT_EQ(lost["error"]["message"], "nowhere/f.stl: no folder nowhere");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "w.stl"));
}

TEST_F(Build, IsQuietOrSpeaksJsonWhenAsked) {
  use_printable("hilbert-cube", "h.ls");
  const auto quiet = run_command(lsolid() + " h.ls -q", dir_);
  EXPECT_EQ(quiet.exit_code, 0);
  EXPECT_EQ(quiet.out, "");
  EXPECT_TRUE(std::filesystem::exists(dir_ / "h.stl"));
  const auto json = run_command(lsolid() + " h.ls --json -o j.stl", dir_);
  EXPECT_EQ(json.exit_code, 0);
  const Json report = Json::parse(json.out);
  // The members in the order docs/cli.md lists them.
  std::vector<std::string> keys;
  for (const auto& [key, value] : report.items()) keys.push_back(key);
  const std::vector<std::string> documented{"output",
                                            "written",
                                            "united",
                                            "segments",
                                            "repeated_segments",
                                            "leaves",
                                            "tubes",
                                            "junction_hulls",
                                            "joints",
                                            "leaf_plates",
                                            "spheres",
                                            "surface_plates",
                                            "contacts",
                                            "booleans",
                                            "union_engine",
                                            "mm_per_unit",
                                            "base",
                                            "lies_flat",
                                            "profile",
                                            "underside_cut_mm",
                                            "decimation",
                                            "colors",
                                            "volumes",
                                            "triangles",
                                            "volume_mm3",
                                            "bounds",
                                            "printable",
                                            "shells",
                                            "pieces",
                                            "loose_pieces",
                                            "genus",
                                            "overhang_mm2",
                                            "needs_supports",
                                            "fits_bed",
                                            "warnings",
                                            "seconds"};
  EXPECT_EQ(keys, documented);
  EXPECT_EQ(report["output"], "j.stl");
  EXPECT_EQ(report["written"], true);
  EXPECT_EQ(report["united"], true);
  EXPECT_EQ(report["segments"], 63);
  EXPECT_EQ(report["repeated_segments"], 0);
  EXPECT_EQ(report["leaves"], 0);
  EXPECT_EQ(report["tubes"], 1);
  EXPECT_EQ(report["printable"], true);
  EXPECT_EQ(report["shells"], 1);
  EXPECT_EQ(report["pieces"], 1);
  EXPECT_EQ(report["loose_pieces"], Json::array());
  EXPECT_EQ(report["genus"], 0);
  EXPECT_TRUE(report["base"].is_null());
  EXPECT_TRUE(report["fits_bed"].is_null());
  EXPECT_EQ(json.out.back(), '\n');
  // Names are JSON strings: quotes and backslashes escaped.
  const auto quoted =
      run_command(lsolid() + " h.ls --json -o 'q\"u\\o.stl'", dir_);
  EXPECT_EQ(quoted.exit_code, 0);
  const std::string quoted_head = "{\"output\":\"q\\\"u\\\\o.stl\",";
  EXPECT_EQ(quoted.out.substr(0, quoted_head.size()), quoted_head);
  EXPECT_EQ(Json::parse(quoted.out)["output"], "q\"u\\o.stl");
  EXPECT_EQ(std::count(json.out.begin(), json.out.end(), '\n'), 1);
}

TEST_F(Build, RefusesAPrintSettingGivenTwice) {
  {
    std::ofstream(dir_ / "t.ls")
        << "wall: 0.8mm\nbase: none\nwall: 2mm\n\u03C9: F\n";
  }
  const auto r = run_command(lsolid() + " t.ls", dir_);
  expect_failure(r, 2,
                 "t.ls:3:7: error: 'wall' is set twice\n"
                 "wall: 2mm\n"
                 "      ^\n");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "t.stl"));
}

TEST_F(Build, ChecksTheOutputFoldersBeforeBuilding) {
  use_printable("branches-90", "b.ls");
  const auto r = run_command(lsolid() + " b.ls --preview nowhere/b.png", dir_);
  expect_failure(r, 4, "error: nowhere/b.png: no folder nowhere\n");
  EXPECT_EQ(r.out, "");  // refused before the build
  EXPECT_FALSE(std::filesystem::exists(dir_ / "b.stl"));
}

TEST_F(Build, RefusesOptionsThatWouldBeIgnored) {
  use_printable("branches-90", "b.ls");
  const auto ascii = run_command(lsolid() + " b.ls --ascii -o b.off", dir_);
  expect_failure(
      ascii, 2,
      "--ascii: error: --ascii is for STL; 'b.off' is not an STL file\n");
  const auto force = run_command(lsolid() + " b.ls --force", dir_);
  EXPECT_EQ(force.exit_code, 2);
  EXPECT_NE(force.err.find("--force requires --bed"), std::string::npos)
      << force.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "b.off"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "b.stl"));
}

TEST_F(Build, LeavesNothingBehindOnBadInput) {
  { std::ofstream(dir_ / "bad.ls") << "\u03C9: F\nF \u2192 F]\n"; }
  { std::ofstream(dir_ / "old.stl") << "keep me"; }
  const auto r = run_command(lsolid() + " bad.ls -o old.stl", dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(read_text(dir_ / "old.stl"), "keep me");
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e :
       std::filesystem::directory_iterator(dir_)) {
    ++entries;
  }
  EXPECT_EQ(entries, 2U);
}

TEST_F(Build, ExitsWithFourWhenTheReportCannotBeWritten) {
  // A build and check exited 0 with the report lost.
  { std::ofstream(dir_ / "f.ls") << "\u03C9: F\n"; }
  ASSERT_EQ(run_command(lsolid() + " f.ls -q", dir_).exit_code, 0);
  for (const std::string command :
       {" f.ls", " f.ls --json", " check f.stl", " check f.stl --json",
        " derive f.ls", " skeleton f.ls --json"}) {
    // The subshell's own output is captured; lsolid's goes to /dev/full.
    // (Appending piecewise avoids a GCC 12 -Wrestrict false alarm.)
    const auto r =
        run_command(std::string("(").append(lsolid()).append(command).append(
                        " > /dev/full)"),
                    dir_);
    EXPECT_EQ(r.exit_code, 4) << command;
    EXPECT_EQ(r.err,
              "error: cannot write to standard output: No space left on "
              "device\n")
        << command;
  }
}

TEST_F(Build, RefusesSpecialFilesAsOutputsBeforeBuilding) {
  // Each was replaced by a regular file.
  { std::ofstream(dir_ / "f.ls") << "\u03C9: F\n"; }
  ASSERT_EQ(::mkfifo((dir_ / "fifo.stl").c_str(), 0644), 0);
  ASSERT_EQ(::mkfifo((dir_ / "m.mtl").c_str(), 0644), 0);
  ASSERT_EQ(::mkfifo((dir_ / "p.png").c_str(), 0644), 0);
  std::filesystem::create_directory(dir_ / "folder.stl");
  std::filesystem::create_symlink("/dev/null", dir_ / "null.stl");
  const int sock = ::socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  const std::string socket_path = (dir_ / "sock.stl").string();
  ASSERT_LT(socket_path.size(), sizeof(address.sun_path));
  std::copy(socket_path.begin(), socket_path.end(), address.sun_path);
  ASSERT_EQ(::bind(sock, reinterpret_cast<const sockaddr*>(&address),
                   sizeof(address)),
            0);
  for (const auto& [args, message] :
       std::vector<std::pair<std::string, std::string>>{
           {"-o fifo.stl",
            "--output: error: 'fifo.stl' is a FIFO (named pipe); "
            "lsolid writes only regular files\n"},
           {"-o folder.stl",
            "--output: error: 'folder.stl' is a directory; "
            "lsolid writes only regular files\n"},
           {"-o null.stl",
            "--output: error: 'null.stl' is a link to a device; "
            "lsolid writes only regular files\n"},
           {"-o sock.stl",
            "--output: error: 'sock.stl' is a socket; lsolid "
            "writes only regular files\n"},
           {"-o m.obj",
            "--output: error: 'm.mtl' is a FIFO (named pipe); "
            "lsolid writes only regular files\n"},
           {"--preview p.png",
            "--preview: error: 'p.png' is a FIFO (named "
            "pipe); lsolid writes only regular files\n"}}) {
    const auto r = run_command(lsolid() + " f.ls " + args, dir_);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(r.err, message) << args;
    EXPECT_EQ(r.out, "") << args;  // refused before building
  }
  ::close(sock);
  EXPECT_TRUE(std::filesystem::is_fifo(dir_ / "fifo.stl"));
  EXPECT_TRUE(std::filesystem::is_fifo(dir_ / "m.mtl"));
  EXPECT_TRUE(std::filesystem::is_directory(dir_ / "folder.stl"));
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
  EXPECT_TRUE(std::filesystem::is_socket(dir_ / "sock.stl"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "f.stl"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "m.obj"));
}

TEST_F(Build, RefusesSpecialFilesAsInputsBeforeOpeningThem) {
  // Opening a FIFO waits for a writer: any command that opened one would
  // hang this test.
  ASSERT_EQ(::mkfifo((dir_ / "fifo.ls").c_str(), 0644), 0);
  ASSERT_EQ(::mkfifo((dir_ / "fifo.v").c_str(), 0644), 0);
  std::filesystem::create_symlink("/dev/zero", dir_ / "zero.ls");
  { std::ofstream(dir_ / "plant.l") << "Lsystem: 1\nAxiom: F\nendlsystem\n"; }
  for (const std::string command : {"", "derive ", "skeleton "}) {
    for (const auto& [input, message] :
         std::vector<std::pair<std::string, std::string>>{
             {"fifo.ls",
              "fifo.ls: error: cannot read file: it is a FIFO (named pipe), "
              "and lsolid reads only regular files\n"},
             {"zero.ls",
              "zero.ls: error: cannot read file: it is a device, and lsolid "
              "reads only regular files\n"},
             {"plant.l --view fifo.v",
              "fifo.v: error: cannot read file: it is a FIFO (named pipe), "
              "and lsolid reads only regular files\n"}}) {
      const auto r = run_command(lsolid() + " " + command + input, dir_);
      EXPECT_EQ(r.exit_code, 2) << command << input;
      EXPECT_EQ(r.err, message) << command << input;
      EXPECT_EQ(r.out, "") << command << input;
    }
  }
  EXPECT_TRUE(std::filesystem::is_fifo(dir_ / "fifo.ls"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "fifo.stl"));
}

TEST_F(Build, WritesThroughASymbolicLinkToItsRegularFile) {
  { std::ofstream(dir_ / "f.ls") << "\u03C9: F\n"; }
  { std::ofstream(dir_ / "real.stl") << "old"; }
  std::filesystem::create_symlink("real.stl", dir_ / "link.stl");
  const auto r = run_command(lsolid() + " f.ls -q -o link.stl", dir_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::is_symlink(dir_ / "link.stl"));
  EXPECT_EQ(run_command(lsolid() + " check real.stl", dir_).exit_code, 0);
}

// A stem (colour 0) with a branch of colour 1 and one of colour 2.
constexpr const char* kThreeColours =
    "n=0, \u03B4=45\u00B0\nwidth: 0.2\n\u03C9: FF[+'F][-''F]F\n";

TEST_F(Build, Writes3mfWithColoursThatPrusaSlicerOpens) {
  use_printable("abop-1.25-bush", "bush.ls");
  const auto r = run_command(lsolid() + " bush.ls -n 3 -o bush.3mf", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Stems take colours 0-2, leaves three more (the bush's ' steps).
  EXPECT_NE(r.out.find("colours: 0 #7B4A2A ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(", 3 #8CC63F ("), std::string::npos) << r.out;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex("triangles: ([0-9]+)\n")));
  const std::string triangles = m[1];
  const auto check = run_command(lsolid() + " check bush.3mf", dir_);
  EXPECT_EQ(check.exit_code, 0) << check.out;
  EXPECT_NE(check.out.find("bush.3mf: " + triangles + " triangles"),
            std::string::npos)
      << check.out;
  const auto prusa = run_command("prusa-slicer --info bush.3mf", dir_);
  ASSERT_EQ(prusa.exit_code, 0) << prusa.err;
  EXPECT_NE(prusa.out.find("number_of_facets = " + triangles + "\n"),
            std::string::npos)
      << prusa.out;
  EXPECT_NE(prusa.out.find("manifold = yes\n"), std::string::npos);
  EXPECT_NE(prusa.out.find("size_x = 99.99"), std::string::npos) << prusa.out;
}

TEST_F(Build, WritesOneVolumePerColourForAMultiMaterialPrinter) {
  { std::ofstream(dir_ / "three.ls") << kThreeColours; }
  const auto r =
      run_command(lsolid() + " three.ls --multi-material -o three.3mf", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::smatch written;
  ASSERT_TRUE(std::regex_search(
      r.out, written,
      std::regex("volumes: 3 for 3 extruders, not overlapping, ([0-9]+) "
                 "triangles written: colour 0 ")))
      << r.out;
  // lsolid check reads the volumes back apart and finds no overlap.
  const auto check = run_command(lsolid() + " check three.3mf", dir_);
  EXPECT_EQ(check.exit_code, 0) << check.out;
  EXPECT_NE(check.out.find("three.3mf: 3 volumes\n"), std::string::npos)
      << check.out;
  EXPECT_NE(check.out.find("volume 3 (colour 2): "), std::string::npos);
  // The colours line counts the triangles written, as check reads them.
  std::size_t read_back = 0;
  const std::regex volume_line("volume [0-9] \\(colour [0-9]\\): ([0-9]+)");
  for (auto it = std::sregex_iterator(check.out.begin(), check.out.end(),
                                      volume_line);
       it != std::sregex_iterator(); ++it) {
    read_back += std::stoul((*it)[1]);
  }
  EXPECT_EQ(read_back, std::stoul(written[1]));
  EXPECT_NE(check.out.find("overlap: none, the volumes only touch"),
            std::string::npos)
      << check.out;
  // PrusaSlicer loads one object of three parts, an extruder each: saved
  // again, its own metadata lists them.
  const auto saved = run_command(
      "prusa-slicer --export-3mf -o saved.3mf three.3mf && unzip -p saved.3mf "
      "Metadata/Slic3r_PE_model.config",
      dir_);
  ASSERT_EQ(saved.exit_code, 0) << saved.err;
  const auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = saved.out.find(what); at != std::string::npos;
         at = saved.out.find(what, at + 1)) {
      ++n;
    }
    return n;
  };
  EXPECT_EQ(count("<object "), 1U) << saved.out;
  EXPECT_EQ(count("<volume "), 3U) << saved.out;
  for (const char* extruder : {"1", "2", "3"}) {
    EXPECT_EQ(count(std::string("key=\"extruder\" value=\"") + extruder + "\""),
              1U)
        << extruder;
  }
  // Given colours, indices of one colour print as one volume: branch 2
  // takes the last colour given, branch 1's.
  const auto two = run_command(
      lsolid() +
          " three.ls --multi-material --colors '#7B4A2A #8CC63F' -o two.3mf "
          "--json",
      dir_);
  ASSERT_EQ(two.exit_code, 0) << two.err;
  const Json colors = Json::parse(two.out)["colors"];
  ASSERT_EQ(colors.size(), 2U) << two.out;  // no colour 2
  EXPECT_EQ(colors[0]["color"], 0);
  EXPECT_EQ(colors[0]["rgb"], "#7B4A2A");
  EXPECT_GT(colors[0]["triangles"].get<int>(), 0);
  EXPECT_EQ(colors[1]["color"], 1);
  EXPECT_EQ(colors[1]["rgb"], "#8CC63F");
  const Json volumes = Json::parse(two.out)["volumes"];
  ASSERT_EQ(volumes.size(), 2U) << two.out;
  EXPECT_EQ(volumes[0]["color"], 0);
  EXPECT_GT(volumes[0]["triangles"].get<int>(), 0);
  EXPECT_EQ(volumes[1]["color"], 1);
  const auto check_two = run_command(lsolid() + " check two.3mf", dir_);
  EXPECT_EQ(check_two.exit_code, 0) << check_two.out;
  EXPECT_NE(check_two.out.find("two.3mf: 2 volumes\n"), std::string::npos);
  const auto bad =
      run_command(lsolid() + " three.ls --colors '#7B4A2A red' -o x.3mf", dir_);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.err,
            "--colors:1:9: error: a colour is #RRGGBB, not 'red'\n#7B4A2A "
            "red\n        ^\n");
  const auto obj = run_command(
      lsolid() + " three.ls --multi-material -o three.obj -q", dir_);
  EXPECT_EQ(obj.exit_code, 0) << obj.err;
  EXPECT_TRUE(std::filesystem::exists(dir_ / "three.mtl"));
  EXPECT_EQ(run_command(lsolid() + " check three.obj", dir_).exit_code, 0);
  const auto plain =
      run_command(lsolid() + " three.ls --colors '#7B4A2A' -q -o p.stl", dir_);
  EXPECT_EQ(plain.exit_code, 0);
  EXPECT_EQ(plain.err,
            "warning: --colors is for .3mf and .obj output; p.stl is written "
            "without colour\n");
  const auto stl =
      run_command(lsolid() + " three.ls --multi-material -o three.stl", dir_);
  EXPECT_EQ(stl.exit_code, 2);
  EXPECT_EQ(stl.err,
            "--multi-material: error: volumes per colour need a .3mf or .obj "
            "output, not 'three.stl'\n");
}

TEST_F(Build, CheckFindsVolumesThatOverlap) {
  // Two unit cubes as two OBJ objects, the second shifted half a cube.
  std::ofstream obj(dir_ / "overlap.obj");
  for (const double dx : {0.0, 0.5}) {
    obj << "o cube\n";
    for (int i = 0; i < 8; ++i) {
      obj << "v " << dx + (i & 1) << " " << ((i >> 1) & 1) << " "
          << ((i >> 2) & 1) << "\n";
    }
    const int b = dx == 0.0 ? 0 : 8;
    for (const auto& f :
         {std::array{1, 3, 2}, std::array{2, 3, 4}, std::array{5, 6, 8},
          std::array{5, 8, 7}, std::array{1, 2, 6}, std::array{1, 6, 5},
          std::array{3, 7, 8}, std::array{3, 8, 4}, std::array{1, 5, 7},
          std::array{1, 7, 3}, std::array{2, 4, 8}, std::array{2, 8, 6}}) {
      obj << "f " << b + f[0] << " " << b + f[1] << " " << b + f[2] << "\n";
    }
  }
  obj.close();
  const auto check = run_command(lsolid() + " check overlap.obj", dir_);
  EXPECT_EQ(check.exit_code, 1) << check.out;
  EXPECT_NE(check.out.find("volume 1 (colour 0): 12 triangles, 1.000 mm³, "
                           "printable\n"),
            std::string::npos)
      << check.out;
  EXPECT_NE(check.out.find("overlap: the volumes overlap"), std::string::npos)
      << check.out;
  EXPECT_NE(check.out.find("verdict: NOT printable\n"), std::string::npos);
}

TEST_F(Build, RefusesUnknownFormatsAndEmptyModels) {
  use_printable("branches-90", "b.ls");
  const auto r = run_command(lsolid() + " b.ls -o b.ply", dir_);
  expect_failure(
      r, 2,
      "--output: error: unknown output format '.ply': use .stl, .off, "
      ".scad, .3mf or .obj\n");
  { std::ofstream(dir_ / "empty.ls") << "\u03C9: A+B\n"; }
  // Drawing nothing is bad input, placed at the axiom.
  const auto empty = run_command(lsolid() + " empty.ls", dir_);
  expect_failure(
      empty, 2,
      "empty.ls:1:4: error: nothing to build: the L-system draws no "
      "segment and no polygon; modules without a turtle meaning draw "
      "nothing (map them with an alias block, e.g. 'aliases: Fl=F "
      "Fr=F')\n\u03C9: A+B\n   ^\n");
  // A skeleton in millimetres cannot be scaled either; in model units it
  // is shown empty, with a warning.
  const auto mm = run_command(lsolid() + " skeleton empty.ls --wall 1mm", dir_);
  EXPECT_EQ(mm.exit_code, 2);
  EXPECT_EQ(mm.err, empty.err);
  EXPECT_EQ(run_command(lsolid() + " skeleton empty.ls", dir_).exit_code, 0);
}

TEST_F(Build, ReadsPrintSettingsFromTheFile) {
  // A thin F: 2 cm tall, as wide as the 1 mm wall.
  {
    std::ofstream(dir_ / "h.ls")
        << "height: 2cm\nwall: 1mm\nbase: none\nwidth: 0.001\n\u03C9: F\n";
  }
  EXPECT_EQ(run_command(lsolid() + " h.ls", dir_).exit_code, 0);
  const auto check = run_command(lsolid() + " check --json h.stl", dir_);
  const Json checked = Json::parse(check.out);
  EXPECT_EQ(checked["bounds"]["min"][2], 0.0) << check.out;
  EXPECT_EQ(checked["bounds"]["max"][2], 20.0) << check.out;
  // An octagon whose sides touch a circle of radius 0.5 mm (0.828 mm²)
  // times 20 mm.
  EXPECT_GE(checked["volume_mm3"].get<double>(), 16.568) << check.out;
  EXPECT_LT(checked["volume_mm3"].get<double>(), 16.569) << check.out;
  // The command line wins: a disc 2 mm thick (two walls) under the foot.
  const auto disc = run_command(lsolid() + " h.ls --base disc", dir_);
  EXPECT_EQ(disc.exit_code, 0);
  EXPECT_NE(disc.out.find("base: a disc of "), std::string::npos);
  EXPECT_NE(
      disc.out.find(" mm radius, 2.0 mm thick, under a foot 1.1 mm wide\n"),
      std::string::npos)
      << disc.out;
  EXPECT_NE(disc.out.find(", from ("), std::string::npos);
  EXPECT_NE(disc.out.find(", 0.00)\n"), std::string::npos) << disc.out;
}

TEST_F(Build, SkeletonInMillimetresWithPrintOptions) {
  const auto r = run_command(lsolid() + " skeleton " +
                             (kSource / "printables/hilbert-cube.ls").string() +
                             " --scale 10mm --wall 1mm --json -n 1");
  EXPECT_EQ(r.exit_code, 0);
  const std::string head =
      "{\"units\": \"mm\", \"segments\": [\n{\"p0\": [0,0,0], \"p1\": [10,0,0]";
  EXPECT_EQ(r.out.substr(0, head.size()), head);
  EXPECT_NE(r.out.find("\"r0\": 1.5"), std::string::npos);
}

TEST(Check, ExitsOneForAnUnprintableMeshAndTwoForAnUnreadableOne) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto off =
      dir / ("lsolid_two_boxes_" + std::to_string(::getpid()) + ".off");
  {
    std::ofstream out(off);
    out << "OFF\n8 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n5 5 5\n6 5 5\n5 6 5\n5 5 "
           "6\n"
           "3 0 2 1\n3 4 5 6\n";
  }
  const auto r = run_command(lsolid() + " check " + off.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("verdict: NOT printable"), std::string::npos);
  EXPECT_NE(r.out.find("boundary edges (the mesh is not closed)"),
            std::string::npos);
  std::filesystem::remove(off);
  const auto missing = run_command(lsolid() + " check /nonexistent.stl");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("cannot read"), std::string::npos);
}

// Whether a file a traced lsolid opened is one it may open: in the model's
// folder, or the system's (its libraries, their configuration, /proc).
bool may_open(const std::filesystem::path& path,
              const std::filesystem::path& model_folder) {
  if (testing::lies_in(path, model_folder)) return true;
  // Named in a system folder (OpenSSL's /usr/lib/ssl/openssl.cnf is a link
  // to /etc/ssl/openssl.cnf).
  for (const std::string system :
       {"/lib/", "/lib64/", "/usr/", "/proc/", "/sys/"}) {
    if (path.string().starts_with(system)) return true;
  }
  return path == "/etc/ld.so.cache" || path == "/etc/ld.so.preload";
}

// A model people download must never make lsolid open a file outside its
// folder, by any route a notation offers to name one: strace records every
// file each command opens, and none is outside the model's folder and the
// system's; no output holds the text of the files it aimed at.
TEST(Trust, NoCommandOpensAFileOutsideTheModelsFolder) {
  const auto root = testing::make_test_dir("lsolid_trust_");
  const auto secret = root / "secret";
  const auto trace = root / "trace.txt";
  // LeakSanitizer stops the world with ptrace, which strace holds already.
  const std::string env = "ASAN_OPTIONS=detect_leaks=0 ";
  for (const testing::HostileModel& model :
       testing::write_hostile_models(root)) {
    const auto dir = root / "models" / model.route;
    for (const std::string command : {"", "derive ", "skeleton "}) {
      const std::string line = env + testing::strace_prefix(trace) + lsolid() +
                               " " + command + model.file + " --dialect " +
                               model.dialect +
                               (command.empty() ? " -o out.stl" : "");
      const auto r = run_command(line, dir);
      SCOPED_TRACE(model.route + ": " + line);
      EXPECT_EQ(r.exit_code, 2) << r.err;
      EXPECT_EQ(r.err.find(testing::kSecretText), std::string::npos) << r.err;
      EXPECT_EQ(r.out.find(testing::kSecretText), std::string::npos) << r.out;
      const auto opened = testing::opened_files(trace, dir);
      // The trace holds the program's own opens: the model, its libraries.
      EXPECT_TRUE(std::any_of(opened.begin(), opened.end(), [&](const auto& p) {
        return p == dir / model.file;
      }));
      for (const auto& path : opened) {
        EXPECT_FALSE(testing::lies_in(path, secret)) << path;
        EXPECT_TRUE(may_open(path, dir)) << path;
      }
      EXPECT_FALSE(std::filesystem::exists(dir / "out.stl"));
    }
  }
  std::filesystem::remove_all(root);
}

// The catalogue of bad inputs, tests/data/diagnostics/cases.txt: a file, the
// exit code lsolid gives it, and the options after it. A case whose model
// names other files (a view file, headers, links) has them in
// companions/STEM/, copied beside it as they are (links stay links).
struct BadInput {
  std::string file;
  int exit_code = 0;
  std::string options;
};

// For test names and failure messages: the case as cases.txt has it.
void PrintTo(const BadInput& c, std::ostream* out) {
  *out << c.file << ' ' << c.exit_code << (c.options.empty() ? "" : " ")
       << c.options;
}

std::vector<BadInput> bad_inputs() {
  std::vector<BadInput> out;
  std::ifstream in(kDiagnostics / "cases.txt");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line.front() == '#') continue;
    std::istringstream words(line);
    BadInput c;
    words >> c.file >> c.exit_code;
    std::getline(words >> std::ws, c.options);
    out.push_back(c);
  }
  return out;
}

class Catalogue : public ::testing::TestWithParam<BadInput> {};

// Each bad input gives exactly its golden standard error and exit code,
// prints nothing on standard output, and leaves an existing output file
// as it was, with nothing else beside it.
TEST_P(Catalogue, GivesItsGoldenErrorAndLeavesTheOutputUntouched) {
  const BadInput& c = GetParam();
  const std::filesystem::path stem = std::filesystem::path(c.file).stem();
  const auto dir =
      std::filesystem::temp_directory_path() /
      ("lsolid_catalogue_" + std::to_string(::getpid()) + "_" + stem.string());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(kDiagnostics / c.file, dir / c.file);
  std::size_t companions = 0;
  const auto companion_folder = kDiagnostics / "companions" / stem;
  if (std::filesystem::is_directory(companion_folder)) {
    std::filesystem::copy(companion_folder, dir,
                          std::filesystem::copy_options::recursive |
                              std::filesystem::copy_options::copy_symlinks);
    for ([[maybe_unused]] const auto& e :
         std::filesystem::directory_iterator(companion_folder)) {
      ++companions;
    }
  }
  const std::string kept = "keep me: " + stem.string() + "\n";
  { std::ofstream(dir / "out.stl", std::ios::binary) << kept; }
  const std::string extension = std::filesystem::path(c.file).extension();
  // L-systems in any notation are built; meshes are checked.
  const bool is_ls =
      extension == ".ls" || extension == ".l" || extension == ".lpy";
  const std::string command =
      is_ls ? lsolid() + " " + c.file + " " + c.options + " -o out.stl"
            : lsolid() + " check " + c.file + " " + c.options;
  const auto r = run_command(command, dir);
  EXPECT_EQ(r.exit_code, c.exit_code) << command;
  EXPECT_EQ(r.err, read_text(kDiagnostics / (stem.string() + ".stderr")))
      << command;
  EXPECT_EQ(r.out, "") << command;
  EXPECT_EQ(read_text(dir / "out.stl"), kept) << command;
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e :
       std::filesystem::directory_iterator(dir)) {
    ++entries;
  }
  // The input, its companions and out.stl, no temporary.
  EXPECT_EQ(entries, 2U + companions) << command;
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Golden, Catalogue, ::testing::ValuesIn(bad_inputs()),
                         [](const auto& test) {
                           std::string name = test.param.file;
                           for (char& c : name) {
                             if (c == '-' || c == '.') c = '_';
                           }
                           return name;
                         });

TEST(CatalogueFolder, ListsEveryInputOnceWithItsGoldenError) {
  std::set<std::string> listed;
  for (const BadInput& c : bad_inputs()) {
    EXPECT_TRUE(listed.insert(c.file).second) << c.file << " twice";
    EXPECT_TRUE(std::filesystem::exists(
        kDiagnostics /
        (std::filesystem::path(c.file).stem().string() + ".stderr")))
        << c.file;
  }
  EXPECT_GE(listed.size(), 60U);
  for (const auto& entry : std::filesystem::directory_iterator(kDiagnostics)) {
    const std::string name = entry.path().filename().string();
    if (name == "cases.txt" || name == "companions" ||
        entry.path().extension() == ".stderr") {
      continue;
    }
    EXPECT_EQ(listed.count(name), 1U) << name << " is not in cases.txt";
  }
  for (const auto& entry :
       std::filesystem::directory_iterator(kDiagnostics / "companions")) {
    const std::string stem = entry.path().filename().string();
    EXPECT_TRUE(std::any_of(listed.begin(), listed.end(),
                            [&](const std::string& file) {
                              return std::filesystem::path(file).stem() == stem;
                            }))
        << "companions/" << stem << " belongs to no case";
  }
}

}  // namespace
}  // namespace lsolid
