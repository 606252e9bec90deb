// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <atomic>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <string_view>

#include "view/view_builder.hpp"

namespace httplib {
class Server;
}

namespace lsolid::cli::view {

/// Where the viewer listens and what it serves besides its own page.
struct ServerOptions {
  std::string host = "127.0.0.1";
  /// 0: the first free port from kDefaultPort on, else any.
  int port = 0;
  /// three.js as Debian's libjs-three installs it (build/three.min.js and
  /// examples/js/controls/OrbitControls.js).
  std::filesystem::path three_dir;
};

/// The port the viewer tries first.
inline constexpr int kDefaultPort = 8400;

/// The event streams served at once: each holds one of the server's
/// threads while it is open.
inline constexpr int kMaxStreams = 16;

/// Whether `host` is a loopback address (127.0.0.0/8, ::1, localhost):
/// the machine's own programs only.
[[nodiscard]] bool is_loopback(std::string_view host);

/// The viewer's HTTP server: its page and assets, three.js, the builder's
/// status (`/status`, and as server-sent events on `/events`), the
/// skeleton and the mesh in binary (`/skeleton?v=`, `/mesh?v=`), the model
/// as a file (`/download/model.stl`, `.3mf`, `.scad`) and the page's
/// controls (`POST /params`). Nothing else: no path names a file, so no
/// path can reach one. Bound to one address, it answers only requests
/// addressed to it by that name (a page of another site that rebinds its
/// name to 127.0.0.1 is refused), and only those a page of another origin
/// did not send (their `Origin` header names another site). At most
/// kMaxStreams pages follow the events at once.
class ViewServer {
 public:
  /// @throws IoError when three.js is not in `options.three_dir`.
  ViewServer(ViewBuilder& builder, ServerOptions options);
  ~ViewServer();
  ViewServer(const ViewServer&) = delete;
  ViewServer& operator=(const ViewServer&) = delete;

  /// Binds the socket and returns the port.
  /// @throws IoError when it cannot.
  int bind();
  /// Serves until stop() (from another thread).
  void serve();
  /// Stops serving.
  void stop();

 private:
  void add_routes();
  void allow_hosts();

  ViewBuilder& builder_;
  ServerOptions options_;
  int port_ = 0;
  // The Host headers answered (name:port); empty when bound to every
  // address, whose names the server cannot know.
  std::set<std::string> allowed_hosts_;
  std::atomic<int> streams_{0};  // event streams open
  std::unique_ptr<httplib::Server> server_;
};

}  // namespace lsolid::cli::view
