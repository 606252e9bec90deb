// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

#include "expressions/expression_compiler.hpp"

namespace lsys::expressions {

// What cpfg's, lpfg's and L-Py's statements share over the expressions:
// variables to load and store (locals, globals, new ones), jumps, and the
// successor an `nproduce` or `produce` emits.
class StatementCompiler : public ExpressionCompiler {
 public:
  using ExpressionCompiler::ExpressionCompiler;

 protected:
  // A slot for what the source cannot name: a loop's counter and bounds.
  Instruction hidden_store(std::size_t at);
  static Instruction load_of(const Instruction& store);
  // `nproduce …` or, in a body that builds its successor, `produce …`:
  // each module's arguments, then Emit.
  void emit_successor(std::vector<Instruction>& code, std::size_t at);
  [[noreturn]] void refuse_python(std::size_t at, const std::string& word);
  // The instruction that reads (Parameter, Global) or writes (StoreSlot,
  // StoreGlobal) a parameter, local or global already known by `name`.
  std::optional<Instruction> variable(const std::string& name, std::size_t at,
                                      Op slot_op, Op global_op) const;
  Instruction load_for(const std::string& name, std::size_t at) const;
  void expression_into(std::vector<Instruction>& code);
  void parenthesised_into(std::vector<Instruction>& code);
  std::size_t jump(std::vector<Instruction>& code, Op op);
  static void land(std::vector<Instruction>& code, std::size_t from);
  // `printf("%f\n", x)`: up to its closing parenthesis, strings included.
  void skip_call();
  // A store into a global or local variable that `name` adds.
  Instruction new_global(const std::string& name, std::size_t at);
  Instruction new_local(const std::string& name, std::size_t at);
  Instruction store_for(const std::string& name, std::size_t at);
  int depth_ = 0;
  Instruction produced_store_;
  int hidden_ = 0;
};

}  // namespace lsys::expressions
