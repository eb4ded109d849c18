// The expression evaluator behind every number of a scenario: muParser with pi, e, the unit deg
// and the parameters defined so far.
#include "tumble/scenario/expression.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "test_constants.hpp"

namespace tumble {
namespace {

using test::kPi;

// The message of the ExpressionError that evaluating `text` throws ("" if none).
std::string error_of(const ExpressionEvaluator& evaluator, const std::string& text) {
  try {
    evaluator.evaluate(text);
  } catch (const ExpressionError& error) {
    return error.what();
  }
  return "";
}

TEST(Expression, PlainNumbersAreReadExactly) {
  const ExpressionEvaluator evaluator;
  EXPECT_EQ(evaluator.evaluate("0.1"), 0.1);
  EXPECT_EQ(evaluator.evaluate("1e-8"), 1e-8);
  EXPECT_EQ(evaluator.evaluate(" -2.5e3 "), -2500.0);
  EXPECT_EQ(evaluator.evaluate("12"), 12.0);
}

TEST(Expression, ConstantsFunctionsAndDegrees) {
  const ExpressionEvaluator evaluator;
  EXPECT_DOUBLE_EQ(evaluator.evaluate("pi/4"), kPi / 4);
  EXPECT_DOUBLE_EQ(evaluator.evaluate("e"), std::numbers::e);
  EXPECT_DOUBLE_EQ(evaluator.evaluate("sqrt(2)/2"), std::sqrt(2.0) / 2);
  EXPECT_DOUBLE_EQ(evaluator.evaluate("30 deg"), kPi / 6);
  EXPECT_DOUBLE_EQ(evaluator.evaluate("30deg"), kPi / 6);
  EXPECT_DOUBLE_EQ(evaluator.evaluate("-90 deg"), -kPi / 2);
  EXPECT_DOUBLE_EQ(evaluator.evaluate("2*1e-3"), 2e-3);
  EXPECT_DOUBLE_EQ(evaluator.evaluate("atan2(1, 1)"), kPi / 4);
}

TEST(Expression, DefinedNamesAreUsableInLaterExpressions) {
  ExpressionEvaluator evaluator;
  evaluator.define("L", 2.0);
  evaluator.define("tilt", evaluator.evaluate("45 deg"));
  EXPECT_DOUBLE_EQ(evaluator.evaluate("sqrt(2)*L/2"), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(evaluator.evaluate("L*cos(tilt)"), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(evaluator.evaluate("L deg"), 2 * kPi / 180);
  EXPECT_EQ(evaluator.names(), (std::vector<std::string>{"L", "tilt"}));
}

TEST(Expression, ReservedAndInvalidNamesCannotBeDefined) {
  ExpressionEvaluator evaluator;
  const auto message_of = [&](const std::string& name) -> std::string {
    try {
      evaluator.define(name, 1.0);
    } catch (const ExpressionError& error) {
      return error.what();
    }
    return "";
  };
  EXPECT_NE(message_of("pi").find("'pi' is reserved"), std::string::npos);
  EXPECT_NE(message_of("deg").find("'deg' is reserved"), std::string::npos);
  // The restitution's usual letter: the message says why it is taken and what to use instead.
  EXPECT_NE(message_of("e").find("'e' is reserved: pi and e are the constants"), std::string::npos);
  EXPECT_NE(message_of("e").find("(a coefficient of restitution, say, as e_r or cor)"),
            std::string::npos);
  EXPECT_NE(message_of("sqrt").find("'sqrt' is a function"), std::string::npos);
  EXPECT_NE(message_of("2x").find("'2x' is not a valid parameter name"), std::string::npos);
  EXPECT_NE(message_of("a b").find("not a valid parameter name"), std::string::npos);
  evaluator.define("a", 1.0);
  EXPECT_NE(message_of("a").find("parameter 'a' is defined twice"), std::string::npos);
}

TEST(Expression, ErrorsCarryTheExpressionAndMuParsersMessage) {
  ExpressionEvaluator evaluator;
  evaluator.define("a", 1.0);
  EXPECT_EQ(error_of(evaluator, "2*(3"), "expression '2*(3': Missing parenthesis");
  EXPECT_EQ(error_of(evaluator, "3*Q"),
            "expression '3*Q': Unexpected token \"Q\" found at position 2.; the parameters "
            "defined here are a (a parameter may use only those above it)");
  try {
    evaluator.evaluate("b+1");
    ADD_FAILURE() << "no error";
  } catch (const ExpressionError& error) {
    EXPECT_EQ(error.unknown_name(), "b");
  }
  EXPECT_EQ(error_of(evaluator, "  "), "expected a number or an expression, got nothing");
  EXPECT_EQ(error_of(evaluator, "1/0"),
            "expression '1/0' evaluates to inf; a finite number is needed");
  EXPECT_EQ(error_of(evaluator, "sqrt(-1)"),
            "expression 'sqrt(-1)' evaluates to nan; a finite number is needed");
}

// muParser's `=` assigns; no expression of tumble may (red-team finding: a sweep's
// `max(prism.w3 = 100)` wrote into the row the other records read). Every form is refused, by
// name, and the comparisons that look like it keep their meaning.
TEST(Expression, AnExpressionCannotAssign) {
  ExpressionEvaluator evaluator;
  evaluator.define("a", 1.0);
  const std::string refused = "'=' would assign a value; an expression only reads its names";
  for (const std::string text :
       {"a = 5", "x = 5", "1 + (a = 2)", "max(a = 100, 1)", "a += 1", "a -= 1", "a *= 2", "a /= 2",
        "(a) = 3", "a = a = 3", "0 ? a = 1 : 2"}) {
    EXPECT_EQ(error_of(evaluator, text),
              "expression '" + text + "': " + refused + " (a comparison is ==, <, >, <= or >=)");
  }
  EXPECT_EQ(evaluator.evaluate("a == 1"), 1.0);
  EXPECT_EQ(evaluator.evaluate("a == 2"), 0.0);
  EXPECT_EQ(evaluator.evaluate("a <= 1"), 1.0);
  EXPECT_EQ(evaluator.evaluate("a >= 2"), 0.0);
  EXPECT_EQ(evaluator.evaluate("a != 1"), 0.0);
  EXPECT_EQ(evaluator.evaluate("a"), 1.0);
}

// A bound expression reads variables through pointers (a row's columns): an assignment would
// write through them. It is refused before the expression is first evaluated, and the variable
// keeps its value.
TEST(Expression, ABoundExpressionCannotWriteItsVariables) {
  double w3 = 1.0, x = 2.0;
  const BoundExpression::Variable variables[] = {{"prism.w3", &w3}, {"ball.x", &x}};
  const auto error_of_bound = [&](const std::string& text) -> std::string {
    try {
      BoundExpression expression(text, variables);
    } catch (const ExpressionError& error) {
      return error.what();
    }
    return "";
  };
  for (const std::string text :
       {"prism.w3 = 100", "max(prism.w3 = 100, 1)", "ball.x + (prism.w3 = -5)",
        "0 ? prism.w3 = 1 : 2", "unknown = 1", "prism.w3 += 1", "(prism.w3) = 3"}) {
    EXPECT_NE(error_of_bound(text).find("expression '" + text + "': '=' would assign a value"),
              std::string::npos)
        << text << ": " << error_of_bound(text);
    EXPECT_EQ(w3, 1.0) << text;
    EXPECT_EQ(x, 2.0) << text;
  }
  const BoundExpression equal("prism.w3 == 1", variables);
  EXPECT_EQ(equal.evaluate(), 1.0);
  const BoundExpression at_most("ball.x <= prism.w3", variables);
  EXPECT_EQ(at_most.evaluate(), 0.0);
  EXPECT_EQ(w3, 1.0);
  EXPECT_EQ(x, 2.0);
}

// A comma outside a function's brackets gives muParser several values, of which it would keep the
// last: "1, 2" is refused, not read as 2 (max(1, 2) is one value).
TEST(Expression, SeveralValuesAreRefused) {
  const ExpressionEvaluator evaluator;
  EXPECT_EQ(error_of(evaluator, "1, 2"),
            "expression '1, 2' gives 2 values (a comma outside a function's brackets); one value "
            "is needed");
  EXPECT_EQ(evaluator.evaluate("max(1, 2)"), 2.0);
  double a = 1.0, e = 5.0;
  const BoundExpression::Variable variables[] = {{"a", &a}, {"E", &e}};
  try {
    BoundExpression expression("a, E", variables);
    ADD_FAILURE() << "no error";
  } catch (const ExpressionError& error) {
    EXPECT_STREQ(error.what(),
                 "expression 'a, E' gives 2 values (a comma outside a function's brackets); one "
                 "value is needed");
  }
}

// An unknown name's hint lists the first parameters, not every one of a large scenario's.
TEST(Expression, TheHintOfManyParametersIsOneLine) {
  ExpressionEvaluator evaluator;
  for (int i = 0; i < 1000; ++i) evaluator.define(fmt::format("p{}", i), i);
  EXPECT_EQ(
      error_of(evaluator, "2*q"),
      "expression '2*q': Unexpected token \"q\" found at position 2.; the parameters "
      "defined here are p0, p1, p2, p3, p4, p5, p6, p7, p8, p9, p10, p11, p12, p13, p14, p15, "
      "p16, p17, p18, p19, ... (1000 in all) (a parameter may use only those above it)");
  EXPECT_EQ(evaluator.evaluate("p999 + p0"), 999.0);
  try {
    evaluator.define("p500", 1.0);
    ADD_FAILURE() << "no error";
  } catch (const ExpressionError& error) {
    EXPECT_STREQ(error.what(), "parameter 'p500' is defined twice");
  }
}

TEST(Expression, NoParametersSaysWhereToDefineThem) {
  const ExpressionEvaluator evaluator;
  EXPECT_NE(error_of(evaluator, "L")
                .find("no parameters are defined here; add them under "
                      "`parameters:`"),
            std::string::npos);
}

}  // namespace
}  // namespace tumble

namespace tumble {
namespace {

// expression_names lists every identifier outside the numbers (a superset of the parameters an
// expression reads: a sweep shares a model on it, so it must never miss one).
TEST(Expression, NamesAnExpressionMayUse) {
  using Names = std::vector<std::string_view>;
  EXPECT_EQ(expression_names("2e3*a + sin(b)"), (Names{"a", "sin", "b"}));
  EXPECT_EQ(expression_names("1e-5"), Names{});
  EXPECT_EQ(expression_names("-.5E+2"), Names{});
  EXPECT_EQ(expression_names("2a"), Names{"a"});
  EXPECT_EQ(expression_names("1e"), Names{"e"});
  EXPECT_EQ(expression_names("x_1*3.5e+2 deg"), (Names{"x_1", "deg"}));
  EXPECT_EQ(expression_names("10^(-decades)"), Names{"decades"});
}

// redefine gives later expressions the new value, through muParser as well as directly.
TEST(Expression, RedefinedValuesReachLaterExpressions) {
  ExpressionEvaluator evaluator;
  evaluator.define("a", 2.0);
  EXPECT_EQ(evaluator.evaluate("a^3 + 1"), 9.0);
  evaluator.redefine("a", 3.0);
  EXPECT_EQ(evaluator.evaluate("a"), 3.0);
  EXPECT_EQ(evaluator.evaluate("a^3 + 1"), 28.0);
  EXPECT_THROW(evaluator.redefine("b", 1.0), ExpressionError);
}

// The forms a BoundExpression reads without muParser (a variable, a comparison of two operands,
// their difference as split_comparison's margin writes it) give muParser's own doubles: each is
// set beside the same operation written so that muParser evaluates it, over values where a
// shortcut would most likely go wrong (equal, signed zeros, infinities, NaN, subnormal).
TEST(Expression, DirectFormsAreMuParsersValues) {
  double a = 0.0, b = 0.0;
  const BoundExpression::Variable variables[] = {{"ball.a", &a}, {"b", &b}};
  const std::vector<std::pair<std::string, std::string>> forms = {
      {"ball.a < b", "(ball.a) < (b)"}, {"ball.a <= b", "(ball.a) <= (b)"},
      {"ball.a > 0", "(ball.a) > (0)"}, {" ball.a >= 2.5 ", "(ball.a) >= (2.5)"},
      {"(ball.a) - (b)", "ball.a - b"}, {"(ball.a) - (0.1)", "ball.a - 0.1"},
      {"(1e-3) - (b)", "1e-3 - b"},     {"ball.a", "(ball.a)"}};
  const double inf = std::numeric_limits<double>::infinity();
  const double values[] = {0.0,
                           -0.0,
                           1.0,
                           2.5,
                           0.1,
                           1e-3,
                           -7.25,
                           4.9e-324,
                           inf,
                           -inf,
                           std::numeric_limits<double>::quiet_NaN()};
  for (const auto& [direct_text, parsed_text] : forms) {
    const BoundExpression direct(direct_text, variables);
    const BoundExpression parsed(parsed_text, variables);
    for (const double x : values) {
      for (const double y : values) {
        a = x;
        b = y;
        const double d = direct.evaluate(), p = parsed.evaluate();
        EXPECT_TRUE(std::memcmp(&d, &p, sizeof d) == 0 || (std::isnan(d) && std::isnan(p)))
            << direct_text << " at " << x << ", " << y << ": " << d << " against " << p;
      }
    }
  }
}

// Compiled AsConstants over a variable, an expression gives what the evaluator gives with that
// variable a constant (muParser folds it as it compiles), bit for bit: the shared-model runs of a
// sweep rely on it. Its optimiser would write x^3 as x*x*x and fold 2*x/3 otherwise.
TEST(Expression, CompiledAsConstantsAnExpressionFoldsAsTheReadDoes) {
  double x = 0.0;
  const BoundExpression::Variable variables[] = {{"x", &x}};
  for (const std::string text :
       {"x^3", "x^4 - x^2", "10^(-x)", "2*x/3", "x/10 + 1", "-x^2", "3 * x * 7", "sin(x) * x",
        "sqrt(x^2 + 1) / x", "x * 30 deg", "x * 1500 rpm / 7", "1 / (x - 3)^5"}) {
    const BoundExpression compiled(text, variables, BoundExpression::Compile::AsConstants);
    for (const double value : {0.1, 0.3, 1.0 / 3.0, 2.7, 7.1, 1e-5, 123.456, -4.4}) {
      ExpressionEvaluator evaluator;
      evaluator.define("x", value);
      x = value;
      double read = 0.0;
      try {
        read = evaluator.evaluate(text);
      } catch (const ExpressionError&) {
        continue;  // not finite there
      }
      const double bound = compiled.evaluate();
      EXPECT_EQ(std::memcmp(&read, &bound, sizeof read), 0)
          << text << " at x = " << value << ": "
          << fmt::format("{:.17g} against {:.17g}", read, bound);
    }
  }
}

}  // namespace
}  // namespace tumble
