// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Expressions of parametric L-systems (ABOP §1.10; cpfg manual §3.2 for the
// C-like operators and degree-based trigonometry). Compiled once to postfix
// code with constants folded, as seed 004 recommends for speed.
#include "lsys/expression.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

#include "expressions/c_statements.hpp"
#include "expressions/expression_compiler.hpp"
#include "expressions/operations.hpp"
#include "expressions/python_lines.hpp"
#include "expressions/python_statements.hpp"
#include "lsys/alphabet.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/module_string.hpp"

namespace lsys {

using expressions::apply;
using expressions::arity;
using expressions::beta;
using expressions::erand48;
using expressions::is_random;
using expressions::kMaxStack;
using expressions::normal;
using expressions::python_colon;
using expressions::python_lines;
using expressions::PythonLine;
using expressions::starts_word;
using Op = Expression::Op;
using Instruction = Expression::Instruction;

Expression Expression::constant(double value) {
  Expression e;
  e.code_.front().value = value;
  return e;
}

double Expression::evaluate(std::span<const double> parameters,
                            Variables* variables) const {
  if (code_.size() == 1) {
    const Instruction& only = code_.front();
    if (only.op == Op::Constant) return only.value;
    if (only.op == Op::Parameter) return parameters[only.slot];
  }
  const double value = run(parameters.data(), nullptr, variables);
  if (!std::isfinite(value)) {
    throw error_at(*source_, offset_,
                   "the value of this expression is not a finite number");
  }
  return value;
}

void Expression::execute(std::span<double> slots, Variables* variables) const {
  (void)run(slots.data(), slots.data(), variables);
}

double Expression::run(const double* read, double* write,
                       Variables* variables) const {
  // A loop of a model that never ends must not hang the program.
  constexpr std::size_t kMaxJumpsBack = 1'000'000;
  std::array<double, kMaxStack> stack{};
  int top = -1;
  std::size_t jumps_back = 0;
  constexpr double kMostDraws = 1e7;
  constexpr std::size_t kMostEmitted = 10'000'000;
  double draws = 0.0;
  const auto need_variables = [&](const Instruction& in) -> Variables& {
    if (variables == nullptr) {
      throw error_at(*source_, in.offset,
                     "cpfg's variables and random numbers are not available "
                     "here");
    }
    return *variables;
  };
  const auto at = [&](int i) -> double& {
    return stack[static_cast<std::size_t>(i)];
  };
  // The global slot of an array's element; fractional subscripts (which
  // cpfg allows) could otherwise reach past the array.
  const auto element = [&](const Instruction& in, double offset) {
    if (!(offset >= 0.0 && offset < in.value)) {
      throw error_at(*source_, in.offset,
                     "fractional subscripts reach past the end of the array");
    }
    return in.slot + static_cast<std::size_t>(offset);
  };
  std::size_t pc = 0;
  while (pc < code_.size()) {
    const Instruction& in = code_[pc++];
    switch (in.op) {
      case Op::Constant:
        at(++top) = in.value;
        break;
      case Op::Parameter:
        at(++top) = read[in.slot];
        break;
      case Op::Global:
        at(++top) = need_variables(in).globals[in.slot];
        break;
      case Op::StoreSlot:
        write[in.slot] = at(top--);
        break;
      case Op::StoreGlobal:
        need_variables(in).globals[in.slot] = at(top--);
        break;
      case Op::CheckIndex: {
        double& i = at(top);
        if (in.slot == 1) {
          if (i != std::trunc(i)) {
            throw error_at(*source_, in.offset,
                           "a list's index must be a whole number");
          }
          if (i < 0.0 && i >= -in.value) i += in.value;
        }
        if (!(i >= 0.0 && i < in.value)) {
          std::string what = "subscript ";
          append_number(what, i);
          what += " is out of range: this dimension of the array has ";
          append_number(what, in.value);
          what += " elements, 0 to ";
          append_number(what, in.value - 1.0);
          throw error_at(*source_, in.offset, what);
        }
        break;
      }
      case Op::GlobalAt:
        at(top) = need_variables(in).globals[element(in, at(top))];
        break;
      case Op::StoreGlobalAt: {
        const double value = at(top--);
        need_variables(in).globals[element(in, at(top--))] = value;
        break;
      }
      case Op::Pop:
        --top;
        break;
      case Op::JumpIfZero:
        if (at(top--) != 0.0) break;
        [[fallthrough]];
      case Op::Jump:
        if (in.slot < pc && ++jumps_back > kMaxJumpsBack) {
          throw error_at(*source_, in.offset,
                         "a loop ran a million times; lsolid stops it");
        }
        pc = in.slot;
        break;
      case Op::Ran:
        at(top) *= erand48(need_variables(in).random_state);
        break;
      case Op::EmitClear:
        need_variables(in).emitted = EmittedModules{};
        break;
      case Op::Emit: {
        // L-Py's nproduce: the module and the values on top of the stack.
        EmittedModules& e = need_variables(in).emitted;
        const auto n = static_cast<int>(in.value);
        if (e.symbols.size() >= kMostEmitted) {
          throw error_at(*source_, in.offset,
                         "this body produces more than 10 million modules; "
                         "lsolid stops it");
        }
        for (int k = top - n + 1; k <= top; ++k) {
          if (!std::isfinite(at(k))) {
            throw error_at(*source_, in.offset,
                           "a parameter of this module is not a finite "
                           "number");
          }
          e.values.push_back(at(k));
        }
        top -= n;
        e.symbols.push_back(in.slot);
        e.begins.push_back(static_cast<std::uint32_t>(e.values.size()));
        break;
      }
      case Op::Iteration:
        at(++top) = need_variables(in).iteration;
        break;
      case Op::Emitted:
        at(++top) = need_variables(in).emitted.symbols.empty() ? 0.0 : 1.0;
        break;
      case Op::Func: {
        // cpfg clamps x to [0, 1]; between samples, a straight line.
        const std::vector<double>& y = (*functions_)[in.slot];
        const double v = at(top);  // NaN reads as 0, as the clamp's low end
        const double x = (v > 0.0 ? std::min(v, 1.0) : 0.0) *
                         static_cast<double>(y.size() - 1);
        const auto i = std::min(static_cast<std::size_t>(x), y.size() - 2);
        const double f = x - static_cast<double>(i);
        at(top) = y[i] + f * (y[i + 1] - y[i]);
        break;
      }
      case Op::Nran: {
        const double deviation = at(top--);
        at(top) = normal(need_variables(in).random_state, at(top), deviation);
        break;
      }
      case Op::Bran: {
        const double b = at(top--);
        at(top) = beta(need_variables(in).random_state, at(top), b);
        break;
      }
      case Op::Biran: {
        // cpfg draws n uniforms; so does lsolid, within a budget of draws
        // per block so that a loop of them cannot run for hours.
        const double p = at(top--);
        const double n = std::max(0.0, std::trunc(at(top)));
        draws += n;
        if (draws > kMostDraws) {
          throw error_at(*source_, in.offset,
                         "biran draws more than 10 million numbers here; "
                         "lsolid stops it");
        }
        double count = 0.0;
        std::uint64_t& state = need_variables(in).random_state;
        for (double i = 0.0; i < n; i += 1.0) {
          if (erand48(state) <= p) count += 1.0;
        }
        at(top) = count;
        break;
      }
      case Op::Srand: {
        // cpfg's srand(s): erand48's state {0x330E, s & 0xFFFF, s >> 16}.
        // A seed beyond 64 bits (or NaN) has no integer: 0, not UB.
        const double value = at(top);
        const auto whole = std::fabs(value) < 9.2e18
                               ? static_cast<std::int64_t>(value)
                               : std::int64_t{0};
        const auto seed =
            static_cast<std::uint64_t>(static_cast<std::uint32_t>(whole));
        need_variables(in).random_state =
            ((seed >> 16U) << 32U) | ((seed & 0xFFFFU) << 16U) | 0x330EU;
        at(top) = 0.0;
        break;
      }
      default: {
        const int n = arity(in.op);
        const double b = n == 2 ? at(top--) : 0.0;
        double& a = at(top);
        bool divide_by_zero = false;
        a = apply(in.op, a, b, divide_by_zero);
        if (divide_by_zero) {
          throw error_at(*source_, in.offset, "division by zero");
        }
      }
    }
  }
  return top >= 0 ? stack[0] : 0.0;
}

namespace {

bool calls_functions(const std::vector<Expression::Instruction>& code) {
  return std::any_of(code.begin(), code.end(),
                     [](const auto& in) { return in.op == Op::Func; });
}

bool touches_variables(const std::vector<Expression::Instruction>& code) {
  return std::any_of(code.begin(), code.end(), [](const auto& in) {
    return in.op == Op::Global || in.op == Op::StoreGlobal ||
           in.op == Op::GlobalAt || in.op == Op::StoreGlobalAt ||
           in.op == Op::EmitClear || in.op == Op::Emit ||
           in.op == Op::Emitted || in.op == Op::Iteration || is_random(in.op);
  });
}

}  // namespace

void Expression::adopt(std::vector<Instruction> code,
                       const ExpressionScope& scope) {
  code_ = std::move(code);
  uses_variables_ = touches_variables(code_);
  if (calls_functions(code_)) functions_ = scope.functions;
}

Expression parse_expression(std::shared_ptr<const SourceFile> source,
                            std::size_t begin, std::size_t end,
                            const ExpressionScope& scope) {
  expressions::ExpressionCompiler compiler(*source, begin, end, scope);
  Expression e;
  e.adopt(compiler.compile(e.stack_depth_), scope);
  std::size_t offset = begin;
  const std::string& text = source->text();
  while (offset < end && (text[offset] == ' ' || text[offset] == '\t')) {
    ++offset;
  }
  e.offset_ = offset;
  if (e.is_constant() && !std::isfinite(e.constant_value())) {
    throw error_at(*source, offset,
                   "the value of this expression is not a finite number");
  }
  e.source_ = std::move(source);
  return e;
}

Expression Expression::slot_equals(std::shared_ptr<const SourceFile> source,
                                   std::size_t offset, std::uint32_t slot,
                                   double value) {
  Expression e;
  e.code_ = {Instruction{.op = Op::Parameter, .slot = slot, .offset = offset},
             Instruction{.op = Op::Constant, .value = value, .offset = offset},
             Instruction{.op = Op::Equal, .offset = offset}};
  e.stack_depth_ = 2;
  e.offset_ = offset;
  e.source_ = std::move(source);
  return e;
}

Expression Expression::slots_equal(
    std::shared_ptr<const SourceFile> source, std::size_t offset,
    std::span<const std::pair<std::uint32_t, double>> slots) {
  Expression e;
  e.code_.clear();  // not the constant 0
  for (const auto& [slot, value] : slots) {
    e.code_.push_back(
        Instruction{.op = Op::Parameter, .slot = slot, .offset = offset});
    e.code_.push_back(
        Instruction{.op = Op::Constant, .value = value, .offset = offset});
    e.code_.push_back(Instruction{.op = Op::Equal, .offset = offset});
    if (e.code_.size() > 3) {
      e.code_.push_back(Instruction{.op = Op::And, .offset = offset});
    }
  }
  e.stack_depth_ = 3;
  e.offset_ = offset;
  e.source_ = std::move(source);
  return e;
}

Expression Expression::statements(std::shared_ptr<const SourceFile> source,
                                  std::size_t begin, std::size_t end,
                                  const ExpressionScope& scope, bool python) {
  Expression e;
  if (python) {
    expressions::PythonStatementCompiler compiler(*source, begin, end, scope);
    e.adopt(compiler.compile_python(e.stack_depth_), scope);
  } else {
    expressions::CStatementCompiler compiler(*source, begin, end, scope);
    e.adopt(compiler.compile_statements(e.stack_depth_), scope);
  }
  e.offset_ = begin;
  e.source_ = std::move(source);
  return e;
}

Expression parse_python_statements(std::shared_ptr<const SourceFile> source,
                                   std::size_t begin, std::size_t end,
                                   const ExpressionScope& scope) {
  return Expression::statements(std::move(source), begin, end, scope, true);
}

namespace {

// Where a line's simple statement starts: after the colon of a compound
// statement's header on the same line (`if x: produce F`), else at the
// line's start.
std::size_t simple_statement_start(std::string_view text,
                                   const PythonLine& line) {
  for (const std::string_view word : {"if", "elif", "else", "for", "while"}) {
    if (!starts_word(text, line.begin, line.end, word)) continue;
    const std::size_t colon = python_colon(text, line.begin, line.end);
    if (colon == std::string_view::npos) return line.begin;
    std::size_t at = colon + 1;
    while (at < line.end && (text[at] == ' ' || text[at] == '\t')) ++at;
    return at;
  }
  return line.begin;
}

}  // namespace

std::vector<std::pair<std::size_t, std::size_t>> python_successors(
    const SourceFile& source, std::size_t begin, std::size_t end) {
  const std::string_view text = std::string_view(source.text()).substr(0, end);
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (const PythonLine& line : python_lines(text, begin, end)) {
    const std::size_t at = simple_statement_start(text, line);
    if (starts_word(text, at, line.end, kProducedLocal)) {
      out.emplace_back(at + kProducedLocal.size(), line.end);
    }
  }
  return out;
}

bool python_builds_successor(const SourceFile& source, std::size_t begin,
                             std::size_t end) {
  const std::string_view text = std::string_view(source.text()).substr(0, end);
  const std::vector<PythonLine> lines = python_lines(text, begin, end);
  return std::any_of(lines.begin(), lines.end(), [&](const PythonLine& line) {
    return starts_word(text, simple_statement_start(text, line), line.end,
                       "nproduce");
  });
}

Expression parse_statements(std::shared_ptr<const SourceFile> source,
                            std::size_t begin, std::size_t end,
                            const ExpressionScope& scope) {
  return Expression::statements(std::move(source), begin, end, scope, false);
}

}  // namespace lsys
