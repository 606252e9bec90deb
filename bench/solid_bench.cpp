// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The solid pipeline's stages (docs/performance.md). Each case runs once per
// repetition; run:
//   build/bench/solid_bench --benchmark_repetitions=3
//       --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <exception>
#include <filesystem>
#include <string>

#include "lsolid/solid.hpp"
#include "lsys/parser.hpp"
#include "lsys/source.hpp"

namespace {

lsys::Grammar load(const std::string& name) {
  return lsys::parse_grammar(
      lsys::load_source(std::filesystem::path(LSOLID_SOURCE_DIR) /
                        "printables" / name),
      {.extra_settings = lsolid::print_setting_names()});
}

// The peak resident set of one build, in a forked child so that the
// figure is this case's alone.
double peak_rss_mib(const lsys::Grammar& grammar, int n, bool multi) {
  const pid_t child = fork();
  if (child == 0) {
    const lsolid::Solid s = lsolid::build_solid(
        grammar,
        {.derivation = {.derivation_length = n}, .multi_material = multi});
    _exit(s.report.validation.is_printable() ? 0 : 1);
  }
  int status = 0;
  rusage usage{};
  if (child < 0 || wait4(child, &status, 0, &usage) != child) return -1.0;
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// With `multi`, also the volumes per colour of --multi-material.
void build(benchmark::State& state, const std::string& file, int n,
           bool multi = false) {
  const lsys::Grammar grammar = load(file);
  lsolid::SolidReport report;
  std::size_t volumes = 0;
  for (auto _ : state) {
    // A build that fails is this case's result, not the end of the run.
    try {
      const lsolid::Solid s = lsolid::build_solid(
          grammar,
          {.derivation = {.derivation_length = n}, .multi_material = multi});
      report = s.report;
      volumes = s.volumes.size();
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      return;
    }
    if (!report.validation.is_printable()) state.SkipWithError("not printable");
  }
  state.counters["segments"] = static_cast<double>(report.segments);
  state.counters["leaves"] = static_cast<double>(report.polygons);
  state.counters["parts"] =
      static_cast<double>(report.tubes + report.joints + report.plates);
  state.counters["booleans"] = static_cast<double>(report.union_stats.booleans);
  state.counters["union_triangles"] =
      static_cast<double>(report.decimation.triangles_before);
  state.counters["triangles"] =
      static_cast<double>(report.validation.triangles);
  state.counters["skeleton_s"] = report.seconds.skeleton;
  state.counters["parts_s"] = report.seconds.parts;
  state.counters["union_s"] = report.seconds.unite;
  state.counters["rounding_s"] = report.seconds.round;
  state.counters["decimate_s"] = report.seconds.decimate;
  state.counters["check_s"] = report.seconds.check;
  if (multi) {
    state.counters["volumes"] = static_cast<double>(volumes);
    state.counters["volumes_s"] = report.seconds.volumes;
  }
  state.counters["peak_rss_MiB"] = peak_rss_mib(grammar, n, multi);
}

BENCHMARK_CAPTURE(build, hilbert_n3, "hilbert-cube.ls", 3)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(build, bush_n5, "abop-1.25-bush.ls", 5)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(build, bush_n6, "abop-1.25-bush.ls", 6)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(build, bush_n7, "abop-1.25-bush.ls", 7)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(build, bush_n5_multi_material, "abop-1.25-bush.ls", 5, true)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

// Decimation alone, of a model's union built once without it: the stage
// that took half of the bush's build at n = 7.
void decimate_union(benchmark::State& state, const std::string& file, int n) {
  const lsolid::Solid united = lsolid::build_solid(
      load(file), {.derivation = {.derivation_length = n}, .decimate = false});
  lsolid::Decimated out;
  for (auto _ : state) out = lsolid::decimate(united.mesh);
  if (!out.refused.empty()) state.SkipWithError(out.refused.c_str());
  state.counters["triangles_before"] =
      static_cast<double>(out.stats.triangles_before);
  state.counters["triangles_after"] =
      static_cast<double>(out.stats.triangles_after);
  state.counters["deviation_mm"] = out.stats.max_deviation_mm;
  state.counters["attempts"] = out.stats.attempts;
}

BENCHMARK_CAPTURE(decimate_union, bush_n6, "abop-1.25-bush.ls", 6)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(decimate_union, bush_n7, "abop-1.25-bush.ls", 7)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
// Leaf plates: large faces beside dense cut regions (1.67 million
// triangles at the gallery's n = 10, most of its build in decimation).
BENCHMARK_CAPTURE(decimate_union, blog_tree_b_n9, "blog-tree-b.ls", 9)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

// Small inputs that were pathological (the speed issue's list): a build
// from the grammar's text.
void build_text(benchmark::State& state, const std::string& text) {
  const lsys::Grammar grammar = lsys::parse_grammar_text(
      text, {.extra_settings = lsolid::print_setting_names()}, "bench.ls");
  lsolid::SolidReport report;
  for (auto _ : state) {
    try {
      report = lsolid::build_solid(grammar).report;
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      return;
    }
    if (!report.validation.is_printable()) state.SkipWithError("not printable");
  }
  state.counters["segments"] = static_cast<double>(report.segments);
  state.counters["booleans"] = static_cast<double>(report.union_stats.booleans);
  state.counters["union_s"] = report.seconds.unite;
  state.counters["rounding_s"] = report.seconds.round;
  state.counters["decimate_s"] = report.seconds.decimate;
}

// The 3D Hilbert curve of printables/hilbert-cube.ls at n = 4, its tubes as
// wide as their spacing, so that each touches its neighbours.
BENCHMARK_CAPTURE(build_text, hilbert_n4_touching,
                  "n=4, \u03B4=90\u00B0\nwidth: 1\nA\n"
                  "A \u2192 B-F+CFC+F-D&F^D-F+&&CFC+F+B//\n"
                  "B \u2192 A&F^CFB^F^D^^-F-D^|F^B|FC^F^A//\n"
                  "C \u2192 |D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//\n"
                  "D \u2192 |CFB-F+B|FA&F^A&&FB-F+B|FC//\n")
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
// 36 branches leaving one node.
BENCHMARK_CAPTURE(build_text, one_node_36_branches,
                  "n=36\n\u03C9: FA\nA \u2192 [&(60)F]/(10)A\n")
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
// Three coincident branches.
BENCHMARK_CAPTURE(build_text, coincident_branches, "\u03C9: F[F][F]F\n")
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
// ABOP fig. 5.5's cordate leaf drawn as a fan of 22 coplanar triangles.
BENCHMARK_CAPTURE(build_text, cordate_fan_leaf,
                  "delta=10\nwidth: 0.5\nderivation length: 12\nbase: none\n"
                  "axiom: !(0.05)F(0.1)\\(30)&(30)FFFFF!(0.045)[A][B]\n"
                  "p1: A -> [[+A{.C.]GC.}]\np2: B -> [[-B{.C.]GC.}]\n"
                  "p3: C -> GC\n")
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
// Lparser's cordate leaf: four leaves of 14 overlapping coplanar polygons.
BENCHMARK_CAPTURE(
    build_text, lparser_cordate_leaf,
    "n = 10\nangle: 10\nwidth: 0.1\nbase: none\n"
    "[|FFFFFFFFFFF]P>(90)P>(90)P>(90)P\nP=[&(10)G[ccA][ccB][a][b]]\n"
    "G=tFtFtFtFtFtFtFtFtFtFtFtFtF\nA=[+A{.].C.}\nB=[-B{.].C.}\nC=tfC\n"
    "a=[+a]d\nb=[-b]d\nd=tFd\naliases: > = /  < = \\  c = '\n")
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
// ABOP fig. 1.24b at its full n, which lies flat (the flat profile).
BENCHMARK_CAPTURE(build, abop_1_24b_flat, "abop-1.24b.ls", 5)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(build, plant_1_26_multi_material, "abop-1.26-plant.ls", 5,
                  true)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
// Lparser's Menger cube at its own n = 4 (from the dialect corpus): 400
// round tubes as wide as 1.43 times their length, overlapping face on face,
// so that every union has faces that touch.
BENCHMARK_CAPTURE(build, lparser_menger_cube_n4,
                  "../tests/data/dialects/lparser/menger-cube.ls", 4)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
