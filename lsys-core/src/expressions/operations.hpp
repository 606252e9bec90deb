// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string_view>

#include "lsys/expression.hpp"

namespace lsys::expressions {

// The operations of compiled expressions and what they compute: shared by
// the compiler, which folds constants with them, and the evaluator.

using Op = Expression::Op;
using Instruction = Expression::Instruction;

constexpr int kMaxStack = 64;
constexpr int kMaxNesting = 200;
constexpr std::size_t kMaxNodes = 4096;
constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

struct Function {
  std::string_view name;
  Op op;
  int arity;
  bool cpfg_only = false;
  bool mathjs_only = false;
  bool python_only = false;
};

constexpr std::array<Function, 27> kFunctions{{
    {"sin", Op::Sin, 1},
    {"cos", Op::Cos, 1},
    {"tan", Op::Tan, 1},
    {"asin", Op::Asin, 1},
    {"acos", Op::Acos, 1},
    {"atan", Op::Atan, 1},
    {"atan2", Op::Atan2, 2},
    {"sqrt", Op::Sqrt, 1},
    {"exp", Op::Exp, 1},
    {"log", Op::Log, 1},
    {"abs", Op::Abs, 1},
    {"floor", Op::Floor, 1},
    {"ceil", Op::Ceil, 1},
    {"min", Op::Min, 2},
    {"max", Op::Max, 2},
    // cpfg's (CPFG Reference Manual §5.1; its utility.c for the random
    // ones): trunc rounds there, as cpfg's code computes it.
    {"fabs", Op::Abs, 1, true},
    {"trunc", Op::Trunc, 1, true},
    {"sign", Op::Sign, 1, true},
    {"ran", Op::Ran, 1, true},
    {"nran", Op::Nran, 2, true},
    {"bran", Op::Bran, 2, true},
    {"biran", Op::Biran, 2, true},
    {"srand", Op::Srand, 1, true},
    // mathjs's (L-system Explorer): round halves up, as JavaScript's
    // Math.round, which is what cpfg's trunc computes.
    {"round", Op::Trunc, 1, false, true},
    {"pow", Op::Power, 2, false, true},
    // Python's (L-Py): int truncates toward zero, round halves to even.
    {"int", Op::Int, 1, false, false, true},
    {"round", Op::RoundHalfEven, 1, false, false, true},
}};

inline int arity(Op op) {
  switch (op) {
    case Op::Constant:
    case Op::Parameter:
    case Op::Global:
    case Op::Iteration:
      return 0;
    case Op::Negate:
    case Op::Not:
    case Op::Func:
    case Op::CheckIndex:
    case Op::GlobalAt:
      return 1;
    default:
      break;
  }
  for (const Function& f : kFunctions) {
    if (f.op == op) return f.arity;
  }
  return 2;
}

// Draws from cpfg's generator or changes it: never folded.
inline bool is_random(Op op) {
  return op == Op::Ran || op == Op::Nran || op == Op::Bran || op == Op::Biran ||
         op == Op::Srand;
}

// erand48: X ← (0x5DEECE66D·X + 0xB) mod 2^48, the value X / 2^48.
inline double erand48(std::uint64_t& state) {
  constexpr std::uint64_t kMask = (std::uint64_t{1} << 48U) - 1;
  state = (0x5DEECE66DULL * state + 0xBULL) & kMask;
  return static_cast<double>(state) * 0x1.0p-48;
}

// The polar method (Marsaglia), as cpfg's nran draws a normal deviate.
inline double normal(std::uint64_t& state, double mean, double deviation) {
  for (;;) {
    const double u = 2.0 * erand48(state) - 1.0;
    const double v = 2.0 * erand48(state) - 1.0;
    const double s = u * u + v * v;
    if (s > 0.0 && s < 1.0) {
      return mean + deviation * u * std::sqrt(-2.0 * std::log(s) / s);
    }
  }
}

// Jöhnk's method for Beta(a, b): exact for any positive a, b.
inline double beta(std::uint64_t& state, double a, double b) {
  if (a <= 0.0 || b <= 0.0) return 0.0;
  for (int tries = 0; tries < 1000000; ++tries) {
    const double x = std::pow(erand48(state), 1.0 / a);
    const double y = std::pow(erand48(state), 1.0 / b);
    if (x + y <= 1.0 && x + y > 0.0) return x / (x + y);
  }
  return a / (a + b);
}

// Applies one operation; `divide_by_zero` is set instead of dividing by 0.
inline double apply(Op op, double a, double b, bool& divide_by_zero) {
  switch (op) {
    case Op::Negate:
      return -a;
    case Op::Not:
      return a == 0.0 ? 1.0 : 0.0;
    case Op::Add:
      return a + b;
    case Op::Subtract:
      return a - b;
    case Op::Multiply:
      return a * b;
    case Op::Divide:
      if (b == 0.0) {
        divide_by_zero = true;
        return 0.0;
      }
      return a / b;
    case Op::Power:
      return std::pow(a, b);
    case Op::Less:
      return a < b ? 1.0 : 0.0;
    case Op::LessEqual:
      return a <= b ? 1.0 : 0.0;
    case Op::Greater:
      return a > b ? 1.0 : 0.0;
    case Op::GreaterEqual:
      return a >= b ? 1.0 : 0.0;
    case Op::Equal:
      return a == b ? 1.0 : 0.0;
    case Op::NotEqual:
      return a != b ? 1.0 : 0.0;
    case Op::And:
      return (a != 0.0 && b != 0.0) ? 1.0 : 0.0;
    case Op::Or:
      return (a != 0.0 || b != 0.0) ? 1.0 : 0.0;
    case Op::Sin:
      return std::sin(a * kRadiansPerDegree);
    case Op::Cos:
      return std::cos(a * kRadiansPerDegree);
    case Op::Tan:
      return std::tan(a * kRadiansPerDegree);
    case Op::Asin:
      return std::asin(a) / kRadiansPerDegree;
    case Op::Acos:
      return std::acos(a) / kRadiansPerDegree;
    case Op::Atan:
      return std::atan(a) / kRadiansPerDegree;
    case Op::Atan2:
      return std::atan2(a, b) / kRadiansPerDegree;
    case Op::Sqrt:
      return std::sqrt(a);
    case Op::Exp:
      return std::exp(a);
    case Op::Log:
      return std::log(a);
    case Op::Abs:
      return std::fabs(a);
    case Op::Floor:
      return std::floor(a);
    case Op::Ceil:
      return std::ceil(a);
    case Op::Min:
      return std::fmin(a, b);
    case Op::Max:
      return std::fmax(a, b);
    case Op::Modulo: {
      // cpfg: the remainder of the operands cut to integers.
      const double d = std::trunc(b);
      if (d == 0.0) {
        divide_by_zero = true;
        return 0.0;
      }
      return std::fmod(std::trunc(a), d);
    }
    case Op::Trunc:
      return std::floor(a + 0.5);
    case Op::Int:
      return std::trunc(a);
    case Op::RoundHalfEven:
      return a - std::remainder(a, 1.0);
    case Op::Sign:
      return a > 0.0 ? 1.0 : (a < 0.0 ? -1.0 : 0.0);
    default:
      break;
  }
  return 0.0;
}

}  // namespace lsys::expressions
