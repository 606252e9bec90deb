// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "lsys/alphabet.hpp"
#include "lsys/contour.hpp"
#include "lsys/expression.hpp"
#include "lsys/settings.hpp"
#include "lsys/source.hpp"
#include "lsys/surface.hpp"
#include "lsys/turtle_command.hpp"

namespace lsys {

/// Every grammar's alphabet starts with these three names, so the deriver
/// can recognise branches and cuts without a lookup.
inline constexpr SymbolId kBranchOpen = 0;   ///< `[`
inline constexpr SymbolId kBranchClose = 1;  ///< `]`
inline constexpr SymbolId kCut = 2;          ///< `%`
/// `*`: in a context of several modules, any one module other than a
/// bracket (`* A < B`). A context that is only `*` is no context, as in
/// cpfg (`* < A > * → AF`), and never reaches the deriver.
inline constexpr SymbolId kAnyModule = 3;

/// A module of a predecessor or context: a name and the number of formal
/// parameters it binds (their slots follow in pattern order).
struct PatternModule {
  SymbolId symbol = 0;
  int parameter_count = 0;
  std::size_t offset = 0;  ///< byte offset in the source
  /// cpfg's `=` in a right context: matches the rest of the current branch,
  /// up to its `]` (which the pattern may then match to leave the branch).
  bool to_branch_end = false;
};

/// The right-hand side of a production (or the axiom), kept flat: a name,
/// a source place and a range of parameter expressions per module, and,
/// when no expression depends on a parameter, their values. About 12 bytes
/// a module besides the expressions, so that a long axiom stays small.
class Successor {
 public:
  /// Appends a module. Brackets must balance when the successor is used.
  /// @pre `offset` fits 32 bits (parse_grammar refuses longer texts).
  void push_back(SymbolId symbol, std::vector<Expression> parameters,
                 std::size_t offset);

  [[nodiscard]] std::size_t size() const noexcept { return symbols_.size(); }
  [[nodiscard]] const std::vector<SymbolId>& symbols() const noexcept {
    return symbols_;
  }
  /// The byte offset in the source of module i. @pre `i < size()`.
  [[nodiscard]] std::size_t offset(std::size_t i) const { return offsets_[i]; }
  /// The parameter expressions of module i. @pre `i < size()`.
  [[nodiscard]] std::span<const Expression> parameters(std::size_t i) const {
    return std::span<const Expression>(expressions_)
        .subspan(begins_[i], begins_[i + 1] - begins_[i]);
  }
  /// Where module i's values start in an instantiated parameter array; entry
  /// `size()` is the total.
  [[nodiscard]] const std::vector<std::uint32_t>& parameter_begins()
      const noexcept {
    return begins_;
  }
  /// True when every parameter expression is constant.
  [[nodiscard]] bool is_constant() const noexcept { return is_constant_; }
  /// True when some parameter expression reads cpfg's variables or draws a
  /// random number.
  [[nodiscard]] bool uses_variables() const noexcept { return uses_variables_; }
  /// The values of a constant successor, laid out by `parameter_begins()`.
  [[nodiscard]] const std::vector<double>& constant_values() const noexcept {
    return constant_values_;
  }
  /// Evaluates every parameter expression into `out` (resized).
  /// @pre `variables` is given when uses_variables().
  /// @throws ParseError from Expression::evaluate.
  void instantiate(std::span<const double> slots, std::vector<double>& out,
                   Variables* variables = nullptr) const;
  /// Makes room for `modules` modules without their parameters.
  void reserve(std::size_t modules);
  /// Frees the room the arrays have beyond their size.
  void shrink_to_fit();

 private:
  std::vector<SymbolId> symbols_;
  std::vector<std::uint32_t> offsets_;
  std::vector<std::uint32_t> begins_{0};
  std::vector<Expression> expressions_;
  std::vector<double> constant_values_;
  bool is_constant_ = true;
  bool uses_variables_ = false;
};

/// A production `lc < pred > rc : condition → successor : probability`
/// (ABOP §1.7, 1.8, 1.10). Formal parameters are numbered left context
/// first, then predecessor, then right context.
struct Production {
  std::vector<PatternModule> left_context;
  PatternModule predecessor;
  /// The further modules of a strict predecessor of several (cpfg's
  /// `F(n) A > ?P(x,y,z)`): they must follow the first in the string with
  /// nothing between, and the successor replaces them all.
  std::vector<PatternModule> predecessor_rest;
  /// May contain `[` and `]` (ABOP p. 32); the left context may not.
  std::vector<PatternModule> right_context;
  std::optional<Expression> condition;
  /// The values a predecessor's parameters must have (L-Py's `A(0)`,
  /// `D(20, k)`), checked before any statement runs; 1 when they match.
  std::optional<Expression> guard;
  /// The weight of a stochastic production; absent means weight 1.
  std::optional<Expression> probability;
  /// cpfg's statements run on every match before the condition, and those
  /// run after it when it holds (parse_statements).
  std::optional<Expression> before;
  std::optional<Expression> after;
  /// How many local variables the statements use, in the slots after the
  /// formal parameters.
  int local_count = 0;
  /// An L-Py rule body makes one production per `produce`, each running
  /// the whole body: a run that does not select this production is undone
  /// (random draws, globals), so that the body runs once per module, as
  /// in L-Py, and the next production's run draws the same numbers. The
  /// body's last production keeps its run whether or not it applies: L-Py
  /// and lpfg keep the draws of a body that produced nothing.
  bool undo_unless_applied = false;
  /// An L-Py body that builds its successor as it runs (`nproduce`): the
  /// modules it produced (Variables::emitted) replace `successor`, which
  /// then holds every module the body may produce, as written, for the
  /// grammar's analyses (its brackets need not balance).
  bool successor_from_body = false;
  Successor successor;
  std::size_t offset = 0;  ///< byte offset of the production

  /// True when the production has a left or right context, or a
  /// predecessor of several modules: whether it applies depends on the
  /// module's neighbours.
  [[nodiscard]] bool is_context_sensitive() const noexcept {
    return !left_context.empty() || !right_context.empty() ||
           !predecessor_rest.empty();
  }
  /// True when the production applies only where a condition or a value
  /// in its predecessor says so.
  [[nodiscard]] bool is_conditional() const noexcept {
    return condition.has_value() || guard.has_value();
  }
  /// True when cpfg's statements run before or after its condition (and
  /// so its successor reads slots they wrote, not the module's values).
  [[nodiscard]] bool has_statements() const noexcept {
    return before.has_value() || after.has_value();
  }
};

/// An L-system as read from a `.ls` file: alphabet, axiom, productions,
/// interpretation rules and settings.
struct Grammar {
  std::shared_ptr<const SourceFile> source;
  Alphabet alphabet;
  Successor axiom;
  std::size_t axiom_offset = 0;
  /// L-Py's axiom written as Python (`Axiom:` above a body of `nproduce`
  /// statements): run once with `axiom_local_count` locals before the
  /// first step, its modules are the axiom, and `axiom` holds every module
  /// it may produce, as Production::successor_from_body does.
  std::optional<Expression> axiom_body;
  int axiom_local_count = 0;
  /// Rewritten in parallel, one step per generation; first applicable wins,
  /// or a weighted choice when any has a probability.
  std::vector<Production> productions;
  /// Applied to each new module right after each step, recursively up to
  /// `settings.maximum_depth`; context-free, deterministic.
  std::vector<Production> decompositions;
  /// Applied while interpreting only (homomorphism, `interpretation:`),
  /// recursively up to `settings.maximum_depth`; context-free, deterministic.
  std::vector<Production> homomorphisms;
  /// The turtle command of each symbol after aliases.
  std::vector<TurtleCommand> commands;
  /// Per symbol, the parameter its command takes when the module has none,
  /// where the notation gives one (Lparser's `'` multiplies the length by
  /// 0.9); empty or absent means the command's own default.
  std::vector<std::optional<double>> default_parameters;
  /// Per symbol, how many of a module's parameters the turtle reads, where
  /// the notation ignores the rest (cpfg's `+(20,0)` turns 20°, and its
  /// `F(l,t,c)` moves l); empty or absent means all.
  std::vector<std::optional<int>> parameters_read;
  Settings settings;
  /// `#define` and `--define` values.
  std::map<std::string, double> constants;
  /// Settings accepted for a client (see ParseOptions::extra_settings).
  std::vector<ExtraSetting> extra_settings;
  /// Things that are legal but probably mistakes (a `--define` the file
  /// never reads), for the caller to show.
  std::vector<std::string> warnings;
  /// The surfaces of the symbols whose command is TurtleCommand::Surface.
  std::map<SymbolId, Surface> surfaces;
  /// The contours `@#(id)` selects, by id (cpfg's view file).
  std::map<int, Contour> contours;
  /// cpfg's global variables, by slot, and its blocks of statements: once
  /// before the axiom, before and after each step, after the last.
  std::vector<std::string> globals;
  /// The values the first globals start at (L-system Explorer's variables,
  /// `zpos = 0`); the others start at 0.
  std::vector<double> initial_globals;
  std::optional<Expression> start;
  std::optional<Expression> start_each;
  std::optional<Expression> end_each;
  std::optional<Expression> end;
  /// True when something reads or writes cpfg's variables or draws random
  /// numbers: the string is then rewritten step by step, in order.
  bool uses_variables = false;
};

/// The global variables as a derivation starts them: each at its initial
/// value, or 0.
[[nodiscard]] Variables initial_variables(const Grammar& grammar);

}  // namespace lsys
