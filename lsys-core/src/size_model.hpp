// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <map>
#include <string>
#include <tuple>

#include "lsys/derivation.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/grammar.hpp"
#include "rule_index.hpp"

namespace lsys {

/// Sizes beyond this are reported as "more than 1e+300".
inline constexpr double kHugeCount = 1e300;

/// What interpreting one module costs through the homomorphism.
struct InterpretationCost {
  double segments = 0.0;  ///< segments drawn
  double modules = 0.0;   ///< modules the turtle executes
};

/// The cost of interpreting each kind of module (name and parameter count),
/// as an upper bound (the dearest alternative of a conditional homomorphism)
/// or a lower bound (the cheapest, or none applying).
class InterpretationCosts {
 public:
  InterpretationCosts(const Grammar& grammar, bool is_lower_bound);
  [[nodiscard]] InterpretationCost cost(SymbolId symbol, int arity,
                                        int depth = 0);
  /// The largest segment count over the arities a module can have.
  [[nodiscard]] double segments_any_arity(SymbolId symbol);
  /// True when each cost is exact: no homomorphism rule has a condition or
  /// a probability, and each module's rules share one arity. Otherwise a
  /// cost is only a bound (a recursive homomorphism whose conditions end
  /// its recursion early may draw far less than its bound).
  [[nodiscard]] bool is_exact() const noexcept { return is_exact_; }

 private:
  const Grammar& grammar_;
  RuleIndex homomorphisms_;
  bool is_lower_bound_;
  bool is_exact_ = true;
  std::map<std::tuple<SymbolId, int, int>, InterpretationCost> memo_;
};

/// The exact size of step n for grammars without conditions, probabilities,
/// contexts or cuts (the count matrix, ABOP §1.2), or nothing.
[[nodiscard]] std::optional<SizePrediction> exact_size(const Grammar& grammar,
                                                       int n);

/// A lower bound of the size of step n for any grammar without cuts: each
/// module grows at least as its cheapest alternative (including staying
/// itself where no production needs to apply), or nothing.
[[nodiscard]] std::optional<SizePrediction> size_lower_bound(
    const Grammar& grammar, int n);

/// True if the axiom, a production or a decomposition makes a `%`: then
/// strings are rewritten whole and sizes are not predicted.
[[nodiscard]] bool has_cut(const Grammar& grammar);

/// A count as text: an integer, or "more than 1e+300" when capped.
[[nodiscard]] std::string count_text(double value);

/// The error for a size limit, located at the file's `n` unless the caller
/// overrode it, else at the axiom: "n = 9 <what>".
[[nodiscard]] ParseError limit_error(const Grammar& grammar,
                                     const DerivationOptions& options, int n,
                                     const std::string& what);

}  // namespace lsys
