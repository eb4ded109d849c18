#pragma once
// Runs an Integrator on an OdeSystem from t0 to t_end and builds on its three calls (step,
// dense_output, restart) everything a simulation needs:
//  - output rows at t0 + k * output_every from the continuous extension, projected as a step's
//    end is (or at every step);
//  - located events: sign changes of the system's g_k between two steps are bracketed and then
//    pinned down by the Illinois variant of regula falsi on the dense output, to a bracket of a
//    few ulps of t; the system then records, jumps (the method restarts) or stops;
//  - breakpoints: a step lands exactly on each, the system may change the state there, and the
//    method restarts, so no step straddles a discontinuity of f;
//  - the solution's smooth pieces (each step, cut at its events), for what reads the run between
//    its rows.
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "tumble/integrators/integrator.hpp"

namespace tumble {

class SolutionPiece;

struct DriverOptions {
  double output_every = 0.0;    // s; 0: one row per accepted step
  long max_steps = 10'000'000;  // accepted steps before the run is declared failed
  // What the failure message calls that budget: the scenario's key, or the command line's option
  // where a sweep or a search sets it for each run.
  std::string_view max_steps_name = "simulate.max_steps";
  long max_rows = 1'000'000;  // output rows before the run is stopped (exit 4): disk, not time
  // A checkpoint at the end of the first accepted step that reaches this time (s), once that
  // step's rows, events and breakpoint are done; with stop_at_checkpoint the run ends there.
  double checkpoint_after = std::numeric_limits<double>::infinity();
  bool stop_at_checkpoint = false;
  // Asked after each accepted step whether to stop there (Python's Ctrl-C); empty: never. The run
  // then ends with the rows so far and IntegrationReport::interrupted.
  std::function<bool()> stop_requested;
  // Called with the state just after each event, jump or change of the system's modes is
  // handled (after an impact's or an impulse's jump, at its instant), for what is read "just
  // after" an event (a sweep's after(EVENT, X)); empty: not called. y is only valid during the
  // call. Several calls may come at one instant: the last has the state the run goes on from.
  std::function<void(double t, const VecX& y)> on_event_state;
  // Called with each smooth piece of the solution the run goes along, in time order: for what
  // is read between the rows (a sweep's max, min, mean and conditions); empty: not called.
  std::function<void(const SolutionPiece& piece)> on_piece;
};

// A smooth piece of the solution: [t_begin, t_end] inside the last step, with no event, jump,
// breakpoint or change of the system's modes inside it (each ends one piece and starts the next).
// The pieces cover the run, and they are the steps' and the events', not the rows': output_every
// does not change them. Valid only during the call it is handed to.
class SolutionPiece {
 public:
  SolutionPiece(const Integrator& integrator, const OdeSystem& system, double t_begin, double t_end,
                bool continues)
      : integrator_(integrator),
        system_(system),
        t_begin_(t_begin),
        t_end_(t_end),
        continues_(continues) {}
  double t_begin() const { return t_begin_; }
  double t_end() const { return t_end_; }
  // Whether it starts where the last piece ended with nothing between: false for the run's first
  // piece and for one after a jump, an event that changed the state, or a change of modes.
  bool continues() const { return continues_; }
  // Whether t is the last step's end, where state_at gives the step's own state (that of the
  // run's row there, if it made one).
  bool is_step_end(double t) const { return t == integrator_.t(); }
  // The state at t in [t_begin, t_end] from the continuous extension, put back on the
  // constraints as a row's is (at a step's end, the step's state): at a row's time, the row's.
  void state_at(double t, VecX& y) const {
    y.resize(integrator_.y().size());  // once: a no-op at the right size
    if (t == integrator_.t()) {
      y = integrator_.y();
    } else {
      integrator_.dense_output(t, y);
      system_.project(t, y);
    }
  }

 private:
  const Integrator& integrator_;
  const OdeSystem& system_;
  double t_begin_, t_end_;
  bool continues_;
};

struct EventRecord {
  double t = 0.0;
  std::size_t index = 0;  // into OdeSystem::events()
  EventAction action = EventAction::Record;
};

struct IntegrationReport {
  bool completed = false;
  double t_reached = 0.0;
  std::string failure;       // why it stopped early, with the time; empty if completed
  bool interrupted = false;  // stopped by DriverOptions::stop_requested
  std::vector<EventRecord> events;
  IntegratorStats stats;
};

// Called with each output row; y is only valid during the call.
using Observer = std::function<void(double t, const VecX& y)>;

// Where the driver stands between two steps. With the integrator's memory (Integrator::
// clone_onto) and the system's own state (a Formulation's HybridState) it is all a run needs to
// go on: a run resumed from them takes the same steps and writes the same rows, bit for bit, as
// one that never stopped.
struct DriverPosition {
  double t0 = 0.0;                  // the run's start: row k is at t0 + k * output_every
  long next_row = 1;                // k of the next row
  long steps = 0;                   // accepted steps so far
  long rows = 0;                    // output rows so far
  long short_steps = 0;             // consecutive accepted steps shorter than 1e-12 of t_end - t0
  VecX g_before;                    // the event functions at the last step's end
  std::vector<EventRecord> events;  // the located events so far
};
struct DriverCheckpoint {
  std::shared_ptr<const Integrator> integrator;  // resumed runs take a clone of it
  DriverPosition position;
};
// Called once, at DriverOptions::checkpoint_after, with the run's checkpoint.
using CheckpointObserver = std::function<void(DriverCheckpoint checkpoint)>;

IntegrationReport integrate(Integrator& integrator, OdeSystem& system, double t0, const VecX& y0,
                            double t_end, const DriverOptions& options, const Observer& observe,
                            const CheckpointObserver& on_checkpoint = {});
// Goes on from a checkpoint: `integrator` is the checkpoint's, cloned onto `system`, and the
// system's own state is the one it had then. Rows come from after the checkpoint's time.
IntegrationReport resume_integration(Integrator& integrator, OdeSystem& system,
                                     const DriverPosition& position, double t_end,
                                     const DriverOptions& options, const Observer& observe,
                                     const CheckpointObserver& on_checkpoint = {});

}  // namespace tumble
