// The expression evaluator behind every number of a scenario: muParser with pi, e, the unit deg
// and the parameters defined so far.
#include "tumble/scenario/expression.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace tumble {
namespace {

constexpr double kPi = std::numbers::pi;

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

}  // namespace
}  // namespace tumble
