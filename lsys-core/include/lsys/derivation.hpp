// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>

#include "lsys/grammar.hpp"
#include "lsys/module_string.hpp"

namespace lsys {

/// How to derive.
struct DerivationOptions {
  /// Overrides the file's `n`.
  std::optional<int> derivation_length;
  /// Overrides the file's `seed`.
  std::optional<std::uint64_t> seed;
  /// Refuse when the turtle would draw more segments than this.
  std::uint64_t max_segments = 20'000'000;
  /// Refuse when the derived string would be longer than this, or the
  /// turtle would read more modules after the homomorphism.
  std::uint64_t max_modules = 200'000'000;
  /// Refuse when a string that must be held whole (contexts, cuts) would
  /// take more memory than this: about 16 bytes a module and 8 a parameter
  /// for each of two steps, and 8 a module for bracket matching.
  std::uint64_t max_memory_bytes = std::uint64_t{2} << 30U;
};

/// The size of the n-th string, predicted from the count matrix of the
/// productions (ABOP §1.2's "growth functions"): module counts per name
/// grow as v(k+1) = v(k)·M.
struct SizePrediction {
  /// False when conditions, probabilities, contexts or cuts make sizes
  /// depend on values; the counts are then upper bounds, or absent.
  bool is_exact = false;
  double modules = 0.0;              ///< length of the derived string
  double segments = 0.0;             ///< drawing modules, after homomorphism
  double interpreted_modules = 0.0;  ///< modules the turtle reads
};

/// The derivation of a grammar, read in chunks. Context-free grammars
/// without `%` stream depth-first from the productions (seed 004's
/// tree-based structure): memory is O(n × longest successor) and the n-th
/// string never exists whole. Others rewrite the whole string step by step.
/// Both give identical strings, stochastic ones included.
class Derivation {
 public:
  /// Prepares the derivation and checks the size limits: against the exact
  /// size where it is predictable, else against a lower bound of it.
  /// @throws ParseError (at the `n` setting, else the axiom) when the
  ///   predicted size exceeds a limit.
  Derivation(const Grammar& grammar, const DerivationOptions& options = {});
  ~Derivation();
  Derivation(const Derivation&) = delete;
  Derivation& operator=(const Derivation&) = delete;

  /// Replaces `chunk` with the next modules of the n-th string (at most
  /// `chunk_size`). Returns false, with `chunk` empty, at the end.
  /// @throws ParseError when an expression fails or a limit is exceeded.
  bool next(ModuleString& chunk, std::size_t chunk_size = 4096);

  /// The derivation length in use.
  [[nodiscard]] int derivation_length() const noexcept;
  /// True when the string streams depth-first.
  [[nodiscard]] bool is_streaming() const noexcept;
  /// cpfg's global variables and random generator as the derivation left
  /// them, for the homomorphism to read while interpreting.
  [[nodiscard]] Variables* variables() noexcept;
  /// The prediction made at construction, if the grammar allowed one.
  [[nodiscard]] const std::optional<SizePrediction>& prediction()
      const noexcept;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

/// The whole n-th string.
/// @throws ParseError as Derivation.
[[nodiscard]] ModuleString derive(const Grammar& grammar,
                                  const DerivationOptions& options = {});

}  // namespace lsys
