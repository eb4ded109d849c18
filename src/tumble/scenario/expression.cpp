#include "tumble/scenario/expression.hpp"

#include <muParser.h>

#include <fmt/format.h>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <string_view>
#include <unordered_map>

namespace tumble {
namespace {

// Units written after a number ("30 deg", "1500 rpm", "15 cm"): each converts to the SI unit the
// key takes (rad, rad/s, m, s). The list is the one reserved_units() names.
double degrees_to_radians(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}
double rpm_to_radians_per_second(double rpm) {
  return rpm * std::numbers::pi / 30.0;
}
double centimetres_to_metres(double cm) {
  return cm / 100.0;
}
double millimetres_to_metres(double mm) {
  return mm / 1000.0;
}
double milliseconds_to_seconds(double ms) {
  return ms / 1000.0;
}

struct Unit {
  const char* name;
  double (*to_si)(double);
};
constexpr Unit kUnits[] = {{"deg", degrees_to_radians},
                           {"rpm", rpm_to_radians_per_second},
                           {"cm", centimetres_to_metres},
                           {"mm", millimetres_to_metres},
                           {"ms", milliseconds_to_seconds}};

bool is_unit(std::string_view name) {
  return std::any_of(std::begin(kUnits), std::end(kUnits),
                     [&](const Unit& unit) { return name == unit.name; });
}

// A plain decimal number, read exactly; nullopt for anything else (left to muParser).
std::optional<double> plain_number(std::string_view text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

bool is_identifier(std::string_view name) {
  if (name.empty()) return false;
  const auto letter = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
  };
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  if (!letter(name.front())) return false;
  return std::all_of(name.begin(), name.end(), [&](char c) { return letter(c) || digit(c); });
}

std::string names_hint(const std::vector<std::string>& names) {
  if (names.empty()) return "no parameters are defined here; add them under `parameters:`";
  return "the parameters defined here are " + listed_names(names) +
         " (a parameter may use only those above it)";
}

// muParser's `=` writes into the variable on its left (a row's column, a reduction's value): the
// one operator of its language with a side effect (2.3 has no +=, -=, *=, /=; it reads them as an
// unexpected '='). Every expression of tumble only reads, so an assignment is refused before the
// expression is first evaluated, by the compiled bytecode (where `==`, `<=` and `>=` are
// comparisons of their own, never an assignment).
bool assigns(const mu::ParserBase& parser) {
  const mu::ParserByteCode& code = parser.GetByteCode();
  if (code.GetSize() == 0) return false;
  const mu::SToken* tokens = code.GetBase();
  return std::any_of(tokens, tokens + code.GetSize(),
                     [](const mu::SToken& token) { return token.Cmd == mu::cmASSIGN; });
}

// An '=' that muParser refused before it could assign: to a constant or a parameter (they are
// folded into numbers), to a bracket, a second '=' in a row, or `+=` and its kin.
bool refused_assignment(const mu::ParserError& error) {
  return error.GetCode() == mu::ecUNEXPECTED_OPERATOR && error.GetToken() == "=";
}

// `x = 1` and `x += 1` with x unknown are refused by muParser for the name, before it reaches the
// '=': compiled again with unknown names allowed (GetUsedVar does), the assignment shows.
bool assigns_with_unknown_names(mu::ParserBase& parser) {
  try {
    parser.GetUsedVar();
    return assigns(parser);
  } catch (const mu::ParserError& error) {
    return refused_assignment(error);
  }
}

ExpressionError assignment_error(const std::string& text) {
  return ExpressionError("expression '" + text +
                             "': '=' would assign a value; an expression only reads its names "
                             "(a comparison is ==, <, >, <= or >=)",
                         "");
}

// A comma outside a function's brackets makes muParser give several values, of which Eval returns
// the last: "1, 2" would silently be 2.
ExpressionError several_values_error(const std::string& text, int count) {
  return ExpressionError(fmt::format("expression '{}' gives {} values (a comma outside a "
                                     "function's brackets); one value is needed",
                                     text, count),
                         "");
}

// The characters of a bound expression's names: columns are named owner.field ("ball.vx"), so the
// dot is part of a name.
constexpr const char* kNameChars =
    "0123456789_.abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ";

// The language's constants and units, on a parser of its own.
void define_constants_and_units(mu::Parser& parser) {
  parser.DefineConst("pi", std::numbers::pi);
  parser.DefineConst("e", std::numbers::e);
  for (const Unit& unit : kUnits) parser.DefinePostfixOprt(unit.name, unit.to_si);
}

// The functions of the expression language (sqrt, sin, ...), which no parameter may be named.
const mu::funmap_type& language_functions() {
  static const mu::Parser prototype;
  return prototype.GetFunDef();
}

}  // namespace

// Most numbers of a scenario are plain numbers or a parameter's name; both are read without
// muParser, whose parser costs tens of microseconds to make and each expression microseconds to
// compile (a sweep reads the scenario once per run). The parser is made at the first expression
// that needs it.
struct ExpressionEvaluator::Impl {
  std::unordered_map<std::string, double> values;
  std::optional<mu::Parser> parser;

  mu::Parser& expression_parser() {
    if (!parser) {
      parser.emplace();
      define_constants_and_units(*parser);
      for (const auto& [name, value] : values) parser->DefineConst(name, value);
    }
    return *parser;
  }
};

ExpressionEvaluator::ExpressionEvaluator() : impl_(std::make_unique<Impl>()) {}

ExpressionEvaluator::~ExpressionEvaluator() = default;

void ExpressionEvaluator::define(const std::string& name, double value) {
  if (!is_identifier(name)) {
    throw ExpressionError("'" + name +
                              "' is not a valid parameter name; use letters, digits and '_', "
                              "starting with a letter",
                          "");
  }
  if (name == "pi" || name == "e" || is_unit(name)) {
    // Every expression of the scenario may use these, so a parameter cannot take their names.
    throw ExpressionError(
        "'" + name +
            "' is reserved: pi and e are the constants 3.14159... and 2.71828... (Euler's "
            "number) every expression may use, and deg, rpm, cm, mm, ms are units written after "
            "a number; rename the parameter" +
            (name == "e" ? " (a coefficient of restitution, say, as e_r or cor)" : ""),
        "");
  }
  const mu::funmap_type& functions = language_functions();
  if (functions.find(name) != functions.end()) {
    throw ExpressionError(
        "'" + name + "' is a function of the expression language; rename the " + "parameter", "");
  }
  // By the values' hash: a scenario's parameters are defined in O(1) each.
  if (impl_->values.contains(name)) {
    throw ExpressionError("parameter '" + name + "' is defined twice", "");
  }
  try {
    if (impl_->parser) impl_->parser->DefineConst(name, value);
  } catch (const mu::Parser::exception_type& error) {
    throw ExpressionError("parameter '" + name + "': " + error.GetMsg(), "");
  }
  impl_->values.emplace(name, value);
  names_.push_back(name);
}

void ExpressionEvaluator::redefine(const std::string& name, double value) {
  const auto defined = impl_->values.find(name);
  if (defined == impl_->values.end()) {
    throw ExpressionError("parameter '" + name + "' is not defined", name);
  }
  defined->second = value;
  // muParser folds a constant into each expression as it compiles it; evaluate() compiles each
  // time, so the new value is what later expressions see.
  if (impl_->parser) impl_->parser->DefineConst(name, value);
}

double ExpressionEvaluator::evaluate(const std::string& expression) const {
  const std::string_view text = trim_blanks(expression);
  if (text.empty()) throw ExpressionError("expected a number or an expression, got nothing", "");
  std::optional<double> value = plain_number(text);
  if (!value) {
    if (const auto parameter = impl_->values.find(std::string(text));
        parameter != impl_->values.end()) {
      value = parameter->second;
    }
  }
  if (!value) {
    try {
      mu::Parser& parser = impl_->expression_parser();
      parser.SetExpr(std::string(text));
      // The parser has constants only, no variable that `=` could write (assigns() is false for
      // any expression that evaluates): an assignment is a compile error, told apart below.
      value = parser.Eval();
      if (parser.GetNumResults() != 1) {
        throw several_values_error(expression, parser.GetNumResults());
      }
    } catch (const mu::Parser::exception_type& error) {
      if (refused_assignment(error) ||
          (impl_->parser && assigns_with_unknown_names(*impl_->parser))) {
        throw assignment_error(expression);
      }
      const bool unknown = error.GetCode() == mu::ecUNASSIGNABLE_TOKEN;
      std::string what = "expression '" + expression + "': " + error.GetMsg();
      if (unknown) what += "; " + names_hint(names_);
      throw ExpressionError(what, unknown ? error.GetToken() : "");
    }
  }
  if (!std::isfinite(*value)) {
    const std::string shown = std::isnan(*value) ? "nan" : fmt::format("{}", *value);
    throw ExpressionError(
        "expression '" + expression + "' evaluates to " + shown + "; a finite number is needed",
        "");
  }
  return *value;
}

std::string listed_names(const std::vector<std::string>& names) {
  constexpr std::size_t kShown = 20;
  if (names.size() <= kShown) return fmt::format("{}", fmt::join(names, ", "));
  return fmt::format("{}, ... ({} in all)", fmt::join(names.begin(), names.begin() + kShown, ", "),
                     names.size());
}

void check_read_only(const std::string& expression) {
  // One parser per thread (a sweep reads scenarios on every thread), made at its first use.
  thread_local mu::Parser parser;
  thread_local bool made = false;
  if (!made) {
    parser.DefineNameChars(kNameChars);
    define_constants_and_units(parser);
    made = true;
  }
  parser.SetExpr(expression);
  if (assigns_with_unknown_names(parser)) throw assignment_error(expression);
}

std::vector<std::string_view> expression_names(std::string_view expression) {
  std::vector<std::string_view> names;
  const auto letter = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
  };
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  std::size_t i = 0;
  while (i < expression.size()) {
    const char c = expression[i];
    if (digit(c) || c == '.') {
      // A number, its exponent's letter included ("2e3"), but nothing after it: "2a" stays a
      // name a (whatever muParser makes of it), so no name is ever missed.
      while (i < expression.size() && (digit(expression[i]) || expression[i] == '.')) ++i;
      if (i + 1 < expression.size() && (expression[i] == 'e' || expression[i] == 'E')) {
        std::size_t j = i + 1;
        if (expression[j] == '+' || expression[j] == '-') ++j;
        if (j < expression.size() && digit(expression[j])) {
          i = j;
          while (i < expression.size() && digit(expression[i])) ++i;
        }
      }
    } else if (letter(c)) {
      const std::size_t start = i;
      while (i < expression.size() && (letter(expression[i]) || digit(expression[i]))) ++i;
      names.push_back(expression.substr(start, i - start));
    } else {
      ++i;
    }
  }
  return names;
}

std::optional<Comparison> split_comparison(const std::string& text) {
  int depth = 0;
  std::optional<std::size_t> at;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (depth != 0) continue;
    if (c == '&' || c == '|' || c == '=' || c == '!') {
      if (c == '=' && at && i == *at + 1) continue;  // <= or >=
      return std::nullopt;
    }
    if (c == '<' || c == '>') {
      if (at) return std::nullopt;
      at = i;
    }
  }
  if (!at) return std::nullopt;
  const std::size_t right = *at + (text[*at + 1] == '=' ? 2 : 1);
  return Comparison{text.substr(0, *at), text.substr(right), text[*at] == '>', right == *at + 2};
}

struct BoundExpression::Impl {
  mu::Parser parser;
};

BoundExpression::BoundExpression(std::string text, std::span<const Variable> variables,
                                 Compile compile)
    : impl_(std::make_unique<Impl>()), text_(std::move(text)) {
  mu::Parser& parser = impl_->parser;
  try {
    if (compile == Compile::AsConstants) parser.EnableOptimizer(false);
    parser.DefineNameChars(kNameChars);
    define_constants_and_units(parser);
    parser.SetExpr(text_);
    // Compiled before any variable is defined, it lists the names it uses (unknown names allowed
    // here; a syntax error throws), and its bytecode, not yet evaluated, shows whether it would
    // assign. Only the variables it names are then defined: a scenario may have a million
    // parameters, and each expression over a row costs one pass over their names, not a million
    // definitions.
    const mu::varmap_type used = parser.GetUsedVar();
    if (assigns(parser)) throw assignment_error(text_);
    std::map<std::string, const double*> found;
    for (const Variable& variable : variables) {
      // The last of a name wins, as a second DefineVar of it would.
      if (used.contains(variable.name)) found.insert_or_assign(variable.name, variable.value);
    }
    for (const auto& [name, unused] : used) {
      const auto variable = found.find(name);
      if (variable == found.end()) {
        throw ExpressionError("expression '" + text_ + "': unknown name '" + name + "'", name);
      }
      // muParser reads the value through the pointer at each evaluation and never writes it (an
      // expression that assigns was refused above).
      parser.DefineVar(name, const_cast<double*>(variable->second));
      used_names_.push_back(name);
    }
    // Defining the variables leaves muParser to compile the expression again at its next
    // evaluation, with allocations: done here, so that evaluating never allocates (an event's
    // function is evaluated inside a run's steps).
    parser.Eval();
    if (parser.GetNumResults() != 1) throw several_values_error(text_, parser.GetNumResults());
    find_direct_form(found);
  } catch (const mu::Parser::exception_type& error) {
    if (refused_assignment(error)) throw assignment_error(text_);
    const bool unknown = error.GetCode() == mu::ecUNASSIGNABLE_TOKEN;
    throw ExpressionError("expression '" + text_ + "': " + error.GetMsg(),
                          unknown ? error.GetToken() : "");
  }
}

BoundExpression::~BoundExpression() = default;

void BoundExpression::find_direct_form(const std::map<std::string, const double*>& found) {
  // An operand's value: a variable's pointer, or a plain number (digits first: no sign, no inf or
  // nan) kept in numbers_[slot]. muParser reads such a number to the same double (both round
  // correctly), and its a - b, a < b, ... are these operations on them.
  const auto operand = [&](std::string_view text, int slot) -> const double* {
    text = trim_blanks(text);
    if (const auto variable = found.find(std::string(text)); variable != found.end()) {
      return variable->second;
    }
    if (text.empty() || !(std::isdigit(static_cast<unsigned char>(text.front())) != 0)) {
      return nullptr;
    }
    const std::optional<double> number = plain_number(text);
    if (!number) return nullptr;
    numbers_[slot] = *number;
    return &numbers_[slot];
  };
  const std::string_view text = trim_blanks(text_);
  if (const double* value = operand(text, 0); value != nullptr && value != &numbers_[0]) {
    direct_ = Direct::Value;
    left_ = value;
    return;
  }
  // The margin split_comparison's Comparison writes: "(A) - (B)".
  if (text.starts_with('(') && text.ends_with(')')) {
    const std::size_t middle = text.find(") - (");
    if (middle != std::string_view::npos &&
        text.find(") - (", middle + 1) == std::string_view::npos) {
      left_ = operand(text.substr(1, middle - 1), 0);
      right_ = operand(text.substr(middle + 5, text.size() - middle - 6), 1);
      if (left_ != nullptr && right_ != nullptr) {
        direct_ = Direct::Difference;
        return;
      }
    }
  }
  if (const auto comparison = split_comparison(text_)) {
    left_ = operand(comparison->left, 0);
    right_ = operand(comparison->right, 1);
    if (left_ != nullptr && right_ != nullptr) {
      const bool or_equal = comparison->or_equal;
      direct_ = comparison->greater ? (or_equal ? Direct::GreaterEqual : Direct::Greater)
                                    : (or_equal ? Direct::LessEqual : Direct::Less);
      return;
    }
  }
  left_ = right_ = nullptr;
}

double BoundExpression::evaluate() const {
  switch (direct_) {
    case Direct::None:
      break;
    case Direct::Value:
      return *left_;
    case Direct::Less:
      return *left_ < *right_ ? 1.0 : 0.0;
    case Direct::LessEqual:
      return *left_ <= *right_ ? 1.0 : 0.0;
    case Direct::Greater:
      return *left_ > *right_ ? 1.0 : 0.0;
    case Direct::GreaterEqual:
      return *left_ >= *right_ ? 1.0 : 0.0;
    case Direct::Difference:
      return *left_ - *right_;
  }
  try {
    return impl_->parser.Eval();
  } catch (const mu::Parser::exception_type& error) {
    throw ExpressionError("expression '" + text_ + "': " + error.GetMsg(), "");
  }
}

}  // namespace tumble
