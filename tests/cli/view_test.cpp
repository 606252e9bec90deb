// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// `lsolid view`'s server, from outside: a real lsolid process on a free
// port, asked over HTTP as the page asks it (the page itself is driven in
// Chromium by tests/browser/view_test.mjs).
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <httplib.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/hostile_models.hpp"
#include "support/run_command.hpp"
#include "support/test_dir.hpp"

namespace lsolid {
namespace {

using Json = nlohmann::json;
using testing::lsolid;
using testing::run_command;

const std::filesystem::path kSource = LSOLID_SOURCE_DIR;

// A port no one listens on now.
int free_port() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address));
  socklen_t length = sizeof(address);
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
  ::close(fd);
  return ntohs(address.sin_port);
}

// A connection that sent `GET path` and read the status line of the
// answer (empty if none came within five seconds); closed when dropped.
class RawRequest {
 public:
  RawRequest(int port, const std::string& path)
      : fd_(::socket(AF_INET, SOCK_STREAM, 0)) {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    timeval timeout{.tv_sec = 5, .tv_usec = 0};
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof(timeout));
    if (::connect(fd_, reinterpret_cast<sockaddr*>(&address),
                  sizeof(address)) != 0) {
      return;
    }
    const std::string request =
        "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) +
        "\r\n\r\n";
    if (::send(fd_, request.data(), request.size(), MSG_NOSIGNAL) < 0) return;
    char c = 0;
    while (::recv(fd_, &c, 1, 0) == 1 && c != '\n') status_line_ += c;
  }
  ~RawRequest() { ::close(fd_); }
  RawRequest(const RawRequest&) = delete;
  RawRequest& operator=(const RawRequest&) = delete;
  const std::string& status_line() const { return status_line_; }

 private:
  int fd_;
  std::string status_line_;
};

// `lsolid view` running in the background, stopped as Ctrl-C stops it.
// With a `trace` file, it runs under strace, which records there every
// file it opens.
class ViewProcess {
 public:
  ViewProcess(const std::filesystem::path& folder, const std::string& file,
              const std::vector<std::string>& options = {},
              const std::filesystem::path& trace = {})
      : port_(free_port()), traced_(!trace.empty()) {
    std::vector<std::string> words{LSOLID_BINARY, "view", file, "--port",
                                   std::to_string(port_)};
    words.insert(words.end(), options.begin(), options.end());
    if (traced_) {
      words.insert(words.begin(),
                   {"/usr/bin/strace", "-f", "-qq", "-e",
                    "trace=open,openat,openat2,creat", "-o", trace.string()});
    }
    log_ = folder / "view.log";
    pid_ = ::fork();
    if (pid_ == 0) {
      if (::chdir(folder.c_str()) != 0) ::_exit(126);
      // LeakSanitizer stops the world with ptrace, which strace holds.
      if (traced_) ::setenv("ASAN_OPTIONS", "detect_leaks=0", 1);
      std::vector<char*> argv;
      for (std::string& w : words) argv.push_back(w.data());
      argv.push_back(nullptr);
      const std::string log = log_.string();
      if (std::freopen(log.c_str(), "w", stdout) == nullptr ||
          std::freopen(log.c_str(), "a", stderr) == nullptr) {
        ::_exit(126);
      }
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    client_ = std::make_unique<httplib::Client>("127.0.0.1", port_);
    client_->set_read_timeout(10, 0);
    // Listening once the page answers.
    for (int i = 0; i < 200 && !client_->Get("/status"); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }
  ~ViewProcess() { stop(); }

  // Stops it with SIGINT; returns its exit code. Under strace, lsolid (the
  // tracer's child) is the one stopped, and strace ends with it.
  int stop() {
    if (pid_ <= 0) return exit_code_;
    pid_t target = pid_;
    if (traced_) {
      std::istringstream children(
          testing::read_text("/proc/" + std::to_string(pid_) + "/task/" +
                             std::to_string(pid_) + "/children"));
      children >> target;
    }
    ::kill(target, SIGINT);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = 0;
    exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return exit_code_;
  }

  httplib::Client& client() { return *client_; }
  int port() const { return port_; }
  std::string log() const { return testing::read_text(log_); }

  Json status() {
    const auto r = client_->Get("/status");
    return r && r->status == 200 ? Json::parse(r->body) : Json();
  }

  // Polls the status until `done` holds of it, for at most `seconds`.
  Json wait_for(const std::function<bool(const Json&)>& done,
                int seconds = 120) {
    const auto until =
        std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    Json s;
    while (std::chrono::steady_clock::now() < until) {
      s = status();
      if (!s.is_null() && done(s)) return s;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ADD_FAILURE() << "timed out; last status: " << s.dump() << "\n" << log();
    return s;
  }

 private:
  int port_;
  bool traced_ = false;
  pid_t pid_ = 0;
  int exit_code_ = -1;
  std::filesystem::path log_;
  std::unique_ptr<httplib::Client> client_;
};

bool built(const Json& s) {
  return s["stage"] == "done" && s["model"].get<int>() > 0 &&
         s["error"].is_null();
}

class View : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::make_test_dir("view"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
  }
  // ABOP's bush (fig. 1.25) as bush.ls: slow at n = 6, quick at n = 2.
  void use_bush() {
    std::filesystem::copy_file(kSource / "printables/abop-1.25-bush.ls",
                               dir_ / "bush.ls");
  }
  // The segments the bush draws at n, as `lsolid skeleton` counts them.
  int bush_segments(int n) {
    const auto r = run_command(
        lsolid() + " skeleton bush.ls -n " + std::to_string(n), dir_);
    return std::stoi(r.out.substr(r.out.find(' ') + 1));
  }
  std::filesystem::path dir_;
};

constexpr const char* kTree =
    "n = 2\n\u03B4 = 25\nwidth: 1\nsize: 40mm\n\u03C9: A\n"
    "A \u2192 F[+A][-A]FA\n";

// What a model refused for naming a file outside its folder shows: its
// own line, never the file it named, and nothing else is opened (strace).
TEST_F(View, ShowsNothingButTheModelWhateverFileItNames) {
  const auto secret = dir_ / "secret";
  const auto trace = dir_ / "trace.txt";
  for (const testing::HostileModel& model :
       testing::write_hostile_models(dir_)) {
    SCOPED_TRACE(model.route);
    const auto folder = dir_ / "models" / model.route;
    Json refused;
    {
      ViewProcess view(folder, model.file, {"--dialect", model.dialect}, trace);
      refused =
          view.wait_for([](const Json& s) { return !s["error"].is_null(); });
      for (const char* path : {"/", "/status"}) {
        const auto r = view.client().Get(path);
        ASSERT_TRUE(r);
        EXPECT_EQ(r->body.find(testing::kSecretText), std::string::npos);
      }
      EXPECT_EQ(view.stop(), 0) << view.log();
      EXPECT_EQ(view.log().find(testing::kSecretText), std::string::npos);
    }
    EXPECT_EQ(refused.dump().find(testing::kSecretText), std::string::npos)
        << refused.dump();
    EXPECT_EQ(refused["model"], 0);
    const auto opened = testing::opened_files(trace, folder);
    EXPECT_TRUE(std::any_of(opened.begin(), opened.end(), [&](const auto& p) {
      return p == folder / model.file;
    }));
    for (const auto& path : opened) {
      EXPECT_FALSE(testing::lies_in(path, secret)) << path;
      EXPECT_FALSE(testing::lies_in(path, dir_) &&
                   !testing::lies_in(path, folder))
          << path;
    }
  }
}

TEST_F(View, RefusesAFifoOrADeviceAsItsFileBeforeServing) {
  ASSERT_EQ(::mkfifo((dir_ / "fifo.ls").c_str(), 0644), 0);
  std::filesystem::create_symlink("/dev/zero", dir_ / "zero.ls");
  for (const auto& [input, kind] :
       std::vector<std::pair<std::string, std::string>>{
           {"fifo.ls", "a FIFO (named pipe)"}, {"zero.ls", "a device"}}) {
    const auto r = run_command(lsolid() + " view " + input, dir_);
    EXPECT_EQ(r.exit_code, 2) << input;
    EXPECT_EQ(r.err, input + ": error: cannot read file: it is " + kind +
                         ", and lsolid reads only regular files\n");
    EXPECT_EQ(r.out, "");
  }
}

// Connections that send a request's first bytes and then a byte now and
// then, as slowly as a server waits for them, for as long as they live.
class SlowClients {
 public:
  SlowClients(int port, int count) {
    for (int i = 0; i < count; ++i) {
      const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
      sockaddr_in address{};
      address.sin_family = AF_INET;
      address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
      address.sin_port = htons(static_cast<std::uint16_t>(port));
      if (::connect(fd, reinterpret_cast<sockaddr*>(&address),
                    sizeof(address)) == 0) {
        const std::string start = "GET /status HTTP/1.1\r\nX-Slow: ";
        ::send(fd, start.data(), start.size(), MSG_NOSIGNAL);
      }
      fds_.push_back(fd);
    }
    dripping_ = std::thread([this] {
      while (!stop_) {
        for (const int fd : fds_) ::send(fd, "a", 1, MSG_NOSIGNAL);
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
      }
    });
  }
  ~SlowClients() {
    stop_ = true;
    dripping_.join();
    for (const int fd : fds_) ::close(fd);
  }
  SlowClients(const SlowClients&) = delete;
  SlowClients& operator=(const SlowClients&) = delete;

 private:
  std::vector<int> fds_;
  std::atomic<bool> stop_{false};
  std::thread dripping_;
};

TEST_F(View, AnswersItsPageWhileOtherClientsHoldSlowConnections) {
  write("tree.ls", kTree);
  ViewProcess view(dir_, "tree.ls");
  view.wait_for(built);
  // Sixty connections once left /status unanswered for 20 s: each held one
  // of the server's threads as long as it kept sending.
  const SlowClients slow(view.port(), 60);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  for (int i = 0; i < 3; ++i) {
    const RawRequest status(view.port(), "/status");
    EXPECT_EQ(status.status_line(), "HTTP/1.1 200 OK\r") << i;
  }
}

TEST_F(View, RefusesAPortAnotherViewerListensOn) {
  write("tree.ls", kTree);
  ViewProcess first(dir_, "tree.ls");
  ASSERT_FALSE(first.status().is_null());
  // cpp-httplib's SO_REUSEPORT let a second viewer bind the port, and the
  // kernel split the requests between two models.
  const auto second = run_command(
      lsolid() + " view tree.ls --port " + std::to_string(first.port()), dir_);
  EXPECT_EQ(second.exit_code, 4);
  EXPECT_EQ(second.err, "error: cannot listen on 127.0.0.1:" +
                            std::to_string(first.port()) + "\n");
}

TEST_F(View, ServesItsPageAndNothingElse) {
  write("tree.ls", kTree);
  ViewProcess view(dir_, "tree.ls");
  auto& client = view.client();
  const auto page = client.Get("/");
  ASSERT_TRUE(page) << view.log();
  EXPECT_EQ(page->status, 200);
  EXPECT_NE(page->body.find("<title>lsolid view</title>"), std::string::npos);
  for (const char* asset : {"/viewer.js", "/viewer.css", "/three/three.min.js",
                            "/three/OrbitControls.js"}) {
    const auto r = client.Get(asset);
    ASSERT_TRUE(r) << asset;
    EXPECT_EQ(r->status, 200) << asset;
    EXPECT_GT(r->body.size(), 100U) << asset;
  }
  // No path names a file: traversals, encoded or not, and any other path
  // find nothing.
  for (const char* path :
       {"/../../../../etc/passwd", "/three/../../../../etc/passwd",
        "/%2e%2e/%2e%2e/%2e%2e/etc/passwd",
        "/three/..%2f..%2f..%2fetc%2fpasswd", "/viewer.js/../tree.ls",
        "/tree.ls", "/three/three.module.js", "/download/model.obj",
        "/download/../tree.ls", "/nothing"}) {
    const auto r = client.Get(path);
    ASSERT_TRUE(r) << path;
    EXPECT_EQ(r->status, 404) << path;
    EXPECT_EQ(r->body.find("root:"), std::string::npos) << path;
  }
  EXPECT_EQ(client.Post("/status", "", "text/plain")->status, 404);
  EXPECT_EQ(client.Post("/params", "not json", "application/json")->status,
            400);
  EXPECT_EQ(client.Get("/mesh?v=banana")->status, 400);
  // A page of another site whose name resolves to 127.0.0.1 is refused.
  httplib::Headers other{
      {"Host", "evil.example:" + std::to_string(view.port())}};
  EXPECT_EQ(client.Get("/status", other)->status, 403);
  EXPECT_EQ(view.stop(), 0);
}

TEST_F(View, RefusesOtherSitesAndBoundsWhatItHolds) {
  write("tree.ls", kTree);
  ViewProcess view(dir_, "tree.ls");
  const Json first = view.wait_for(built);
  auto& client = view.client();
  const std::string own = "http://127.0.0.1:" + std::to_string(view.port());
  // A page of another site may send a form or open an event stream to
  // 127.0.0.1; its Origin names it, and it is refused.
  const httplib::Headers evil{{"Origin", "http://evil.example"}};
  EXPECT_EQ(
      client.Post("/params", evil, R"({"n": "1"})", "application/json")->status,
      403);
  EXPECT_EQ(client.Get("/events", evil)->status, 403);
  // A body that is not JSON is refused before it is read as such (a
  // browser sends JSON across sites only after asking, and is refused).
  EXPECT_EQ(client.Post("/params", R"({"n": "1"})", "text/plain")->status, 415);
  // A body larger than any the page sends is refused.
  EXPECT_EQ(
      client
          .Post("/params", "{\"n\": \"" + std::string(1 << 20, '1') + "\"}",
                "application/json")
          ->status,
      413);
  EXPECT_EQ(view.status()["builds"], first["builds"]);  // nothing was built
  // The page's own requests pass.
  const httplib::Headers mine{{"Origin", own}};
  EXPECT_EQ(
      client.Post("/params", mine, R"({"n": "1"})", "application/json")->status,
      202);
  view.wait_for(
      [](const Json& s) { return built(s) && s["controls"]["n"] == 1; });
  // Event streams are bounded, and the rest of the server answers while
  // they are all open.
  {
    std::vector<std::unique_ptr<RawRequest>> streams;
    for (int i = 0; i < 16; ++i) {
      streams.push_back(std::make_unique<RawRequest>(view.port(), "/events"));
      ASSERT_EQ(streams.back()->status_line(), "HTTP/1.1 200 OK\r") << i;
    }
    EXPECT_EQ(RawRequest(view.port(), "/events").status_line(),
              "HTTP/1.1 503 Service Unavailable\r");
    const auto status = client.Get("/status");
    ASSERT_TRUE(status);
    EXPECT_EQ(status->status, 200);
  }
  // Closed, their threads are freed within the streams' beat (2 s).
  std::string again;
  for (int i = 0; i < 100 && again != "HTTP/1.1 200 OK\r"; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    again = RawRequest(view.port(), "/events").status_line();
  }
  EXPECT_EQ(again, "HTTP/1.1 200 OK\r");
  EXPECT_EQ(view.stop(), 0);
}

TEST_F(View, BuildsTheFileAndBuildsItAgainWhenItIsSaved) {
  write("tree.ls", kTree);
  ViewProcess view(dir_, "tree.ls");
  const Json first = view.wait_for(built);
  EXPECT_EQ(first["report"]["printable"], true);
  EXPECT_EQ(first["report"]["segments"], 8);  // F[+A][-A]FA at n = 2
  EXPECT_GT(first["skeleton"].get<int>(), 0);
  EXPECT_EQ(first["controls"]["bed_mm"], Json::parse("[220, 220, 250]"));
  EXPECT_EQ(first["report"]["fits_bed"], true);
  const auto mesh =
      view.client().Get("/mesh?v=" + std::to_string(first["model"].get<int>()));
  ASSERT_TRUE(mesh);
  EXPECT_EQ(mesh->status, 200);
  EXPECT_EQ(mesh->body.substr(0, 4), "LSM1");
  // Saved with n = 3: built again, without asking.
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  std::string three(kTree);
  three[4] = '3';  // n = 3
  write("tree.ls", three);
  const Json second = view.wait_for(
      [&](const Json& s) { return built(s) && s["model"] != first["model"]; });
  EXPECT_EQ(second["report"]["segments"], 26);
  // An old version is gone, not served as if current.
  EXPECT_EQ(view.client()
                .Get("/mesh?v=" + std::to_string(first["model"].get<int>()))
                ->status,
            410);
}

TEST_F(View, ShowsAnErrorAtItsLineAndKeepsTheLastModel) {
  write("tree.ls", kTree);
  ViewProcess view(dir_, "tree.ls");
  const Json good = view.wait_for(built);
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  write("tree.ls", std::string(kTree) + "A \u2192 F[+A\n");
  const Json bad =
      view.wait_for([](const Json& s) { return !s["error"].is_null(); });
  EXPECT_EQ(bad["error"]["line"], 7);
  EXPECT_NE(bad["error"]["message"].get<std::string>().find("'['"),
            std::string::npos)
      << bad.dump();
  EXPECT_NE(bad["error"]["text"].get<std::string>().find("tree.ls:7:"),
            std::string::npos);
  EXPECT_EQ(bad["model"], good["model"]);  // the last good model stays
  // Mended: the error goes and a model comes.
  write("tree.ls", kTree);
  const Json mended = view.wait_for(
      [&](const Json& s) { return built(s) && s["model"] != good["model"]; });
  // A control's bad value is an error of its own; the command line shown
  // stays the one that builds the model shown.
  ASSERT_EQ(
      view.client()
          .Post("/params", R"({"n": "3", "wall": "-5"})", "application/json")
          ->status,
      202);
  const Json refused =
      view.wait_for([](const Json& s) { return !s["error"].is_null(); });
  EXPECT_NE(refused["error"]["text"].get<std::string>().find("--wall"),
            std::string::npos)
      << refused.dump();
  EXPECT_EQ(refused["model"], mended["model"]);
  EXPECT_EQ(refused["command"], mended["command"]);
}

TEST_F(View, BuildsWhatTheControlsAskCancellingABuildInFlight) {
  use_bush();
  ViewProcess view(dir_, "bush.ls", {"-n", "2"});
  const Json first = view.wait_for(built);
  // A slow build (n = 6) asked for and, before it ends, a quick one: the
  // slow one is cancelled and never shown.
  auto& client = view.client();
  ASSERT_EQ(client.Post("/params", R"({"n": "6"})", "application/json")->status,
            202);
  view.wait_for([](const Json& s) {
    return s["stage"] != "done" && s["stage"] != "parse" &&
           s["stage"] != "skeleton";
  });
  ASSERT_EQ(
      client
          .Post("/params", R"({"n": "3", "wall": "1mm"})", "application/json")
          ->status,
      202);
  const Json last = view.wait_for(
      [&](const Json& s) { return built(s) && s["model"] != first["model"]; });
  EXPECT_EQ(last["cancelled"].get<int>(), first["cancelled"].get<int>() + 1);
  EXPECT_EQ(last["builds"].get<int>(), first["builds"].get<int>() + 1);
  EXPECT_EQ(last["controls"]["n"], 3);
  EXPECT_EQ(last["controls"]["wall_mm"], 1.0);
  EXPECT_EQ(last["report"]["segments"], bush_segments(3));
  EXPECT_NE(last["command"].get<std::string>().find("-n 3"), std::string::npos);
  EXPECT_NE(last["command"].get<std::string>().find("--wall 1mm"),
            std::string::npos);
  // Requests from several clients at once, then one more: each is
  // accepted, none is queued behind another (a request replaces the one
  // not yet drawn), and the last is what is built.
  std::vector<std::thread> clients;
  std::atomic<int> accepted{0};
  for (int i = 0; i < 8; ++i) {
    clients.emplace_back([&, i] {
      httplib::Client other("127.0.0.1", view.port());
      const auto r = other.Post(
          "/params", "{\"n\": \"" + std::to_string(1 + i % 3) + "\"}",
          "application/json");
      if (r && r->status == 202) ++accepted;
    });
  }
  for (std::thread& thread : clients) thread.join();
  EXPECT_EQ(accepted, 8);
  ASSERT_EQ(client.Post("/params", R"({"n": "4"})", "application/json")->status,
            202);
  const Json newest = view.wait_for([&](const Json& s) {
    return built(s) && s["controls"]["n"] == 4 && s["model"] != last["model"];
  });
  const int ended = newest["builds"].get<int>() +
                    newest["cancelled"].get<int>() - last["builds"].get<int>() -
                    last["cancelled"].get<int>();
  EXPECT_GE(ended, 1);
  EXPECT_LE(ended, 9);
  EXPECT_TRUE(newest["error"].is_null()) << newest.dump();
  EXPECT_EQ(newest["report"]["segments"], bush_segments(4));
}

TEST_F(View, DrawsTheBedItIsGivenAndSaysWhetherTheModelFits) {
  write("tree.ls", kTree);  // 40 mm tall
  ViewProcess view(dir_, "tree.ls", {"--bed", "30x30x30mm"});
  const Json shown = view.wait_for(built);
  EXPECT_EQ(shown["controls"]["bed_mm"], Json::parse("[30, 30, 30]"));
  EXPECT_EQ(shown["report"]["fits_bed"], false);
  EXPECT_NE(shown["command"].get<std::string>().find("--bed 30x30x30mm"),
            std::string::npos);
  EXPECT_EQ(view.stop(), 0);
  const auto bad = run_command(lsolid() + " view tree.ls --bed 30x30", dir_);
  EXPECT_EQ(bad.exit_code, 2) << bad.out;
  EXPECT_NE(bad.err.find("--bed"), std::string::npos) << bad.err;
}

TEST_F(View, KeepsTheModelWhenTheFileIsDeletedAndBuildsItWhenItIsBack) {
  write("tree.ls", kTree);
  ViewProcess view(dir_, "tree.ls");
  const Json good = view.wait_for(built);
  std::filesystem::remove(dir_ / "tree.ls");
  const Json gone =
      view.wait_for([](const Json& s) { return !s["error"].is_null(); });
  EXPECT_NE(gone["error"]["message"].get<std::string>().find("gone"),
            std::string::npos);
  EXPECT_EQ(gone["model"], good["model"]);
  write("tree.ls", kTree);
  view.wait_for(
      [&](const Json& s) { return built(s) && s["model"] != good["model"]; });
}

TEST_F(View, DownloadsTheModelShown) {
  write("tree.ls", kTree);
  ViewProcess view(dir_, "tree.ls");
  const Json shown = view.wait_for(built);
  auto& client = view.client();
  const auto stl = client.Get("/download/model.stl");
  ASSERT_TRUE(stl);
  EXPECT_EQ(stl->status, 200);
  EXPECT_EQ(stl->get_header_value("Content-Disposition"),
            "attachment; filename=\"tree.stl\"");
  std::ofstream(dir_ / "got.stl", std::ios::binary) << stl->body;
  const auto checked = run_command(lsolid() + " check --json got.stl", dir_);
  EXPECT_EQ(checked.exit_code, 0) << checked.out;
  EXPECT_EQ(Json::parse(checked.out)["triangles"],
            shown["report"]["triangles"]);
  // The command line the page shows writes the same bytes.
  const std::string command = shown["command"].get<std::string>();
  EXPECT_EQ(command, "lsolid tree.ls -o tree.stl");
  const auto built_here =
      run_command(lsolid() + " tree.ls -q -o cli.stl", dir_);
  ASSERT_EQ(built_here.exit_code, 0) << built_here.err;
  EXPECT_EQ(testing::read_text(dir_ / "cli.stl"), stl->body);
  const auto threemf = client.Get("/download/model.3mf");
  ASSERT_TRUE(threemf);
  EXPECT_EQ(threemf->body.substr(0, 2), "PK");  // a zip
  const auto scad = client.Get("/download/model.scad");
  ASSERT_TRUE(scad);
  EXPECT_NE(scad->body.find("module lsolid_tree()"), std::string::npos);
}

}  // namespace
}  // namespace lsolid
