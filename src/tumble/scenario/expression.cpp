#include "tumble/scenario/expression.hpp"

#include <muParser.h>

#include <fmt/format.h>
#include <algorithm>
#include <charconv>
#include <cmath>
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

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
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
  return "the parameters defined here are " + fmt::format("{}", fmt::join(names, ", ")) +
         " (a parameter may use only those above it)";
}

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
    throw ExpressionError("'" + name +
                              "' is reserved (the constants pi and e, the units deg, rpm, cm, mm, "
                              "ms); rename the parameter",
                          "");
  }
  const mu::funmap_type& functions = language_functions();
  if (functions.find(name) != functions.end()) {
    throw ExpressionError(
        "'" + name + "' is a function of the expression language; rename the " + "parameter", "");
  }
  if (std::find(names_.begin(), names_.end(), name) != names_.end()) {
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
  const std::string_view text = trim(expression);
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
      value = parser.Eval();
    } catch (const mu::Parser::exception_type& error) {
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
  return Comparison{text.substr(0, *at), text.substr(right), text[*at] == '>'};
}

struct BoundExpression::Impl {
  mu::Parser parser;
};

BoundExpression::BoundExpression(std::string text, std::span<const Variable> variables)
    : impl_(std::make_unique<Impl>()), text_(std::move(text)) {
  mu::Parser& parser = impl_->parser;
  try {
    // Columns are named owner.field ("ball.vx"): the dot is part of a name.
    parser.DefineNameChars("0123456789_.abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ");
    define_constants_and_units(parser);
    for (const Variable& variable : variables) {
      // muParser reads the value through the pointer at each evaluation and never writes it.
      parser.DefineVar(variable.name, const_cast<double*>(variable.value));
    }
    parser.SetExpr(text_);
    // Compiles it (a syntax error throws here) and lists its names, known or not.
    for (const auto& used : parser.GetUsedVar()) {
      const std::string& name = used.first;
      const bool known = std::any_of(variables.begin(), variables.end(),
                                     [&](const Variable& v) { return v.name == name; });
      if (!known) {
        throw ExpressionError("expression '" + text_ + "': unknown name '" + name + "'", name);
      }
      used_names_.push_back(name);
    }
    // Listing the names leaves muParser to compile the expression again at its next evaluation,
    // with allocations: done here, so that evaluating never allocates (an event's function is
    // evaluated inside a run's steps).
    parser.Eval();
    // A lone variable ("ball.vx", a sweep's usual record) is read without muParser's evaluation:
    // the same double, a sixth of the cost.
    for (const Variable& variable : variables) {
      if (variable.name == trim(text_)) direct_ = variable.value;
    }
  } catch (const mu::Parser::exception_type& error) {
    const bool unknown = error.GetCode() == mu::ecUNASSIGNABLE_TOKEN;
    throw ExpressionError("expression '" + text_ + "': " + error.GetMsg(),
                          unknown ? error.GetToken() : "");
  }
}

BoundExpression::~BoundExpression() = default;

double BoundExpression::evaluate() const {
  if (direct_ != nullptr) return *direct_;
  try {
    return impl_->parser.Eval();
  } catch (const mu::Parser::exception_type& error) {
    throw ExpressionError("expression '" + text_ + "': " + error.GetMsg(), "");
  }
}

}  // namespace tumble
