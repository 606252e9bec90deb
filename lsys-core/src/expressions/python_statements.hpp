// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "expressions/python_lines.hpp"
#include "expressions/statement_compiler.hpp"

namespace lsys::expressions {

// L-Py's rule bodies and hooks: Python's statements by indentation.
class PythonStatementCompiler : public StatementCompiler {
 public:
  using StatementCompiler::StatementCompiler;
  // The Python body of an L-Py rule (parse_python_statements): the
  // local kProducedLocal starts at 0 and each `produce` sets it to its
  // number; what follows a `produce` in its block, or a block that may
  // have produced, is skipped when one has.
  std::vector<Instruction> compile_python(int& stack_depth);

 private:
  bool python_block(std::vector<Instruction>& code, std::size_t& li, int indent,
                    std::string_view whole);
  // One statement, compound or simple, from line li on; returns whether it
  // may have produced.
  bool python_statement(std::vector<Instruction>& code, std::size_t& li,
                        int indent, std::string_view whole);
  // The `:` that ends the header of a compound statement from pos_.
  std::size_t header_colon(std::string_view whole, const PythonLine& line);
  // `if` (or `elif`) at pos_ of line li: the condition, its suite, and
  // the `elif` or `else` that follows at the same indentation.
  bool python_if(std::vector<Instruction>& code, std::size_t& li, int indent,
                 std::string_view whole);

  // A loop's bookkeeping: the jumps its `break`s and `continue`s wait to
  // have landed.
  struct Loop {
    std::vector<std::size_t> breaks;
    std::vector<std::size_t> continues;
  };
  // Stops a loop once its body has produced: `produce` ends the body.
  void leave_loop_if_produced(std::vector<Instruction>& code,
                              std::vector<std::size_t>& exits);
  // `for name in range(…):` at pos_ of line li. Python evaluates range's
  // arguments once and assigns the name at the start of each pass, so the
  // body may change the name without changing the count.
  bool python_for(std::vector<Instruction>& code, std::size_t& li, int indent,
                  std::string_view whole);
  // `while c:` at pos_ of line li.
  bool python_while(std::vector<Instruction>& code, std::size_t& li, int indent,
                    std::string_view whole);
  // What follows a compound statement's colon: a simple statement on the
  // same line, or a block of deeper lines.
  bool python_suite(std::vector<Instruction>& code, std::size_t& li, int indent,
                    std::size_t after_colon, std::string_view whole);
  // `pass`, `produce …`, or an assignment, up to the end of text_.
  bool python_simple(std::vector<Instruction>& code);
  // Python's scoping: in a rule, a name assigned without `global` is
  // local even where a global of that name exists; `global x` makes the
  // assignment reach (or create) the global x. A hook's names are global.
  Instruction python_store_for(const std::string& name, std::size_t at);
  std::vector<PythonLine> lines_;
  std::vector<std::string> declared_globals_;  // by `global`
  int produces_ = 0;
  std::vector<Loop> loops_;
};

}  // namespace lsys::expressions
