// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "expressions/statement_compiler.hpp"

#include <algorithm>

namespace lsys::expressions {

Instruction StatementCompiler::hidden_store(std::size_t at) {
  std::string name = "#";
  name += std::to_string(++hidden_);
  if (scope_.locals != nullptr) return new_local(name, at);
  return new_global(name, at);
}

Instruction StatementCompiler::load_of(const Instruction& store) {
  return Instruction{
      .op = store.op == Op::StoreGlobal ? Op::Global : Op::Parameter,
      .slot = store.slot,
      .offset = store.offset};
}

void StatementCompiler::emit_successor(std::vector<Instruction>& code,
                                       std::size_t at) {
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

[[noreturn]] void StatementCompiler::refuse_python(std::size_t at,
                                                   const std::string& word) {
  fail(at, (word.empty() ? std::string("this Python statement")
                         : "Python's '" + word + "'") +
               " is not supported: lsolid runs assignments, "
               "if/elif/else, for … in range(…), while, break, continue, "
               "pass, global, print, produce and nproduce "
               "(docs/dialects/lpy.md)");
}

std::optional<Instruction> StatementCompiler::variable(const std::string& name,
                                                       std::size_t at,
                                                       Op slot_op,
                                                       Op global_op) const {
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

Instruction StatementCompiler::load_for(const std::string& name,
                                        std::size_t at) const {
  if (const auto load = variable(name, at, Op::Parameter, Op::Global)) {
    return *load;
  }
  fail(at, "undefined name '" + name + "'");
}

void StatementCompiler::expression_into(std::vector<Instruction>& code) {
  nodes_.clear();
  const int root = parse_conditional();
  depth_ = std::max(depth_, emit(root, code));
}

void StatementCompiler::parenthesised_into(std::vector<Instruction>& code) {
  if (!accept("(")) fail(pos_, "expected '('");
  expression_into(code);
  if (!accept(")")) fail(pos_, "expected ')'");
}

std::size_t StatementCompiler::jump(std::vector<Instruction>& code, Op op) {
  code.push_back(Instruction{.op = op, .offset = pos_});
  return code.size() - 1;
}

void StatementCompiler::land(std::vector<Instruction>& code, std::size_t from) {
  code[from].slot = static_cast<std::uint32_t>(code.size());
}

void StatementCompiler::skip_call() {
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

Instruction StatementCompiler::new_global(const std::string& name,
                                          std::size_t at) {
  scope_.globals->push_back(name);
  return Instruction{
      .op = Op::StoreGlobal,
      .slot = static_cast<std::uint32_t>(scope_.globals->size() - 1),
      .offset = at};
}

Instruction StatementCompiler::new_local(const std::string& name,
                                         std::size_t at) {
  scope_.locals->push_back(name);
  return Instruction{.op = Op::StoreSlot,
                     .slot = static_cast<std::uint32_t>(
                         scope_.parameters.size() + scope_.locals->size() - 1),
                     .offset = at};
}

Instruction StatementCompiler::store_for(const std::string& name,
                                         std::size_t at) {
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

}  // namespace lsys::expressions
