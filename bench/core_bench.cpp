// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Derivation and turtle throughput (docs/performance.md). Run:
//   build/bench/core_bench --benchmark_repetitions=5
//       --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <string>

#include "lsys/derivation.hpp"
#include "lsys/interpretation.hpp"
#include "lsys/parser.hpp"
#include "lsys/source.hpp"

namespace {

lsys::Grammar load(const std::string& name) {
  return lsys::parse_grammar(lsys::load_source(
      std::filesystem::path(LSOLID_SOURCE_DIR) / "printables" / name));
}

// Runs `work` once in a forked child and returns the child's peak resident
// set, so each benchmark's figure is its own and not the process's maximum
// so far. The child starts with the parent's current (small) footprint.
double peak_rss_mib(const std::function<void()>& work) {
  const pid_t child = fork();
  if (child == 0) {
    work();
    _exit(0);
  }
  int status = 0;
  rusage usage{};
  if (child < 0 || wait4(child, &status, 0, &usage) != child) return -1.0;
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// Modules per second of the derivation alone (what `lsolid derive --stats`
// does).
void derive_only(benchmark::State& state, const std::string& file, int n) {
  const lsys::Grammar grammar = load(file);
  std::size_t modules = 0;
  for (auto _ : state) {
    lsys::Derivation d(grammar,
                       {.derivation_length = n, .max_segments = 1'000'000'000});
    lsys::ModuleString chunk;
    modules = 0;
    while (d.next(chunk)) modules += chunk.size();
    benchmark::DoNotOptimize(modules);
  }
  state.SetItemsProcessed(
      static_cast<std::int64_t>(state.iterations() * modules));
  state.counters["modules"] = static_cast<double>(modules);
  state.counters["peak_rss_MiB"] = peak_rss_mib([&] {
    lsys::Derivation d(grammar,
                       {.derivation_length = n, .max_segments = 1'000'000'000});
    lsys::ModuleString chunk;
    while (d.next(chunk)) benchmark::DoNotOptimize(chunk.size());
  });
}

// Modules per second of derivation plus turtle, building the skeleton.
void derive_and_walk(benchmark::State& state, const std::string& file, int n) {
  const lsys::Grammar grammar = load(file);
  std::size_t modules = 0;
  {
    lsys::Derivation d(grammar, {.derivation_length = n});
    lsys::ModuleString chunk;
    while (d.next(chunk)) modules += chunk.size();
  }
  std::size_t segments = 0;
  for (auto _ : state) {
    const lsys::Skeleton s = lsys::interpret(grammar, {.derivation_length = n});
    segments = s.segments.size();
    benchmark::DoNotOptimize(segments);
  }
  state.SetItemsProcessed(
      static_cast<std::int64_t>(state.iterations() * modules));
  state.counters["modules"] = static_cast<double>(modules);
  state.counters["segments"] = static_cast<double>(segments);
  state.counters["peak_rss_MiB"] = peak_rss_mib([&] {
    const lsys::Skeleton s = lsys::interpret(grammar, {.derivation_length = n});
    benchmark::DoNotOptimize(s.segments.data());
  });
}

// Parsing many productions and declared names (it was quadratic: 16,000
// names took 13 s, 100,000 productions more than 120 s).
void parse_many(benchmark::State& state, bool declared) {
  std::string text;
  if (declared) {
    text = "module ";
    for (int i = 0; i < 16'000; ++i) {
      text.append("mod").append(std::to_string(i)).append(", ");
    }
    text += "leaf\naxiom: mod0 mod15999 leaf\n";
  } else {
    text = "axiom: A0\n";
    for (int i = 0; i < 100'000; ++i) {
      // (Appending piecewise avoids a GCC 12 -Wrestrict false alarm.)
      text.append("A").append(std::to_string(i)).append(" -> F A");
      text.append(std::to_string(i + 1)).append("\n");
    }
  }
  for (auto _ : state) {
    const lsys::Grammar g = lsys::parse_grammar_text(text);
    benchmark::DoNotOptimize(g.productions.size());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(text.size()));
}

BENCHMARK_CAPTURE(parse_many, productions_100k, false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(parse_many, module_names_16k, true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(derive_and_walk, hilbert_n7, "hilbert-cube.ls", 7)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(derive_and_walk, bush_n7, "abop-1.25-bush.ls", 7)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(derive_only, hilbert_n7, "hilbert-cube.ls", 7)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(derive_only, hilbert_n8, "hilbert-cube.ls", 8)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(derive_and_walk, honda_n10, "honda-2.1a.ls", 10)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
