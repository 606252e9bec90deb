// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The temporary-and-rename write behind every output, so that a file is
// complete or absent (POSIX rename is atomic within one file system).
#include "atomic_write.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "lsolid/errors.hpp"
#include "lsolid/output_file.hpp"
#include "lsys/source.hpp"

namespace lsolid {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path,
                       const std::string& what) {
  throw IoError(path.string() + ": " + what);
}

}  // namespace

std::filesystem::path output_target(const std::filesystem::path& path) {
  // Renaming over a link would replace the link with a file; follow it
  // (at most 40 links, as the kernel does) and write its target instead.
  constexpr int kMostLinks = 40;
  std::filesystem::path target = path;
  for (int links = 0;; ++links) {
    std::error_code error;
    const auto status = std::filesystem::symlink_status(target, error);
    if (error || status.type() == std::filesystem::file_type::not_found) {
      return target;
    }
    if (status.type() == std::filesystem::file_type::regular) return target;
    if (status.type() != std::filesystem::file_type::symlink) {
      throw IoError("'" + path.string() + "' is " +
                    (target == path ? "" : "a link to ") +
                    std::string(lsys::describe_file_type(status.type())) +
                    "; lsolid writes only regular files");
    }
    if (links == kMostLinks) {
      throw IoError("'" + path.string() +
                    "' is a symbolic link in a loop; lsolid writes only "
                    "regular files");
    }
    const std::filesystem::path next = std::filesystem::read_symlink(target);
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
}

void write_file_atomically(const std::filesystem::path& requested,
                           const std::string& data) {
  const std::filesystem::path path = output_target(requested);
  std::filesystem::path folder = path.parent_path();
  if (folder.empty()) folder = ".";
  // A hidden temporary beside the target, so that rename stays on one file
  // system. (Appending piecewise avoids a GCC 12 -Wrestrict false alarm.)
  std::string name(1, '.');
  name.append(path.filename().string()).append(".XXXXXX");
  std::string temp = (folder / name).string();
  const int fd = ::mkstemp(temp.data());
  if (fd < 0)
    fail(path,
         std::string("cannot create a file here: ") + std::strerror(errno));
  const auto abandon = [&](const std::string& what) {
    const int saved = errno;
    ::close(fd);
    ::unlink(temp.c_str());
    fail(path, what + ": " + std::strerror(saved));
  };
  std::size_t written = 0;
  while (written < data.size()) {
    const ssize_t n = ::write(fd, data.data() + written, data.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      abandon("cannot write");
    }
    written += static_cast<std::size_t>(n);
  }
  // mkstemp makes the file private; give it the mode a new file would get.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  if (::fchmod(fd, 0666 & ~mask) != 0 || ::fsync(fd) != 0) {
    abandon("cannot write");
  }
  if (::close(fd) != 0) {
    ::unlink(temp.c_str());
    fail(path, std::string("cannot write: ") + std::strerror(errno));
  }
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const int saved = errno;
    ::unlink(temp.c_str());
    fail(path,
         std::string("cannot rename into place: ") + std::strerror(saved));
  }
}

}  // namespace lsolid
