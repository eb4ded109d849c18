#include "tumble/sweep/outcome.hpp"

#include "tumble/scenario/expression.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <stdexcept>
#include <string_view>

namespace tumble {
namespace {

struct NamedReduction {
  std::string_view name;
  ReductionKind kind;
};
// What of the modes an outcome may read, as modes.NAME.
constexpr std::string_view kModesValues[] = {"stable", "unstable", "growth_rate", "frequency"};

constexpr NamedReduction kReductions[] = {{"final", ReductionKind::Final},
                                          {"max", ReductionKind::Max},
                                          {"min", ReductionKind::Min},
                                          {"mean", ReductionKind::Mean},
                                          {"time_of_max", ReductionKind::TimeOfMax},
                                          {"first", ReductionKind::First},
                                          {"count", ReductionKind::Count},
                                          {"jump", ReductionKind::Jump},
                                          {"after", ReductionKind::After}};

bool name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '.';
}

// The first word of an event's text, without its punctuation ("slides: the friction..." ->
// "slides"); a slip that stops is named by "stops".
std::string event_kind(const std::string& what) {
  const auto end = what.find_first_of(" :,");
  const std::string word = what.substr(0, end);
  return word == "slip" ? "stops" : word;
}

// How many arguments a reduction's brackets hold: its commas outside inner brackets, plus one
// ("abs(a), max(b, c)" holds two).
std::size_t top_level_arguments(std::string_view argument) {
  std::size_t count = 1;
  int depth = 0;
  for (const char c : argument) {
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (c == ',' && depth == 0) ++count;
  }
  return count;
}

}  // namespace

bool is_row_condition(const std::string& argument) {
  return argument.find_first_of("<>=!") != std::string::npos;
}

double ModesOutcome::value(const std::string& what) const {
  if (what == "stable") return stable;
  if (what == "unstable") return unstable;
  if (what == "growth_rate") return growth_rate;
  return frequency;
}

bool Outcome::reads_modes() const {
  return std::any_of(reductions.begin(), reductions.end(),
                     [](const Reduction& r) { return r.kind == ReductionKind::Modes; });
}

bool Outcome::reads_run() const {
  return std::any_of(reductions.begin(), reductions.end(),
                     [](const Reduction& r) { return r.kind != ReductionKind::Modes; });
}

bool Reduction::over_events() const {
  return (kind == ReductionKind::First || kind == ReductionKind::Count) &&
         !is_row_condition(argument);
}

Outcome parse_outcome(std::string name, const std::string& text) {
  Outcome outcome;
  outcome.name = std::move(name);
  outcome.text = text;
  std::size_t i = 0;
  while (i < text.size()) {
    // A name starts where the character before it cannot continue one (so "1e5" stays a number).
    if (!name_char(text[i]) || (i > 0 && name_char(text[i - 1]))) {
      outcome.expression += text[i++];
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && name_char(text[end])) ++end;
    const std::string_view word(text.data() + i, end - i);
    if (word.substr(0, 6) == "modes.") {
      const std::string_view what = word.substr(6);
      if (std::find(std::begin(kModesValues), std::end(kModesValues), what) ==
          std::end(kModesValues)) {
        throw std::invalid_argument(
            fmt::format("'{}': {} is not what tumble modes says: use modes.stable, modes.unstable, "
                        "modes.growth_rate (1/s) or modes.frequency (rad/s)",
                        text, word));
      }
      outcome.expression += fmt::format("__r{}", outcome.reductions.size());
      outcome.reductions.push_back({ReductionKind::Modes, std::string(what), {}});
      i = end;
      continue;
    }
    const auto known = std::find_if(std::begin(kReductions), std::end(kReductions),
                                    [&](const NamedReduction& r) { return r.name == word; });
    std::size_t open = end;
    while (open < text.size() && (text[open] == ' ' || text[open] == '\t')) ++open;
    if (known == std::end(kReductions) || open == text.size() || text[open] != '(') {
      outcome.expression.append(word);
      i = end;
      continue;
    }
    int depth = 0;
    std::size_t close = open;
    for (; close < text.size(); ++close) {
      if (text[close] == '(') ++depth;
      if (text[close] == ')' && --depth == 0) break;
    }
    if (close == text.size()) {
      throw std::invalid_argument(
          fmt::format("'{}': {}( at column {} is not closed", text, word, i + 1));
    }
    const std::string argument(
        trim_blanks(std::string_view(text).substr(open + 1, close - open - 1)));
    if (argument.empty()) {
      throw std::invalid_argument(fmt::format(
          "'{}': {}() needs {}", text, word,
          known->kind == ReductionKind::First || known->kind == ReductionKind::Count
              ? "an event (e.g. ball.rolls, impulse.kick) or a condition (e.g. ball.vx < 0)"
              : "a column or an expression of columns, e.g. ball.vx"));
    }
    if (known->kind == ReductionKind::Jump || known->kind == ReductionKind::After) {
      // The event's name has no comma: the first one ends it (X may hold more, atan2(a, b)).
      const auto comma = argument.find(',');
      if (top_level_arguments(argument) != 2) {
        throw std::invalid_argument(
            known->kind == ReductionKind::Jump
                ? fmt::format("'{}': jump() takes a jump and what of it, e.g. jump(impulse.ball, "
                              "knob.Fx) or jump(lock.brake, KE_after); got '{}'",
                              text, argument)
                : fmt::format("'{}': after() takes an event and an expression of the columns, "
                              "e.g. after(floor.rolls, disk.vx); got '{}'",
                              text, argument));
      }
      outcome.expression += fmt::format("__r{}", outcome.reductions.size());
      outcome.reductions.push_back({known->kind,
                                    std::string(trim_blanks(argument.substr(0, comma))),
                                    std::string(trim_blanks(argument.substr(comma + 1)))});
      i = close + 1;
      continue;
    }
    // One argument each: muParser would read "a, E" as two values and keep the last.
    if (const std::size_t count = top_level_arguments(argument); count != 1) {
      throw std::invalid_argument(
          fmt::format("'{}': {}() takes one argument ({}), got {}: '{}'", text, word,
                      known->kind == ReductionKind::First || known->kind == ReductionKind::Count
                          ? "an event or a condition"
                          : "a column or an expression of columns",
                      count, argument));
    }
    outcome.expression += fmt::format("__r{}", outcome.reductions.size());
    outcome.reductions.push_back({known->kind, argument, {}});
    i = close + 1;
  }
  if (outcome.reductions.empty()) {
    throw std::invalid_argument(
        fmt::format("'{}' names no reduction of the run: use final(X), max(X), min(X), mean(X), "
                    "time_of_max(X) of a column or expression X, first(EVENT), count(EVENT), "
                    "jump(JUMP, FIELD), after(EVENT, X), or modes.stable, modes.growth_rate, ...",
                    text));
  }
  return outcome;
}

Outcome parse_record(const std::string& argument) {
  const auto eq = argument.find('=');
  const std::string name(trim_blanks(std::string_view(argument).substr(0, eq)));
  const bool identifier =
      !name.empty() && !(name[0] >= '0' && name[0] <= '9') &&
      std::all_of(name.begin(), name.end(), [](char c) { return name_char(c) && c != '.'; });
  if (eq == std::string::npos || !identifier || eq + 1 == argument.size()) {
    throw std::invalid_argument(fmt::format(
        "'{}': expected NAME=REDUCTION, e.g. top=max(frame.angle) (NAME: letters, digits, _)",
        argument));
  }
  return parse_outcome(name, argument.substr(eq + 1));
}

const std::vector<std::string>& event_kinds() {
  static const std::vector<std::string> kinds = {"slides", "rolls", "sticks", "apart", "touchdown",
                                                 "impact", "lifts", "tips",   "stops"};
  return kinds;
}

bool names_contact_event(const std::string& event, const std::string& contact,
                         const ContactEventRecord& record) {
  return event.size() > contact.size() && event.compare(0, contact.size(), contact) == 0 &&
         event[contact.size()] == '.' &&
         event.compare(contact.size() + 1, std::string::npos, event_kind(record.what)) == 0;
}

bool names_jump(const std::string& event, const JumpRecord& record) {
  // record.what: "impulse NAME", "lock NAME", "motor NAME starts".
  const auto space = record.what.find(' ');
  if (space == std::string::npos) return false;
  const auto end = record.what.find(' ', space + 1);
  const std::string name =
      record.what.substr(0, space) + "." +
      record.what.substr(space + 1, end == std::string::npos ? std::string::npos : end - space - 1);
  return event == name;
}

}  // namespace tumble
