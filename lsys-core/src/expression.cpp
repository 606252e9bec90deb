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
#include "lsys/module_string.hpp"

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

int arity(Op op) {
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
bool is_random(Op op) {
  return op == Op::Ran || op == Op::Nran || op == Op::Bran || op == Op::Biran ||
         op == Op::Srand;
}

// erand48: X ← (0x5DEECE66D·X + 0xB) mod 2^48, the value X / 2^48.
double erand48(std::uint64_t& state) {
  constexpr std::uint64_t kMask = (std::uint64_t{1} << 48U) - 1;
  state = (0x5DEECE66DULL * state + 0xBULL) & kMask;
  return static_cast<double>(state) * 0x1.0p-48;
}

// The polar method (Marsaglia), as cpfg's nran draws a normal deviate.
double normal(std::uint64_t& state, double mean, double deviation) {
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
double beta(std::uint64_t& state, double a, double b) {
  if (a <= 0.0 || b <= 0.0) return 0.0;
  for (int tries = 0; tries < 1000000; ++tries) {
    const double x = std::pow(erand48(state), 1.0 / a);
    const double y = std::pow(erand48(state), 1.0 / b);
    if (x + y <= 1.0 && x + y > 0.0) return x / (x + y);
  }
  return a / (a + b);
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

struct Node {
  Instruction instruction;
  int a = -1;
  int b = -1;
  int c = -1;  // Select's third operand
};

// A logical line of Python: its first and last bytes of code (comments
// and trailing blanks left out), and its indentation in columns.
struct PythonLine {
  std::size_t begin;
  std::size_t end;
  int indent;
};

bool is_word_byte(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

// True when bytes from `at` hold the word `word` whole.
bool starts_word(std::string_view text, std::size_t at, std::size_t end,
                 std::string_view word) {
  return text.substr(at, end - at).starts_with(word) &&
         (at + word.size() >= end || !is_word_byte(text[at + word.size()]));
}

// Python's lines in bytes [begin, end) of `text`: a line goes on while a
// bracket is open or it ends with `\`; `#` outside strings starts a
// comment; a tab indents to the next multiple of 8 (Python's tokenizer).
// The first line may start inside a line (after a rule's colon).
std::vector<PythonLine> python_lines(std::string_view text, std::size_t begin,
                                     std::size_t end) {
  std::vector<PythonLine> lines;
  std::size_t i = begin;
  while (i < end) {
    std::size_t line_start = i;
    while (line_start > 0 && text[line_start - 1] != '\n') --line_start;
    int column = 0;
    std::size_t first = line_start;
    for (; first < end && (text[first] == ' ' || text[first] == '\t' ||
                           text[first] == '\r' || first < i);
         ++first) {
      column = text[first] == '\t' ? (column / 8 + 1) * 8 : column + 1;
    }
    int depth = 0;
    char quote = 0;
    std::size_t code_end = first;
    std::size_t j = first;
    // L-Py reads `produce …` and `nproduce …` to the end of the line as
    // L-system modules, where `[` and `]` are branches, not Python's
    // brackets (`nproduce [ +(60)` opens a branch a later line closes).
    bool statement_start = true;
    bool successor = false;
    for (; j < end; ++j) {
      const char c = text[j];
      if (statement_start && c != ' ' && c != '\t') {
        statement_start = false;
        successor = depth == 0 && (starts_word(text, j, end, "produce") ||
                                   starts_word(text, j, end, "nproduce"));
      }
      if (quote != 0) {
        if (c == '\\') {
          ++j;
        } else if (c == quote) {
          quote = 0;
        }
        code_end = j + 1;
        continue;
      }
      if (c == '#') {
        while (j < end && text[j] != '\n') ++j;
        if (depth > 0) continue;
        break;
      }
      if (c == '\n') {
        if (depth > 0) continue;
        std::size_t k = code_end;
        if (k > first && text[k - 1] == '\\') continue;
        break;
      }
      if (c == '\'' || c == '"') quote = c;
      if (!successor) {
        if (c == '(' || c == '[' || c == '{') ++depth;
        if ((c == ')' || c == ']' || c == '}') && depth > 0) --depth;
        if (c == ':' && depth == 0) statement_start = true;
      }
      if (c != ' ' && c != '\t' && c != '\r') code_end = j + 1;
    }
    if (code_end > first) lines.push_back(PythonLine{first, code_end, column});
    i = j + 1;
  }
  return lines;
}

// The first `:` of bytes [from, end) outside brackets and strings.
std::size_t python_colon(std::string_view text, std::size_t from,
                         std::size_t end) {
  int depth = 0;
  char quote = 0;
  for (std::size_t j = from; j < end; ++j) {
    const char c = text[j];
    if (quote != 0) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '(' || c == '[' || c == '{') {
      ++depth;
    } else if (c == ')' || c == ']' || c == '}') {
      --depth;
    } else if (c == ':' && depth == 0) {
      return j;
    }
  }
  return std::string_view::npos;
}

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
    const int root = parse_conditional();
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

  // mathjs's operator words (`a and not b`), as whole words only, so that
  // a parameter named `order` is not `or` and `der`.
  bool accept_word(std::string_view word) {
    if (!scope_.mathjs && !scope_.python) return false;
    skip_space();
    if (!text_.substr(pos_).starts_with(word)) return false;
    const std::size_t end = pos_ + word.size();
    if (end < text_.size() &&
        (std::isalnum(static_cast<unsigned char>(text_[end])) != 0 ||
         text_[end] == '_')) {
      return false;
    }
    pos_ = end;
    return true;
  }

  int add(Op op, std::size_t offset, int a = -1, int b = -1) {
    if (nodes_.size() >= kMaxNodes) fail(offset, "expression is too long");
    nodes_.push_back(Node{Instruction{.op = op, .offset = offset}, a, b});
    return static_cast<int>(nodes_.size()) - 1;
  }

  // Folds a node whose operands are constants into a constant.
  int fold(int index) {
    Node& node = nodes_[static_cast<std::size_t>(index)];
    if (is_random(node.instruction.op) ||
        node.instruction.op == Op::Iteration ||
        node.instruction.op == Op::CheckIndex ||
        node.instruction.op == Op::GlobalAt) {
      return index;
    }
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

  // cpfg's `c ? a : b`, right-associative, below `||`.
  int parse_conditional() {
    const int condition = parse_or();
    if (scope_.python) {
      // Python's `yes if condition else no`.
      skip_space();
      const std::size_t at = pos_;
      if (!accept_word("if")) return condition;
      const int test = parse_or();
      if (!accept_word("else")) fail(pos_, "expected 'else' after 'if'");
      const int no = parse_conditional();
      const int node = add(Op::Select, at, test, condition);
      nodes_.back().c = no;
      return node;
    }
    if (!scope_.cpfg) return condition;
    skip_space();
    const std::size_t at = pos_;
    if (!accept("?")) return condition;
    const int yes = parse_conditional();
    if (!accept(":")) fail(pos_, "expected ':' after '?' and a value");
    const int no = parse_conditional();
    const Instruction test =
        nodes_[static_cast<std::size_t>(condition)].instruction;
    if (test.op == Op::Constant) return test.value != 0.0 ? yes : no;
    const int node = add(Op::Select, at, condition, yes);
    nodes_.back().c = no;
    return node;
  }

  int parse_or() {
    int left = parse_and();
    for (;;) {
      const std::size_t at = (skip_space(), pos_);
      if (!accept("||") && !accept_word("or")) return left;
      left = binary(Op::Or, at, left, parse_and());
    }
  }

  int parse_and() {
    int left = parse_not();
    for (;;) {
      const std::size_t at = (skip_space(), pos_);
      if (!accept("&&") && !accept_word("and")) return left;
      left = binary(Op::And, at, left, parse_not());
    }
  }

  // Python's `not` binds more loosely than a comparison: `not a == b` is
  // `not (a == b)`.
  int parse_not() {
    if (!scope_.python) return parse_comparison();
    skip_space();
    const std::size_t at = pos_;
    if (accept_word("not")) return fold(add(Op::Not, at, parse_not()));
    return parse_comparison();
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
    // Python chains comparisons: `0 < x < 3` is `0 < x and x < 3`.
    int chain = -1;
    int previous = left;
    for (;;) {
      skip_space();
      const std::size_t at = pos_;
      bool matched = false;
      for (const auto& [token, op] : kOps) {
        if (scope_.python && token == "=") continue;
        if (accept(token)) {
          const int right = parse_sum();
          if (scope_.python) {
            const int test = binary(op, at, previous, right);
            chain = chain < 0 ? test : binary(Op::And, at, chain, test);
            previous = right;
          } else {
            left = binary(op, at, left, right);
          }
          matched = true;
          break;
        }
      }
      if (!matched) return chain < 0 ? left : chain;
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
      } else if (scope_.python && accept("//")) {
        left = fold(
            add(Op::Floor, at, binary(Op::Divide, at, left, parse_unary())));
      } else if (accept("/")) {
        left = binary(Op::Divide, at, left, parse_unary());
      } else if (scope_.python && accept("%")) {
        // Python's remainder takes the divisor's sign: a − b·⌊a/b⌋.
        const int b = parse_unary();
        const int quotient =
            fold(add(Op::Floor, at, binary(Op::Divide, at, left, b)));
        left = binary(Op::Subtract, at, left,
                      binary(Op::Multiply, at, b, quotient));
      } else if ((scope_.cpfg && accept("%")) ||
                 (scope_.mathjs && accept_word("mod"))) {
        left = binary(Op::Modulo, at, left, parse_unary());
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
    if (!scope_.python && accept_word("not")) {
      return fold(add(Op::Not, at, parse_unary()));
    }
    return parse_power();
  }

  int parse_power() {
    const int base = parse_primary();
    skip_space();
    const std::size_t at = pos_;
    // `**` is Python's spelling, as L-Py files write it; Python's `^` is
    // an exclusive or.
    if (scope_.python && text_.substr(pos_).starts_with("^")) {
      fail(at,
           "Python's '^' (a bitwise exclusive or) is not supported; "
           "'**' is the power");
    }
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
      if (scope_.c_language) {
        // C's casts: `(int)x` truncates, `(float)x` and its kin are x.
        skip_space();
        const std::string type(peek_word());
        for (std::string_view t : {"int", "long", "float", "double"}) {
          if (type != t) continue;
          const std::size_t saved = pos_;
          pos_ += type.size();
          skip_space();
          if (!accept(")")) {
            pos_ = saved;
            break;
          }
          const int operand = parse_unary();
          return type == "int" || type == "long"
                     ? fold(add(Op::Int, at, operand))
                     : operand;
        }
      }
      const int inner = parse_conditional();
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
    std::string_view token = text_.substr(at, end - at);
    if (scope_.c_language && token.size() > 1 &&
        (token.back() == 'f' || token.back() == 'F') &&
        token.find_first_of("xX") == std::string_view::npos) {
      token.remove_suffix(1);  // C's float literal, `1.f`, `0.5f`
    }
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
    if (scope_.python && pos_ + 1 < text_.size() && text_[pos_] == '.' &&
        (name == "math" || name == "random" ||
         (scope_.python_modules != nullptr &&
          std::find(scope_.python_modules->begin(),
                    scope_.python_modules->end(),
                    name) != scope_.python_modules->end()))) {
      ++pos_;  // math.sqrt(x) is sqrt(x)
      return parse_name();
    }
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == '(') return parse_call(name, at);
    if (const ArrayVariable* array = array_named(name)) {
      const int index = parse_subscripts(*array, at);
      const int node = add(Op::GlobalAt, at, index);
      nodes_.back().instruction.slot = array->first;
      nodes_.back().instruction.value = element_count(*array);
      return node;
    }
    if (!frames_.empty()) {
      // Inside a Python function: its parameters, then what is global; not
      // the calling rule's parameters and locals.
      for (const auto& [parameter, node] : frames_.back()) {
        if (parameter == name) return node;
      }
      return parse_global_name(name, at);
    }
    for (std::size_t i = 0; i < scope_.parameters.size(); ++i) {
      if (scope_.parameters[i] == name) {
        const int node = add(Op::Parameter, at);
        nodes_.back().instruction.slot = static_cast<std::uint32_t>(i);
        return node;
      }
    }
    if (const auto slot = local_slot(name)) {
      const int node = add(Op::Parameter, at);
      nodes_.back().instruction.slot = *slot;
      return node;
    }
    return parse_global_name(name, at);
  }

  // A global variable or a constant.
  int parse_global_name(const std::string& name, std::size_t at) {
    if (const auto slot = global_slot(name)) {
      const int node = add(Op::Global, at);
      nodes_.back().instruction.slot = *slot;
      return node;
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
    if (scope_.undefined != nullptr) {
      // cpfg adds the name with the value 0; read before anything assigns
      // it, it is 0 (an assignment then makes it a variable, store_for).
      scope_.undefined->emplace_back(name, at);
      return add(Op::Constant, at);
    }
    refuse_imported(name, at);
    fail(at, "undefined name '" + name + "'");
  }

  // cpfg's func(id, x): id names a function of the view file, from 1.
  int parse_func(std::size_t at) {
    accept("(");
    const int id = parse_conditional();
    if (!accept(",")) fail(pos_, "expected ',' after the function's number");
    const int x = parse_conditional();
    if (!accept(")")) fail(pos_, "expected ')'");
    const Instruction number = nodes_[static_cast<std::size_t>(id)].instruction;
    if (number.op != Op::Constant) {
      fail(number.offset, "func's first argument must be a constant");
    }
    const std::size_t count =
        scope_.functions == nullptr ? 0 : scope_.functions->size();
    const double k = number.value;
    if (k < 1.0 || k > static_cast<double>(count) || k != std::floor(k)) {
      std::array<char, 32> text{};
      const auto written =
          std::to_chars(text.data(), text.data() + text.size(), k);
      fail(number.offset, "func(" + std::string(text.data(), written.ptr) +
                              ", ...): the view file names " +
                              std::to_string(count) +
                              (count == 1 ? " function" : " functions"));
    }
    const int node = add(Op::Func, at, x);
    nodes_.back().instruction.slot = static_cast<std::uint32_t>(k) - 1;
    return node;
  }

  // mathjs's random(), random(max), random(min, max): uniform numbers from
  // the generator of cpfg's ran, so that a file gives the same model on
  // every run (mathjs's own are never the same twice).
  // A call's arguments, from its `(` to its `)`.
  std::vector<int> parse_arguments() {
    accept("(");
    std::vector<int> args;
    if (!accept(")")) {
      for (;;) {
        args.push_back(parse_conditional());
        if (accept(")")) break;
        if (!accept(",")) fail(pos_, "expected ',' or ')'");
      }
    }
    return args;
  }

  int parse_random(std::size_t at) {
    std::vector<int> args = parse_arguments();
    if (args.size() > 2) {
      fail(at, "'random' takes at most 2 arguments, " +
                   std::to_string(args.size()) + " given");
    }
    if (args.empty()) {
      args.push_back(add(Op::Constant, at));
      nodes_.back().instruction.value = 1.0;
    }
    if (args.size() == 1) return add(Op::Ran, at, args[0]);
    const int span = binary(Op::Subtract, at, args[1], args[0]);
    return binary(Op::Add, at, args[0], add(Op::Ran, at, span));
  }

  int parse_call(const std::string& name, std::size_t at) {
    if (scope_.cpfg && name == "func") return parse_func(at);
    if (scope_.python && name == "getIterationNb") {
      if (!parse_arguments().empty()) {
        fail(at, "'getIterationNb' takes no arguments");
      }
      return add(Op::Iteration, at);
    }
    if ((scope_.mathjs && name == "random") ||
        (scope_.python && (name == "random" || name == "uniform"))) {
      return parse_random(at);
    }
    if (scope_.python && name == "choice") {
      // Python's choice([a, b, …]) of a list written in place: one of them,
      // each as likely, by one draw.
      skip_space();
      if (!accept("(")) fail(pos_, "expected '('");
      skip_space();
      if (!accept("["))
        fail(pos_,
             "lsolid reads 'choice' of a list written in place, as choice([-1, "
             "1])");
      std::vector<int> options;
      for (;;) {
        options.push_back(parse_conditional());
        skip_space();
        if (accept(",")) continue;
        if (!accept("]")) fail(pos_, "expected ']'");
        break;
      }
      skip_space();
      if (!accept(")")) fail(pos_, "expected ')'");
      const int count = add(Op::Constant, at);
      nodes_.back().instruction.value = static_cast<double>(options.size());
      const int k = add(Op::Floor, at, add(Op::Ran, at, count));
      int node = options.back();
      for (std::size_t i = options.size() - 1; i-- > 0;) {
        const int bound = add(Op::Constant, at);
        nodes_.back().instruction.value = static_cast<double>(i + 1);
        const int choice =
            add(Op::Select, at, add(Op::Less, at, k, bound), options[i]);
        nodes_.back().c = node;
        node = choice;
      }
      return node;
    }
    if (scope_.python && name == "randrange") {
      // Python's randrange(b) and randrange(a, b): a whole number from a
      // (0) up to b, b left out.
      std::vector<int> args = parse_arguments();
      if (args.empty() || args.size() > 2) {
        fail(at, "lsolid reads 'randrange' of 1 or 2 arguments");
      }
      if (args.size() == 1) {
        const int zero = add(Op::Constant, at);
        args.insert(args.begin(), zero);
      }
      const int span = binary(Op::Subtract, at, args[1], args[0]);
      return binary(Op::Add, at, args[0],
                    add(Op::Floor, at, add(Op::Ran, at, span)));
    }
    if (scope_.python && name == "randint") {
      // Python's randint(a, b): a whole number from a to b, both included.
      std::vector<int> args = parse_arguments();
      if (args.size() != 2) fail(at, "'randint' takes 2 arguments");
      const int one = add(Op::Constant, at);
      nodes_.back().instruction.value = 1.0;
      const int span =
          binary(Op::Add, at, binary(Op::Subtract, at, args[1], args[0]), one);
      return fold(add(Op::Floor, at,
                      binary(Op::Add, at, args[0], add(Op::Ran, at, span))));
    }
    if (scope_.python_functions != nullptr) {
      if (const auto it = scope_.python_functions->find(name);
          it != scope_.python_functions->end()) {
        return inline_python_function(name, it->second, at);
      }
    }
    if (scope_.python && name == "float") {
      // Python's float(x): x, in a language of doubles.
      const std::vector<int> args = parse_arguments();
      if (args.size() != 1) fail(at, "'float' takes 1 argument here");
      return args.front();
    }
    const auto available = [&](const Function& f) {
      if (f.cpfg_only) return scope_.cpfg;
      if (f.python_only) return scope_.python;
      if (f.mathjs_only) {
        return scope_.mathjs ||
               ((scope_.python || scope_.c_language) && f.name == "pow");
      }
      return true;
    };
    const Function* function = nullptr;
    for (const Function& f : kFunctions) {
      if (f.name == name && available(f)) {
        function = &f;
        break;
      }
    }
    if (function == nullptr) {
      refuse_imported(name, at);
      fail(at, "'" + name + "' is not a function");
    }
    std::vector<int> args = parse_arguments();
    if (static_cast<int>(args.size()) != function->arity) {
      fail(at, "'" + name + "' takes " + std::to_string(function->arity) +
                   (function->arity == 1 ? " argument, " : " arguments, ") +
                   std::to_string(args.size()) + " given");
    }
    if (scope_.radians) return call_in_radians(function->op, at, args);
    return fold(add(function->op, at, args[0], args.size() > 1 ? args[1] : -1));
  }

  // A call of an L-Py function of one `return`: its expression compiled
  // here, each parameter standing for its argument's tree.
  int inline_python_function(const std::string& name, const PythonFunction& f,
                             std::size_t at) {
    std::vector<int> args = parse_arguments();
    if (args.size() != f.parameters.size()) {
      fail(at, "'" + name + "' takes " + std::to_string(f.parameters.size()) +
                   " arguments, " + std::to_string(args.size()) + " given");
    }
    std::vector<std::pair<std::string, int>> frame;
    for (std::size_t i = 0; i < args.size(); ++i) {
      frame.emplace_back(f.parameters[i], args[i]);
    }
    const Nesting guard(*this);
    const std::string_view saved_text = text_;
    const std::size_t saved_pos = pos_;
    frames_.push_back(std::move(frame));
    const auto compile = [&](std::size_t begin, std::size_t end) {
      text_ = std::string_view(source_.text()).substr(0, end);
      pos_ = begin;
      const int compiled = parse_conditional();
      skip_space();
      if (pos_ < text_.size()) {
        fail(pos_, "unexpected '" + std::string(peek_code_point()) +
                       "' in expression");
      }
      return compiled;
    };
    int node = compile(f.begin, f.end);
    for (auto b = f.branches.rbegin(); b != f.branches.rend(); ++b) {
      const int test = compile(b->condition_begin, b->condition_end);
      const int yes = compile(b->value_begin, b->value_end);
      const int choice = add(Op::Select, b->condition_begin, test, yes);
      nodes_.back().c = node;
      node = choice;
    }
    frames_.pop_back();
    text_ = saved_text;
    pos_ = saved_pos;
    return node;
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
    if (node.instruction.op == Op::Select) {
      int depth = emit(node.a, code);
      const std::size_t to_else = code.size();
      code.push_back(Instruction{.op = Op::JumpIfZero});
      depth = std::max(depth, emit(node.b, code));
      const std::size_t to_end = code.size();
      code.push_back(Instruction{.op = Op::Jump});
      code[to_else].slot = static_cast<std::uint32_t>(code.size());
      depth = std::max(depth, emit(node.c, code));
      code[to_end].slot = static_cast<std::uint32_t>(code.size());
      return depth;
    }
    int depth = 1;
    if (node.a >= 0) depth = emit(node.a, code);
    if (node.b >= 0) depth = std::max(depth, 1 + emit(node.b, code));
    code.push_back(node.instruction);
    return depth;
  }

  static double element_count(const ArrayVariable& array) {
    double n = 1.0;
    for (const std::uint32_t d : array.dimensions) n *= d;
    return n;
  }

  // A name of a Python module that lsolid does not run, refused by name.
  void refuse_imported(const std::string& name, std::size_t at) const {
    if (scope_.python_imports == nullptr) return;
    const auto it = scope_.python_imports->find(name);
    if (it == scope_.python_imports->end()) return;
    std::string what = "'";
    what += name;
    what += "' comes from Python's module ";
    what += it->second;
    what +=
        ", which lsolid does not run; it reads math and random "
        "(docs/dialects/lpy.md)";
    fail(at, what);
  }

  const ArrayVariable* array_named(std::string_view name) const {
    if (scope_.arrays == nullptr) return nullptr;
    for (const ArrayVariable& a : *scope_.arrays) {
      if (a.name == name) return &a;
    }
    return nullptr;
  }

  // `[i][j]…` after an array's name at pos_: the offset of the element,
  // as cpfg's generate.c computes it, each subscript checked against its
  // dimension (cpfg clamps one out of range, with a warning; lsolid stops).
  int parse_subscripts(const ArrayVariable& array, std::size_t at) {
    int index = -1;
    for (const std::uint32_t dimension : array.dimensions) {
      skip_space();
      if (!accept("[")) {
        fail(pos_,
             "'" + array.name + "' is an array of " +
                 std::to_string(array.dimensions.size()) +
                 (array.dimensions.size() == 1 ? " dimension" : " dimensions") +
                 ": expected '['");
      }
      const std::size_t subscript_at = pos_;
      const int subscript = parse_conditional();
      if (!accept("]")) fail(pos_, "expected ']'");
      const int checked = add(Op::CheckIndex, subscript_at, subscript);
      nodes_.back().instruction.value = dimension;
      nodes_.back().instruction.slot = array.python ? 1 : 0;
      if (index < 0) {
        index = checked;
        continue;
      }
      const int size = add(Op::Constant, at);
      nodes_.back().instruction.value = dimension;
      index = add(Op::Add, at, add(Op::Multiply, at, index, size), checked);
    }
    return index;
  }

  std::optional<std::uint32_t> local_slot(const std::string& name) const {
    if (scope_.locals == nullptr) return std::nullopt;
    const auto& locals = *scope_.locals;
    for (std::size_t i = 0; i < locals.size(); ++i) {
      if (locals[i] == name) {
        return static_cast<std::uint32_t>(scope_.parameters.size() + i);
      }
    }
    return std::nullopt;
  }

  std::optional<std::uint32_t> global_slot(const std::string& name) const {
    if (scope_.globals == nullptr) return std::nullopt;
    const auto& globals = *scope_.globals;
    for (std::size_t i = 0; i < globals.size(); ++i) {
      if (globals[i] == name) return static_cast<std::uint32_t>(i);
    }
    return std::nullopt;
  }

 public:
  // cpfg's statements (CPFG Reference Manual §3.2): straight into code,
  // each expression through the tree and its folding.
  std::vector<Instruction> compile_statements(int& stack_depth) {
    std::vector<Instruction> code;
    const std::size_t at = pos_;
    if (scope_.read_successor && scope_.locals != nullptr) {
      // An lpfg body: it applies when a `produce` ran (which ends it).
      code.push_back(Instruction{.op = Op::Constant, .offset = at});
      produced_store_ = store_for(std::string(kProducedLocal), at);
      code.push_back(produced_store_);
      code.push_back(Instruction{.op = Op::EmitClear, .offset = at});
    }
    skip_space();
    if (accept("{")) {
      statement_list(code, true);
      skip_space();
      if (pos_ < text_.size()) {
        fail(pos_, "unexpected '" + std::string(peek_code_point()) +
                       "' after the statements");
      }
    } else {
      statement_list(code, false);
    }
    for (const std::size_t r : returns_) land(code, r);
    stack_depth = std::max(1, depth_);
    if (stack_depth > kMaxStack) fail(pos_, "statements are nested too deeply");
    return code;
  }

  // The Python body of an L-Py rule (parse_python_statements): the
  // local kProducedLocal starts at 0 and each `produce` sets it to its
  // number; what follows a `produce` in its block, or a block that may
  // have produced, is skipped when one has.
  std::vector<Instruction> compile_python(int& stack_depth) {
    const std::string_view whole = text_;
    lines_ = python_lines(whole, pos_, whole.size());
    std::vector<Instruction> code;
    const std::size_t at = pos_;
    // A rule's body has locals; L-Py's hooks (`def Start():`) have none
    // and produce nothing.
    if (scope_.locals != nullptr) {
      code.push_back(Instruction{.op = Op::Constant, .offset = at});
      produced_store_ = store_for(std::string(kProducedLocal), at);
      code.push_back(produced_store_);
    }
    const bool builds = static_cast<bool>(scope_.read_successor);
    if (builds) code.push_back(Instruction{.op = Op::EmitClear, .offset = at});
    depth_ = 1;
    std::size_t li = 0;
    if (!lines_.empty()) python_block(code, li, lines_.front().indent, whole);
    if (li < lines_.size()) fail(lines_[li].begin, "unexpected indentation");
    text_ = whole;
    if (builds && scope_.locals != nullptr) {
      // L-Py's LsysRule::__postcall_function: a body that ends without
      // `produce` applies when it has `nproduce`d something.
      code.push_back(Instruction{
          .op = Op::Parameter, .slot = produced_store_.slot, .offset = at});
      code.push_back(Instruction{.op = Op::Emitted, .offset = at});
      code.push_back(Instruction{.op = Op::Or, .offset = at});
      code.push_back(produced_store_);
      depth_ = std::max(depth_, 2);
    }
    stack_depth = std::max(1, depth_);
    if (stack_depth > kMaxStack) fail(at, "statements are nested too deeply");
    return code;
  }

 private:
  bool python_block(std::vector<Instruction>& code, std::size_t& li, int indent,
                    std::string_view whole) {
    const Nesting guard(*this);
    std::vector<std::size_t> skips;
    bool produced = false;
    while (li < lines_.size() && lines_[li].indent >= indent) {
      if (lines_[li].indent > indent) {
        fail(lines_[li].begin, "unexpected indentation");
      }
      if (produced) {
        code.push_back(Instruction{.op = Op::Parameter,
                                   .slot = produced_store_.slot,
                                   .offset = lines_[li].begin});
        code.push_back(Instruction{.op = Op::Not, .offset = lines_[li].begin});
        skips.push_back(jump(code, Op::JumpIfZero));
      }
      produced = python_statement(code, li, indent, whole) || produced;
    }
    for (const std::size_t skip : skips) land(code, skip);
    return produced;
  }

  // One statement, compound or simple, from line li on; returns whether it
  // may have produced.
  bool python_statement(std::vector<Instruction>& code, std::size_t& li,
                        int indent, std::string_view whole) {
    const PythonLine& line = lines_[li];
    text_ = whole.substr(0, line.end);
    pos_ = line.begin;
    if (starts_word(whole, pos_, line.end, "if")) {
      pos_ += 2;
      return python_if(code, li, indent, whole);
    }
    if (starts_word(whole, pos_, line.end, "for")) {
      pos_ += 3;
      return python_for(code, li, indent, whole);
    }
    if (starts_word(whole, pos_, line.end, "while")) {
      pos_ += 5;
      return python_while(code, li, indent, whole);
    }
    for (const std::string_view word : {"elif", "else"}) {
      if (starts_word(whole, pos_, line.end, word)) {
        fail(pos_, "'" + std::string(word) + "' without 'if'");
      }
    }
    ++li;
    const bool produced = python_simple(code);
    text_ = whole;
    return produced;
  }

  // The `:` that ends the header of a compound statement from pos_.
  std::size_t header_colon(std::string_view whole, const PythonLine& line) {
    const std::size_t colon = python_colon(whole, pos_, line.end);
    if (colon == std::string_view::npos) fail(line.end, "expected ':'");
    return colon;
  }

  // `if` (or `elif`) at pos_ of line li: the condition, its suite, and
  // the `elif` or `else` that follows at the same indentation.
  bool python_if(std::vector<Instruction>& code, std::size_t& li, int indent,
                 std::string_view whole) {
    const PythonLine line = lines_[li];
    const std::size_t colon = header_colon(whole, line);
    text_ = whole.substr(0, colon);
    expression_into(code);
    skip_space();
    if (pos_ < colon) fail(pos_, "expected ':'");
    const std::size_t to_else = jump(code, Op::JumpIfZero);
    bool produced = python_suite(code, li, indent, colon + 1, whole);
    if (li < lines_.size() && lines_[li].indent == indent) {
      const PythonLine& next = lines_[li];
      const bool is_elif = starts_word(whole, next.begin, next.end, "elif");
      if (is_elif || starts_word(whole, next.begin, next.end, "else")) {
        const std::size_t to_end = jump(code, Op::Jump);
        land(code, to_else);
        text_ = whole.substr(0, next.end);
        if (is_elif) {
          pos_ = next.begin + 4;
          produced = python_if(code, li, indent, whole) || produced;
        } else {
          pos_ = next.begin + 4;
          if (!accept(":")) fail(pos_, "expected ':' after 'else'");
          produced = python_suite(code, li, indent, pos_, whole) || produced;
        }
        land(code, to_end);
        text_ = whole;
        return produced;
      }
    }
    land(code, to_else);
    text_ = whole;
    return produced;
  }

  // A loop's bookkeeping: the jumps its `break`s and `continue`s wait to
  // have landed.
  struct Loop {
    std::vector<std::size_t> breaks;
    std::vector<std::size_t> continues;
  };

  // Stops a loop once its body has produced: `produce` ends the body.
  void leave_loop_if_produced(std::vector<Instruction>& code,
                              std::vector<std::size_t>& exits) {
    if (scope_.locals == nullptr) return;
    code.push_back(Instruction{
        .op = Op::Parameter, .slot = produced_store_.slot, .offset = pos_});
    code.push_back(Instruction{.op = Op::Not, .offset = pos_});
    exits.push_back(jump(code, Op::JumpIfZero));
  }

  // A slot for what the source cannot name: a loop's counter and bounds.
  Instruction hidden_store(std::size_t at) {
    std::string name = "#";
    name += std::to_string(++hidden_);
    if (scope_.locals != nullptr) return new_local(name, at);
    return new_global(name, at);
  }

  static Instruction load_of(const Instruction& store) {
    return Instruction{
        .op = store.op == Op::StoreGlobal ? Op::Global : Op::Parameter,
        .slot = store.slot,
        .offset = store.offset};
  }

  // `for name in range(…):` at pos_ of line li. Python evaluates range's
  // arguments once and assigns the name at the start of each pass, so the
  // body may change the name without changing the count.
  bool python_for(std::vector<Instruction>& code, std::size_t& li, int indent,
                  std::string_view whole) {
    const PythonLine line = lines_[li];
    const std::size_t colon = header_colon(whole, line);
    text_ = whole.substr(0, colon);
    skip_space();
    const std::size_t name_at = pos_;
    const std::string name(peek_word());
    if (name.empty() || !is_name_start(static_cast<unsigned char>(name[0]))) {
      fail(pos_, "expected a name after 'for'");
    }
    pos_ += name.size();
    skip_space();
    if (peek_word() != "in") {
      fail(pos_, "lsolid runs 'for' loops over range(…) only");
    }
    pos_ += 2;
    skip_space();
    if (peek_word() != "range") {
      fail(pos_, "lsolid runs 'for' loops over range(…) only");
    }
    pos_ += 5;
    skip_space();
    if (!accept("(")) fail(pos_, "expected '(' after 'range'");
    const Instruction counter = hidden_store(name_at);
    const Instruction stop = hidden_store(name_at);
    const Instruction step = hidden_store(name_at);
    const auto constant = [&](double value, const Instruction& store) {
      code.push_back(
          Instruction{.op = Op::Constant, .value = value, .offset = name_at});
      code.push_back(store);
    };
    std::vector<std::size_t> starts;
    int count = 0;
    double step_value = 1.0;
    for (;;) {
      const std::size_t begin = code.size();
      expression_into(code);
      starts.push_back(begin);
      ++count;
      if (count == 1) code.push_back(stop);
      if (count == 2) code.push_back(stop);
      if (count == 3) {
        const bool is_constant =
            code.size() == begin + 1 && code.back().op == Op::Constant;
        if (is_constant && code.back().value == 0.0) {
          fail(code.back().offset, "range's step cannot be 0");
        }
        step_value = is_constant ? code.back().value : 0.0;
        code.push_back(step);
      }
      if (accept(")")) break;
      if (count == 3 || !accept(",")) fail(pos_, "expected ',' or ')'");
      if (count == 1) {
        // range(start, stop): what was read is the start.
        code.back() = counter;
      }
    }
    if (count == 1) constant(0.0, counter);
    if (count < 3) constant(1.0, step);
    skip_space();
    if (pos_ < colon) fail(pos_, "expected ':'");
    depth_ = std::max(depth_, 4);
    Loop loop;
    const auto top = static_cast<std::uint32_t>(code.size());
    leave_loop_if_produced(code, loop.breaks);
    const auto compare = [&](Op op) {
      code.push_back(load_of(counter));
      code.push_back(load_of(stop));
      code.push_back(Instruction{.op = op, .offset = name_at});
    };
    if (step_value > 0.0) {
      compare(Op::Less);
    } else if (step_value < 0.0) {
      compare(Op::Greater);
    } else {
      // A step known only when running: (step > 0 and i < stop) or
      // (step < 0 and i > stop); a step of 0 never enters the loop.
      code.push_back(load_of(step));
      code.push_back(Instruction{.op = Op::Constant, .offset = name_at});
      code.push_back(Instruction{.op = Op::Greater, .offset = name_at});
      compare(Op::Less);
      code.push_back(Instruction{.op = Op::And, .offset = name_at});
      code.push_back(load_of(step));
      code.push_back(Instruction{.op = Op::Constant, .offset = name_at});
      code.push_back(Instruction{.op = Op::Less, .offset = name_at});
      compare(Op::Greater);
      code.push_back(Instruction{.op = Op::And, .offset = name_at});
      code.push_back(Instruction{.op = Op::Or, .offset = name_at});
    }
    loop.breaks.push_back(jump(code, Op::JumpIfZero));
    code.push_back(load_of(counter));
    code.push_back(python_store_for(name, name_at));
    loops_.push_back(std::move(loop));
    const bool produced = python_suite(code, li, indent, colon + 1, whole);
    Loop body = std::move(loops_.back());
    loops_.pop_back();
    for (const std::size_t c : body.continues) land(code, c);
    code.push_back(load_of(counter));
    code.push_back(load_of(step));
    code.push_back(Instruction{.op = Op::Add, .offset = name_at});
    code.push_back(counter);
    code.push_back(Instruction{.op = Op::Jump, .slot = top, .offset = name_at});
    for (const std::size_t b : body.breaks) land(code, b);
    text_ = whole;
    return produced;
  }

  // `while c:` at pos_ of line li.
  bool python_while(std::vector<Instruction>& code, std::size_t& li, int indent,
                    std::string_view whole) {
    const PythonLine line = lines_[li];
    const std::size_t colon = header_colon(whole, line);
    const std::size_t at = pos_;
    Loop loop;
    const auto top = static_cast<std::uint32_t>(code.size());
    leave_loop_if_produced(code, loop.breaks);
    text_ = whole.substr(0, colon);
    expression_into(code);
    skip_space();
    if (pos_ < colon) fail(pos_, "expected ':'");
    loop.breaks.push_back(jump(code, Op::JumpIfZero));
    loops_.push_back(std::move(loop));
    const bool produced = python_suite(code, li, indent, colon + 1, whole);
    Loop body = std::move(loops_.back());
    loops_.pop_back();
    for (const std::size_t c : body.continues) land(code, c);
    code.push_back(Instruction{.op = Op::Jump, .slot = top, .offset = at});
    for (const std::size_t b : body.breaks) land(code, b);
    text_ = whole;
    return produced;
  }

  // `nproduce …` or, in a body that builds its successor, `produce …`:
  // each module's arguments, then Emit.
  void emit_successor(std::vector<Instruction>& code, std::size_t at) {
    skip_space();
    const std::size_t end = text_.size();
    const std::string_view whole = text_;
    for (const SuccessorModuleText& m : scope_.read_successor(pos_, end)) {
      int pushed = 0;
      for (const auto& [begin, arg_end] : m.arguments) {
        text_ = whole.substr(0, arg_end);
        pos_ = begin;
        const int before = depth_;
        depth_ = 0;
        expression_into(code);
        skip_space();
        if (pos_ < arg_end) {
          fail(pos_, "unexpected '" + std::string(peek_code_point()) + "'");
        }
        depth_ = std::max(before, depth_ + pushed);
        ++pushed;
      }
      if (pushed + 1 > kMaxStack) fail(m.offset, "too many parameters");
      code.push_back(Instruction{.op = Op::Emit,
                                 .slot = m.symbol,
                                 .value = static_cast<double>(pushed),
                                 .offset = m.offset});
    }
    text_ = whole;
    pos_ = end;
    (void)at;
  }

  // What follows a compound statement's colon: a simple statement on the
  // same line, or a block of deeper lines.
  bool python_suite(std::vector<Instruction>& code, std::size_t& li, int indent,
                    std::size_t after_colon, std::string_view whole) {
    const PythonLine line = lines_[li++];
    text_ = whole.substr(0, line.end);
    pos_ = after_colon;
    skip_space();
    if (pos_ < line.end) {
      const bool produced = python_simple(code);
      text_ = whole;
      return produced;
    }
    if (li >= lines_.size() || lines_[li].indent <= indent) {
      fail(line.end, "expected an indented block after ':'");
    }
    return python_block(code, li, lines_[li].indent, whole);
  }

  // `pass`, `produce …`, or an assignment, up to the end of text_.
  bool python_simple(std::vector<Instruction>& code) {
    skip_space();
    const std::size_t at = pos_;
    const std::string word(peek_word());
    bool produced = false;
    if (word == "pass") {
      pos_ += word.size();
    } else if (word == "global") {
      pos_ += word.size();
      for (;;) {
        skip_space();
        const std::string name(peek_word());
        if (name.empty()) fail(pos_, "expected a name after 'global'");
        declared_globals_.push_back(name);
        pos_ += name.size();
        if (!accept(",")) break;
      }
    } else if (word == "print" || word == "seed" ||
               (word == "random" &&
                text_.substr(pos_).starts_with("random.seed("))) {
      // Printing, and seeding Python's generator (lsolid draws from its
      // own), change nothing lsolid builds.
      if (word == "random") pos_ += 7;  // `random.`
      skip_call();
    } else if ((word == kProducedLocal || word == "nproduce") &&
               scope_.locals == nullptr) {
      fail(at, "'" + word + "' outside a rule");
    } else if (word == "nproduce") {
      if (!scope_.read_successor) refuse_python(at, word);
      pos_ += word.size();
      emit_successor(code, at);
    } else if (word == kProducedLocal && scope_.read_successor) {
      pos_ += word.size();
      emit_successor(code, at);
      code.push_back(
          Instruction{.op = Op::Constant, .value = 1.0, .offset = at});
      code.push_back(produced_store_);
      return true;
    } else if (word == "break" || word == "continue") {
      if (loops_.empty()) fail(at, "'" + word + "' outside a loop");
      pos_ += word.size();
      auto& jumps =
          word == "break" ? loops_.back().breaks : loops_.back().continues;
      jumps.push_back(jump(code, Op::Jump));
    } else if (word == kProducedLocal) {
      code.push_back(Instruction{.op = Op::Constant,
                                 .value = static_cast<double>(++produces_),
                                 .offset = at});
      code.push_back(produced_store_);
      return true;  // the successor is the rule's, read apart
    } else if (!word.empty() &&
               is_name_start(static_cast<unsigned char>(word.front()))) {
      pos_ += word.size();
      skip_space();
      const std::string_view rest = text_.substr(pos_);
      Op op = Op::Constant;
      for (const auto& [token, o] :
           {std::pair{"+=", Op::Add}, std::pair{"-=", Op::Subtract},
            std::pair{"*=", Op::Multiply}, std::pair{"/=", Op::Divide}}) {
        if (rest.starts_with(token)) op = o;
      }
      if (op == Op::Constant &&
          (!rest.starts_with("=") || rest.starts_with("=="))) {
        refuse_python(at, word);
      }
      pos_ += op == Op::Constant ? 1 : 2;
      if (word == kProducedLocal) fail(at, "'produce' cannot be assigned");
      const Instruction store = python_store_for(word, at);
      if (op != Op::Constant) {
        code.push_back(load_for(word, at));
        ++depth_;
      }
      expression_into(code);
      if (op != Op::Constant) {
        code.push_back(Instruction{.op = op, .offset = at});
        --depth_;
        depth_ = std::max(depth_, 2);
      }
      code.push_back(store);
    } else {
      refuse_python(at, word);
    }
    skip_space();
    accept(";");
    skip_space();
    if (pos_ < text_.size()) {
      fail(pos_, "unexpected '" + std::string(peek_code_point()) +
                     "' after the statement");
    }
    return produced;
  }

  // Python's scoping: in a rule, a name assigned without `global` is
  // local even where a global of that name exists; `global x` makes the
  // assignment reach (or create) the global x. A hook's names are global.
  Instruction python_store_for(const std::string& name, std::size_t at) {
    const bool declared =
        std::find(declared_globals_.begin(), declared_globals_.end(), name) !=
        declared_globals_.end();
    if (declared && scope_.globals != nullptr) {
      if (const auto slot = global_slot(name)) {
        return Instruction{.op = Op::StoreGlobal, .slot = *slot, .offset = at};
      }
      return new_global(name, at);
    }
    const bool parameter =
        std::find(scope_.parameters.begin(), scope_.parameters.end(), name) !=
        scope_.parameters.end();
    if (scope_.locals != nullptr && !parameter && !local_slot(name)) {
      return new_local(name, at);
    }
    return store_for(name, at);
  }

  [[noreturn]] void refuse_python(std::size_t at, const std::string& word) {
    fail(at, (word.empty() ? std::string("this Python statement")
                           : "Python's '" + word + "'") +
                 " is not supported: lsolid runs assignments, "
                 "if/elif/else, for … in range(…), while, break, continue, "
                 "pass, global, print, produce and nproduce "
                 "(docs/dialects/lpy.md)");
  }

  // The instruction that reads (Parameter, Global) or writes (StoreSlot,
  // StoreGlobal) a parameter, local or global already known by `name`.
  std::optional<Instruction> variable(const std::string& name, std::size_t at,
                                      Op slot_op, Op global_op) const {
    for (std::size_t i = 0; i < scope_.parameters.size(); ++i) {
      if (scope_.parameters[i] == name) {
        return Instruction{
            .op = slot_op, .slot = static_cast<std::uint32_t>(i), .offset = at};
      }
    }
    if (const auto slot = local_slot(name)) {
      return Instruction{.op = slot_op, .slot = *slot, .offset = at};
    }
    if (const auto slot = global_slot(name)) {
      return Instruction{.op = global_op, .slot = *slot, .offset = at};
    }
    return std::nullopt;
  }

  Instruction load_for(const std::string& name, std::size_t at) const {
    if (const auto load = variable(name, at, Op::Parameter, Op::Global)) {
      return *load;
    }
    fail(at, "undefined name '" + name + "'");
  }

  // lpfg's C++ beside cpfg's statements: typed declarations (`float x =
  // e, y;`), `for`, `x += e` and its kin, `i++`, and `produce` and
  // `nproduce` (ExpressionScope::read_successor). True if `word` began
  // one of these.
  bool c_statement(std::vector<Instruction>& code, const std::string& word,
                   std::size_t at) {
    static constexpr std::array<std::string_view, 7> kTypes{
        "float", "double", "int", "bool", "long", "unsigned", "const"};
    if (std::find(kTypes.begin(), kTypes.end(), word) != kTypes.end()) {
      pos_ += word.size();
      for (;;) {
        skip_space();
        const std::string more(peek_word());
        if (std::find(kTypes.begin(), kTypes.end(), more) == kTypes.end()) {
          break;
        }
        pos_ += more.size();
      }
      for (;;) {
        skip_space();
        const std::size_t name_at = pos_;
        const std::string name(peek_word());
        if (name.empty() ||
            !is_name_start(static_cast<unsigned char>(name.front()))) {
          fail(pos_, "expected a variable's name");
        }
        pos_ += name.size();
        const Instruction store = store_for(name, name_at);
        skip_space();
        if (accept("=")) {
          expression_into(code);
        } else {
          code.push_back(Instruction{.op = Op::Constant, .offset = name_at});
        }
        code.push_back(store);
        skip_space();
        if (!accept(",")) break;
      }
      expect_semicolon();
      return true;
    }
    if (word == "for") {
      pos_ += word.size();
      skip_space();
      if (!accept("(")) fail(pos_, "expected '('");
      skip_space();
      if (!accept(";")) statement(code);
      const auto top = static_cast<std::uint32_t>(code.size());
      std::optional<std::size_t> to_end;
      skip_space();
      if (!accept(";")) {
        expression_into(code);
        to_end = jump(code, Op::JumpIfZero);
        expect_semicolon();
      }
      // The step runs after the body: compiled apart, then appended.
      std::vector<Instruction> step;
      skip_space();
      if (!accept(")")) {
        c_simple(step);
        skip_space();
        if (!accept(")")) fail(pos_, "expected ')'");
      }
      body(code);
      code.insert(code.end(), step.begin(), step.end());
      code.push_back(Instruction{.op = Op::Jump, .slot = top, .offset = at});
      if (to_end) land(code, *to_end);
      return true;
    }
    if ((word == "produce" || word == "nproduce") && scope_.read_successor) {
      // The modules up to the `;` that ends the statement.
      pos_ += word.size();
      const std::size_t end = c_statement_end(pos_);
      const std::string_view whole = text_;
      text_ = whole.substr(0, end);
      emit_successor(code, at);
      text_ = whole;
      pos_ = end + 1;
      if (word == "produce") {
        code.push_back(
            Instruction{.op = Op::Constant, .value = 1.0, .offset = at});
        code.push_back(produced_store_);
        returns_.push_back(jump(code, Op::Jump));
      }
      return true;
    }
    if (word == "produce" || word == "nproduce") {
      fail(at, "'" + word + "' outside a rule");
    }
    for (std::string_view keyword :
         {"switch", "case", "return", "break", "continue", "goto", "new",
          "delete", "std", "auto", "struct", "class"}) {
      if (word == keyword) {
        std::string what = "C++'s '";
        what += word;
        what +=
            "' is not supported: lsolid reads declarations, assignments, if, "
            "for, while, do, produce and nproduce (docs/dialects/lpfg.md)";
        fail(at, what);
      }
    }
    if (!word.empty() &&
        is_name_start(static_cast<unsigned char>(word.front()))) {
      const std::size_t saved = pos_;
      std::vector<Instruction> simple;
      if (c_simple(simple, true)) {
        code.insert(code.end(), simple.begin(), simple.end());
        expect_semicolon();
        return true;
      }
      pos_ = saved;
    }
    return false;
  }

  // `x += e`, `x -= e`, `x *= e`, `x /= e`, `x++`, `x--`, `++x`, `--x`, or
  // (unless `only_updates`) `x = e`: into `code`. False, having read
  // nothing, when none of these stands at pos_.
  bool c_simple(std::vector<Instruction>& code, bool only_updates = false) {
    skip_space();
    const std::size_t at = pos_;
    Op op = Op::Constant;
    bool by_one = false;
    if (accept("++") || accept("--")) {
      op = text_[at] == '+' ? Op::Add : Op::Subtract;
      by_one = true;
      skip_space();
    }
    const std::size_t name_at = pos_;
    const std::string name(peek_word());
    if (name.empty() ||
        !is_name_start(static_cast<unsigned char>(name.front())))
      fail(pos_, "expected a variable's name");
    pos_ += name.size();
    skip_space();
    if (!by_one) {
      for (const auto& [token, o] :
           {std::pair{"+=", Op::Add}, std::pair{"-=", Op::Subtract},
            std::pair{"*=", Op::Multiply}, std::pair{"/=", Op::Divide},
            std::pair{"++", Op::Add}, std::pair{"--", Op::Subtract}}) {
        if (accept(token)) {
          op = o;
          by_one = std::string_view(token) == "++" ||
                   std::string_view(token) == "--";
          break;
        }
      }
    }
    if (op == Op::Constant) {
      if (only_updates || !accept("=")) {
        pos_ = at;
        return false;
      }
      expression_into(code);
      code.push_back(store_for(name, name_at));
      return true;
    }
    const Instruction store = store_for(name, name_at);
    code.push_back(Instruction{
        .op = store.op == Op::StoreGlobal ? Op::Global : Op::Parameter,
        .slot = store.slot,
        .offset = name_at});
    if (by_one) {
      code.push_back(
          Instruction{.op = Op::Constant, .value = 1.0, .offset = at});
    } else {
      const int before = depth_;
      depth_ = 0;
      expression_into(code);
      depth_ = std::max(before, depth_ + 1);
    }
    code.push_back(Instruction{.op = op, .offset = at});
    code.push_back(store);
    depth_ = std::max(depth_, 2);
    return true;
  }

  // The `;` that ends the statement from `from`, outside brackets.
  std::size_t c_statement_end(std::size_t from) const {
    int depth = 0;
    for (std::size_t k = from; k < text_.size(); ++k) {
      const char c = text_[k];
      if (c == '(' || c == '[' || c == '{') ++depth;
      if (c == ')' || c == ']' || c == '}') --depth;
      if (c == ';' && depth == 0) return k;
    }
    fail(from, "expected ';' after the statement");
  }

  void statement_list(std::vector<Instruction>& code, bool until_brace) {
    const Nesting guard(*this);
    for (;;) {
      skip_space();
      if (pos_ >= text_.size()) {
        if (until_brace) fail(pos_, "expected '}'");
        return;
      }
      if (until_brace && accept("}")) return;
      statement(code);
    }
  }

  void body(std::vector<Instruction>& code) {
    skip_space();
    if (accept("{")) {
      statement_list(code, true);
    } else {
      statement(code);
    }
  }

  std::string_view peek_word() const {
    std::size_t end = pos_;
    while (end < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[end])) != 0 ||
            text_[end] == '_')) {
      ++end;
    }
    return text_.substr(pos_, end - pos_);
  }

  void expression_into(std::vector<Instruction>& code) {
    nodes_.clear();
    const int root = parse_conditional();
    depth_ = std::max(depth_, emit(root, code));
  }

  void parenthesised_into(std::vector<Instruction>& code) {
    if (!accept("(")) fail(pos_, "expected '('");
    expression_into(code);
    if (!accept(")")) fail(pos_, "expected ')'");
  }

  void expect_semicolon() {
    if (accept(";")) return;
    if (scope_.mathjs && (pos_ >= text_.size() || text_[pos_] == '}' ||
                          line_ended_before(pos_))) {
      return;  // mathjs ends a statement at `;`, a line's end or the block's
    }
    fail(pos_, "expected ';' after the statement");
  }

  // True when a line break stands between `at` and the text before it.
  bool line_ended_before(std::size_t at) const {
    while (at > 0 && std::isspace(static_cast<unsigned char>(text_[at - 1]))) {
      if (text_[--at] == '\n') return true;
    }
    return false;
  }

  std::size_t jump(std::vector<Instruction>& code, Op op) {
    code.push_back(Instruction{.op = op, .offset = pos_});
    return code.size() - 1;
  }

  static void land(std::vector<Instruction>& code, std::size_t from) {
    code[from].slot = static_cast<std::uint32_t>(code.size());
  }

  void statement(std::vector<Instruction>& code) {
    const Nesting guard(*this);
    skip_space();
    const std::size_t at = pos_;
    if (accept(";")) return;
    const std::string word(peek_word());
    if (word == "if") {
      pos_ += word.size();
      skip_space();
      parenthesised_into(code);
      const std::size_t to_else = jump(code, Op::JumpIfZero);
      body(code);
      skip_space();
      if (peek_word() == "else") {
        pos_ += 4;
        const std::size_t to_end = jump(code, Op::Jump);
        land(code, to_else);
        body(code);
        land(code, to_end);
      } else {
        land(code, to_else);
      }
      return;
    }
    if (word == "while") {
      pos_ += word.size();
      skip_space();
      const std::size_t start = code.size();
      parenthesised_into(code);
      const std::size_t to_end = jump(code, Op::JumpIfZero);
      body(code);
      code.push_back(Instruction{.op = Op::Jump,
                                 .slot = static_cast<std::uint32_t>(start),
                                 .offset = at});
      land(code, to_end);
      return;
    }
    if (word == "do") {
      pos_ += word.size();
      const std::size_t start = code.size();
      body(code);
      skip_space();
      if (peek_word() != "while") fail(pos_, "expected 'while' after 'do'");
      pos_ += 5;
      skip_space();
      parenthesised_into(code);
      code.push_back(Instruction{.op = Op::Not, .offset = at});
      code.push_back(Instruction{.op = Op::JumpIfZero,
                                 .slot = static_cast<std::uint32_t>(start),
                                 .offset = at});
      expect_semicolon();
      return;
    }
    if (word == "printf" || word == "fprintf" || word == "fflush" ||
        (scope_.c_language && word == "Printf")) {
      skip_call();
      expect_semicolon();
      return;
    }
    if (scope_.c_language) {
      if (c_statement(code, word, at)) return;
    }

    if (!word.empty() &&
        std::isdigit(static_cast<unsigned char>(word.front())) == 0) {
      std::size_t after = pos_ + word.size();
      while (after < text_.size() &&
             (text_[after] == ' ' || text_[after] == '\t'))
        ++after;
      if (after < text_.size() && text_[after] == '=' &&
          (after + 1 >= text_.size() || text_[after + 1] != '=')) {
        pos_ = after + 1;
        const Instruction store = store_for(word, at);
        expression_into(code);
        code.push_back(store);
        expect_semicolon();
        return;
      }
      if (const ArrayVariable* array = array_named(word);
          array != nullptr && after < text_.size() && text_[after] == '[') {
        // `a[i][j] = e;`: the element's offset, then the value.
        pos_ += word.size();
        nodes_.clear();
        const int index_depth = emit(parse_subscripts(*array, at), code);
        skip_space();
        if (!accept("=") || (pos_ < text_.size() && text_[pos_] == '=')) {
          fail(pos_, "expected '=' after an array's element");
        }
        nodes_.clear();
        const int value_depth = emit(parse_conditional(), code);
        depth_ = std::max({depth_, index_depth, 1 + value_depth});
        code.push_back(Instruction{.op = Op::StoreGlobalAt,
                                   .slot = array->first,
                                   .value = element_count(*array),
                                   .offset = at});
        expect_semicolon();
        return;
      }
    }
    expression_into(code);
    code.push_back(Instruction{.op = Op::Pop, .offset = at});
    expect_semicolon();
  }

  // `printf("%f\n", x)`: up to its closing parenthesis, strings included.
  void skip_call() {
    pos_ += peek_word().size();
    skip_space();
    if (!accept("(")) fail(pos_, "expected '('");
    int depth = 1;
    while (pos_ < text_.size() && depth > 0) {
      const char c = text_[pos_++];
      if (c == '"' || (scope_.python && c == '\'')) {
        while (pos_ < text_.size() && text_[pos_] != c) {
          if (text_[pos_] == '\\') ++pos_;
          ++pos_;
        }
        ++pos_;
      } else if (c == '(') {
        ++depth;
      } else if (c == ')') {
        --depth;
      }
    }
    if (depth > 0) fail(pos_, "expected ')'");
  }

  // A store into a global or local variable that `name` adds.
  Instruction new_global(const std::string& name, std::size_t at) {
    scope_.globals->push_back(name);
    return Instruction{
        .op = Op::StoreGlobal,
        .slot = static_cast<std::uint32_t>(scope_.globals->size() - 1),
        .offset = at};
  }

  Instruction new_local(const std::string& name, std::size_t at) {
    scope_.locals->push_back(name);
    return Instruction{
        .op = Op::StoreSlot,
        .slot = static_cast<std::uint32_t>(scope_.parameters.size() +
                                           scope_.locals->size() - 1),
        .offset = at};
  }

  Instruction store_for(const std::string& name, std::size_t at) {
    if (const auto store = variable(name, at, Op::StoreSlot, Op::StoreGlobal)) {
      return *store;
    }
    if (scope_.assign_globals && scope_.globals != nullptr) {
      return new_global(name, at);
    }
    if (scope_.locals != nullptr) {
      return new_local(name, at);
    }
    fail(at, "cannot assign to '" + name + "' here");
  }

  const SourceFile& source_;
  std::string_view text_;
  std::size_t pos_;
  const ExpressionScope& scope_;
  std::vector<Node> nodes_;
  int nesting_ = 0;
  int depth_ = 0;
  std::vector<PythonLine> lines_;
  std::vector<std::string> declared_globals_;  // by `global`
  std::vector<std::size_t> returns_;  // lpfg's `produce`: jumps to the end
  // The arguments of the Python functions being compiled in place.
  std::vector<std::vector<std::pair<std::string, int>>> frames_;
  Instruction produced_store_;
  int produces_ = 0;
  std::vector<Loop> loops_;
  int hidden_ = 0;
};

}  // namespace

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
  Compiler compiler(*source, begin, end, scope);
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
  Compiler compiler(*source, begin, end, scope);
  Expression e;
  e.adopt(python ? compiler.compile_python(e.stack_depth_)
                 : compiler.compile_statements(e.stack_depth_),
          scope);
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
