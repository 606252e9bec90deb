// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "expressions/statement_compiler.hpp"

namespace lsys::expressions {

// cpfg's statements (CPFG Reference Manual §3.2) and lpfg's C++ bodies.
class CStatementCompiler : public StatementCompiler {
 public:
  using StatementCompiler::StatementCompiler;
  // cpfg's statements (CPFG Reference Manual §3.2): straight into code,
  // each expression through the tree and its folding.
  std::vector<Instruction> compile_statements(int& stack_depth);

 private:
  // lpfg's C++ beside cpfg's statements: typed declarations (`float x =
  // e, y;`), `for`, `x += e` and its kin, `i++`, and `produce` and
  // `nproduce` (ExpressionScope::read_successor). True if `word` began
  // one of these.
  bool c_statement(std::vector<Instruction>& code, const std::string& word,
                   std::size_t at);
  // `x += e`, `x -= e`, `x *= e`, `x /= e`, `x++`, `x--`, `++x`, `--x`, or
  // (unless `only_updates`) `x = e`: into `code`. False, having read
  // nothing, when none of these stands at pos_.
  bool c_simple(std::vector<Instruction>& code, bool only_updates = false);
  // The `;` that ends the statement from `from`, outside brackets.
  std::size_t c_statement_end(std::size_t from) const;
  void statement_list(std::vector<Instruction>& code, bool until_brace);
  void body(std::vector<Instruction>& code);
  void expect_semicolon();
  // True when a line break stands between `at` and the text before it.
  bool line_ended_before(std::size_t at) const;
  void statement(std::vector<Instruction>& code);
  std::vector<std::size_t> returns_;  // lpfg's `produce`: jumps to the end
};

}  // namespace lsys::expressions
