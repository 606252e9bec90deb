// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include <fmt/format.h>
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <thread>

#include "commands.hpp"
#include "lsolid/errors.hpp"
#include "lsys/source.hpp"
#include "view/view_builder.hpp"
#include "view/view_server.hpp"

namespace lsolid::cli {

void run_view(const ViewCommand& command) {
  // Refused as a build refuses it (a FIFO, a device, a folder), before
  // the server starts.
  (void)lsys::load_source(command.input.file);
  if (!view::is_loopback(command.host)) {
    std::fprintf(stderr,
                 "warning: serving on %s: anyone who can reach this address "
                 "can see the model and make lsolid build\n",
                 command.host.c_str());
  }
  // Ctrl-C and SIGTERM reach one thread that stops the server; the others
  // (the server's pool, the builder) never see them.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  view::ViewBuilder builder(command.input, command.print, command.bed);
  view::ViewServer server(builder, {.host = command.host,
                                    .port = command.port,
                                    .three_dir = LSOLID_THREE_JS_DIR});
  const int port = server.bind();
  fmt::print("lsolid view: http://{}:{}/ shows {} (Ctrl-C stops)\n",
             command.host, port, command.input.file);
  std::fflush(stdout);
  builder.start();
  std::thread stopper([&] {
    int signal = 0;
    sigwait(&signals, &signal);
    builder.stop();
    server.stop();
  });
  server.serve();
  if (!builder.stopping()) ::kill(::getpid(), SIGTERM);  // wakes the stopper
  stopper.join();
  builder.stop();
}

}  // namespace lsolid::cli
