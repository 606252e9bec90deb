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

namespace lsolid {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path,
                       const std::string& what) {
  throw IoError(path.string() + ": " + what);
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path,
                           const std::string& data) {
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
