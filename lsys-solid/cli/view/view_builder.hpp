// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "commands.hpp"
#include "json.hpp"
#include "lsolid/solid.hpp"

namespace lsolid::cli::view {

/// What the page may change without touching the file, as text the way a
/// maker types it on the command line; each is checked as the command
/// line's option is when the model is built.
struct ViewParams {
  std::optional<std::string> derivation_length;  ///< -n
  std::optional<std::string> seed;
  std::optional<std::string> size;
  std::optional<std::string> wall;
  std::optional<std::string> tolerance;
  std::optional<std::string> base;
  std::map<std::string, std::string> defines;  ///< NAME → value
};

/// A model built for the page: the mesh it shows and downloads, and what
/// it was built from.
struct ViewModel {
  Solid solid;
  std::vector<Rgb> palette;  ///< the file's or the command line's colours
  std::string source;        ///< the watched file, whose name downloads take
};

/// What the page is told, as one snapshot: the versions of the skeleton and
/// the model it should fetch, where the build is, the report, the error.
struct ViewStatus {
  std::uint64_t version = 0;   ///< bumps with every change of the snapshot
  std::uint64_t skeleton = 0;  ///< version of the skeleton to fetch, 0: none
  std::uint64_t model = 0;     ///< version of the model to fetch, 0: none
  std::string stage;           ///< "parse", "skeleton", "union" … or "done"
  double fraction = 0.0;
  Json report;                  ///< of the model shown, or null
  Json error;                   ///< the last build's error, or null
  Json controls;                ///< the parameters and the file's constants
  std::string command;          ///< the command line that builds what is asked
  std::uint64_t builds = 0;     ///< builds that ended, with a model or error
  std::uint64_t cancelled = 0;  ///< builds abandoned for a newer request
};

/// Builds the watched file in the background, in two steps on two threads:
/// the drawer parses the file and draws its skeleton, shown at once; the
/// builder makes the solid from that skeleton. A newer request (a saved
/// file, a changed parameter) is drawn as soon as it comes, while the build
/// in flight is cancelled at its next progress report; the last good
/// skeleton and model stay shown until new ones replace them.
class ViewBuilder {
 public:
  /// @pre `input.file` names the watched file; `bed` is the printer's
  ///   build volume in millimetres, given (`--bed`) or not.
  ViewBuilder(GrammarInput input, PrintInput print,
              std::optional<std::string> bed);
  ~ViewBuilder();
  ViewBuilder(const ViewBuilder&) = delete;
  ViewBuilder& operator=(const ViewBuilder&) = delete;

  /// Starts the drawer, the builder and the file watcher.
  void start();
  /// Stops them; a build in flight is cancelled.
  void stop();

  /// Asks for a build with these parameters (the newest wins).
  void request(ViewParams params);
  /// Asks for a build because the file changed.
  void file_changed();

  /// The snapshot now.
  [[nodiscard]] ViewStatus status() const;
  /// Waits until the snapshot's version is past `seen`, or `timeout_ms`
  /// passes, or the builder stops; returns the snapshot then.
  [[nodiscard]] ViewStatus wait_for_change(std::uint64_t seen,
                                           int timeout_ms) const;
  /// The skeleton of `version` in the binary form encoding.hpp describes,
  /// or nothing if it is no longer the current one.
  [[nodiscard]] std::optional<std::string> skeleton(
      std::uint64_t version) const;
  /// The model's mesh of `version` in its binary form, or nothing if it is
  /// no longer the current one.
  [[nodiscard]] std::optional<std::string> mesh(std::uint64_t version) const;
  /// The model shown now, or nothing.
  [[nodiscard]] std::shared_ptr<const ViewModel> current_model() const;
  /// Whether the builder is stopping.
  [[nodiscard]] bool stopping() const { return stopping_; }

 private:
  struct Job;  // what the drawer hands the builder
  void draw_requests();
  void build_jobs();
  void watch();
  void draw(std::uint64_t generation, const ViewParams& params);
  void build(Job job);
  void fail(std::uint64_t generation, Json error);
  [[nodiscard]] std::string command_line(const ViewParams& params) const;
  void publish_locked();

  const GrammarInput input_;
  const PrintInput print_;
  const std::optional<std::string> bed_text_;
  const glm::dvec3 bed_mm_;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;  // status_.version moved on
  std::condition_variable wanted_changed_;   // a request arrived
  std::condition_variable job_ready_;        // the drawer left a job
  std::atomic<std::uint64_t> wanted_{1};     // the generation asked for
  std::uint64_t drawn_ = 0;                  // the last generation drawn
  std::unique_ptr<Job> job_;                 // the newest job not yet built
  std::atomic<bool> stopping_{false};
  ViewParams params_;
  ViewStatus status_;
  std::string skeleton_bytes_;
  std::string model_bytes_;
  std::shared_ptr<const ViewModel> model_;
  std::thread drawer_;
  std::thread builder_;
  std::thread watcher_;
};

}  // namespace lsolid::cli::view
