// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "expressions/c_statements.hpp"

#include <algorithm>

namespace lsys::expressions {

std::vector<Instruction> CStatementCompiler::compile_statements(
    int& stack_depth) {
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

bool CStatementCompiler::c_statement(std::vector<Instruction>& code,
                                     const std::string& word, std::size_t at) {
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

bool CStatementCompiler::c_simple(std::vector<Instruction>& code,
                                  bool only_updates) {
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
  if (name.empty() || !is_name_start(static_cast<unsigned char>(name.front())))
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
        by_one =
            std::string_view(token) == "++" || std::string_view(token) == "--";
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
    code.push_back(Instruction{.op = Op::Constant, .value = 1.0, .offset = at});
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

std::size_t CStatementCompiler::c_statement_end(std::size_t from) const {
  int depth = 0;
  for (std::size_t k = from; k < text_.size(); ++k) {
    const char c = text_[k];
    if (c == '(' || c == '[' || c == '{') ++depth;
    if (c == ')' || c == ']' || c == '}') --depth;
    if (c == ';' && depth == 0) return k;
  }
  fail(from, "expected ';' after the statement");
}

void CStatementCompiler::statement_list(std::vector<Instruction>& code,
                                        bool until_brace) {
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

void CStatementCompiler::body(std::vector<Instruction>& code) {
  skip_space();
  if (accept("{")) {
    statement_list(code, true);
  } else {
    statement(code);
  }
}

void CStatementCompiler::expect_semicolon() {
  if (accept(";")) return;
  if (scope_.mathjs &&
      (pos_ >= text_.size() || text_[pos_] == '}' || line_ended_before(pos_))) {
    return;  // mathjs ends a statement at `;`, a line's end or the block's
  }
  fail(pos_, "expected ';' after the statement");
}

bool CStatementCompiler::line_ended_before(std::size_t at) const {
  while (at > 0 && std::isspace(static_cast<unsigned char>(text_[at - 1]))) {
    if (text_[--at] == '\n') return true;
  }
  return false;
}

void CStatementCompiler::statement(std::vector<Instruction>& code) {
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

}  // namespace lsys::expressions
