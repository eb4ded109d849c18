#include "tumble/sweep/run_recorder.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

namespace tumble {

// One reduction over the rows: an expression of the columns and parameters, and what has been
// gathered of it so far.
struct RunRecorder::RowReduction {
  ReductionKind kind;
  BoundExpression value;
  // For first() and count() of a comparison A < B: A - B, whose zero is where it turns.
  std::unique_ptr<BoundExpression> margin;
  std::size_t rows = 0;
  double last = 0.0, best = 0.0, t_best = 0.0;
  double t_first = 0.0, t_last = 0.0, integral = 0.0;
  bool held = false;  // whether the condition held at the last row
  double last_margin = 0.0, turned_at = 0.0, turns = 0.0;

  RowReduction(ReductionKind k, std::string text, std::span<const BoundExpression::Variable> vars)
      : kind(k), value(text, vars) {
    if (const auto comparison = split_comparison(text)) {
      margin = std::make_unique<BoundExpression>(comparison->margin(), vars);
    }
  }

  bool counts_turns() const { return kind == ReductionKind::First || kind == ReductionKind::Count; }

  void observe_turn(double t) {
    const bool holds = value.evaluate() != 0.0;
    const double m = margin ? margin->evaluate() : 0.0;
    if (holds && !(rows > 0 && held)) {
      // Where A - B crossed zero between the rows, or this row where that is not known.
      double at = t;
      if (rows > 0 && margin && m != last_margin && std::isfinite(m) &&
          std::isfinite(last_margin)) {
        at = t_last + (t - t_last) * last_margin / (last_margin - m);
      }
      if (turns == 0.0) turned_at = at;
      ++turns;
    }
    held = holds;
    last_margin = m;
    t_last = t;
    ++rows;
  }

  void observe(double t) {
    switch (kind) {
      case ReductionKind::First:
      case ReductionKind::Count:
        observe_turn(t);
        return;
      case ReductionKind::Final:
        last = value.evaluate();
        break;
      case ReductionKind::Mean: {
        const double v = value.evaluate();
        if (rows == 0) {
          t_first = t;
        } else {
          integral += 0.5 * (t - t_last) * (v + last);  // trapezoidal rule between rows
        }
        last = v;
        break;
      }
      default: {  // max, min, time_of_max
        const double v = value.evaluate();
        const bool better = kind == ReductionKind::Min ? v < best : v > best;
        if (rows == 0 || better) {
          best = v;
          t_best = t;
        }
        break;
      }
    }
    t_last = t;
    ++rows;
  }

  double result() const {
    if (rows == 0) return std::numeric_limits<double>::quiet_NaN();
    switch (kind) {
      case ReductionKind::Final:
        return last;
      case ReductionKind::Max:
      case ReductionKind::Min:
        return best;
      case ReductionKind::TimeOfMax:
        return t_best;
      case ReductionKind::Mean:
        return t_last > t_first ? integral / (t_last - t_first) : last;
      case ReductionKind::First:
        return turns > 0.0 ? turned_at : std::numeric_limits<double>::quiet_NaN();
      case ReductionKind::Count:
        return turns;
      default:
        return std::numeric_limits<double>::quiet_NaN();
    }
  }
};

// after(EVENT, X): X in each state just after an event, jump or change of modes of the run (t,
// value), in time order; finish() picks the last one at the instant of EVENT's first occurrence.
struct RunRecorder::AfterEvent {
  BoundExpression value;
  std::vector<std::pair<double, double>> samples;

  AfterEvent(const std::string& text, std::span<const BoundExpression::Variable> vars)
      : value(text, vars) {}
};

namespace {

// Whether the scenario can have the event `event` names; if not, why not.
std::string event_problem(const std::string& event, const Scenario& scenario) {
  const auto dot = event.find('.');
  if (dot == std::string::npos) {
    return "expected CONTACT.KIND, event.NAME, impulse.NAME, lock.NAME or motor.NAME";
  }
  const std::string source = event.substr(0, dot), name = event.substr(dot + 1);
  if (source == "event") {
    for (const UserEventSpec& e : scenario.events) {
      if (e.name == name) return "";
    }
    return "the scenario's events: has no event " + name;
  }
  if (source == "impulse") {
    for (const ImpulseSpec& i : scenario.impulses) {
      if (i.name == name) return "";
    }
    return "the scenario has no impulse " + name;
  }
  if (source == "lock" || source == "motor") {
    for (const JointSpec& j : scenario.joints) {
      if (j.name == name) return "";
    }
    return "the scenario has no joint " + name;
  }
  for (const ContactSpec& c : scenario.contacts) {
    if (c.name != source) continue;
    const auto& kinds = event_kinds();
    if (std::find(kinds.begin(), kinds.end(), name) != kinds.end()) return "";
    return fmt::format("a contact's events are {}", fmt::join(kinds, ", "));
  }
  return "no contact, event, impulse, lock or motor is named " + source;
}

// What an expression's unknown name may be instead.
std::string unknown_name_hint(const ExpressionError& error) {
  return error.unknown_name().empty()
             ? ""
             : "; the columns are the trajectory CSV's (t, BODY.x, BODY.w1, JOINT.angle, "
               "CONTACT.slip, E, ...) and the parameters are the scenario's";
}

}  // namespace

// Throws std::invalid_argument for a field that names none of them.
RunRecorder::JumpField RunRecorder::jump_field(const std::string& field,
                                               std::span<const std::string> joints) {
  if (field == "KE_before") return {JumpField::What::KineticEnergyBefore, 0, 0};
  if (field == "KE_after") return {JumpField::What::KineticEnergyAfter, 0, 0};
  static constexpr std::string_view kComponents[6] = {"Fx", "Fy", "Fz", "Mx", "My", "Mz"};
  const auto dot = field.rfind('.');
  if (dot != std::string::npos) {
    const auto joint = std::find(joints.begin(), joints.end(), field.substr(0, dot));
    const auto component = std::find(std::begin(kComponents), std::end(kComponents),
                                     std::string_view(field).substr(dot + 1));
    if (joint != joints.end() && component != std::end(kComponents)) {
      return {JumpField::What::ReactionImpulse, static_cast<std::size_t>(joint - joints.begin()),
              static_cast<int>(component - std::begin(kComponents))};
    }
  }
  throw std::invalid_argument(fmt::format(
      "a jump's field is KE_before, KE_after or JOINT.Fx, .Fy, .Fz, .Mx, .My, .Mz (its reaction "
      "impulse; the joints are {}), not '{}'",
      joints.empty() ? std::string("none") : fmt::format("{}", fmt::join(joints, ", ")), field));
}

RunRecorder::RunRecorder(std::span<const Outcome> outcomes, const ColumnLayout& layout,
                         const Scenario& scenario)
    : layout_(layout), row_(layout, scenario.parameters) {
  const std::span<const BoundExpression::Variable> row_variables = row_.variables();
  const std::span<const BoundExpression::Variable> parameter_variables = row_.parameter_variables();
  for (const Outcome& outcome : outcomes) {
    OutcomeSlots slots;
    slots.reductions = outcome.reductions;
    slots.values = std::make_unique<std::vector<double>>(outcome.reductions.size(), 0.0);
    std::vector<BoundExpression::Variable> value_variables(parameter_variables.begin(),
                                                           parameter_variables.end());
    for (std::size_t r = 0; r < outcome.reductions.size(); ++r) {
      const Reduction& reduction = outcome.reductions[r];
      value_variables.push_back({fmt::format("__r{}", r), &(*slots.values)[r]});
      if (reduction.kind == ReductionKind::Modes) {
        slots.row_reduction.push_back(0);
        continue;
      }
      if (reduction.kind == ReductionKind::Jump) {
        const std::string source = reduction.argument.substr(0, reduction.argument.find('.'));
        std::string why = source == "impulse" || source == "lock" || source == "motor"
                              ? event_problem(reduction.argument, scenario)
                              : "expected impulse.NAME, lock.NAME or motor.NAME";
        if (why.empty()) {
          try {
            slots.jump_field.resize(outcome.reductions.size());
            slots.jump_field[r] = jump_field(reduction.field, layout.joints);
            slots.row_reduction.push_back(0);
            continue;
          } catch (const std::invalid_argument& e) {
            why = e.what();
          }
        }
        throw std::invalid_argument(fmt::format("{}: jump({}, {}): {}", outcome.text,
                                                reduction.argument, reduction.field, why));
      }
      if (reduction.kind == ReductionKind::After) {
        if (const std::string why = event_problem(reduction.argument, scenario); !why.empty()) {
          throw std::invalid_argument(fmt::format("{}: after({}, {}): {}", outcome.text,
                                                  reduction.argument, reduction.field, why));
        }
        try {
          after_events_.push_back(std::make_unique<AfterEvent>(reduction.field, row_variables));
        } catch (const ExpressionError& error) {
          throw std::invalid_argument(
              fmt::format("{}: {}{}", outcome.text, error.what(), unknown_name_hint(error)));
        }
        slots.row_reduction.push_back(after_events_.size() - 1);
        continue;
      }
      if (reduction.over_events()) {
        if (const std::string why = event_problem(reduction.argument, scenario); !why.empty()) {
          throw std::invalid_argument(
              fmt::format("{}: event '{}': {}", outcome.text, reduction.argument, why));
        }
        slots.row_reduction.push_back(0);
        continue;
      }
      try {
        row_reductions_.push_back(
            std::make_unique<RowReduction>(reduction.kind, reduction.argument, row_variables));
      } catch (const ExpressionError& error) {
        throw std::invalid_argument(
            fmt::format("{}: {}{}", outcome.text, error.what(), unknown_name_hint(error)));
      }
      slots.row_reduction.push_back(row_reductions_.size() - 1);
    }
    try {
      slots.expression = std::make_unique<BoundExpression>(outcome.expression, value_variables);
    } catch (const ExpressionError& error) {
      throw std::invalid_argument(fmt::format("{}: {}", outcome.text, error.what()));
    }
    outcomes_.push_back(std::move(slots));
  }
  // Only the columns the reductions read are taken from each row.
  std::vector<const BoundExpression*> read;
  for (const auto& reduction : row_reductions_) {
    read.push_back(&reduction->value);
    if (reduction->margin) read.push_back(reduction->margin.get());
  }
  for (const auto& after : after_events_) read.push_back(&after->value);
  row_.read_by(read);
}

RunRecorder::~RunRecorder() = default;

bool RunRecorder::fits(const ColumnLayout& layout, const Scenario& scenario) const {
  // The same owners give the same columns.
  if (layout.bodies != layout_.bodies || layout.joints != layout_.joints ||
      layout.joint_coordinates != layout_.joint_coordinates ||
      layout.contacts != layout_.contacts || layout.elements != layout_.elements ||
      layout.planar != layout_.planar ||
      scenario.parameters.size() != row_.parameter_names().size()) {
    return false;
  }
  std::size_t i = 0;
  for (const auto& [name, value] : scenario.parameters) {
    if (name != row_.parameter_names()[i++]) return false;
  }
  return true;
}

void RunRecorder::start(const Scenario& scenario) {
  row_.set_parameters(scenario.parameters);
  for (const auto& reduction : row_reductions_) {
    reduction->rows = 0;
    reduction->integral = 0.0;
    reduction->turns = 0.0;
  }
  for (const auto& after : after_events_) after->samples.clear();
}

void RunRecorder::observe(const OutputRow& row) {
  if (row_reductions_.empty()) return;  // events only: the rows are not needed
  row_.take(row);
  for (const auto& reduction : row_reductions_) reduction->observe(row.t);
}

void RunRecorder::observe_event_state(const OutputRow& row) {
  if (after_events_.empty()) return;
  row_.take(row);
  for (const auto& after : after_events_)
    after->samples.emplace_back(row.t, after->value.evaluate());
}

std::vector<double> RunRecorder::finish(std::span<const ContactEventRecord> events,
                                        std::span<const JumpRecord> jumps,
                                        std::span<const UserEventRecord> user_events,
                                        const ModesOutcome* modes) const {
  std::vector<double> results;
  for (const OutcomeSlots& slots : outcomes_) {
    for (std::size_t r = 0; r < slots.reductions.size(); ++r) {
      const Reduction& reduction = slots.reductions[r];
      double& value = (*slots.values)[r];
      if (reduction.kind == ReductionKind::Modes) {
        value = modes ? modes->value(reduction.argument) : std::numeric_limits<double>::quiet_NaN();
        continue;
      }
      if (reduction.kind == ReductionKind::Jump) {
        // At its first occurrence.
        const JumpField& field = slots.jump_field[r];
        value = std::numeric_limits<double>::quiet_NaN();
        for (const JumpRecord& jump : jumps) {
          if (!names_jump(reduction.argument, jump)) continue;
          if (field.what == JumpField::What::KineticEnergyBefore) {
            value = jump.kinetic_energy_before;
          } else if (field.what == JumpField::What::KineticEnergyAfter) {
            value = jump.kinetic_energy_after;
          } else if (field.joint < jump.reaction_impulses.size()) {
            const JointReaction& impulse = jump.reaction_impulses[field.joint];
            value = field.component < 3 ? impulse.F_W(field.component)
                                        : impulse.M_J_W(field.component - 3);
          }
          break;
        }
        continue;
      }
      const bool after = reduction.kind == ReductionKind::After;
      if (!reduction.over_events() && !after) {
        value = row_reductions_[slots.row_reduction[r]]->result();
        continue;
      }
      // Contact events, jumps and the scenario's events are each in time order; the first is the
      // earliest of them.
      double first = std::numeric_limits<double>::quiet_NaN();
      double count = 0.0;
      for (const ContactEventRecord& e : events) {
        if (!names_contact_event(reduction.argument, layout_.contacts[e.contact], e)) continue;
        if (count == 0.0 || e.t < first) first = e.t;
        ++count;
      }
      for (const JumpRecord& jump : jumps) {
        if (!names_jump(reduction.argument, jump)) continue;
        if (count == 0.0 || jump.t < first) first = jump.t;
        ++count;
      }
      for (const UserEventRecord& e : user_events) {
        if (reduction.argument != "event." + e.name) continue;
        if (count == 0.0 || e.t < first) first = e.t;
        ++count;
      }
      if (after) {
        // The last state at that instant: the one the run went on from.
        value = std::numeric_limits<double>::quiet_NaN();
        for (const auto& [t, x] : after_events_[slots.row_reduction[r]]->samples) {
          if (t > first) break;
          if (t == first) value = x;
        }
        continue;
      }
      value = reduction.kind == ReductionKind::First ? first : count;
    }
    results.push_back(slots.expression->evaluate());
  }
  return results;
}

}  // namespace tumble
