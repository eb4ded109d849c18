#pragma once
// What a sweep records of each run, and what `tumble find` asks of it: an expression over
// reductions of the run, such as `max(frame.angle) > pi/4` or `first(ball.rolls)`.
//   final(X), max(X), min(X), mean(X), time_of_max(X): X is an expression of the trajectory's
//     columns (ball.vx, hinge.angle, E, ...) and the scenario's parameters, over the run's rows;
//     mean is the average over time (trapezoidal rule between rows);
//   first(EVENT), count(EVENT): the time of an event's first occurrence (nan if none) and how
//     many there were. EVENT is CONTACT.KIND for a contact's events (KIND one of event_kinds()),
//     or impulse.NAME, lock.NAME, motor.NAME for the jumps at an impulse, a lock or a motor's
//     start;
//   jump(JUMP, FIELD): at a jump's first occurrence (JUMP: impulse.NAME, lock.NAME, motor.NAME;
//     nan if none), FIELD: KE_before or KE_after (J, the whole system's), or JOINT.Fx ... JOINT.Mz
//     (the joint's reaction impulse, N s and N m s about the joint point, world: events.csv's);
//   after(EVENT, X): X, an expression of the columns and parameters as for final(), in the state
//     just after EVENT's first occurrence (nan if none): after an impact's or an impulse's jump,
//     after the contacts' modes are decided again there (the rolling speed once a slip stops:
//     after(floor.rolls, disk.vx); the rebound: after(floor.impact, ball.vz));
//   modes.stable, modes.unstable, modes.growth_rate, modes.frequency: what `tumble modes` says of
//     the run's initial state (modes_outcome()), with no parentheses: a verdict (1 or 0), the
//     largest real part of the eigenvalues (1/s), the lowest natural frequency among the modes
//     that oscillate without growing (rad/s; nan if none). An outcome of these alone needs no
//     integration.
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "tumble/contact/contact_status.hpp"
#include "tumble/dynamics/hybrid_state.hpp"

namespace tumble {

enum class ReductionKind { Final, Max, Min, Mean, TimeOfMax, First, Count, Jump, After, Modes };

struct Reduction {
  ReductionKind kind = ReductionKind::Final;
  // A row expression, an EVENT name or a CONDITION for First and Count, or for Modes what of the
  // modes ("stable", "growth_rate", ...).
  std::string argument;
  std::string field;  // Jump: what of it (KE_before, KE_after, JOINT.Fx, ...); After: X
  bool over_events() const;
};

// The values the modes.* names read, from the modes of a run's initial state.
struct ModesOutcome {
  double stable = 0.0, unstable = 0.0;  // 1 or 0: the verdict
  double growth_rate = 0.0;             // max Re lambda, 1/s
  // The lowest |lambda| of the modes that oscillate without growing, rad/s; nan if none.
  double frequency = std::numeric_limits<double>::quiet_NaN();
  double value(const std::string& what) const;  // by the name after "modes."
};

// Whether the argument of first() or count() is a condition of the columns (it compares) rather
// than an event's name.
bool is_row_condition(const std::string& argument);

// "max(abs(hinge.angle)) > 0.5" becomes the expression "__r0 > 0.5" over the values of its
// reductions, {Max, "abs(hinge.angle)"}.
struct Outcome {
  std::string name;                   // the sweep.csv column; for find, "condition"
  std::string text;                   // as given
  std::string expression;             // with each reduction replaced by __r0, __r1, ...
  std::vector<Reduction> reductions;  // in order of appearance
  bool reads_modes() const;           // a modes.* name
  bool reads_run() const;             // a reduction of the rows or the events
};

// Throws std::invalid_argument, naming the text, when it has no reduction, a reduction without
// its closing parenthesis, with nothing inside it, or with more than one argument (final(a, E)).
Outcome parse_outcome(std::string name, const std::string& text);
// "NAME=REDUCTION" (a --record argument); NAME must be an identifier.
Outcome parse_record(const std::string& argument);

// What each contact event is named by (CONTACT.KIND): its kind, the first word of what the event
// says ("slides", "rolls", "sticks", "apart", "touchdown", "impact", "lifts", "tips", "stops").
const std::vector<std::string>& event_kinds();
// Whether a contact event (by its contact's name) or a jump is the one `event` names.
bool names_contact_event(const std::string& event, const std::string& contact,
                         const ContactEventRecord& record);
bool names_jump(const std::string& event, const JumpRecord& record);

}  // namespace tumble
