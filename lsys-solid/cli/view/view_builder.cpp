// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The viewer's builds: a drawer thread reads the file and draws the
// skeleton of the newest request, a builder thread makes its solid, one at
// a time, and a watcher thread polls the file. A build reports its
// progress at each stage and inside the long ones (the union after each
// boolean, the decimation as it goes); there the builder checks whether a
// newer request came and, if so, abandons the build by throwing Cancelled
// through the library, which holds its state in values and releases it
// on the way out.
#include "view/view_builder.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <system_error>
#include <utility>

#include "lsolid/errors.hpp"
#include "lsolid/overhang.hpp"
#include "lsolid/scale.hpp"
#include "lsolid/units.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/interpretation.hpp"
#include "report_json.hpp"
#include "view/encoding.hpp"

namespace lsolid::cli::view {
namespace {

// Not an std::exception: no handler in the library that mends or reports a
// failure takes it for one.
struct Cancelled {};

constexpr auto kWatchInterval = std::chrono::milliseconds(200);
// A change is built once the file has kept its size and time this long:
// a save that truncates the file and then writes it, caught between the
// two, showed "no axiom" at 1:1 for the empty file before the real one (a
// failure of the browser test on a loaded machine). At most kSettleRounds
// waits, so a file that never stops changing is still built.
constexpr auto kSettleInterval = std::chrono::milliseconds(60);
constexpr int kSettleRounds = 20;
// Progress is told at most this often, and at every change of stage.
constexpr auto kProgressInterval = std::chrono::milliseconds(100);
// The bed drawn without --bed: the Creality Ender 3's build volume, about
// the smallest of the common desktop printers', so a model that fits it
// fits most.
constexpr glm::dvec3 kDefaultBedMm{220.0, 220.0, 250.0};

// What the watcher compares: a save changes the size or the time.
struct FileStamp {
  bool exists = false;
  std::uintmax_t size = 0;
  std::filesystem::file_time_type time{};
  bool operator==(const FileStamp&) const = default;
};

FileStamp stamp_of(const std::filesystem::path& path) {
  std::error_code error;
  FileStamp out;
  const auto status = std::filesystem::status(path, error);
  if (error || !std::filesystem::is_regular_file(status)) return out;
  out.exists = true;
  out.size = std::filesystem::file_size(path, error);
  out.time = std::filesystem::last_write_time(path, error);
  return out;
}

Json error_json(const lsys::Diagnostic& d) {
  return Json{{"file", d.file},
              {"line", d.line},
              {"column", d.column},
              {"message", d.message},
              {"source_line", d.source_line},
              {"text", lsys::format_diagnostic(d)}};
}

Json error_json(const std::string& message) {
  return Json{{"file", ""},        {"line", 0},
              {"column", 0},       {"message", message},
              {"source_line", ""}, {"text", "error: " + message + "\n"}};
}

// A range for a constant's slider where one is clear: a fraction stays in
// [0, 1], an angle-like or other whole number from 0 to twice it, anything
// else from 0 to twice its size.
Json constant_json(const std::string& name, double value) {
  double low = 0.0;
  double high = 1.0;
  double step = 0.01;
  if (value == std::floor(value) && std::fabs(value) >= 1.0) {
    high = std::max(10.0, 2.0 * std::fabs(value));
    low = value < 0.0 ? -high : 0.0;
    step = 1.0;
  } else if (value < 0.0 || value > 1.0) {
    high = 2.0 * std::fabs(value);
    low = value < 0.0 ? -high : 0.0;
    step = high / 200.0;
  }
  return Json{{"name", name},
              {"value", value},
              {"min", low},
              {"max", high},
              {"step", step}};
}

// The colours of the first colour indices, for the skeleton's lines (the
// report names those of the model).
Json palette_json(const std::vector<Rgb>& colors) {
  Json out = Json::array();
  for (int i = 0; i < 32; ++i) out.push_back(hex(palette_color(i, colors)));
  return out;
}

// The page's error for the exception being handled: bad input and failed
// geometry or I/O worded as the command line words them, anything else as
// the bug it is.
Json current_error() {
  try {
    throw;
  } catch (const lsys::ParseError& e) {
    return error_json(e.diagnostic());
  } catch (const GeometryError& e) {
    return error_json(e.what());
  } catch (const IoError& e) {
    return error_json(e.what());
  } catch (const std::exception& e) {
    return error_json(
        std::string("an internal check failed (a bug in lsolid; please "
                    "report it with this file): ") +
        e.what());
  }
}

// The --define list a build uses: the command line's, in its order (a
// value may use a constant defined before it), with the page's values in
// place of theirs, and the page's others after them.
std::vector<std::string> merged_defines(
    const std::vector<std::string>& given,
    const std::map<std::string, std::string>& page) {
  std::vector<std::string> out;
  std::set<std::string> placed;
  for (const std::string& define : given) {
    const std::string name = define.substr(0, define.find('='));
    const auto it = page.find(name);
    if (it == page.end()) {
      out.push_back(define);
    } else if (placed.insert(name).second) {
      out.push_back(name + "=" + it->second);
    }
  }
  for (const auto& [name, value] : page) {
    if (placed.count(name) == 0) out.push_back(name + "=" + value);
  }
  return out;
}

// A word of a command line, quoted for a POSIX shell where it must be.
std::string shell_word(const std::string& word) {
  const bool plain = !word.empty() &&
                     word.find_first_not_of(
                         "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                         "0123456789._-/=+,:@%") == std::string::npos;
  if (plain) return word;
  std::string out = "'";
  for (const char c : word) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

}  // namespace

// A skeleton drawn, with what the solid is to be built with.
struct ViewBuilder::Job {
  std::uint64_t generation = 0;
  std::string command;  // the command line that builds the same
  lsys::Grammar grammar;
  lsys::Skeleton skeleton;
  SolidOptions options;
};

ViewBuilder::ViewBuilder(GrammarInput input, PrintInput print,
                         std::optional<std::string> bed)
    : input_(std::move(input)),
      print_(std::move(print)),
      bed_text_(std::move(bed)),
      bed_mm_(bed_text_ ? parse_bed_mm(*bed_text_, "--bed") : kDefaultBedMm) {
  status_.report = nullptr;
  status_.error = nullptr;
  status_.controls = nullptr;
  status_.stage = "parse";
  status_.command = command_line(params_);
}

ViewBuilder::~ViewBuilder() { stop(); }

void ViewBuilder::start() {
  drawer_ = std::thread([this] { draw_requests(); });
  builder_ = std::thread([this] { build_jobs(); });
  watcher_ = std::thread([this] { watch(); });
}

void ViewBuilder::stop() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wanted_changed_.notify_all();
  job_ready_.notify_all();
  changed_.notify_all();
  for (std::thread* t : {&drawer_, &builder_, &watcher_}) {
    if (t->joinable()) t->join();
  }
}

void ViewBuilder::request(ViewParams params) {
  {
    const std::lock_guard lock(mutex_);
    params_ = std::move(params);
    ++wanted_;
    publish_locked();
  }
  wanted_changed_.notify_all();
  changed_.notify_all();
}

void ViewBuilder::file_changed() {
  {
    const std::lock_guard lock(mutex_);
    ++wanted_;
  }
  wanted_changed_.notify_all();
}

ViewStatus ViewBuilder::status() const {
  const std::lock_guard lock(mutex_);
  return status_;
}

ViewStatus ViewBuilder::wait_for_change(std::uint64_t seen,
                                        int timeout_ms) const {
  std::unique_lock lock(mutex_);
  changed_.wait_for(lock, std::chrono::milliseconds(timeout_ms),
                    [&] { return status_.version > seen || stopping_; });
  return status_;
}

std::optional<std::string> ViewBuilder::skeleton(std::uint64_t version) const {
  const std::lock_guard lock(mutex_);
  if (version != status_.skeleton || skeleton_bytes_.empty()) {
    return std::nullopt;
  }
  return skeleton_bytes_;
}

std::optional<std::string> ViewBuilder::mesh(std::uint64_t version) const {
  const std::lock_guard lock(mutex_);
  if (version != status_.model || model_bytes_.empty()) return std::nullopt;
  return model_bytes_;
}

std::shared_ptr<const ViewModel> ViewBuilder::current_model() const {
  const std::lock_guard lock(mutex_);
  return model_;
}

void ViewBuilder::publish_locked() { ++status_.version; }

void ViewBuilder::draw_requests() {
  for (;;) {
    std::uint64_t generation = 0;
    ViewParams params;
    {
      std::unique_lock lock(mutex_);
      wanted_changed_.wait(lock, [&] { return stopping_ || wanted_ > drawn_; });
      if (stopping_) return;
      generation = wanted_;
      params = params_;
    }
    draw(generation, params);
    const std::lock_guard lock(mutex_);
    drawn_ = generation;
  }
}

void ViewBuilder::build_jobs() {
  for (;;) {
    std::unique_ptr<Job> job;
    {
      std::unique_lock lock(mutex_);
      job_ready_.wait(lock, [&] { return stopping_ || job_ != nullptr; });
      if (stopping_) return;
      job = std::move(job_);
      if (job->generation != wanted_) continue;  // a newer one is being drawn
    }
    build(std::move(*job));
  }
}

void ViewBuilder::watch() {
  const std::filesystem::path path = input_.file;
  FileStamp last = stamp_of(path);
  bool reported_missing = false;
  while (!stopping_) {
    {
      std::unique_lock lock(mutex_);
      wanted_changed_.wait_for(lock, kWatchInterval,
                               [&] { return stopping_.load(); });
    }
    if (stopping_) return;
    FileStamp now = stamp_of(path);
    if (now == last) continue;
    for (int round = 0; round < kSettleRounds && !stopping_; ++round) {
      {
        std::unique_lock lock(mutex_);
        wanted_changed_.wait_for(lock, kSettleInterval,
                                 [&] { return stopping_.load(); });
      }
      const FileStamp again = stamp_of(path);
      if (again == now) break;
      now = again;
    }
    if (stopping_) return;
    last = now;
    if (!now.exists) {
      // A deleted file, or an editor's save by rename caught between the
      // two: the model stays, and the file is built when it is back.
      if (!reported_missing) {
        const std::lock_guard lock(mutex_);
        status_.error = error_json(
            input_.file +
            ": the file is gone; the model shown stays until it is back");
        publish_locked();
        reported_missing = true;
      }
      changed_.notify_all();
      continue;
    }
    reported_missing = false;
    file_changed();
  }
}

std::string ViewBuilder::command_line(const ViewParams& params) const {
  std::vector<std::string> words{"lsolid", input_.file};
  const auto option = [&](const char* name,
                          const std::optional<std::string>& value) {
    if (!value) return;
    words.emplace_back(name);
    words.push_back(*value);
  };
  option("-n", params.derivation_length ? params.derivation_length
                                        : input_.derivation_length);
  option("--seed", params.seed ? params.seed : input_.seed);
  for (const std::string& define :
       merged_defines(input_.defines, params.defines)) {
    words.emplace_back("--define");
    words.push_back(define);
  }
  option("--max-segments", input_.max_segments);
  option("--max-modules", input_.max_modules);
  option("--max-memory", input_.max_memory);
  if (input_.dialect) option("--dialect", input_.dialect);
  if (!input_.system.empty()) option("--system", input_.system);
  if (!input_.view_file.empty()) option("--view", input_.view_file);
  option("--roll", input_.roll);
  const bool page_sizes = params.size.has_value();
  option("--height", page_sizes ? std::nullopt : print_.height);
  option("--size", params.size ? params.size : print_.size);
  option("--scale", page_sizes ? std::nullopt : print_.scale);
  option("--wall", params.wall ? params.wall : print_.wall);
  option("--tolerance", params.tolerance ? params.tolerance : print_.tolerance);
  option("--base", params.base ? params.base : print_.base);
  option("--colors", print_.colors);
  option("--profile", print_.profile);
  option("--bed", bed_text_);
  words.emplace_back("-o");
  words.push_back(
      std::filesystem::path(input_.file).replace_extension(".stl").string());
  std::string out;
  for (const std::string& word : words) {
    if (!out.empty()) out += ' ';
    out += shell_word(word);
  }
  return out;
}

void ViewBuilder::fail(std::uint64_t generation, Json error) {
  {
    const std::lock_guard lock(mutex_);
    if (wanted_ != generation) return;  // a newer request is on its way
    status_.error = std::move(error);
    ++status_.builds;
    status_.stage = "done";
    status_.fraction = 1.0;
    publish_locked();
  }
  changed_.notify_all();
}

void ViewBuilder::draw(std::uint64_t generation, const ViewParams& params) {
  const auto stage = [&](const char* name) {
    {
      const std::lock_guard lock(mutex_);
      status_.stage = name;
      status_.fraction = 0.0;
      publish_locked();
    }
    changed_.notify_all();
  };
  GrammarInput input = input_;
  if (params.derivation_length) {
    input.derivation_length = params.derivation_length;
  }
  if (params.seed) input.seed = params.seed;
  input.defines = merged_defines(input_.defines, params.defines);
  PrintInput print = print_;
  if (params.size) {
    print.size = params.size;
    print.height.reset();
    print.scale.reset();
  }
  if (params.wall) print.wall = params.wall;
  if (params.tolerance) print.tolerance = params.tolerance;
  if (params.base) print.base = params.base;
  try {
    stage("parse");
    lsys::Grammar grammar = load_grammar(input);
    const lsys::DerivationOptions derivation = derivation_options(input);
    const lsys::InterpretOptions interpretation = interpret_options(input);
    const PrintSettings settings = print_settings(grammar, print);
    // The controls: what the model is built with now, and one per constant
    // the file defines.
    Json constants = Json::array();
    for (const auto& [name, value] : grammar.constants) {
      constants.push_back(constant_json(name, value));
    }
    Json controls{
        {"n", derivation.derivation_length.value_or(
                  grammar.settings.derivation_length)},
        {"seed", derivation.seed.value_or(grammar.settings.seed)},
        {"size_mm", settings.height_mm ? nullptr
                    : settings.scale_mm_per_unit
                        ? nullptr
                        : Json(settings.size_mm.value_or(kDefaultSizeMm))},
        {"wall_mm", settings.wall_mm},
        {"tolerance_mm", settings.tolerance_mm},
        {"base", settings.base == Base::Auto   ? "auto"
                 : settings.base == Base::Disc ? "disc"
                                               : "none"},
        {"constants", std::move(constants)},
        {"palette", palette_json(settings.colors)},
        {"bed_mm", {bed_mm_.x, bed_mm_.y, bed_mm_.z}},
        {"warnings", grammar.warnings}};
    stage("skeleton");
    lsys::Skeleton drawn = lsys::interpret(grammar, derivation, interpretation);
    if (lsys::draws_nothing(drawn)) {
      throw lsys::nothing_drawn_error(grammar, drawn);
    }
    // The skeleton at the size asked for, standing on the bed's centre: a
    // first look while the solid is built (which places it exactly).
    ScaledSkeleton scaled = scale_to_print(drawn, settings);
    const lsys::Bounds box = lsys::bounds(scaled.skeleton);
    const glm::dvec3 shift(-(box.min.x + box.max.x) / 2.0,
                           -(box.min.y + box.max.y) / 2.0, -box.min.z);
    for (lsys::Segment& s : scaled.skeleton.segments) {
      s.p0 += shift;
      s.p1 += shift;
    }
    for (lsys::Polygon& polygon : scaled.skeleton.polygons) {
      for (glm::dvec3& p : polygon.points) p += shift;
    }
    std::string skeleton = encode_skeleton(scaled.skeleton);
    auto job =
        std::make_unique<Job>(Job{.generation = generation,
                                  .command = command_line(params),
                                  .grammar = std::move(grammar),
                                  .skeleton = std::move(drawn),
                                  .options = {.derivation = derivation,
                                              .interpretation = interpretation,
                                              .print = settings,
                                              .preview_colors = true}});
    {
      const std::lock_guard lock(mutex_);
      if (wanted_ != generation) return;  // drawn again at once
      skeleton_bytes_ = std::move(skeleton);
      status_.skeleton = status_.version + 1;
      status_.controls = std::move(controls);
      status_.error = nullptr;
      status_.stage = "parts";
      status_.fraction = 0.0;
      publish_locked();
      job_ = std::move(job);
    }
    job_ready_.notify_one();
    changed_.notify_all();
  } catch (const std::exception&) {
    fail(generation, current_error());
  }
}

void ViewBuilder::build(Job job) {
  const std::uint64_t generation = job.generation;
  const auto cancelled = [&] { return stopping_ || wanted_ != generation; };
  auto last_told = std::chrono::steady_clock::now() - kProgressInterval;
  job.options.progress = [&](std::string_view stage, double fraction) {
    const auto now = std::chrono::steady_clock::now();
    {
      // Under the lock: a newer request's stage or error, published in
      // between, is never overwritten by this build's.
      const std::lock_guard lock(mutex_);
      if (cancelled()) throw Cancelled{};
      if (status_.stage == stage && now - last_told < kProgressInterval &&
          fraction < 1.0) {
        return;
      }
      status_.stage = std::string(stage);
      status_.fraction = fraction;
      publish_locked();
    }
    last_told = now;
    changed_.notify_all();
  };
  try {
    Solid solid = build_solid(job.grammar, job.skeleton, job.options);
    const PrintSettings& settings = job.options.print;
    const ValidationReport& v = solid.report.validation;
    const OverhangReport over = overhang(solid.mesh);
    Json report = report_json(solid, over, bed_mm_, fits_bed(v.bounds, bed_mm_),
                              "", false, true, true, settings.colors);
    report["problems"] = v.problems();
    std::string bytes = encode_mesh(solid.mesh, solid.colors, over.triangles);
    auto model =
        std::make_shared<ViewModel>(ViewModel{.solid = std::move(solid),
                                              .palette = settings.colors,
                                              .source = input_.file});
    {
      const std::lock_guard lock(mutex_);
      if (cancelled()) throw Cancelled{};
      model_ = std::move(model);
      model_bytes_ = std::move(bytes);
      status_.model = status_.version + 1;
      status_.report = std::move(report);
      status_.command = std::move(job.command);
      ++status_.builds;
      status_.stage = "done";
      status_.fraction = 1.0;
      publish_locked();
    }
    changed_.notify_all();
  } catch (const Cancelled&) {
    {
      const std::lock_guard lock(mutex_);
      ++status_.cancelled;
      publish_locked();
    }
    changed_.notify_all();
  } catch (const std::exception&) {
    fail(generation, current_error());
  }
}

}  // namespace lsolid::cli::view
