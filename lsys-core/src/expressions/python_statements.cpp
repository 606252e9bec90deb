// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "expressions/python_statements.hpp"

#include <algorithm>

namespace lsys::expressions {

std::vector<Instruction> PythonStatementCompiler::compile_python(
    int& stack_depth) {
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

bool PythonStatementCompiler::python_block(std::vector<Instruction>& code,
                                           std::size_t& li, int indent,
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

bool PythonStatementCompiler::python_statement(std::vector<Instruction>& code,
                                               std::size_t& li, int indent,
                                               std::string_view whole) {
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

std::size_t PythonStatementCompiler::header_colon(std::string_view whole,
                                                  const PythonLine& line) {
  const std::size_t colon = python_colon(whole, pos_, line.end);
  if (colon == std::string_view::npos) fail(line.end, "expected ':'");
  return colon;
}

bool PythonStatementCompiler::python_if(std::vector<Instruction>& code,
                                        std::size_t& li, int indent,
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

void PythonStatementCompiler::leave_loop_if_produced(
    std::vector<Instruction>& code, std::vector<std::size_t>& exits) {
  if (scope_.locals == nullptr) return;
  code.push_back(Instruction{
      .op = Op::Parameter, .slot = produced_store_.slot, .offset = pos_});
  code.push_back(Instruction{.op = Op::Not, .offset = pos_});
  exits.push_back(jump(code, Op::JumpIfZero));
}

bool PythonStatementCompiler::python_for(std::vector<Instruction>& code,
                                         std::size_t& li, int indent,
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

bool PythonStatementCompiler::python_while(std::vector<Instruction>& code,
                                           std::size_t& li, int indent,
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

bool PythonStatementCompiler::python_suite(std::vector<Instruction>& code,
                                           std::size_t& li, int indent,
                                           std::size_t after_colon,
                                           std::string_view whole) {
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

bool PythonStatementCompiler::python_simple(std::vector<Instruction>& code) {
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
    code.push_back(Instruction{.op = Op::Constant, .value = 1.0, .offset = at});
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

Instruction PythonStatementCompiler::python_store_for(const std::string& name,
                                                      std::size_t at) {
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

}  // namespace lsys::expressions
