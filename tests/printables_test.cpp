// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The gallery as a test: every printable (printables/*.ls in lsolid's or
// Lparser's notation, *.l in Fractint's, *.lpy in L-Py's) parses, derives
// and is walked by the turtle, giving the counts its `expect:` comment line
// states; and `lsolid FILE` turns it into an STL that `lsolid check` and
// admesh accept, at the `n` of its `test:` line where the full model is too
// slow for CI.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "lsolid/print_settings.hpp"
#include "lsys/interpretation.hpp"
#include "lsys/parser.hpp"
#include "lsys/source.hpp"
#include "support/mesh_checks.hpp"
#include "support/run_command.hpp"

namespace {

const std::filesystem::path kPrintables =
    std::filesystem::path(LSOLID_SOURCE_DIR) / "printables";

// The printables: `.ls` files in lsolid's notation or Lparser's, `.l`
// (Fractint, one system) and `.lpy` (L-Py), by file name.
std::vector<std::string> printable_names() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(kPrintables)) {
    const auto extension = entry.path().extension();
    if (extension == ".ls" || extension == ".l" || extension == ".lpy") {
      names.push_back(entry.path().filename().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

struct Expectation {
  std::size_t segments = 0;
  std::size_t polygons = 0;
};

// A comment line of any notation: `//` (lsolid), `#` (Lparser, L-Py) or
// `;` (Fractint), then `key:`.
std::string comment_line(const char* key) {
  return std::string(R"((?://|#|;) )") + key + ": ";
}

Expectation expectation(const std::string& text) {
  std::smatch match;
  static const std::regex kLine(comment_line("expect") +
                                R"(segments (\d+), polygons (\d+))");
  if (!std::regex_search(text, match, kLine)) {
    ADD_FAILURE() << "no 'expect: segments N, polygons M' comment line";
    return {};
  }
  return {std::stoul(match[1]), std::stoul(match[2])};
}

class Printable : public ::testing::TestWithParam<std::string> {};

// The options the gallery builds a printable with, from its `options:`
// line: only `-n N`, the order a Fractint file cannot hold.
std::string options_of(const std::string& text) {
  std::smatch match;
  static const std::regex kLine(comment_line("options") + R"((-n \d+))");
  return std::regex_search(text, match, kLine) ? match[1].str() : "";
}

TEST_P(Printable, DerivesTheStatedSkeleton) {
  const auto source = lsys::load_source(kPrintables / GetParam());
  ASSERT_TRUE(source->text().starts_with("//") ||
              source->text().starts_with("#") ||
              source->text().starts_with(";"))
      << "each printable starts with a comment naming its source";
  const Expectation expected = expectation(source->text());
  lsys::Grammar grammar = lsys::parse_grammar(
      source, {.extra_settings = lsolid::print_setting_names()});
  const std::string options = options_of(source->text());
  if (!options.empty()) {
    grammar.settings.derivation_length = std::stoi(options.substr(3));
  }
  // Each printable in lsolid's notation carries the settings of a good
  // print; the others are read verbatim and take the defaults.
  const auto states = [&](const std::string& key) {
    return std::any_of(
        grammar.extra_settings.begin(), grammar.extra_settings.end(),
        [&](const lsys::ExtraSetting& s) { return s.key == key; });
  };
  if (lsys::detect_dialect(source->text()) == lsys::Dialect::Ls) {
    EXPECT_TRUE(states("size"));
    EXPECT_TRUE(states("wall"));
  }
  const lsys::Skeleton skeleton = lsys::interpret(grammar);
  EXPECT_EQ(skeleton.segments.size(), expected.segments);
  EXPECT_EQ(skeleton.polygons.size(), expected.polygons);
  EXPECT_EQ(skeleton.degenerate_polygons, 0U);
  for (const lsys::Segment& s : skeleton.segments) {
    ASSERT_TRUE(std::isfinite(s.p1.x) && std::isfinite(s.p1.y) &&
                std::isfinite(s.p1.z));
    ASSERT_GE(s.start_diameter, 0.0);
  }
}

// The volume the solid test must build, from the file's `// volume: V mm³`
// line: the model's volume at the test's n, met to within 1% (decimation
// may move the surface by its tolerance; a lost branch or leaf moves the
// volume by more).
std::optional<double> stated_volume_mm3(const std::string& text) {
  std::smatch match;
  static const std::regex kLine(comment_line("volume") +
                                R"(([0-9]+(?:\.[0-9]+)?) mm³)");
  if (!std::regex_search(text, match, kLine)) return std::nullopt;
  return std::stod(match[1]);
}

// The volume the build reports (`volume: V mm³`).
std::optional<double> reported_volume_mm3(const std::string& report) {
  std::smatch match;
  static const std::regex kLine(
      R"((?:^|\n)volume: ([0-9]+(?:\.[0-9]+)?) mm³\n)");
  if (!std::regex_search(report, match, kLine)) return std::nullopt;
  return std::stod(match[1]);
}

// The derivation length for the solid test: the file's `// test: n = K`,
// else the file's own.
std::string test_length_option(const std::string& text) {
  std::smatch match;
  static const std::regex kLine(comment_line("test") + R"(n = (\d+))");
  return std::regex_search(text, match, kLine) ? " -n " + match[1].str() : "";
}

TEST_P(Printable, BuildsAnStlThatCheckAndAdmeshAccept) {
  const std::string name = GetParam();
  const std::string text = lsolid::testing::read_text(kPrintables / name);
  const auto stl =
      std::filesystem::temp_directory_path() /
      ("lsolid_gallery_" + std::to_string(::getpid()) + "_" + name + ".stl");
  const auto built = lsolid::testing::run_command(
      lsolid::testing::lsolid() + " '" + (kPrintables / name).string() + "'" +
      test_length_option(text) + " -o '" + stl.string() + "'");
  ASSERT_EQ(built.exit_code, 0) << built.out << built.err;
  EXPECT_NE(built.out.find("check: printable"), std::string::npos) << built.out;
  EXPECT_NE(built.out.find("; 1 shell,"), std::string::npos) << built.out;
  const std::optional<double> stated = stated_volume_mm3(text);
  const std::optional<double> reported = reported_volume_mm3(built.out);
  ASSERT_TRUE(stated) << "no 'volume: V mm³' comment line";
  ASSERT_TRUE(reported) << built.out;
  EXPECT_NEAR(*reported, *stated, 0.01 * *stated) << built.out;
  const auto checked = lsolid::testing::run_command(
      lsolid::testing::lsolid() + " check --json '" + stl.string() + "'");
  EXPECT_EQ(checked.exit_code, 0) << checked.out;
  EXPECT_EQ(nlohmann::json::parse(checked.out)["shells"], 1) << checked.out;
  lsolid::testing::expect_admesh_agrees(stl);
  std::filesystem::remove(stl);
}

// The exact union engine against the corefinement, its oracle, on each
// printable at its test n, before decimation, in doubles (OFF): the same
// validity, shells and genus, the volume to 10⁻⁶ (the engines round and
// mend their intermediate unions apart), and no fallback of the exact
// engine (a union of parts that touch is the corefinement's by design).
TEST_P(Printable, UnitesAsTheCorefinementDoes) {
  const std::string name = GetParam();
  const std::string text = lsolid::testing::read_text(kPrintables / name);
  std::array<nlohmann::json, 2> reports;
  const std::array<const char*, 2> engines{"exact", "corefine"};
  for (std::size_t i = 0; i < 2; ++i) {
    const auto off = std::filesystem::temp_directory_path() /
                     ("lsolid_oracle_" + std::to_string(::getpid()) + "_" +
                      engines[i] + "_" + name + ".off");
    std::string command = lsolid::testing::lsolid();
    command += " '" + (kPrintables / name).string() + "'";
    command += test_length_option(text);
    command += " --no-decimate --json -q --union-engine ";
    command += engines[i];
    command += " -o '" + off.string() + "'";
    const auto built = lsolid::testing::run_command(command);
    ASSERT_EQ(built.exit_code, 0) << engines[i] << ": " << built.err;
    reports[i] = nlohmann::json::parse(built.out);
    std::filesystem::remove(off);
  }
  const nlohmann::json& exact = reports[0];
  const nlohmann::json& oracle = reports[1];
  EXPECT_TRUE(exact["printable"].get<bool>());
  EXPECT_EQ(exact["printable"], oracle["printable"]);
  EXPECT_EQ(exact["shells"], oracle["shells"]);
  EXPECT_EQ(exact["genus"], oracle["genus"]);
  const double v = oracle["volume_mm3"].get<double>();
  EXPECT_NEAR(exact["volume_mm3"].get<double>(), v, 1e-6 * v);
  if (exact["united"].get<bool>() && !exact["union_engine"].is_null()) {
    EXPECT_EQ(exact["union_engine"]["fallbacks"], 0)
        << exact["union_engine"]["fallback_reason"];
  }
}

// A printable's section of docs/gallery.md: its command and the figures
// its build reported (scripts/gallery-page writes them).
struct GalleryEntry {
  std::string command;
  std::string triangles;
  std::string volume;
  std::string size;
  int seconds = -1;
  std::string check;
};

std::optional<GalleryEntry> gallery_entry(const std::string& stem) {
  const std::string page = lsolid::testing::read_text(
      std::filesystem::path(LSOLID_SOURCE_DIR) / "docs/gallery.md");
  const std::string heading = "\n## " + stem + "\n";
  const std::size_t begin = page.find(heading);
  if (begin == std::string::npos) return std::nullopt;
  const std::size_t end = page.find("\n## ", begin + heading.size());
  const std::string section = page.substr(begin, end - begin);
  std::smatch m;
  GalleryEntry entry;
  static const std::regex kCommand(R"(```sh\n(.*)\n```)");
  if (std::regex_search(section, m, kCommand)) entry.command = m[1];
  static const std::regex kRow(
      R"(\n\| (\d+) \| ([\d.]+) mm³ \| ([\d.]+ x [\d.]+ x [\d.]+) mm \| )"
      R"((\d+) s \| (.*) \|)");
  if (!std::regex_search(section, m, kRow)) return entry;
  entry.triangles = m[1];
  entry.volume = m[2];
  entry.size = m[3];
  entry.seconds = std::stoi(m[4]);
  entry.check = m[5];
  return entry;
}

// The first group of `pattern` in a build's report, as gallery-page reads it.
std::string reported(const std::string& report, const char* pattern) {
  std::smatch m;
  return std::regex_search(report, m, std::regex(pattern)) ? m[1].str() : "";
}

// Builds whose page entry says they took at most this long are repeated
// here; the longer ones (ternary 2.8b, blog tree B) are repeated by
// `cmake --build build --target gallery`, which writes the page.
constexpr int kQuickSeconds = 15;

// docs/gallery.md shows what the code builds: its entry of each printable
// names the command, and a quick one built again reports the same
// triangles, volume, size and check (the page once showed 27,502 triangles
// for ABOP fig. 1.26's plant, which built 24,504, the same every run).
TEST_P(Printable, IsShownInTheGalleryAsItBuilds) {
  const std::string name = GetParam();
  const std::string text = lsolid::testing::read_text(kPrintables / name);
  const std::string stem = std::filesystem::path(name).stem().string();
  const std::optional<GalleryEntry> entry = gallery_entry(stem);
  ASSERT_TRUE(entry) << "docs/gallery.md has no section '## " << stem << "'";
  const std::string options = options_of(text);
  EXPECT_EQ(entry->command, "build/lsolid printables/" + name +
                                (options.empty() ? "" : " " + options));
  ASSERT_GE(entry->seconds, 0) << "no figures for " << stem;
  if (entry->seconds > kQuickSeconds) {
    GTEST_SKIP() << stem << " took " << entry->seconds
                 << " s: checked by the gallery target, not here";
  }
  const auto stl =
      std::filesystem::temp_directory_path() /
      ("lsolid_page_" + std::to_string(::getpid()) + "_" + stem + ".stl");
  const auto built = lsolid::testing::run_command(
      lsolid::testing::lsolid() + " '" + (kPrintables / name).string() + "' " +
      options + " -o '" + stl.string() + "'");
  std::filesystem::remove(stl);
  ASSERT_EQ(built.exit_code, 0) << built.err;
  EXPECT_EQ(entry->triangles, reported(built.out, R"(\ntriangles: (\d+))"))
      << "scripts/build-gallery writes the page again";
  EXPECT_EQ(entry->volume, reported(built.out, R"(\nvolume: ([\d.]+) mm³)"));
  EXPECT_EQ(entry->size,
            reported(built.out, R"(\nsize: ([\d.]+ x [\d.]+ x [\d.]+) mm)"));
  EXPECT_EQ(entry->check,
            reported(built.out, R"(\ncheck: printable: [^;\n]*; ([^\n]*))"));
}

INSTANTIATE_TEST_SUITE_P(Gallery, Printable,
                         ::testing::ValuesIn(printable_names()),
                         [](const auto& test) {
                           // abop_1_25_bush for an `.ls` file, as before
                           // other notations came; fractint_penrose1_l.
                           std::string name = test.param;
                           if (name.ends_with(".ls"))
                             name.resize(name.size() - 3);
                           std::replace_if(
                               name.begin(), name.end(),
                               [](char c) {
                                 return std::isalnum(
                                            static_cast<unsigned char>(c)) == 0;
                               },
                               '_');
                           return name;
                         });

}  // namespace
