// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "lsys/source.hpp"

namespace lsys {

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

  /// True when the value does not depend on parameters.
  [[nodiscard]] bool is_constant() const noexcept {
    return code_.size() == 1 && code_.front().op == Op::Constant;
  }
  /// The value of a constant expression.
  /// @pre `is_constant()`.
  [[nodiscard]] double constant_value() const noexcept {
    return code_.front().value;
  }
  /// Evaluates with the actual parameter values in slot order.
  /// @pre `parameters.size()` covers every slot the expression reads.
  /// @throws ParseError at the operator for division by zero, and at the
  ///   expression when the result is not a finite number.
  [[nodiscard]] double evaluate(std::span<const double> parameters) const;
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
    Max
  };
  /// One instruction: `value` for Constant, `slot` for Parameter, `offset`
  /// for the error position of Divide.
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
  std::vector<Instruction> code_{Instruction{}};
  std::shared_ptr<const SourceFile> source_;
  std::size_t offset_ = 0;
  int stack_depth_ = 1;
};

/// Compiles the expression in bytes [begin, end) of a source.
/// @throws ParseError for a syntax error, a bad number, an undefined name, a
///   wrong argument count, or a constant division by zero.
[[nodiscard]] Expression parse_expression(
    std::shared_ptr<const SourceFile> source, std::size_t begin,
    std::size_t end, const ExpressionScope& scope);

}  // namespace lsys
