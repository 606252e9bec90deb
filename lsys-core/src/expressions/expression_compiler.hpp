// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "expressions/operations.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/expression.hpp"
#include "lsys/source.hpp"

namespace lsys::expressions {

// A node of the expression tree the compiler builds before folding it.
struct Node {
  Instruction instruction;
  int a = -1;
  int b = -1;
  int c = -1;  // Select's third operand
};

// Recursive descent over bytes [begin, end) of the source, building a tree
// that is folded and flattened to postfix code afterwards.
class ExpressionCompiler {
 public:
  ExpressionCompiler(const SourceFile& source, std::size_t begin,
                     std::size_t end, const ExpressionScope& scope)
      : source_(source),
        text_(std::string_view(source.text()).substr(0, end)),
        pos_(begin),
        scope_(scope) {}
  std::vector<Instruction> compile(int& stack_depth);

 protected:
  [[noreturn]] void fail(std::size_t offset, std::string message) const;
  void skip_space();
  std::string_view peek_code_point() const;
  // Consumes `token` if it is next (after spaces).
  bool accept(std::string_view token);
  // mathjs's operator words (`a and not b`), as whole words only, so that
  // a parameter named `order` is not `or` and `der`.
  bool accept_word(std::string_view word);
  int add(Op op, std::size_t offset, int a = -1, int b = -1);
  // Folds a node whose operands are constants into a constant.
  int fold(int index);
  int binary(Op op, std::size_t offset, int a, int b);
  // cpfg's `c ? a : b`, right-associative, below `||`.
  int parse_conditional();
  int parse_or();
  int parse_and();
  // Python's `not` binds more loosely than a comparison: `not a == b` is
  // `not (a == b)`.
  int parse_not();
  int parse_comparison();
  int parse_sum();
  int parse_product();

  // Recursion guard: deeply nested input must not exhaust the stack.
  struct Nesting {
    explicit Nesting(ExpressionCompiler& c) : compiler(c) {
      if (++compiler.nesting_ > kMaxNesting) {
        compiler.fail(compiler.pos_, "expression is nested too deeply");
      }
    }
    ~Nesting() { --compiler.nesting_; }
    Nesting(const Nesting&) = delete;
    Nesting& operator=(const Nesting&) = delete;
    ExpressionCompiler& compiler;
  };
  int parse_unary();
  int parse_power();
  static bool is_name_start(unsigned char c);
  int parse_primary();
  bool is_operator_code_point() const;
  int parse_number();
  int parse_name();
  // A global variable or a constant.
  int parse_global_name(const std::string& name, std::size_t at);
  // cpfg's func(id, x): id names a function of the view file, from 1.
  int parse_func(std::size_t at);
  // A call's arguments, from its `(` to its `)`.
  std::vector<int> parse_arguments();
  // mathjs's random(), random(max), random(min, max): uniform numbers from
  // the generator of cpfg's ran, so that a file gives the same model on
  // every run (mathjs's own are never the same twice).
  int parse_random(std::size_t at);
  int parse_call(const std::string& name, std::size_t at);
  // A call of an L-Py function of one `return`: its expression compiled
  // here, each parameter standing for its argument's tree.
  int inline_python_function(const std::string& name, const PythonFunction& f,
                             std::size_t at);
  // The code runs in degrees; radians are converted on the way in (sin,
  // cos, tan) or out (the inverses).
  int call_in_radians(Op op, std::size_t at, std::vector<int>& args);
  // Appends the postfix code of a subtree; returns its stack depth.
  int emit(int index, std::vector<Instruction>& code) const;
  static double element_count(const ArrayVariable& array);
  // A name of a Python module that lsolid does not run, refused by name.
  void refuse_imported(const std::string& name, std::size_t at) const;
  const ArrayVariable* array_named(std::string_view name) const;
  // `[i][j]…` after an array's name at pos_: the offset of the element,
  // as cpfg's generate.c computes it, each subscript checked against its
  // dimension (cpfg clamps one out of range, with a warning; lsolid stops).
  int parse_subscripts(const ArrayVariable& array, std::size_t at);
  std::optional<std::uint32_t> local_slot(const std::string& name) const;
  std::optional<std::uint32_t> global_slot(const std::string& name) const;
  std::string_view peek_word() const;

  const SourceFile& source_;
  std::string_view text_;
  std::size_t pos_;
  const ExpressionScope& scope_;
  std::vector<Node> nodes_;
  int nesting_ = 0;
  // The arguments of the Python functions being compiled in place.
  std::vector<std::vector<std::pair<std::string, int>>> frames_;
};

}  // namespace lsys::expressions
