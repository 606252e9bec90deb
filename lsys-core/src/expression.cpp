// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Expressions of parametric L-systems (ABOP §1.10; cpfg manual §3.2 for the
// C-like operators and degree-based trigonometry). Compiled once to postfix
// code with constants folded, as seed 004 recommends for speed.
#include "lsys/expression.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>
#include <string_view>

#include "lsys/alphabet.hpp"
#include "lsys/diagnostic.hpp"

namespace lsys {
namespace {

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
};

constexpr std::array<Function, 15> kFunctions{{
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
}};

int arity(Op op) {
  switch (op) {
    case Op::Constant:
    case Op::Parameter:
      return 0;
    case Op::Negate:
    case Op::Not:
      return 1;
    default:
      break;
  }
  for (const Function& f : kFunctions) {
    if (f.op == op) return f.arity;
  }
  return 2;
}

// Applies one operation; `divide_by_zero` is set instead of dividing by 0.
double apply(Op op, double a, double b, bool& divide_by_zero) {
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
    case Op::Constant:
    case Op::Parameter:
      break;
  }
  return 0.0;
}

struct Node {
  Instruction instruction;
  int a = -1;
  int b = -1;
};

// Recursive descent over bytes [begin, end) of the source, building a tree
// that is folded and flattened to postfix code afterwards.
class Compiler {
 public:
  Compiler(const SourceFile& source, std::size_t begin, std::size_t end,
           const ExpressionScope& scope)
      : source_(source),
        text_(std::string_view(source.text()).substr(0, end)),
        pos_(begin),
        scope_(scope) {}

  std::vector<Instruction> compile(int& stack_depth) {
    skip_space();
    if (pos_ >= text_.size()) fail(pos_, "expected an expression");
    const int root = parse_or();
    skip_space();
    if (pos_ < text_.size()) {
      fail(pos_,
           "unexpected '" + std::string(peek_code_point()) + "' in expression");
    }
    std::vector<Instruction> code;
    stack_depth = emit(root, code);
    if (stack_depth > kMaxStack)
      fail(nodes_[0].instruction.offset, "expression is nested too deeply");
    return code;
  }

 private:
  [[noreturn]] void fail(std::size_t offset, std::string message) const {
    throw error_at(source_, offset, std::move(message));
  }

  void skip_space() {
    while (pos_ < text_.size() &&
           (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\r' ||
            text_[pos_] == '\n')) {
      ++pos_;
    }
  }

  std::string_view peek_code_point() const {
    return text_.substr(pos_, code_point_length(text_.substr(pos_)));
  }

  // Consumes `token` if it is next (after spaces).
  bool accept(std::string_view token) {
    skip_space();
    if (text_.substr(pos_).starts_with(token)) {
      pos_ += token.size();
      return true;
    }
    return false;
  }

  int add(Op op, std::size_t offset, int a = -1, int b = -1) {
    if (nodes_.size() >= kMaxNodes) fail(offset, "expression is too long");
    nodes_.push_back(Node{Instruction{.op = op, .offset = offset}, a, b});
    return static_cast<int>(nodes_.size()) - 1;
  }

  // Folds a node whose operands are constants into a constant.
  int fold(int index) {
    Node& node = nodes_[static_cast<std::size_t>(index)];
    const auto is_const = [&](int i) {
      return i < 0 ||
             nodes_[static_cast<std::size_t>(i)].instruction.op == Op::Constant;
    };
    if (!is_const(node.a) || !is_const(node.b)) return index;
    const double a =
        node.a < 0 ? 0.0
                   : nodes_[static_cast<std::size_t>(node.a)].instruction.value;
    const double b =
        node.b < 0 ? 0.0
                   : nodes_[static_cast<std::size_t>(node.b)].instruction.value;
    bool divide_by_zero = false;
    const double value = apply(node.instruction.op, a, b, divide_by_zero);
    if (divide_by_zero) fail(node.instruction.offset, "division by zero");
    node.instruction.op = Op::Constant;
    node.instruction.value = value;
    node.a = node.b = -1;
    return index;
  }

  int binary(Op op, std::size_t offset, int a, int b) {
    return fold(add(op, offset, a, b));
  }

  int parse_or() {
    int left = parse_and();
    for (;;) {
      const std::size_t at = (skip_space(), pos_);
      if (!accept("||")) return left;
      left = binary(Op::Or, at, left, parse_and());
    }
  }

  int parse_and() {
    int left = parse_comparison();
    for (;;) {
      const std::size_t at = (skip_space(), pos_);
      if (!accept("&&")) return left;
      left = binary(Op::And, at, left, parse_comparison());
    }
  }

  int parse_comparison() {
    int left = parse_sum();
    static constexpr std::array<std::pair<std::string_view, Op>, 10> kOps{{
        {"<=", Op::LessEqual},
        {">=", Op::GreaterEqual},
        {"==", Op::Equal},
        {"!=", Op::NotEqual},
        {"\u2264", Op::LessEqual},
        {"\u2265", Op::GreaterEqual},
        {"\u2260", Op::NotEqual},
        {"<", Op::Less},
        {">", Op::Greater},
        {"=", Op::Equal},
    }};
    for (;;) {
      skip_space();
      const std::size_t at = pos_;
      bool matched = false;
      for (const auto& [token, op] : kOps) {
        if (accept(token)) {
          left = binary(op, at, left, parse_sum());
          matched = true;
          break;
        }
      }
      if (!matched) return left;
    }
  }

  int parse_sum() {
    int left = parse_product();
    for (;;) {
      skip_space();
      const std::size_t at = pos_;
      if (accept("+")) {
        left = binary(Op::Add, at, left, parse_product());
      } else if (accept("-") || accept("\u2212")) {
        left = binary(Op::Subtract, at, left, parse_product());
      } else {
        return left;
      }
    }
  }

  int parse_product() {
    int left = parse_unary();
    for (;;) {
      skip_space();
      const std::size_t at = pos_;
      if ((!text_.substr(pos_).starts_with("**") && accept("*")) ||
          accept("\u00D7") || accept("\u00B7")) {
        left = binary(Op::Multiply, at, left, parse_unary());
      } else if (accept("/")) {
        left = binary(Op::Divide, at, left, parse_unary());
      } else {
        return left;
      }
    }
  }

  // Recursion guard: deeply nested input must not exhaust the stack.
  struct Nesting {
    explicit Nesting(Compiler& c) : compiler(c) {
      if (++compiler.nesting_ > kMaxNesting) {
        compiler.fail(compiler.pos_, "expression is nested too deeply");
      }
    }
    ~Nesting() { --compiler.nesting_; }
    Nesting(const Nesting&) = delete;
    Nesting& operator=(const Nesting&) = delete;
    Compiler& compiler;
  };

  int parse_unary() {
    const Nesting guard(*this);
    skip_space();
    const std::size_t at = pos_;
    if (accept("-") || accept("\u2212")) {
      return fold(add(Op::Negate, at, parse_unary()));
    }
    if (accept("+")) return parse_unary();
    if (text_.substr(pos_).starts_with("!") &&
        !text_.substr(pos_).starts_with("!=")) {
      ++pos_;
      return fold(add(Op::Not, at, parse_unary()));
    }
    return parse_power();
  }

  int parse_power() {
    const int base = parse_primary();
    skip_space();
    const std::size_t at = pos_;
    // `**` is Python's spelling, as L-Py files write it.
    if (accept("^") || accept("**")) {
      return binary(Op::Power, at, base, parse_unary());
    }
    return base;
  }

  static bool is_name_start(unsigned char c) {
    return std::isalpha(c) != 0 || c == '_' || c >= 0x80U;
  }

  int parse_primary() {
    skip_space();
    const std::size_t at = pos_;
    if (pos_ >= text_.size()) fail(pos_, "expected an expression");
    const auto c = static_cast<unsigned char>(text_[pos_]);
    if (accept("(")) {
      const int inner = parse_or();
      if (!accept(")")) fail(pos_, "expected ')'");
      return inner;
    }
    if (std::isdigit(c) != 0 || c == '.') return parse_number();
    if (is_name_start(c) && !is_operator_code_point()) return parse_name();
    fail(at, "expected an expression");
  }

  bool is_operator_code_point() const {
    for (std::string_view op :
         {"\u2264", "\u2265", "\u2260", "\u2212", "\u00D7", "\u00B7", "\u00B0",
          "\u00BA", "\u02DA", "\u25E6"}) {
      if (text_.substr(pos_).starts_with(op)) return true;
    }
    return false;
  }

  int parse_number() {
    const std::size_t at = pos_;
    std::size_t end = pos_;
    while (end < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[end])) != 0 ||
            text_[end] == '.' || text_[end] == '_' ||
            ((text_[end] == '+' || text_[end] == '-') && end > at &&
             (text_[end - 1] == 'e' || text_[end - 1] == 'E')))) {
      ++end;
    }
    const std::string_view token = text_.substr(at, end - at);
    double value = 0.0;
    const auto [ptr, ec] =
        std::from_chars(token.data(), token.data() + token.size(), value,
                        std::chars_format::general);
    if (ec != std::errc() || ptr != token.data() + token.size()) {
      fail(at, "bad number '" + std::string(token) + "'");
    }
    pos_ = end;
    // 45° is 45: angles are in degrees anyway. PDFs also give º, ˚ and ◦.
    for (std::string_view degree : {"\u00B0", "\u00BA", "\u02DA", "\u25E6"}) {
      if (accept(degree)) break;
    }
    const int node = add(Op::Constant, at);
    nodes_.back().instruction.value = value;
    return node;
  }

  int parse_name() {
    const std::size_t at = pos_;
    std::size_t end = pos_;
    while (end < text_.size()) {
      const auto ch = static_cast<unsigned char>(text_[end]);
      if (std::isalnum(ch) != 0 || ch == '_') {
        ++end;
      } else if (ch >= 0x80U) {
        pos_ = end;
        if (is_operator_code_point()) break;
        end += code_point_length(text_.substr(end));
      } else {
        break;
      }
    }
    pos_ = end;
    const std::string name(text_.substr(at, end - at));
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == '(') return parse_call(name, at);
    for (std::size_t i = 0; i < scope_.parameters.size(); ++i) {
      if (scope_.parameters[i] == name) {
        const int node = add(Op::Parameter, at);
        nodes_.back().instruction.slot = static_cast<std::uint32_t>(i);
        return node;
      }
    }
    if (scope_.constants != nullptr) {
      if (const auto it = scope_.constants->find(name);
          it != scope_.constants->end()) {
        const int node = add(Op::Constant, at);
        nodes_.back().instruction.value = it->second;
        if (scope_.used_constants != nullptr)
          scope_.used_constants->insert(name);
        return node;
      }
    }
    fail(at, "undefined name '" + name + "'");
  }

  int parse_call(const std::string& name, std::size_t at) {
    const Function* function = nullptr;
    for (const Function& f : kFunctions) {
      if (f.name == name) function = &f;
    }
    if (function == nullptr) fail(at, "'" + name + "' is not a function");
    accept("(");
    std::vector<int> args;
    skip_space();
    if (!accept(")")) {
      for (;;) {
        args.push_back(parse_or());
        if (accept(")")) break;
        if (!accept(",")) fail(pos_, "expected ',' or ')'");
      }
    }
    if (static_cast<int>(args.size()) != function->arity) {
      fail(at, "'" + name + "' takes " + std::to_string(function->arity) +
                   (function->arity == 1 ? " argument, " : " arguments, ") +
                   std::to_string(args.size()) + " given");
    }
    if (scope_.radians) return call_in_radians(function->op, at, args);
    return fold(add(function->op, at, args[0], args.size() > 1 ? args[1] : -1));
  }

  // The code runs in degrees; radians are converted on the way in (sin,
  // cos, tan) or out (the inverses).
  int call_in_radians(Op op, std::size_t at, std::vector<int>& args) {
    const auto constant = [&](double value) {
      const int node = add(Op::Constant, at);
      nodes_.back().instruction.value = value;
      return node;
    };
    const double degrees_per_radian = 180.0 / 3.14159265358979323846;
    if (op == Op::Sin || op == Op::Cos || op == Op::Tan) {
      args[0] = binary(Op::Multiply, at, args[0], constant(degrees_per_radian));
      return fold(add(op, at, args[0]));
    }
    const int result =
        fold(add(op, at, args[0], args.size() > 1 ? args[1] : -1));
    if (op == Op::Asin || op == Op::Acos || op == Op::Atan || op == Op::Atan2) {
      return binary(Op::Multiply, at, result,
                    constant(1.0 / degrees_per_radian));
    }
    return result;
  }

  // Appends the postfix code of a subtree; returns its stack depth.
  int emit(int index, std::vector<Instruction>& code) const {
    const Node& node = nodes_[static_cast<std::size_t>(index)];
    int depth = 1;
    if (node.a >= 0) depth = emit(node.a, code);
    if (node.b >= 0) depth = std::max(depth, 1 + emit(node.b, code));
    code.push_back(node.instruction);
    return depth;
  }

  const SourceFile& source_;
  std::string_view text_;
  std::size_t pos_;
  const ExpressionScope& scope_;
  std::vector<Node> nodes_;
  int nesting_ = 0;
};

}  // namespace

Expression Expression::constant(double value) {
  Expression e;
  e.code_.front().value = value;
  return e;
}

double Expression::evaluate(std::span<const double> parameters) const {
  if (code_.size() == 1) {
    const Instruction& only = code_.front();
    return only.op == Op::Constant ? only.value : parameters[only.slot];
  }
  std::array<double, kMaxStack> stack{};
  int top = -1;
  for (const Instruction& in : code_) {
    switch (in.op) {
      case Op::Constant:
        stack[static_cast<std::size_t>(++top)] = in.value;
        break;
      case Op::Parameter:
        stack[static_cast<std::size_t>(++top)] = parameters[in.slot];
        break;
      default: {
        const int n = arity(in.op);
        const double b = n == 2 ? stack[static_cast<std::size_t>(top--)] : 0.0;
        double& a = stack[static_cast<std::size_t>(top)];
        bool divide_by_zero = false;
        a = apply(in.op, a, b, divide_by_zero);
        if (divide_by_zero) {
          throw error_at(*source_, in.offset, "division by zero");
        }
      }
    }
  }
  const double value = stack[0];
  if (!std::isfinite(value)) {
    throw error_at(*source_, offset_,
                   "the value of this expression is not a finite number");
  }
  return value;
}

Expression parse_expression(std::shared_ptr<const SourceFile> source,
                            std::size_t begin, std::size_t end,
                            const ExpressionScope& scope) {
  Compiler compiler(*source, begin, end, scope);
  Expression e;
  e.code_ = compiler.compile(e.stack_depth_);
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

}  // namespace lsys
