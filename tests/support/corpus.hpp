// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace lsolid::testing {

/// The published systems of tests/data/dialects/ and what lsolid must make
/// of each, as tests/data/dialects/corpus.tsv lists them.
inline const std::filesystem::path kCorpus =
    std::filesystem::path(LSOLID_SOURCE_DIR) / "tests" / "data" / "dialects";

struct Entry {
  std::string file;
  std::string system;  // empty: none
  std::string n;       // empty: the file's own
  std::string expect;
  std::string build;  // "no", "" for the file's own n, or an n
};

inline std::vector<Entry> corpus() {
  std::ifstream in(kCorpus / "corpus.tsv");
  std::vector<Entry> entries;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line.front() == '#') continue;
    std::vector<std::string> fields;
    std::stringstream stream(line);
    std::string field;
    while (std::getline(stream, field, '\t')) fields.push_back(field);
    if (fields.size() != 5) {
      ADD_FAILURE() << "corpus.tsv: expected 5 fields: " << line;
      continue;
    }
    const auto dash = [](const std::string& s) { return s == "-" ? "" : s; };
    entries.push_back(Entry{fields[0], dash(fields[1]), dash(fields[2]),
                            fields[3], dash(fields[4])});
  }
  return entries;
}

// Shown by GoogleTest instead of the struct's bytes.
inline void PrintTo(const Entry& e, std::ostream* out) {
  *out << e.file << (e.system.empty() ? "" : " --system " + e.system);
}

inline std::vector<Entry> buildable() {
  std::vector<Entry> out;
  for (const Entry& e : corpus()) {
    if (e.build != "no") out.push_back(e);
  }
  return out;
}

inline std::string name_of(const Entry& e) {
  std::string name = e.file + (e.system.empty() ? "" : "_" + e.system);
  std::replace_if(
      name.begin(), name.end(),
      [](char c) { return std::isalnum(static_cast<unsigned char>(c)) == 0; },
      '_');
  return name;
}

}  // namespace lsolid::testing
