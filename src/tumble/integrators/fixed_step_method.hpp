#pragma once
// What rk4 and rkmk4 share: a fixed step on a grid t_grid + n h (computed, not accumulated, so
// long runs do not drift) that lands on t_stop exactly and restarts the grid there; the end of
// each step (project, then f at the new state, which is both the continuous extension's end slope
// and the next step's k1); and the cubic Hermite continuous extension (hermite.hpp).
#include <string_view>

#include "tumble/integrators/integrator.hpp"
#include "tumble/integrators/step_size_control.hpp"

namespace tumble {

class FixedStepMethod : public Integrator {
 public:
  bool adaptive() const override { return false; }

  void start(OdeSystem& system, double t0, const VecX& y0, double t_end) override;
  void restart(double t, const VecX& y) override;
  void dense_output(double t, VecX& y_out) const override;
  // The grid the steps are on and f at both ends of the last step (the continuous extension's);
  // the stages are scratch.
  void archive_memory(StateArchive& archive) override;

 protected:
  // Throws std::invalid_argument unless control.fixed_step > 0; the tolerances are ignored.
  FixedStepMethod(std::string_view method_name, const StepControl& control);

  // Sizes a derived method's own workspace for a state of n components (called by start()).
  virtual void prepare(OdeSystem& system, Eigen::Index n);
  // Applied to every dense output after the interpolation.
  virtual void finish_dense_output(VecX& y_out) const;

  // Where the step from t_ ends; throws unless t_stop lies ahead.
  step_control::FixedStepEnd begin_step(double t_stop) const;
  // Makes y_new_ the state at end.t_new: project, f there, the grid advanced.
  StepOutcome accept_step(const step_control::FixedStepEnd& end);

  std::string_view method_name_;
  OdeSystem* system_ = nullptr;
  double direction_ = 1.0;  // +1 forward in time, -1 backward
  double t_grid_ = 0.0;     // s, where the current grid of steps starts
  long grid_steps_ = 0;     // steps taken on it
  VecX f_previous_;         // f(t_previous, y_previous): k1 of the last step
  VecX f_current_;          // f(t, y): the next step's k1
  VecX k2_, k3_, k4_;
  VecX y_stage_;
  VecX y_new_;
};

}  // namespace tumble
