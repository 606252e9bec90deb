// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/expression.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "lsys/diagnostic.hpp"

namespace lsys {
namespace {

struct Compiled {
  std::shared_ptr<const SourceFile> source;
  Expression expression;
};

Compiled compile(const std::string& text,
                 std::vector<std::string> parameters = {},
                 const std::map<std::string, double>* constants = nullptr) {
  auto source = std::make_shared<const SourceFile>("e.ls", text);
  Expression e =
      parse_expression(source, 0, text.size(),
                       ExpressionScope{.parameters = std::move(parameters),
                                       .constants = constants});
  return {source, e};
}

double value(const std::string& text, std::vector<double> args = {},
             std::vector<std::string> names = {}) {
  return compile(text, std::move(names)).expression.evaluate(args);
}

std::string error(const std::string& text,
                  std::vector<std::string> names = {}) {
  try {
    (void)compile(text, std::move(names));
  } catch (const ParseError& e) {
    return std::to_string(e.diagnostic().column) + ": " +
           e.diagnostic().message;
  }
  return "no error";
}

TEST(Expression, FollowsCPrecedenceWithPowerAboveUnaryMinus) {
  EXPECT_EQ(value("1 + 2 * 3"), 7.0);
  EXPECT_EQ(value("(1 + 2) * 3"), 9.0);
  EXPECT_EQ(value("-2^2"), -4.0);
  EXPECT_EQ(value("2^3^2"), 512.0);
  EXPECT_EQ(value("10 - 4 - 3"), 3.0);
  EXPECT_EQ(value("12 / 4 / 3"), 1.0);
  EXPECT_EQ(value("1 < 2 && 3 >= 3 || 0"), 1.0);
  EXPECT_EQ(value("!(2 > 1)"), 0.0);
  EXPECT_EQ(value("1 = 1"), 1.0);
  EXPECT_EQ(value("1 != 1"), 0.0);
  EXPECT_EQ(value("3 \u2264 2"), 0.0);
}

TEST(Expression, UsesDegreesForTrigonometryAsCpfg) {
  EXPECT_NEAR(value("sin(30)"), 0.5, 1e-15);
  EXPECT_NEAR(value("cos(60)"), 0.5, 1e-15);
  EXPECT_NEAR(value("atan2(1, 1)"), 45.0, 1e-12);
  EXPECT_NEAR(value("asin(1)"), 90.0, 1e-12);
  EXPECT_EQ(value("min(3, max(1, 2))"), 2.0);
  EXPECT_EQ(value("floor(2.7) + ceil(0.2) + abs(-1)"), 4.0);
  EXPECT_NEAR(value("sqrt(2) * exp(0) + log(1)"), std::sqrt(2.0), 1e-15);
}

TEST(Expression, ReadsParametersBySlot) {
  EXPECT_EQ(value("l * r + w", {2.0, 3.0, 1.0}, {"l", "w", "r"}), 5.0);
}

TEST(Expression, FoldsConstantsAtCompileTime) {
  const std::map<std::string, double> constants{{"r1", 0.9}};
  const Compiled c = compile("r1 * 2 + sin(90)", {}, &constants);
  EXPECT_TRUE(c.expression.is_constant());
  EXPECT_DOUBLE_EQ(c.expression.constant_value(), 2.8);
  EXPECT_FALSE(compile("x * 2", {"x"}).expression.is_constant());
}

TEST(Expression, ParametersShadowConstants) {
  const std::map<std::string, double> constants{{"x", 100.0}};
  const std::vector<double> args{1.0};
  EXPECT_EQ(compile("x", {"x"}, &constants).expression.evaluate(args), 1.0);
}

TEST(Expression, AcceptsTheDegreeSign) { EXPECT_EQ(value("22.5\u00B0"), 22.5); }

TEST(Expression, ReportsErrorsAtTheirColumn) {
  EXPECT_EQ(error("1 + y"), "5: undefined name 'y'");
  EXPECT_EQ(error("1.2.3"), "1: bad number '1.2.3'");
  EXPECT_EQ(error("2x"), "1: bad number '2x'");
  EXPECT_EQ(error("1 + 1e"), "5: bad number '1e'");
  EXPECT_EQ(error("(1 + 2"), "7: expected ')'");
  EXPECT_EQ(error("1 +"), "4: expected an expression");
  EXPECT_EQ(error("1 2"), "3: unexpected '2' in expression");
  EXPECT_EQ(error("atan2(1)"), "1: 'atan2' takes 2 arguments, 1 given");
  EXPECT_EQ(error("sin(1, 2)"), "1: 'sin' takes 1 argument, 2 given");
  EXPECT_EQ(error("foo(1)"), "1: 'foo' is not a function");
  EXPECT_EQ(error("4 / (2 - 2)"), "3: division by zero");
  EXPECT_EQ(error("sqrt(-1)"),
            "1: the value of this expression is not a finite number");
  EXPECT_EQ(error(""), "1: expected an expression");
}

TEST(Expression, ReportsDivisionByZeroWhileEvaluating) {
  const Compiled c = compile("x / y", {"x", "y"});
  const std::vector<double> args{1.0, 0.0};
  try {
    (void)c.expression.evaluate(args);
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.diagnostic().column, 3);
    EXPECT_EQ(e.diagnostic().message, "division by zero");
  }
  const std::vector<double> ok{1.0, 4.0};
  EXPECT_EQ(c.expression.evaluate(ok), 0.25);
}

TEST(Expression, ReportsNonFiniteResultsWhileEvaluating) {
  const Compiled c = compile("log(x)", {"x"});
  const std::vector<double> args{0.0};
  EXPECT_THROW((void)c.expression.evaluate(args), ParseError);
}

}  // namespace
}  // namespace lsys
