#pragma once
// The numbers of a scenario are expressions, evaluated by muParser (not by hand-written code):
// the usual operators and functions (sqrt, sin, cos, atan2, ...), the constants pi and e, the
// parameters defined so far, and the postfix unit deg ("30 deg" = 30 pi / 180 rad).
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tumble {

// The text without its leading and trailing spaces and tabs (an expression, a --record's name).
inline std::string_view trim_blanks(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// An expression that cannot be evaluated. what() reads "expression 'L*q': <muParser's message>"
// with a hint of the names that are defined; unknown_name() is the name muParser did not know, if
// that was the trouble.
class ExpressionError : public std::runtime_error {
 public:
  ExpressionError(const std::string& what, std::string unknown_name)
      : std::runtime_error(what), unknown_name_(std::move(unknown_name)) {}
  const std::string& unknown_name() const { return unknown_name_; }

 private:
  std::string unknown_name_;
};

class ExpressionEvaluator {
 public:
  ExpressionEvaluator();
  ~ExpressionEvaluator();
  ExpressionEvaluator(const ExpressionEvaluator&) = delete;
  ExpressionEvaluator& operator=(const ExpressionEvaluator&) = delete;

  // Makes `name` usable in later expressions with this value. Throws ExpressionError for a name
  // that is not an identifier, or that is taken (pi, e, deg, a function such as sqrt, or a name
  // already defined).
  void define(const std::string& name, double value);
  // Gives a defined name another value, for the expressions evaluated after (a sweep's next run).
  // Throws ExpressionError for a name that is not defined.
  void redefine(const std::string& name, double value);

  // The value of the expression; a plain number ("1e-8") is read exactly as strtod would. Throws
  // ExpressionError for a syntax error, an unknown name, or a result that is not finite.
  double evaluate(const std::string& expression) const;

  // The names given to define(), in order.
  const std::vector<std::string>& names() const { return names_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<std::string> names_;
};

// Names for a message: "a, b, c", or the first 20 and how many there are ("p0, p1, ..., p19, ...
// (1000000 in all)"), so that the message of a scenario of a million parameters stays a line.
std::string listed_names(const std::vector<std::string>& names);

// Throws ExpressionError if the expression would assign (muParser's `=`, which writes into a
// variable), whatever names it uses: every expression of tumble only reads. An expression that is
// wrong otherwise passes here, for the error where it is evaluated. BoundExpression and
// ExpressionEvaluator::evaluate refuse assignments themselves; this lets a reader refuse one where
// it reads the text (an event's condition, compiled only when a run starts).
void check_read_only(const std::string& expression);

// The names an expression may use: each identifier outside its numbers ("2e3*a + sin(b)" gives
// a, sin, b). A superset of the parameters it reads, never missing one, so a name not listed is
// a name the expression's value cannot depend on.
std::vector<std::string_view> expression_names(std::string_view expression);

// A condition that is one comparison "A < B" (or >, <=, >=) outside parentheses, without && or
// ||: where it turns is where A - B crosses zero.
struct Comparison {
  std::string left, right;
  bool greater = false;   // > or >=: it becomes true as A - B rises through zero
  bool or_equal = false;  // <= or >=
  std::string margin() const { return "(" + left + ") - (" + right + ")"; }
};
// The comparison `text` is, if it is one.
std::optional<Comparison> split_comparison(const std::string& text);

// An expression over variables whose values change between evaluations (a row's columns, a
// run's parameters), compiled once and evaluated many times, with the constants and units of
// the scenario's expressions. A variable's name may hold dots: the columns are named "ball.vx".
class BoundExpression {
 public:
  struct Variable {
    std::string name;
    const double* value;  // read at each evaluation; must outlive the expression
  };
  // How muParser compiles it. Optimised: its optimiser folds constants and rewrites some forms
  // over variables (x^3 as x*x*x, ...), which may round otherwise than the same text over
  // constants. AsConstants: the operations as written, each one what muParser's folding computes
  // where the variables are constants (a scenario's parameters, ExpressionEvaluator), so the
  // same doubles as a read of the scenario at those values.
  enum class Compile { Optimised, AsConstants };
  // Throws ExpressionError for a syntax error or a name that is not among `variables`.
  BoundExpression(std::string text, std::span<const Variable> variables,
                  Compile compile = Compile::Optimised);
  ~BoundExpression();
  BoundExpression(const BoundExpression&) = delete;
  BoundExpression& operator=(const BoundExpression&) = delete;

  // The value now (which may be infinite or NaN: a row's quotient by zero).
  double evaluate() const;
  const std::string& text() const { return text_; }
  // The variables it reads.
  const std::vector<std::string>& used_names() const { return used_names_; }

 private:
  struct Impl;
  // What a few common forms reduce to, read without muParser's evaluation (the same doubles, a
  // sixth of the cost): a lone variable ("ball.vx", a sweep's usual record), a comparison of two
  // operands ("prism.w3 < 0", a first()'s condition) and their difference ("(prism.w3) - (0)",
  // the margin that locates where it turns true). An operand is a variable or a plain number.
  enum class Direct { None, Value, Less, LessEqual, Greater, GreaterEqual, Difference };
  void find_direct_form(const std::map<std::string, const double*>& found);

  std::unique_ptr<Impl> impl_;
  std::string text_;
  std::vector<std::string> used_names_;
  Direct direct_ = Direct::None;
  const double* left_ = nullptr;  // the operands of a direct form (Value: left_ alone)
  const double* right_ = nullptr;
  double numbers_[2] = {0.0, 0.0};  // a number operand's value, where left_ or right_ points
};

}  // namespace tumble
