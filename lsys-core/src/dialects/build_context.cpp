// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "dialects/build_context.hpp"

namespace lsys::dialects {

double BuildContext::constant(Range r) const {
  ExpressionScope scope{.constants = &grammar.constants,
                        .used_constants = &used_constants,
                        .radians = draft.syntax.radians,
                        .mathjs = draft.syntax.mathjs,
                        .c_language = draft.syntax.c_language};
  if (draft.syntax.python) {
    scope.python = true;
    scope.python_modules = &draft.python_modules;
    scope.python_functions = &draft.python_functions;
    scope.python_imports = &draft.python_imports;
  }
  const Expression e = parse_expression(scan.source(), r.begin, r.end, scope);
  if (!e.is_constant()) {
    scan.fail(r.begin,
              "a constant's value must be a number or arithmetic over numbers "
              "and constants, not a random number");
  }
  return e.constant_value();
}

ExpressionScope BuildContext::statement_scope(
    ExpressionScope scope, std::vector<std::string>* locals) {
  if (draft.syntax.python) {
    // L-Py: a rule body's names are local unless a hook made them global.
    scope.python = true;
    scope.python_modules = &draft.python_modules;
    scope.python_functions = &draft.python_functions;
    scope.python_imports = &draft.python_imports;
    scope.locals = locals;
    scope.globals = &grammar.globals;
    scope.arrays = &arrays;
    return scope;
  }
  if (!draft.syntax.cpfg_statements) return scope;
  scope.locals = locals;
  scope.globals = &grammar.globals;
  scope.arrays = &arrays;
  scope.cpfg = true;
  scope.c_language = draft.syntax.c_language;
  if (!scope.c_language && !draft.syntax.mathjs) {
    scope.undefined = &undefined;
  }
  if (scope.c_language) scope.python_functions = &draft.python_functions;
  scope.functions = draft.functions;
  return scope;
}

}  // namespace lsys::dialects
