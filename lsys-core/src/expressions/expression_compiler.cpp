// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Expressions of parametric L-systems (ABOP §1.10; cpfg manual §3.2 for the
// C-like operators and degree-based trigonometry): recursive descent to a
// tree, folded and flattened to postfix code, as seed 004 recommends for
// speed.
#include "expressions/expression_compiler.hpp"

#include <algorithm>

#include "lsys/alphabet.hpp"

namespace lsys::expressions {

std::vector<Instruction> ExpressionCompiler::compile(int& stack_depth) {
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

[[noreturn]] void ExpressionCompiler::fail(std::size_t offset,
                                           std::string message) const {
  throw error_at(source_, offset, std::move(message));
}

void ExpressionCompiler::skip_space() {
  while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' ||
                                 text_[pos_] == '\r' || text_[pos_] == '\n')) {
    ++pos_;
  }
}

std::string_view ExpressionCompiler::peek_code_point() const {
  return text_.substr(pos_, code_point_length(text_.substr(pos_)));
}

bool ExpressionCompiler::accept(std::string_view token) {
  skip_space();
  if (text_.substr(pos_).starts_with(token)) {
    pos_ += token.size();
    return true;
  }
  return false;
}

bool ExpressionCompiler::accept_word(std::string_view word) {
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

int ExpressionCompiler::add(Op op, std::size_t offset, int a, int b) {
  if (nodes_.size() >= kMaxNodes) fail(offset, "expression is too long");
  nodes_.push_back(Node{Instruction{.op = op, .offset = offset}, a, b});
  return static_cast<int>(nodes_.size()) - 1;
}

int ExpressionCompiler::fold(int index) {
  Node& node = nodes_[static_cast<std::size_t>(index)];
  if (is_random(node.instruction.op) || node.instruction.op == Op::Iteration ||
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

int ExpressionCompiler::binary(Op op, std::size_t offset, int a, int b) {
  return fold(add(op, offset, a, b));
}

int ExpressionCompiler::parse_conditional() {
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

int ExpressionCompiler::parse_or() {
  int left = parse_and();
  for (;;) {
    const std::size_t at = (skip_space(), pos_);
    if (!accept("||") && !accept_word("or")) return left;
    left = binary(Op::Or, at, left, parse_and());
  }
}

int ExpressionCompiler::parse_and() {
  int left = parse_not();
  for (;;) {
    const std::size_t at = (skip_space(), pos_);
    if (!accept("&&") && !accept_word("and")) return left;
    left = binary(Op::And, at, left, parse_not());
  }
}

int ExpressionCompiler::parse_not() {
  if (!scope_.python) return parse_comparison();
  skip_space();
  const std::size_t at = pos_;
  if (accept_word("not")) return fold(add(Op::Not, at, parse_not()));
  return parse_comparison();
}

int ExpressionCompiler::parse_comparison() {
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

int ExpressionCompiler::parse_sum() {
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

int ExpressionCompiler::parse_product() {
  int left = parse_unary();
  for (;;) {
    skip_space();
    const std::size_t at = pos_;
    if ((!text_.substr(pos_).starts_with("**") && accept("*")) ||
        accept("\u00D7") || accept("\u00B7")) {
      left = binary(Op::Multiply, at, left, parse_unary());
    } else if (scope_.python && accept("//")) {
      left =
          fold(add(Op::Floor, at, binary(Op::Divide, at, left, parse_unary())));
    } else if (accept("/")) {
      left = binary(Op::Divide, at, left, parse_unary());
    } else if (scope_.python && accept("%")) {
      // Python's remainder takes the divisor's sign: a − b·⌊a/b⌋.
      const int b = parse_unary();
      const int quotient =
          fold(add(Op::Floor, at, binary(Op::Divide, at, left, b)));
      left =
          binary(Op::Subtract, at, left, binary(Op::Multiply, at, b, quotient));
    } else if ((scope_.cpfg && accept("%")) ||
               (scope_.mathjs && accept_word("mod"))) {
      left = binary(Op::Modulo, at, left, parse_unary());
    } else {
      return left;
    }
  }
}

int ExpressionCompiler::parse_unary() {
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

int ExpressionCompiler::parse_power() {
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

bool ExpressionCompiler::is_name_start(unsigned char c) {
  return std::isalpha(c) != 0 || c == '_' || c >= 0x80U;
}

int ExpressionCompiler::parse_primary() {
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
        return type == "int" || type == "long" ? fold(add(Op::Int, at, operand))
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

bool ExpressionCompiler::is_operator_code_point() const {
  for (std::string_view op :
       {"\u2264", "\u2265", "\u2260", "\u2212", "\u00D7", "\u00B7", "\u00B0",
        "\u00BA", "\u02DA", "\u25E6"}) {
    if (text_.substr(pos_).starts_with(op)) return true;
  }
  return false;
}

int ExpressionCompiler::parse_number() {
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

int ExpressionCompiler::parse_name() {
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
        std::find(scope_.python_modules->begin(), scope_.python_modules->end(),
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

int ExpressionCompiler::parse_global_name(const std::string& name,
                                          std::size_t at) {
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
      if (scope_.used_constants != nullptr) scope_.used_constants->insert(name);
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

int ExpressionCompiler::parse_func(std::size_t at) {
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

std::vector<int> ExpressionCompiler::parse_arguments() {
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

int ExpressionCompiler::parse_random(std::size_t at) {
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

int ExpressionCompiler::parse_call(const std::string& name, std::size_t at) {
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

int ExpressionCompiler::inline_python_function(const std::string& name,
                                               const PythonFunction& f,
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
      fail(pos_,
           "unexpected '" + std::string(peek_code_point()) + "' in expression");
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

int ExpressionCompiler::call_in_radians(Op op, std::size_t at,
                                        std::vector<int>& args) {
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
  const int result = fold(add(op, at, args[0], args.size() > 1 ? args[1] : -1));
  if (op == Op::Asin || op == Op::Acos || op == Op::Atan || op == Op::Atan2) {
    return binary(Op::Multiply, at, result, constant(1.0 / degrees_per_radian));
  }
  return result;
}

int ExpressionCompiler::emit(int index, std::vector<Instruction>& code) const {
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

double ExpressionCompiler::element_count(const ArrayVariable& array) {
  double n = 1.0;
  for (const std::uint32_t d : array.dimensions) n *= d;
  return n;
}

void ExpressionCompiler::refuse_imported(const std::string& name,
                                         std::size_t at) const {
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

const ArrayVariable* ExpressionCompiler::array_named(
    std::string_view name) const {
  if (scope_.arrays == nullptr) return nullptr;
  for (const ArrayVariable& a : *scope_.arrays) {
    if (a.name == name) return &a;
  }
  return nullptr;
}

int ExpressionCompiler::parse_subscripts(const ArrayVariable& array,
                                         std::size_t at) {
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

std::optional<std::uint32_t> ExpressionCompiler::local_slot(
    const std::string& name) const {
  if (scope_.locals == nullptr) return std::nullopt;
  const auto& locals = *scope_.locals;
  for (std::size_t i = 0; i < locals.size(); ++i) {
    if (locals[i] == name) {
      return static_cast<std::uint32_t>(scope_.parameters.size() + i);
    }
  }
  return std::nullopt;
}

std::optional<std::uint32_t> ExpressionCompiler::global_slot(
    const std::string& name) const {
  if (scope_.globals == nullptr) return std::nullopt;
  const auto& globals = *scope_.globals;
  for (std::size_t i = 0; i < globals.size(); ++i) {
    if (globals[i] == name) return static_cast<std::uint32_t>(i);
  }
  return std::nullopt;
}

std::string_view ExpressionCompiler::peek_word() const {
  std::size_t end = pos_;
  while (end < text_.size() &&
         (std::isalnum(static_cast<unsigned char>(text_[end])) != 0 ||
          text_[end] == '_')) {
    ++end;
  }
  return text_.substr(pos_, end - pos_);
}

}  // namespace lsys::expressions
