// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_command.hpp"

namespace lsolid::testing {

/// The text of every file in a HostileModels' secret folder: no output of
/// lsolid's may hold it.
inline constexpr const char* kSecretText = "SECRET-CONTENT-7f3a";

/// A model that tries to read a file outside its folder, by one route.
struct HostileModel {
  std::string route;  ///< what it tries, for failure messages
  std::string file;   ///< the model, in its own folder
  std::string dialect;
};

/// A folder `root` holding `secret/` (files a model must never open) and,
/// for each route a model may take to name a file (an absolute name, `..`,
/// a link to a file, a link to a folder; in an `#include` of a cpfg, lpfg
/// or L-system Explorer file, in a view file's `#include`, `function:`,
/// `function set:`, `surface:` and `contour:`, and the view file itself),
/// a folder `models/ROUTE/` with a model that takes it.
inline std::vector<HostileModel> write_hostile_models(
    const std::filesystem::path& root) {
  namespace fs = std::filesystem;
  const fs::path secret = root / "secret";
  fs::create_directories(secret);
  for (const char* name : {"secret.h", "secret.func", "secret.fset", "secret.s",
                           "secret.con", "secret.v"}) {
    std::ofstream(secret / name) << kSecretText << "\n";
  }
  std::vector<HostileModel> models;
  const auto folder = [&](const std::string& route) {
    const fs::path dir = root / "models" / route;
    fs::create_directories(dir);
    fs::create_symlink(secret / "secret.h", dir / "link.h");
    fs::create_symlink(secret, dir / "out");
    return dir;
  };
  const std::string cpfg = "Lsystem: 1\nderivation length: 1\nAxiom: F\n";
  const std::vector<std::pair<std::string, std::string>> names{
      {"absolute", (secret / "secret.h").string()},
      {"parent", "../../secret/secret.h"},
      {"linked-file", "link.h"},
      {"linked-folder", "out/secret.h"}};
  for (const auto& [how, name] : names) {
    const std::string include = "#include \"" + name + "\"\n";
    std::ofstream(folder("cpfg-include-" + how) / "m.l") << include << cpfg;
    std::ofstream(folder("lpfg-include-" + how) / "m.l")
        << "#include <lpfgall.h>\n"
        << include << "derivation length: 1;\nAxiom: F(1);\n";
    std::ofstream(folder("lowclouds-include-" + how) / "m.ls")
        << "delta=22.5\n"
        << include << "axiom: F\n";
    models.push_back({"cpfg-include-" + how, "m.l", "cpfg"});
    models.push_back({"lpfg-include-" + how, "m.l", "lpfg"});
    models.push_back({"lowclouds-include-" + how, "m.ls", "lowclouds"});
    for (const std::string view : {"#include", "function:", "function set:",
                                   "surface: l", "contour: 1"}) {
      std::string route =
          "view-" + view.substr(0, view.find_first_of(":")) + "-" + how;
      for (char& c : route) {
        if (c == ' ' || c == '#') c = '_';
      }
      const fs::path dir = folder(route);
      std::ofstream(dir / "m.l") << cpfg;
      std::ofstream(dir / "m.v")
          << "angle increment: 30\n"
          << (view == "#include" ? include : view + " " + name + "\n");
      models.push_back({route, "m.l", "cpfg"});
    }
  }
  const fs::path linked_view = folder("view-file-linked");
  std::ofstream(linked_view / "m.l") << cpfg;
  fs::create_symlink(secret / "secret.v", linked_view / "m.v");
  models.push_back({"view-file-linked", "m.l", "cpfg"});
  return models;
}

/// The files a traced program opened: each name given to open, openat,
/// openat2 or creat in `strace -f -o trace` output, made absolute against
/// `cwd` (the folder the program ran in, which lsolid never changes).
inline std::vector<std::filesystem::path> opened_files(
    const std::filesystem::path& trace, const std::filesystem::path& cwd) {
  static const std::regex open_call(
      R"re(\b(?:open|openat|openat2|creat)\((?:[^,"]*, )?"((?:[^"\\]|\\.)*)")re");
  std::vector<std::filesystem::path> out;
  std::istringstream lines(read_text(trace));
  std::string line;
  while (std::getline(lines, line)) {
    std::smatch match;
    if (!std::regex_search(line, match, open_call)) continue;
    const std::filesystem::path name = match[1].str();
    out.push_back(name.is_absolute() ? name : cwd / name);
  }
  return out;
}

/// Whether `path`, its links resolved as far as they go, lies in `folder`.
inline bool lies_in(const std::filesystem::path& path,
                    const std::filesystem::path& folder) {
  std::error_code error;
  const auto resolved = std::filesystem::weakly_canonical(path, error);
  const auto base = std::filesystem::weakly_canonical(folder, error);
  const auto [end, _] =
      std::mismatch(base.begin(), base.end(), resolved.begin(), resolved.end());
  return end == base.end();
}

/// The strace command that records every file a program opens into
/// `trace`, quoted for a shell.
inline std::string strace_prefix(const std::filesystem::path& trace) {
  return "strace -f -qq -e trace=open,openat,openat2,creat -o '" +
         trace.string() + "' ";
}

}  // namespace lsolid::testing
