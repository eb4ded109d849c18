#include "tumble/integrators/driver.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "tumble/math/sign_change.hpp"

namespace tumble {

namespace {

bool crosses(double g_before, double g_after, EventDirection direction) {
  const bool rising = g_before < 0.0 && g_after >= 0.0;
  const bool falling = g_before > 0.0 && g_after <= 0.0;
  switch (direction) {
    case EventDirection::Rising:
      return rising;
    case EventDirection::Falling:
      return falling;
    case EventDirection::Both:
      return rising || falling;
  }
  return false;
}

// The output schedule: row k at t0 + k * every (computed, never accumulated, so no drift), and
// always a last row at t_end.
class OutputClock {
 public:
  OutputClock(double t0, double t_end, double every, long next_row)
      : t0_(t0), t_end_(t_end), every_(every), k_(next_row) {}
  bool every_step() const { return every_ <= 0.0; }
  double next() const { return row_time(k_); }
  // The time of the row before the next (none: every step makes a row, or none was made yet).
  std::optional<double> previous() const {
    if (every_step() || k_ < 1) return std::nullopt;
    return row_time(k_ - 1);
  }
  void advance() { ++k_; }
  long next_row() const { return k_; }

 private:
  double row_time(long k) const {
    const double t = t0_ + static_cast<double>(k) * every_;
    // A row within round-off of the end is the end row.
    return t > t_end_ - 1e-12 * std::max(1.0, std::abs(t_end_)) ? t_end_ : t;
  }

  double t0_, t_end_, every_;
  long k_;
};

}  // namespace

namespace {

// A step shorter than this fraction of the run's span, kCollapsedSteps times in a row, ends the
// run: its step size has collapsed.
constexpr double kCollapsedStep = 1e-12;
constexpr long kCollapsedSteps = 1000;

// Events this many, within kChatterWindow of the run's span, end the run: its events chatter. A
// Zeno-like sequence that settles (a bouncing ball's bounces, shrinking geometrically until the
// contact settles) takes tens; a cone that lands on its side while its apex slides, flipping
// between the two every nanosecond, took 790,882 events (56 MB of events, 7 GB of memory with
// the defaults) in 1.6e-4 s.
constexpr std::size_t kChatterEvents = 1000;
constexpr double kChatterWindow = 1e-6;

bool chatters(const std::vector<EventRecord>& events, double span) {
  return events.size() >= kChatterEvents &&
         events.back().t - events[events.size() - kChatterEvents].t < kChatterWindow * span;
}

// The steps from where `position` says the run stands (after start, or at a checkpoint) to
// t_end.
void drive(Integrator& integrator, OdeSystem& system, DriverPosition& position, double t_end,
           const DriverOptions& options, const Observer& observe,
           const CheckpointObserver& on_checkpoint, IntegrationReport& report) {
  const std::size_t event_count = system.events().size();
  const auto event_specs = system.events();
  const Eigen::Index n = integrator.y().size();
  VecX y_row(n), y_event(n);
  VecX& g_before = position.g_before;
  VecX g_after(g_before.size()), g_probe(g_before.size());
  // Which events this step has handled: two located at the same instant (two conditions on the
  // same quantity) are both reported.
  std::vector<char> handled_here(static_cast<std::size_t>(g_before.size()), 0);
  OutputClock clock(position.t0, t_end, options.output_every, position.next_row);
  bool checkpoint_due = static_cast<bool>(on_checkpoint);

  // Rows in (t_previous, t_upto] from the continuous extension of the last step; with
  // `including` false, in (t_previous, t_upto).
  auto emit_rows_until = [&](double t_upto, bool including = true) {
    if (clock.every_step()) return;
    for (double t = clock.next(); t < t_upto || (including && t == t_upto); t = clock.next()) {
      if (t == integrator.t()) {
        observe(t, integrator.y());
      } else {
        // Between steps the continuous extension drifts off the constraints by the local error;
        // a row shows the state put back on them, as every step's end is.
        integrator.dense_output(t, y_row);
        system.project(t, y_row);
        observe(t, y_row);
      }
      clock.advance();
      if (t >= t_end) break;
    }
  };

  // The state just after an event, a jump or a change of modes, for whoever reads it.
  const auto event_state = [&](double t, const VecX& y) {
    if (options.on_event_state) options.on_event_state(t, y);
  };

  // The root of g_k inside the last step, on the dense output.
  auto locate = [&](std::size_t k) {
    const auto ki = static_cast<Eigen::Index>(k);
    return sign_change_in(integrator.t_previous(), integrator.t(), g_before(ki), g_after(ki),
                          [&](double c) {
                            integrator.dense_output(c, y_event);
                            system.event_functions(c, y_event, g_probe);
                            return g_probe(ki);
                          });
  };

  // The run's smooth pieces, for whoever reads the solution between the rows: each ends at an
  // event, a jump, a breakpoint or a step's end, and the next starts there.
  double piece_start = integrator.t();
  bool piece_continues = false;  // the run's first piece, or one after a jump, starts afresh
  auto piece_until = [&](double t_upto) {
    if (!options.on_piece) return;
    if (t_upto > piece_start || !piece_continues) {
      options.on_piece(SolutionPiece(integrator, system, piece_start, t_upto, piece_continues));
    }
    piece_start = t_upto;
    piece_continues = true;
  };
  auto piece_restarts = [&](double t) {
    piece_start = t;
    piece_continues = false;
  };

  long steps = position.steps;
  bool stopped_by_event = false;
  while (integrator.t() < t_end) {
    // The budget is of steps taken and handled: the run stops before a step past it.
    if (steps >= options.max_steps) {
      report.failure =
          fmt::format("stopped at t = {:.17g} s after {} = {} steps; raise it or loosen rtol",
                      integrator.t(), options.max_steps_name, options.max_steps);
      break;
    }
    const double t_stop = std::min(t_end, system.next_breakpoint(integrator.t()));
    integrator.bound_next_step(system.step_limit(integrator.t(), integrator.y()));
    if (event_count > 0 && system.events_rescreened()) {
      system.event_functions(integrator.t(), integrator.y(), g_before);
    }
    const StepOutcome outcome = integrator.step(t_stop);
    if (outcome != StepOutcome::Ok) {
      report.failure =
          outcome == StepOutcome::StepSizeUnderflow
              ? fmt::format(
                    "step size underflow at t = {:.17g} s: the solution is too stiff or "
                    "singular there for rtol/atol",
                    integrator.t())
              : fmt::format("the state became non-finite (NaN or infinity) after t = {:.17g} s",
                            integrator.t());
      break;
    }
    // A run whose steps have shrunk to nothing beside its span would take them until max_steps
    // (10 million by default: minutes) and get nowhere: values so extreme (x1e100) or a solution
    // so singular that no step of a sensible size meets rtol/atol. A thousand such steps in a row
    // are no transient: an impact or a breakpoint costs a few.
    if (integrator.t() - integrator.t_previous() < kCollapsedStep * (t_end - position.t0)) {
      if (++position.short_steps >= kCollapsedSteps) {
        report.failure = fmt::format(
            "the step size collapsed at t = {:.17g} s: the last {} steps were each shorter than "
            "{:g} of the run's {:g} s (the last {:.3g} s); the values are too extreme or the "
            "solution too stiff or singular there for rtol/atol",
            integrator.t(), kCollapsedSteps, kCollapsedStep, t_end - position.t0,
            integrator.t() - integrator.t_previous());
        break;
      }
    } else {
      position.short_steps = 0;
    }
    if (options.stop_requested && options.stop_requested()) {
      report.failure = fmt::format("interrupted at t = {:.17g} s", integrator.t());
      report.interrupted = true;
      break;
    }
    ++steps;

    bool restarted = false, stopped = false, chattered = false;
    if (event_count > 0) {
      system.event_functions(integrator.t(), integrator.y(), g_after);
      // Handle the crossings of this step in time order, until one changes the state.
      std::size_t handled = 0;
      double t_last_event = integrator.t_previous();
      std::fill(handled_here.begin(), handled_here.end(), 0);
      while (handled < event_count) {
        double t_first = std::numeric_limits<double>::infinity();
        std::size_t k_first = event_count;
        for (std::size_t k = 0; k < event_count; ++k) {
          const auto ki = static_cast<Eigen::Index>(k);
          if (handled_here[k] || !crosses(g_before(ki), g_after(ki), event_specs[k].direction)) {
            continue;
          }
          const double t_k = locate(k);
          if (t_k >= t_last_event && (t_k > t_last_event || handled > 0) && t_k < t_first) {
            t_first = t_k;
            k_first = k;
          }
        }
        if (k_first == event_count) break;
        emit_rows_until(t_first);
        if (t_first == integrator.t()) {
          y_event = integrator.y();
        } else {
          integrator.dense_output(t_first, y_event);
        }
        piece_until(t_first);
        const EventAction action = system.on_event(k_first, t_first, y_event);
        report.events.push_back({t_first, k_first, action});
        t_last_event = t_first;
        handled_here[k_first] = 1;
        ++handled;
        if (chatters(report.events, t_end - position.t0)) {
          report.failure = fmt::format(
              "events chatter at t = {:.17g} s: the last {} came within {:.3g} s (the last: {}); "
              "the system switches faster than the motion can tell its modes apart, and would "
              "take millions of events to get nowhere",
              t_first, kChatterEvents,
              t_first - report.events[report.events.size() - kChatterEvents].t,
              event_specs[k_first].name);
          chattered = true;
          break;
        }
        if (action == EventAction::Record) {
          event_state(t_first, y_event);
          continue;
        }
        if (action == EventAction::Stop) {
          // The run ends with a row at the event, unless the schedule's row fell there.
          if (clock.previous() != t_first) observe(t_first, y_event);
          event_state(t_first, y_event);
          report.t_reached = t_first;
          stopped = true;
          stopped_by_event = true;
        } else {
          system.project(t_first, y_event);
          integrator.restart(t_first, y_event);
          system.event_functions(t_first, integrator.y(), g_before);
          event_state(t_first, integrator.y());
          piece_restarts(t_first);
          restarted = true;
        }
        break;
      }
    }
    if (stopped || chattered) break;
    if (restarted) continue;

    // At a breakpoint the row at its instant waits for the jump: a load, an impulse, a motor's
    // start or a lock acts from its time on (`from <= t`), so that row shows the state after it.
    const bool breakpoint = integrator.t() == t_stop && t_stop < t_end;
    emit_rows_until(integrator.t(), !breakpoint);
    if (clock.every_step() && !breakpoint) observe(integrator.t(), integrator.y());
    piece_until(integrator.t());
    if (event_count > 0) {
      g_before = g_after;
      if (system.refresh_event_functions(integrator.t(), integrator.y())) {
        system.event_functions(integrator.t(), integrator.y(), g_before);
        event_state(integrator.t(), integrator.y());
        piece_restarts(integrator.t());
      }
    }

    if (breakpoint) {
      // A breakpoint: the system may change the state (an impulse), then the method restarts so
      // that no step straddles the discontinuity.
      VecX& y_break = y_event;
      y_break = integrator.y();
      system.at_breakpoint(t_stop, y_break);
      system.project(t_stop, y_break);
      integrator.restart(t_stop, y_break);
      piece_restarts(t_stop);
      emit_rows_until(t_stop);
      if (clock.every_step()) observe(t_stop, integrator.y());
      event_state(t_stop, integrator.y());
      if (event_count > 0) {
        g_probe = g_before;  // just before the jump
        system.event_functions(t_stop, integrator.y(), g_before);
        // A condition the jump itself turns is at the jump's instant: the steps after it see it
        // already turned, and would never report it.
        for (std::size_t k = 0; k < event_count && !stopped; ++k) {
          const auto ki = static_cast<Eigen::Index>(k);
          if (!event_specs[k].across_jumps ||
              !crosses(g_probe(ki), g_before(ki), event_specs[k].direction)) {
            continue;
          }
          y_break = integrator.y();
          const EventAction action = system.on_event(k, t_stop, y_break);
          report.events.push_back({t_stop, k, action});
          if (action == EventAction::Stop) {
            // The run ends with a row at the jump, unless one was made there.
            if (!clock.every_step() && clock.previous() != t_stop) observe(t_stop, integrator.y());
            report.t_reached = t_stop;
            stopped = true;
            stopped_by_event = true;
          }
        }
        if (stopped) {
          piece_until(t_stop);  // the state the run ends in, just after the jump
          break;
        }
      }
    }

    if (checkpoint_due && integrator.t() >= options.checkpoint_after) {
      checkpoint_due = false;
      position.next_row = clock.next_row();
      position.steps = steps;  // (position.rows is kept up to date by the row counter)
      position.events = report.events;
      on_checkpoint({integrator.clone_onto(system), position});
      if (options.stop_at_checkpoint) break;
    }
  }
  if (!stopped_by_event) report.t_reached = integrator.t();
}

IntegrationReport run_driver(Integrator& integrator, OdeSystem& system, DriverPosition& position,
                             double t_end, const DriverOptions& options, const Observer& observe,
                             const CheckpointObserver& on_checkpoint,
                             const std::function<void(const Observer&)>& start) {
  IntegrationReport report;
  report.events = position.events;
  // Rows are counted against max_rows: a run whose rows would fill the disk (one per adaptive
  // step, which the reader cannot count beforehand) stops with the rows so far, as a failure.
  const Observer counted = [&](double t, const VecX& y) {
    if (++position.rows > options.max_rows) {
      throw std::runtime_error(fmt::format(
          "it would write more than simulate.max_rows = {} output rows; write less often "
          "(simulate.output_every), or raise max_rows on purpose",
          options.max_rows));
    }
    observe(t, y);
  };
  try {
    start(counted);
    drive(integrator, system, position, t_end, options, counted, on_checkpoint, report);
  } catch (const std::runtime_error& e) {
    // The system found it cannot go on (e.g. contact constraints that contradict each other):
    // the run fails there, with the rows so far, like a step size underflow.
    report.failure = fmt::format("at t = {:.17g} s: {}", integrator.t(), e.what());
    report.t_reached = integrator.t();
  }
  report.stats = integrator.stats();
  report.completed = report.failure.empty();
  return report;
}

}  // namespace

IntegrationReport integrate(Integrator& integrator, OdeSystem& system, double t0, const VecX& y0,
                            double t_end, const DriverOptions& options, const Observer& observe,
                            const CheckpointObserver& on_checkpoint) {
  DriverPosition position;
  position.t0 = t0;
  position.g_before.resize(static_cast<Eigen::Index>(system.events().size()));
  return run_driver(integrator, system, position, t_end, options, observe, on_checkpoint,
                    [&](const Observer& first_row) {
                      system.begin(t0, y0);
                      integrator.start(system, t0, y0, t_end);
                      first_row(t0, integrator.y());
                      if (position.g_before.size() > 0)
                        system.event_functions(t0, integrator.y(), position.g_before);
                    });
}

IntegrationReport resume_integration(Integrator& integrator, OdeSystem& system,
                                     const DriverPosition& position, double t_end,
                                     const DriverOptions& options, const Observer& observe,
                                     const CheckpointObserver& on_checkpoint) {
  DriverPosition resumed = position;
  return run_driver(integrator, system, resumed, t_end, options, observe, on_checkpoint,
                    [](const Observer&) {});
}

}  // namespace tumble
