// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The README's promises about the project itself.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "support/run_command.hpp"

namespace lsolid {
namespace {

const std::filesystem::path kSource = LSOLID_SOURCE_DIR;

// The lines of the README's shell blocks.
std::vector<std::string> readme_commands() {
  const std::string readme = testing::read_text(kSource / "README.md");
  std::vector<std::string> commands;
  std::size_t pos = 0;
  while ((pos = readme.find("```sh\n", pos)) != std::string::npos) {
    pos += 6;
    const std::size_t end = readme.find("\n```", pos);
    commands.push_back(readme.substr(pos, end - pos));
    pos = end;
  }
  return commands;
}

TEST(Project, ReadmeQuickStartIsTwoCommands) {
  const auto commands = readme_commands();
  ASSERT_EQ(commands.size(), 2U);
  for (const std::string& c : commands) {
    EXPECT_EQ(c.find('\n'), std::string::npos) << c;
    EXPECT_TRUE(c.starts_with("scripts/install-deps && ")) << c;
  }
  EXPECT_NE(commands[0].find("build/lsolid"), std::string::npos);
  EXPECT_NE(commands[0].find("printables/"), std::string::npos);
  EXPECT_NE(commands[1].find("ctest"), std::string::npos);
}

TEST(Project, CiRunsTheReadmesTestCommand) {
  const auto commands = readme_commands();
  ASSERT_EQ(commands.size(), 2U);
  const std::string ci = testing::read_text(kSource / ".ci/run");
  EXPECT_NE(ci.find("\n" + commands[1] + "\n"), std::string::npos);
}

// Every source file of the project, relative to the source folder.
std::vector<std::filesystem::path> sources() {
  std::vector<std::filesystem::path> out;
  for (const char* folder : {"lsys-core", "lsys-solid", "tests", "bench"}) {
    for (const auto& entry :
         std::filesystem::recursive_directory_iterator(kSource / folder)) {
      const std::string ext = entry.path().extension().string();
      // This file names what it looks for.
      if (entry.path().filename() == "project_test.cpp") continue;
      if (ext == ".cpp" || ext == ".hpp") {
        out.push_back(std::filesystem::relative(entry.path(), kSource));
      }
    }
  }
  return out;
}

TEST(Project, CgalIsIncludedOnlyInItsFolderUnderOnePolicy) {
  // Inline CGAL code is shared between the translation units that include
  // it, so its checks are set once, in lsys-solid/CMakeLists.txt, for all of
  // them; a file that set its own would make which check runs depend on the
  // linker.
  std::size_t cgal_files = 0;
  for (const auto& file : sources()) {
    const std::string text = testing::read_text(kSource / file);
    const bool in_cgal_folder =
        file.string().starts_with("lsys-solid/src/cgal/");
    if (text.find("#include <CGAL/") != std::string::npos) {
      EXPECT_TRUE(in_cgal_folder) << file << " includes CGAL";
      ++cgal_files;
    }
    for (const char* macro : {"#undef NDEBUG", "#define NDEBUG",
                              "#define CGAL_NO_", "#define CGAL_CHECK_"}) {
      EXPECT_EQ(text.find(macro), std::string::npos) << file << ": " << macro;
    }
  }
  EXPECT_GE(cgal_files, 10U);
  const std::string cmake =
      testing::read_text(kSource / "lsys-solid/CMakeLists.txt");
  EXPECT_NE(cmake.find("target_compile_options(lsolid_cgal PRIVATE -UNDEBUG)"),
            std::string::npos);
  EXPECT_NE(cmake.find("CGAL_NO_ASSERTIONS"), std::string::npos);
}

TEST(Project, EachDependencyIsIncludedOnlyBehindItsBoundary) {
  // One folder (or file) per dependency (docs/design.md, "Layout"): a
  // library's headers are included only there, so that replacing it, or
  // reading how lsolid uses it, takes one place.
  const std::vector<std::pair<std::string, std::string>> homes{
      {"#include <CGAL/", "lsys-solid/src/cgal/"},
      {"#include <OpenMesh/", "lsys-solid/src/openmesh/"},
      {"#include <polyclipping/", "lsys-solid/src/clipper/"},
      {"#include <GL/", "lsys-solid/src/osmesa/"},
      {"#include <Model/COM/", "lsys-solid/src/io/threemf.cpp"},
      {"#include <png.h>", "lsys-solid/src/io/png.cpp"},
      {"#include <CLI/", "lsys-solid/cli/"},
      {"#include <nlohmann/", "lsys-solid/cli/"},
      {"#include <httplib.h>", "lsys-solid/cli/view/"}};
  std::map<std::string, std::size_t> found;
  for (const auto& file : sources()) {
    const std::string name = file.generic_string();
    if (!name.starts_with("lsys-core/") && !name.starts_with("lsys-solid/")) {
      continue;  // tests and benchmarks may read files their own way
    }
    const std::string text = testing::read_text(kSource / file);
    for (const auto& [include, home] : homes) {
      if (text.find(include) == std::string::npos) continue;
      ++found[include];
      EXPECT_TRUE(name.starts_with(home)) << name << " has " << include;
    }
    // lsys-core depends on GLM alone.
    if (name.starts_with("lsys-core/")) {
      for (const char* other : {"#include <fmt/", "#include <boost/",
                                "#include <CGAL/", "#include <OpenMesh/"}) {
        EXPECT_EQ(text.find(other), std::string::npos) << name << ": " << other;
      }
    }
  }
  for (const auto& [include, home] : homes) {
    EXPECT_GT(found[include], 0U) << include << " is used nowhere";
  }
}

// The names of Markdown documents in `text` (`docs/design.md`, `README.md`).
std::vector<std::string> documents_named(const std::string& text) {
  static const std::regex kDocument(R"([A-Za-z0-9_./-]+\.md\b)");
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), kDocument);
       it != std::sregex_iterator(); ++it) {
    out.push_back(it->str());
  }
  return out;
}

// A document is in the repository if it is there relative to the file that
// names it, to the root, or to docs/, and lies under the root.
bool in_repository(const std::filesystem::path& named_in,
                   const std::string& document) {
  const std::filesystem::path root = std::filesystem::weakly_canonical(kSource);
  for (const std::filesystem::path& base :
       {named_in.parent_path(), kSource, kSource / "docs"}) {
    const std::filesystem::path p =
        std::filesystem::weakly_canonical(base / document);
    const std::string relative = std::filesystem::relative(p, root).string();
    if (!relative.starts_with("..") && std::filesystem::exists(p)) return true;
  }
  return false;
}

TEST(Project, EveryDocumentACommentOrDocNamesIsInTheRepository) {
  // The repository speaks for itself: a comment or a page that cites a
  // document a clone does not have cites nothing.
  std::vector<std::filesystem::path> files;
  for (const auto& file : sources()) files.push_back(kSource / file);
  files.push_back(kSource / "README.md");
  for (const auto& entry :
       std::filesystem::recursive_directory_iterator(kSource / "docs")) {
    if (entry.path().extension() == ".md") files.push_back(entry.path());
  }
  std::size_t named = 0;
  for (const auto& file : files) {
    for (const std::string& document :
         documents_named(testing::read_text(file))) {
      ++named;
      EXPECT_TRUE(in_repository(file, document))
          << file << " names " << document;
    }
  }
  EXPECT_GT(named, 10U);
}

TEST(Project, EverySourceFileTheDesignNamesExists) {
  // docs/design.md is the map of the code: each stage with the files that
  // hold it. A file it names that is gone makes the map lie.
  const std::string design = testing::read_text(kSource / "docs/design.md");
  static const std::regex kFile(R"(`([A-Za-z0-9_./-]+\.(?:cpp|hpp))`)");
  std::size_t named = 0;
  for (auto it = std::sregex_iterator(design.begin(), design.end(), kFile);
       it != std::sregex_iterator(); ++it) {
    const std::string file = (*it)[1].str();
    ++named;
    bool exists = false;
    for (const char* root :
         {"", "lsys-core/", "lsys-solid/", "lsys-core/include/lsys/",
          "lsys-solid/include/lsolid/", "lsys-core/src/", "lsys-solid/src/"}) {
      exists = exists || std::filesystem::exists(kSource / (root + file));
    }
    EXPECT_TRUE(exists) << "docs/design.md names " << file;
  }
  EXPECT_GT(named, 40U);
}

}  // namespace
}  // namespace lsolid
