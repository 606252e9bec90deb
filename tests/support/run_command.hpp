// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace lsolid::testing {

/// What a command printed and returned.
struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Runs a shell command line in `directory`, capturing stdout and stderr.
inline CommandResult run_command(const std::string& command_line,
                                 const std::filesystem::path& directory = ".") {
  const auto stamp =
      std::to_string(::getpid()) + "_" + std::to_string(std::rand());
  const auto base =
      std::filesystem::temp_directory_path() / ("lsolid_" + stamp);
  const std::string out = base.string() + ".out";
  const std::string err = base.string() + ".err";
  const std::string full = "cd '" + directory.string() + "' && " +
                           command_line + " > '" + out + "' 2> '" + err + "'";
  const int status = std::system(full.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_text(out);
  result.err = read_text(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return result;
}

/// Runs a shell command line in `directory` as run_command does, and gives
/// the peak resident set of the program it runs (the shell execs it), in
/// KiB.
inline long peak_rss_kib(const std::string& command_line,
                         const std::filesystem::path& directory = ".") {
  const std::string full =
      "cd '" + directory.string() + "' && exec " + command_line;
  const pid_t child = ::fork();
  if (child == 0) {
    ::execl("/bin/sh", "sh", "-c", full.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  rusage usage{};
  if (child < 0 || ::wait4(child, &status, 0, &usage) != child) return -1;
  return usage.ru_maxrss;
}

/// The lsolid binary under test, quoted for a shell.
inline std::string lsolid() { return std::string("'") + LSOLID_BINARY + "'"; }

}  // namespace lsolid::testing
