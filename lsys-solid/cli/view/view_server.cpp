// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// cpp-httplib (Debian's libcpp-httplib-dev) serves the viewer: a thread
// pool answers requests, and each page's event stream holds one of its
// threads, waiting on the builder's next snapshot.
#include "view/view_server.hpp"

#include <fcntl.h>
#include <httplib.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "lsolid/errors.hpp"
#include "lsolid/mesh_io.hpp"
#include "lsolid/rounding.hpp"
#include "view/assets.hpp"

namespace lsolid::cli::view {
namespace {

// A stream writes at least this often (a comment when nothing changed), so
// that a closed page is noticed and its thread freed within this time.
constexpr int kEventWaitMs = 2000;
// The largest request body: the controls are a few hundred bytes.
constexpr std::size_t kMaxBodyBytes = 64 * 1024;
// The server's threads: the event streams and many more for the rest. A
// thread serves one connection at a time, however slowly its client
// sends, so a few slow clients (sixty local connections left /status
// unanswered for 20 s with 24 threads) must not take them all; an idle
// thread costs only its stack's address space.
constexpr std::size_t kThreads = kMaxStreams + 112;
// How long a request may pause between bytes, and an idle kept-alive
// connection wait: the page's requests are a few hundred bytes from the
// same machine.
constexpr int kReadTimeoutSeconds = 1;
constexpr int kKeepAliveSeconds = 2;

Json status_json(const ViewStatus& s) {
  return Json{
      {"version", s.version}, {"skeleton", s.skeleton},  {"model", s.model},
      {"stage", s.stage},     {"fraction", s.fraction},  {"report", s.report},
      {"error", s.error},     {"controls", s.controls},  {"command", s.command},
      {"builds", s.builds},   {"cancelled", s.cancelled}};
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// A text value of the page's controls, or nothing when it is absent,
// null or empty.
std::optional<std::string> text_of(const Json& body, const char* key) {
  if (!body.contains(key) || body[key].is_null()) return std::nullopt;
  std::string text =
      body[key].is_string() ? body[key].get<std::string>() : body[key].dump();
  if (text.empty()) return std::nullopt;
  return text;
}

// The model written in `format` to a private temporary folder and read
// back: the bytes the command line would write.
std::string model_file(const ViewModel& model, MeshFormat format,
                       const std::string& name) {
  std::string folder =
      (std::filesystem::temp_directory_path() / "lsolid-view-XXXXXX").string();
  if (::mkdtemp(folder.data()) == nullptr) {
    throw IoError("cannot make a folder in " + folder);
  }
  const std::filesystem::path path = std::filesystem::path(folder) / name;
  try {
    // The model is built as an STL keeps it (so that its STL is the
    // command line's); a 3MF and OpenSCAD keep other precisions.
    if (format == MeshFormat::ThreeMf) {
      const std::optional<ColoredMesh> threemf = rounded_for(
          ColoredMesh{.mesh = model.solid.mesh, .colors = model.solid.colors},
          format);
      if (!threemf) {
        throw GeometryError(
            "the model is not printable at the precision a 3MF keeps");
      }
      write_colored({*threemf}, path, format, model.palette);
    } else if (format == MeshFormat::Scad) {
      const std::optional<TriangleMesh> scad =
          rounded_for(model.solid.mesh, format);
      if (!scad) {
        throw GeometryError(
            "the model is not printable at the precision OpenSCAD keeps");
      }
      write_mesh(*scad, path, format);
    } else {
      write_mesh(model.solid.mesh, path, format);
    }
  } catch (...) {
    std::filesystem::remove_all(folder);
    throw;
  }
  std::string bytes = read_file(path);
  std::filesystem::remove_all(folder);
  return bytes;
}

}  // namespace

bool is_loopback(std::string_view host) {
  return host == "localhost" || host == "::1" || host == "[::1]" ||
         host.substr(0, 4) == "127.";
}

ViewServer::ViewServer(ViewBuilder& builder, ServerOptions options)
    : builder_(builder),
      options_(std::move(options)),
      server_(std::make_unique<httplib::Server>()) {
  server_->new_task_queue = [] { return new httplib::ThreadPool(kThreads); };
  server_->set_payload_max_length(kMaxBodyBytes);
  server_->set_read_timeout(kReadTimeoutSeconds);
  server_->set_keep_alive_timeout(kKeepAliveSeconds);
  // cpp-httplib sets SO_REUSEPORT, which lets a second viewer bind the same
  // port and the kernel share the requests between two models: only
  // SO_REUSEADDR (a restart may reuse a port in TIME_WAIT), so that a busy
  // port is refused.
  server_->set_socket_options([](socket_t sock) {
    const int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof(yes));
  });
  add_routes();
}

void ViewServer::allow_hosts() {
  const std::string& host = options_.host;
  if (host == "0.0.0.0" || host == "::" || host.empty()) return;
  const std::string port = ":" + std::to_string(port_);
  const bool ipv6 = host.find(':') != std::string::npos;
  allowed_hosts_.insert((ipv6 ? "[" + host + "]" : host) + port);
  if (is_loopback(host)) {
    for (const char* name : {"127.0.0.1", "localhost", "[::1]"}) {
      allowed_hosts_.insert(name + port);
    }
  }
}

ViewServer::~ViewServer() = default;

int ViewServer::bind() {
  if (options_.port != 0) {
    if (!server_->bind_to_port(options_.host.c_str(), options_.port)) {
      throw IoError("cannot listen on " + options_.host + ":" +
                    std::to_string(options_.port));
    }
    port_ = options_.port;
    allow_hosts();
    return port_;
  }
  for (int port = kDefaultPort; port < kDefaultPort + 10; ++port) {
    if (server_->bind_to_port(options_.host.c_str(), port)) {
      port_ = port;
      allow_hosts();
      return port_;
    }
  }
  port_ = server_->bind_to_any_port(options_.host.c_str());
  if (port_ <= 0) throw IoError("cannot listen on " + options_.host);
  allow_hosts();
  return port_;
}

void ViewServer::serve() { server_->listen_after_bind(); }

void ViewServer::stop() { server_->stop(); }

void ViewServer::add_routes() {
  httplib::Server& s = *server_;
  // Only requests for this server's own name are answered: a page of
  // another site whose name was made to resolve to 127.0.0.1 (DNS
  // rebinding) names that site in its Host header. And only those the page
  // of another site did not send: a browser names the sending page's
  // origin on a cross-site request (a form's POST, an EventSource), which
  // would otherwise pass, as it names this server as its Host.
  s.set_pre_routing_handler(
      [this](const httplib::Request& request, httplib::Response& response) {
        const std::string host = request.get_header_value("Host");
        const std::string origin = request.get_header_value("Origin");
        const bool host_ok =
            allowed_hosts_.empty() || allowed_hosts_.count(host) > 0;
        const bool origin_ok = origin.empty() || origin == "http://" + host;
        if (host_ok && origin_ok) {
          return httplib::Server::HandlerResponse::Unhandled;
        }
        response.status = 403;
        response.set_content("forbidden\n", "text/plain");
        return httplib::Server::HandlerResponse::Handled;
      });
  const auto asset = [&s](const char* path, std::string_view text,
                          const char* type) {
    s.Get(path, [text, type](const httplib::Request&, httplib::Response& r) {
      r.set_header("Cache-Control", "no-cache");
      r.set_content(text.data(), text.size(), type);
    });
  };
  asset("/", kIndexHtml, "text/html; charset=utf-8");
  asset("/viewer.js", kViewerJs, "text/javascript; charset=utf-8");
  asset("/viewer.css", kViewerCss, "text/css; charset=utf-8");
  // three.js is read once, here: a viewer without it would show a blank
  // page, so it is refused at the start instead.
  const auto three = [this, &s](const char* path, std::filesystem::path file) {
    const std::filesystem::path where = options_.three_dir / file;
    std::string bytes = read_file(where);
    if (bytes.empty()) {
      throw IoError(where.string() +
                    ": three.js is not there (on Debian, install libjs-three)");
    }
    s.Get(path, [bytes = std::move(bytes)](const httplib::Request&,
                                           httplib::Response& r) {
      r.set_content(bytes, "text/javascript; charset=utf-8");
    });
  };
  three("/three/three.min.js", "build/three.min.js");
  three("/three/OrbitControls.js", "examples/js/controls/OrbitControls.js");
  s.Get("/status", [this](const httplib::Request&, httplib::Response& r) {
    r.set_header("Cache-Control", "no-cache");
    r.set_content(status_json(builder_.status())
                      .dump(-1, ' ', false, Json::error_handler_t::replace),
                  "application/json");
  });
  s.Get("/events", [this](const httplib::Request&, httplib::Response& r) {
    if (streams_.fetch_add(1) >= kMaxStreams) {
      streams_.fetch_sub(1);
      r.status = 503;
      r.set_content("too many pages follow this model; close one\n",
                    "text/plain");
      return;
    }
    r.set_header("Cache-Control", "no-cache");
    r.set_chunked_content_provider(
        "text/event-stream",
        [this, seen = std::uint64_t{0}](std::size_t,
                                        httplib::DataSink& sink) mutable {
          const ViewStatus status =
              builder_.wait_for_change(seen, kEventWaitMs);
          if (builder_.stopping()) {
            sink.done();
            return false;
          }
          std::string message = ": waiting\n\n";
          if (status.version != seen) {
            seen = status.version;
            message = "data: " +
                      status_json(status).dump(-1, ' ', false,
                                               Json::error_handler_t::replace) +
                      "\n\n";
          }
          return sink.write(message.data(), message.size());
        },
        [this](bool) { streams_.fetch_sub(1); });
  });
  const auto binary = [this, &s](const char* path, bool mesh) {
    s.Get(path,
          [this, mesh](const httplib::Request& request, httplib::Response& r) {
            std::uint64_t version = 0;
            try {
              version = std::stoull(request.get_param_value("v"));
            } catch (const std::exception&) {
              r.status = 400;
              return;
            }
            const std::optional<std::string> bytes =
                mesh ? builder_.mesh(version) : builder_.skeleton(version);
            if (!bytes) {
              r.status = 410;  // a newer one replaced it
              return;
            }
            r.set_content(*bytes, "application/octet-stream");
          });
  };
  binary("/skeleton", false);
  binary("/mesh", true);
  const auto download = [this, &s](const char* path, MeshFormat format,
                                   const char* extension, const char* type) {
    s.Get(path, [this, format, extension, type](const httplib::Request&,
                                                httplib::Response& r) {
      const std::shared_ptr<const ViewModel> model = builder_.current_model();
      if (!model) {
        r.status = 404;
        return;
      }
      const std::string name =
          std::filesystem::path(model->source).stem().string() + extension;
      try {
        r.set_content(model_file(*model, format, name), type);
      } catch (const std::exception& e) {
        r.status = 500;
        r.set_content(e.what(), "text/plain");
        return;
      }
      r.set_header("Content-Disposition",
                   "attachment; filename=\"" + name + "\"");
    });
  };
  download("/download/model.stl", MeshFormat::StlBinary, ".stl", "model/stl");
  download("/download/model.3mf", MeshFormat::ThreeMf, ".3mf", "model/3mf");
  download("/download/model.scad", MeshFormat::Scad, ".scad",
           "text/plain; charset=utf-8");
  s.Post("/params", [this](const httplib::Request& request,
                           httplib::Response& r) {
    // JSON only: a browser sends it across sites only after asking
    // (a preflight this server never grants).
    if (request.get_header_value("Content-Type").rfind("application/json", 0) !=
        0) {
      r.status = 415;
      r.set_content("expected application/json\n", "text/plain");
      return;
    }
    Json body;
    try {
      body = Json::parse(request.body);
    } catch (const std::exception&) {
      r.status = 400;
      r.set_content("expected a JSON object\n", "text/plain");
      return;
    }
    if (!body.is_object()) {
      r.status = 400;
      return;
    }
    ViewParams params{.derivation_length = text_of(body, "n"),
                      .seed = text_of(body, "seed"),
                      .size = text_of(body, "size"),
                      .wall = text_of(body, "wall"),
                      .tolerance = text_of(body, "tolerance"),
                      .base = text_of(body, "base")};
    if (body.contains("defines") && body["defines"].is_object()) {
      for (const auto& [name, value] : body["defines"].items()) {
        params.defines[name] =
            value.is_string() ? value.get<std::string>() : value.dump();
      }
    }
    builder_.request(std::move(params));
    r.status = 202;
    r.set_content(status_json(builder_.status())
                      .dump(-1, ' ', false, Json::error_handler_t::replace),
                  "application/json");
  });
}

}  // namespace lsolid::cli::view
