#pragma once
// One interface for every time-stepping method. A method advances one accepted step at a time,
// never past a stop time the driver gives it (an output time is NOT a stop: outputs come from the
// continuous extension), and can evaluate the state anywhere inside its last step. The driver
// (driver.hpp) builds outputs, event location, breakpoints and jumps on these three calls.
#include <array>
#include <limits>
#include <memory>
#include <string>
#include <string_view>

#include "tumble/integrators/ode_system.hpp"
#include "tumble/integrators/tolerances.hpp"
#include "tumble/math/state_archive.hpp"

namespace tumble {

struct StepControl {
  double rtol = tolerances::kDefaultRtol;  // relative tolerance (ode45's default)
  double atol = tolerances::kDefaultAtol;  // absolute tolerance (ode45's default)
  double initial_step = 0.0;               // s; 0: chosen as ode45 does (dop853: as Hairer's code)
  double max_step = 0.0;    // s; 0: a tenth of the span as ode45 (dop853: the span, as Hairer)
  double fixed_step = 0.0;  // s; the step of fixed-step methods (required for them)
};

struct IntegratorStats {
  long accepted_steps = 0;
  long rejected_steps = 0;
  long rhs_evaluations = 0;
};

enum class StepOutcome { Ok, StepSizeUnderflow, NonFiniteState };

class Integrator {
 public:
  virtual ~Integrator() = default;

  virtual std::string_view name() const = 0;
  virtual int order() const = 0;
  virtual bool adaptive() const = 0;

  // Sizes the workspace for `system` (the only place that allocates) and starts at (t0, y0),
  // heading for t_end (which sets the direction and ode45's default bounds on the step).
  virtual void start(OdeSystem& system, double t0, const VecX& y0, double t_end) = 0;

  // Restarts from a new state at time t (after an event jump or a breakpoint), keeping the
  // workspace, the statistics and, for adaptive methods, the current step size as a first guess.
  virtual void restart(double t, const VecX& y) = 0;

  // A copy of this method as it stands mid-run (its step size, its last step and the continuous
  // extension over it, its statistics: everything its next step depends on), driving `system`
  // from now on. A run's checkpoint keeps one; the resumed run goes on with it.
  virtual std::unique_ptr<Integrator> clone_onto(OdeSystem& system) const = 0;

  // The same memory field by field, for a checkpoint file: saved, or loaded into a method of the
  // same name and control that start() has sized for the same system (a load checks every
  // vector's length against that: StateArchive::fail where it does not fit).
  virtual void archive_memory(StateArchive& archive) = 0;

  // One accepted step that ends at or before t_stop (and lands on it exactly if it would pass).
  virtual StepOutcome step(double t_stop) = 0;

  // Bounds the next step's length (s; +infinity: no bound) for an adaptive method, on top of its
  // error control and max_step; a fixed-step method ignores it.
  void bound_next_step(double h_abs) { step_bound_ = h_abs; }

  // The state at t in [t_previous(), t()] from the method's continuous extension.
  virtual void dense_output(double t, VecX& y_out) const = 0;

  double t() const { return t_; }
  double t_previous() const { return t_previous_; }
  const VecX& y() const { return y_; }
  const VecX& y_previous() const { return y_previous_; }
  // The step size the method would try next (for reports and restarts).
  double step_size() const { return h_; }
  // The counts so far (a method made of others, `auto`, adds theirs up).
  virtual IntegratorStats stats() const { return stats_; }

  // |h| rho: the last accepted step's length times the method's estimate of the largest
  // |eigenvalue| of df/dy there, or 0 where it has none (no step yet, or a method that makes
  // none). Against the method's own bound on h |lambda| it says whether stability rather than
  // accuracy held the step (an explicit method) or would hold an explicit one (an implicit
  // method): what `auto` switches on (auto_switching.hpp).
  virtual double last_step_h_lambda() const { return 0.0; }

 protected:
  // The memory every method has (t, y and the step before, h, the step bound, the statistics).
  void archive_common(StateArchive& archive);
  // The direction of integration in time: 1 or -1.
  static void archive_direction(StateArchive& archive, double& direction);
  // A workspace vector's values; a load keeps its length, which start() gave it.
  static void archive_sized(StateArchive& archive, std::string_view key, VecX& values);
  // An embedded Runge-Kutta pair's memory: its direction in time, its largest step, and both sets
  // of stages ("k0_1".."k1_N": the last accepted step's, set `accepted`, for the continuous
  // extension and a first-same-as-last f; the other is scratch, kept as cheaply).
  template <std::size_t N>
  static void archive_stage_sets(StateArchive& archive, double& direction, double& h_max,
                                 int& accepted, std::array<std::array<VecX, N>, 2>& sets) {
    archive_direction(archive, direction);
    archive.number("h_max", h_max);
    archive.require("h_max", h_max > 0.0, "the largest step, > 0");
    archive.integer("accepted", accepted);
    if (accepted != 0 && accepted != 1) archive.fail("accepted", "0 or 1");
    for (std::size_t set = 0; set < sets.size(); ++set) {
      for (std::size_t i = 0; i < N; ++i) {
        std::string key = "k";
        key += std::to_string(set);
        key += '_';
        key += std::to_string(i + 1);
        archive_sized(archive, key, sets[set][i]);
      }
    }
  }

  double t_ = 0.0;
  double t_previous_ = 0.0;
  double h_ = 0.0;
  double step_bound_ = std::numeric_limits<double>::infinity();  // see bound_next_step
  VecX y_;
  VecX y_previous_;
  // mutable: a lazy continuous extension (dop853) evaluates f inside the const dense_output()
  // and counts those evaluations honestly.
  mutable IntegratorStats stats_;
};

// The methods by their scenario names: dopri5, dop853, rk4, rkmk4, radau5, trbdf2, auto. Throws
// std::invalid_argument for an unknown name or a control that does not fit the method (e.g. rk4
// without a step).
std::unique_ptr<Integrator> make_integrator(std::string_view name, const StepControl& control);

}  // namespace tumble
