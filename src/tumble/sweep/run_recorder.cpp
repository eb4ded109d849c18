#include "tumble/sweep/run_recorder.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

namespace tumble {

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
        reductions_.push_back(
            std::make_unique<RunReduction>(reduction.kind, reduction.argument, row_variables));
      } catch (const ExpressionError& error) {
        throw std::invalid_argument(
            fmt::format("{}: {}{}", outcome.text, error.what(), unknown_name_hint(error)));
      }
      slots.row_reduction.push_back(reductions_.size() - 1);
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
  for (const auto& reduction : reductions_) {
    read.push_back(&reduction->value());
    if (reduction->margin()) read.push_back(reduction->margin());
    (reduction->reads_pieces() ? reads_pieces_ : reads_rows_) = true;
    switch (reduction->kind()) {
      case ReductionKind::Mean:
        piece_samples_ = PieceSamples::Need::Mean;
        break;
      case ReductionKind::Max:
      case ReductionKind::Min:
      case ReductionKind::TimeOfMax:
        piece_samples_ = std::max(piece_samples_, PieceSamples::Need::Middle);
        break;
      default:
        break;
    }
  }
  for (const auto& after : after_events_) read.push_back(&after->value);
  row_.read_by(read);
}

RunRecorder::~RunRecorder() = default;

bool RunRecorder::fits(const ColumnLayout& layout, const Scenario& scenario) const {
  // The same owners give the same columns.
  if (layout.bodies != layout_.bodies || layout.joints != layout_.joints ||
      layout.joint_coordinates != layout_.joint_coordinates ||
      layout.contacts != layout_.contacts || layout.contact_columns != layout_.contact_columns ||
      layout.elements != layout_.elements || layout.planar != layout_.planar ||
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
  run_row_t_.reset();
  for (const auto& reduction : reductions_) reduction->start();
  for (const auto& after : after_events_) after->samples.clear();
}

void RunRecorder::observe(const OutputRow& row) {
  if (!reads_rows_ && !reads_pieces_) return;
  row_.take(row);
  run_row_t_ = row.t;
  if (!reads_rows_) return;  // final() alone reads rows
  for (const auto& reduction : reductions_) {
    if (!reduction->reads_pieces()) reduction->observe_row();
  }
}

void RunRecorder::observe_piece(PieceRows& piece) {
  if (!reads_pieces_) return;
  const bool extras = row_.reads_extras(), quantities = row_.reads_quantities();
  const auto load = [&](double t) {
    // A run's row has every column; at a step's end it is the state the piece gives there.
    const bool holds_row = run_row_t_ == t && piece.is_step_end(t) && !piece.planar();
    run_row_t_.reset();
    if (!holds_row) row_.take(piece.row_at(t, extras, quantities));
  };
  const PieceSamples samples =
      PieceSamples::on(piece.t_begin(), piece.t_end(), !piece.continues(), piece_samples_);
  for (int k = samples.fresh_start ? 0 : 1; k < samples.count; ++k) {
    load(samples.t[static_cast<std::size_t>(k)]);
    for (const auto& reduction : reductions_) {
      if (reduction->reads_pieces()) reduction->take_sample(k);
    }
  }
  for (const auto& reduction : reductions_) {
    if (reduction->reads_pieces()) reduction->observe_piece(samples, load);
  }
}

void RunRecorder::observe_event_state(const OutputRow& row) {
  if (after_events_.empty()) return;
  row_.take(row);
  run_row_t_.reset();
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
        value = reductions_[slots.row_reduction[r]]->result();
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
