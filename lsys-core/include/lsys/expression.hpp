// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "lsys/source.hpp"

namespace lsys {

/// cpfg's functions for `func(id, x)`: for each id from 1, the values y at
/// equally spaced x from 0 to 1 (vlab's `.func` files).
using FunctionTable = std::vector<std::vector<double>>;

/// A Python function of one `return` (L-Py's `def alpha(x): return 30 -
/// 10*x`), or of returns chosen by `if`/`elif`/`else`: its parameters and
/// the bytes of the returned expressions, which a call compiles in place
/// with the arguments bound to the parameters.
struct PythonFunction {
  std::vector<std::string> parameters;
  std::size_t begin = 0;
  std::size_t end = 0;
  /// `if c: return a` (and `elif`) before the last return: the bytes of
  /// each condition and of its value, tried in order.
  struct Branch {
    std::size_t condition_begin = 0;
    std::size_t condition_end = 0;
    std::size_t value_begin = 0;
    std::size_t value_end = 0;
  };
  std::vector<Branch> branches;
};

/// A module of a successor as written: its name (interned) and the bytes of
/// each argument, for a Python body that builds its successor as it runs
/// (ExpressionScope::read_successor).
struct SuccessorModuleText {
  std::uint32_t symbol = 0;
  std::size_t offset = 0;
  std::vector<std::pair<std::size_t, std::size_t>> arguments;
};

/// One of cpfg's arrays (`define: { array len[4][13] = {…}; }`): a run of
/// global variables from `first`, row by row, of the dimensions given.
struct ArrayVariable {
  std::string name;
  std::uint32_t first = 0;
  std::vector<std::uint32_t> dimensions;
  /// A Python list: an index is a whole number, and a negative one counts
  /// from the end (`a[-1]`).
  bool python = false;
};

/// The names an expression may use: the formal parameters of the production
/// it belongs to (ABOP §1.10), in slot order, and named constants
/// (`#define`, `--define`), which are folded at compile time.
struct ExpressionScope {
  std::vector<std::string> parameters;
  const std::map<std::string, double>* constants = nullptr;
  /// When set, receives the names of the constants the expression reads.
  std::set<std::string>* used_constants = nullptr;
  /// Trigonometric functions take and give radians (Python's math, as L-Py
  /// files use it) instead of degrees (cpfg).
  bool radians = false;
  /// cpfg's local variables of a production: names its statement blocks
  /// assign, in the slots after the parameters. A statement block that
  /// assigns a new name adds it.
  std::vector<std::string>* locals = nullptr;
  /// cpfg's global variables, assigned in `Start:` and its kin. A block
  /// compiled with `assign_globals` adds the new names it assigns.
  std::vector<std::string>* globals = nullptr;
  bool assign_globals = false;
  /// cpfg's arrays, which `name[i][j]` reads and statements assign.
  const std::vector<ArrayVariable>* arrays = nullptr;
  /// What `func(id, x)` reads, when the view file names functions.
  std::shared_ptr<const FunctionTable> functions;
  /// cpfg's operators and functions besides ABOP's: `%`, `?:`, `trunc`,
  /// `sign`, `fabs`, and the random `ran`, `nran`, `bran`, `biran`,
  /// `srand`.
  bool cpfg = false;
  /// L-system Explorer's expressions, which are mathjs's: the words `and`,
  /// `or`, `not` and `mod` beside `&&`, `||`, `!` and `%`, and statements
  /// whose last `;` may be left out (`{v = i}`).
  bool mathjs = false;
  /// Python's expressions, as L-Py writes them: `and`, `or`, `not`,
  /// `x if c else y`, `%` (floored) and `//`, `random()` and
  /// `uniform(a, b)`; statements are Python's (parse_python_statements).
  bool python = false;
  /// When set (cpfg), a name that nothing defines reads as 0, as cpfg
  /// takes it ("Identifier not previously defined"); its name and place
  /// are added here, for a warning.
  std::vector<std::pair<std::string, std::size_t>>* undefined = nullptr;
  /// lpfg's C++ (with cpfg): typed declarations, `for`, `+=` and `++`,
  /// `pow`, and, with read_successor, `produce …;` and `nproduce …;`.
  bool c_language = false;
  /// Names that stand for Python's modules `math` and `random` (`import
  /// random as rd`): `rd.uniform(0, 1)` is `uniform(0, 1)`.
  const std::vector<std::string>* python_modules = nullptr;
  /// Names that L-Py's imports of other modules bind (`np` of `import numpy
  /// as np`, `deepcopy` of `from copy import deepcopy`), by their module:
  /// refused where they are used, naming the module.
  const std::map<std::string, std::string>* python_imports = nullptr;
  /// L-Py's functions of one `return`, which calls compile in place.
  const std::map<std::string, PythonFunction>* python_functions = nullptr;
  /// When set, a Python body builds its successor as it runs (L-Py's
  /// `nproduce`, and an axiom written as Python): `nproduce …` and
  /// `produce …` append their modules, read by this function from the
  /// bytes [begin, end) of the statement, to Variables::emitted.
  std::function<std::vector<SuccessorModuleText>(std::size_t, std::size_t)>
      read_successor;
};

/// The modules a Python body has appended with `nproduce` or `produce`
/// (ExpressionScope::read_successor): their symbols, and their values laid
/// out as Successor::parameter_begins lays them out.
struct EmittedModules {
  std::vector<std::uint32_t> symbols;
  std::vector<std::uint32_t> begins{0};
  std::vector<double> values;
};

/// What cpfg's expressions share while deriving: its global variables and
/// the state of its random number generator, erand48's 48-bit linear
/// congruence, which starts where cpfg's does (0x330E) so that `ran()`
/// gives cpfg's numbers.
struct Variables {
  std::vector<double> globals;
  std::uint64_t random_state = 0x330E;
  /// What the running Python body has produced so far.
  EmittedModules emitted;
  /// The derivation step being made, from 0 (L-Py's getIterationNb()).
  int iteration = 0;
};

/// An arithmetic or logical expression compiled once into code for a small
/// stack machine, so that deriving never re-parses text (seed 004's
/// "parameter inlining"). Booleans are 1 and 0.
///
/// Operators, loosest first: `||`; `&&`; `< <= > >= == != =` (`=` compares,
/// as ABOP's conditions write it); `+ -`; `* /`; unary `- + !`; `^` (power,
/// right-associative). Functions: `sin cos tan asin acos atan atan2` (in
/// degrees, as cpfg), `sqrt exp log abs floor ceil min max`.
class Expression {
 public:
  /// The constant 0.
  Expression() = default;
  /// A constant.
  [[nodiscard]] static Expression constant(double value);
  /// 1 when slot `slot` holds `value`, else 0: which `produce` of an L-Py
  /// rule body ran (parse_python_statements), placed at `offset` of
  /// `source`.
  [[nodiscard]] static Expression slot_equals(
      std::shared_ptr<const SourceFile> source, std::size_t offset,
      std::uint32_t slot, double value);

  /// 1 when each slot holds its value, else 0: the values an L-Py
  /// predecessor requires (`A(0)`), placed at `offset` of `source`.
  /// @pre `slots` is not empty.
  [[nodiscard]] static Expression slots_equal(
      std::shared_ptr<const SourceFile> source, std::size_t offset,
      std::span<const std::pair<std::uint32_t, double>> slots);

  /// True when the value does not depend on parameters.
  [[nodiscard]] bool is_constant() const noexcept {
    return code_.size() == 1 && code_.front().op == Op::Constant;
  }
  /// The value of a constant expression.
  /// @pre `is_constant()`.
  [[nodiscard]] double constant_value() const noexcept {
    return code_.front().value;
  }
  /// Evaluates with the actual parameter values in slot order (and the
  /// production's local variables after them).
  /// @pre `parameters.size()` covers every slot the expression reads, and
  ///   `variables` is given when uses_variables().
  /// @throws ParseError at the operator for division by zero, and at the
  ///   expression when the result is not a finite number.
  [[nodiscard]] double evaluate(std::span<const double> parameters,
                                Variables* variables = nullptr) const;
  /// Runs a statement block (parse_statements), which may change `slots`
  /// and the global variables.
  /// @pre as evaluate.
  /// @throws ParseError as evaluate, and when a loop runs a million times.
  void execute(std::span<double> slots, Variables* variables) const;
  /// True when the code reads or writes global variables or draws random
  /// numbers, so that its value depends on what ran before.
  [[nodiscard]] bool uses_variables() const noexcept { return uses_variables_; }
  /// The byte offset of the expression in its source.
  [[nodiscard]] std::size_t offset() const noexcept { return offset_; }

  /// Operations of the stack machine (public for the compiler only).
  enum class Op : std::uint8_t {
    Constant,
    Parameter,
    Negate,
    Not,
    Add,
    Subtract,
    Multiply,
    Divide,
    Power,
    Less,
    LessEqual,
    Greater,
    GreaterEqual,
    Equal,
    NotEqual,
    And,
    Or,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Atan2,
    Sqrt,
    Exp,
    Log,
    Abs,
    Floor,
    Ceil,
    Min,
    Max,
    Modulo,
    Trunc,
    Sign,
    Ran,
    Nran,
    Bran,
    Biran,
    Srand,
    Global,
    StoreSlot,
    StoreGlobal,
    Pop,
    Jump,
    JumpIfZero,
    Select,
    Func,
    Int,
    RoundHalfEven,
    Iteration,
    EmitClear,
    Emit,
    Emitted,
    CheckIndex,
    GlobalAt,
    StoreGlobalAt
  };
  /// One instruction: `value` for Constant, `slot` for Parameter, Global,
  /// the stores, and the jump target; `offset` for the error position.
  /// Emit appends the module `slot` with the `value` values on top of the
  /// stack to Variables::emitted; EmitClear empties it; Emitted pushes
  /// 1 when it holds modules (and checks that its brackets balance).
  /// CheckIndex fails unless 0 <= top < `value` (an array's dimension;
  /// with `slot` 1, Python's, a whole number from −value, made positive);
  /// GlobalAt pushes the global `slot` + trunc(top), StoreGlobalAt stores
  /// the top there, the index below it.
  struct Instruction {
    Op op = Op::Constant;
    std::uint32_t slot = 0;
    double value = 0.0;
    std::size_t offset = 0;
  };

 private:
  friend Expression parse_expression(std::shared_ptr<const SourceFile>,
                                     std::size_t, std::size_t,
                                     const ExpressionScope&);
  // cpfg's statements, or an L-Py rule's Python body.
  static Expression statements(std::shared_ptr<const SourceFile> source,
                               std::size_t begin, std::size_t end,
                               const ExpressionScope& scope, bool python);
  friend Expression parse_statements(std::shared_ptr<const SourceFile>,
                                     std::size_t, std::size_t,
                                     const ExpressionScope&);
  friend Expression parse_python_statements(std::shared_ptr<const SourceFile>,
                                            std::size_t, std::size_t,
                                            const ExpressionScope&);
  double run(const double* read, double* write, Variables* variables) const;
  // Takes compiled code and notes what it needs while running.
  void adopt(std::vector<Instruction> code, const ExpressionScope& scope);

  std::vector<Instruction> code_{Instruction{}};
  std::shared_ptr<const SourceFile> source_;
  std::size_t offset_ = 0;
  int stack_depth_ = 1;
  bool uses_variables_ = false;
  std::shared_ptr<const FunctionTable> functions_;
};

/// Compiles the expression in bytes [begin, end) of a source.
/// @throws ParseError for a syntax error, a bad number, an undefined name, a
///   wrong argument count, or a constant division by zero.
[[nodiscard]] Expression parse_expression(
    std::shared_ptr<const SourceFile> source, std::size_t begin,
    std::size_t end, const ExpressionScope& scope);

/// Compiles cpfg's statements in bytes [begin, end): `{ x = e; if (c) { … }
/// else { … } while (c) { … } do { … } while (c); f(…); }` (the outer braces
/// optional). An assignment to a parameter changes it for the rest of the
/// production; to a new name, makes a local (or, with
/// `scope.assign_globals`, a global) variable. `printf` and `fprintf`
/// statements are skipped: lsolid prints nothing of a model's own.
/// @throws ParseError as parse_expression, and for a malformed statement.
[[nodiscard]] Expression parse_statements(
    std::shared_ptr<const SourceFile> source, std::size_t begin,
    std::size_t end, const ExpressionScope& scope);

/// The local variable in which parse_python_statements records which
/// `produce` ran: 0 for none, k for the k-th in the text.
inline constexpr std::string_view kProducedLocal = "produce";
/// Compiles the Python body of an L-Py rule in bytes [begin, end), lines
/// whose indentation makes the blocks: `name = e` (and `+=`, `-=`, `*=`,
/// `/=`), `if c:` / `elif c:` / `else:` (a simple statement may follow the
/// colon on its line), `for name in range(…):`, `while c:`, `pass`, and
/// `produce …`, which sets the local kProducedLocal to its number and ends
/// the body. With `scope.read_successor`, the body builds its successor:
/// `nproduce …` appends modules, `produce …` appends its own, sets
/// kProducedLocal to 1 and ends the body, and at the end kProducedLocal is
/// 1 when anything was produced. `#` starts a comment. Expressions are
/// Python's (ExpressionScope::python).
/// @pre `scope.locals` is set, or `scope.globals` for a hook.
/// @throws ParseError as parse_expression, for bad indentation, and at any
///   other Python statement (`return`, `break`, `nproduce` where nothing
///   reads a successor, …), which lsolid does not run.
[[nodiscard]] Expression parse_python_statements(
    std::shared_ptr<const SourceFile> source, std::size_t begin,
    std::size_t end, const ExpressionScope& scope);
/// The `produce` statements of an L-Py rule body in bytes [begin, end), in
/// the order parse_python_statements numbers them: for each, the bytes of
/// its successor.
[[nodiscard]] std::vector<std::pair<std::size_t, std::size_t>>
python_successors(const SourceFile& source, std::size_t begin, std::size_t end);
/// True when the L-Py rule body in bytes [begin, end) has an `nproduce`
/// statement: it builds its successor as it runs
/// (ExpressionScope::read_successor).
[[nodiscard]] bool python_builds_successor(const SourceFile& source,
                                           std::size_t begin, std::size_t end);
}  // namespace lsys
