// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// C resolves `#include "name"` beside the including file, then in the -I
// folders; vlab's cpfg reads a view file's companions from the object's
// folder. Joining a folder and a name as std::filesystem does keeps `..`
// and lets an absolute name replace the folder, so a downloaded model could
// read (and an error quote) any file of the user's: here a name is checked
// before anything is opened, and only the folders the user chose are read.
#include "dialects/companion_files.hpp"

#include <algorithm>
#include <system_error>

#include "lsys/diagnostic.hpp"

namespace lsys::dialects {
namespace {

constexpr std::string_view kOnlyOwnFolder =
    "a model reads only files in its own folder (--include-dir allows "
    "another)";

std::filesystem::path folder_of(const std::string& file) {
  const std::filesystem::path folder =
      std::filesystem::path(file).parent_path();
  return folder.empty() ? std::filesystem::path(".") : folder;
}

// The folder as the kernel sees it, links resolved; empty if it is not one.
std::filesystem::path canonical_folder(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::path canonical = std::filesystem::canonical(folder, error);
  if (error || !std::filesystem::is_directory(canonical, error)) return {};
  return canonical;
}

bool is_within(const std::filesystem::path& path,
               const std::filesystem::path& folder) {
  auto p = path.begin();
  for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
    if (p == path.end() || *p != *f) return false;
  }
  return p != path.end();
}

}  // namespace

CompanionFiles::CompanionFiles(const std::string& model_name,
                               const ParseOptions& options) {
  std::vector<std::filesystem::path> folders{folder_of(model_name)};
  if (!options.view_file.empty()) {
    folders.push_back(folder_of(options.view_file));
  }
  for (const std::string& folder : options.include_dirs) {
    folders.emplace_back(folder);
  }
  for (const std::filesystem::path& folder : folders) {
    std::filesystem::path canonical = canonical_folder(folder);
    if (!canonical.empty() &&
        std::find(roots_.begin(), roots_.end(), canonical) == roots_.end()) {
      roots_.push_back(std::move(canonical));
    }
  }
}

std::optional<std::string> CompanionFiles::refusal(
    const std::filesystem::path& path) const {
  std::error_code error;
  const std::filesystem::path canonical =
      std::filesystem::canonical(path, error);
  if (error) return "cannot read file: " + error.message();
  return refusal_of_canonical(canonical);
}

std::optional<std::string> CompanionFiles::refusal_of_canonical(
    const std::filesystem::path& canonical) const {
  std::error_code error;
  if (std::none_of(roots_.begin(), roots_.end(), [&](const auto& root) {
        return is_within(canonical, root);
      })) {
    return "a symbolic link leads it out of the model's folder; " +
           std::string(kOnlyOwnFolder);
  }
  const auto type = std::filesystem::status(canonical, error).type();
  if (type != std::filesystem::file_type::regular) {
    return "it is " + std::string(describe_file_type(type)) +
           ", not a regular file";
  }
  return std::nullopt;
}

std::shared_ptr<const SourceFile> CompanionFiles::load(
    const SourceFile& naming, std::size_t offset, std::string_view what,
    const std::string& name) {
  const auto fail = [&](std::string_view why) {
    std::string message(what);
    message += " \"";
    message += name;
    message += "\": ";
    message += why;
    throw error_at(naming, offset, std::move(message));
  };
  const std::filesystem::path relative(name);
  if (name.empty()) fail("an empty name");
  if (relative.is_absolute() || relative.has_root_name()) {
    fail("an absolute name; " + std::string(kOnlyOwnFolder));
  }
  for (const std::filesystem::path& part : relative) {
    if (part == "..") {
      fail("a name that leaves the folder ('..'); " +
           std::string(kOnlyOwnFolder));
    }
  }
  // Beside the naming file first, as C does, then in each allowed folder.
  std::vector<std::filesystem::path> candidates{
      std::filesystem::path(naming.name()).parent_path() / relative};
  for (const std::filesystem::path& root : roots_) {
    candidates.push_back(root / relative);
  }
  for (const std::filesystem::path& candidate : candidates) {
    std::error_code error;
    const auto link = std::filesystem::symlink_status(candidate, error);
    if (error || !std::filesystem::exists(link)) continue;
    const std::filesystem::path canonical =
        std::filesystem::canonical(candidate, error);
    if (error) fail("cannot read file: " + error.message());
    if (const auto why = refusal_of_canonical(canonical)) fail(*why);
    auto& file = read_[canonical];
    if (!file) file = load_source(candidate);
    named_bytes_ += file->text().size();
    if (named_bytes_ > kMaxSourceBytes) {
      fail("the files this model names come to more than " +
           std::to_string(kMaxSourceBytes) + " bytes, counting each time " +
           "one is named (a file that includes another many times?)");
    }
    return file;
  }
  std::string missing =
      "no such file beside this one (" + candidates.front().string() + ")";
  if (roots_.size() > 1) missing += " or in another allowed folder";
  fail(missing);
  return nullptr;
}

}  // namespace lsys::dialects
