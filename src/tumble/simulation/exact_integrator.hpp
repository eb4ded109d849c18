#pragma once
// `integrator: exact` for bodies on which no load acts: each body's rotation is the
// Euler-Poinsot solution (TorqueFreeMotion) and its COM follows the parabola of uniform
// gravity. It takes one "step" to each stop time (with events, steps of at most an eighth of a
// turn, at whose ends the driver looks for them) and evaluates the closed form wherever the
// driver asks, so outputs, events and reports work as for the numerical methods.
#include <vector>

#include "tumble/dynamics/formulation.hpp"
#include "tumble/exact/torque_free.hpp"
#include "tumble/integrators/integrator.hpp"

namespace tumble {

class ExactIntegrator final : public Integrator {
 public:
  std::string_view name() const override { return "exact"; }
  int order() const override { return 0; }
  bool adaptive() const override { return false; }
  // Whether the closed form is the motion of the model's bodies: free bodies (no joints, springs,
  // impulses or contacts) on which no load acts; gravity is allowed.
  static bool fits(const Model& model);

  // The system must run a rigid-body formulation (OdeSystem::rigid_body_formulation: the
  // formulation, or the scenario's events on it) of a model that fits (std::invalid_argument).
  void start(OdeSystem& system, double t0, const VecX& y0, double t_end) override;
  void restart(double t, const VecX& y) override;
  std::unique_ptr<Integrator> clone_onto(OdeSystem& system) const override;
  // The state the closed form starts from (the motion after it follows from it).
  void archive_memory(StateArchive& archive) override;
  StepOutcome step(double t_stop) override;
  void dense_output(double t, VecX& y_out) const override;

 private:
  const Formulation* formulation_ = nullptr;
  // The closed form's start: each body's state at t_start_ and its torque-free rotation from it.
  void begin_closed_form(double t, const VecX& y);

  double t_start_ = 0.0;  // time of the initial (or restart) state
  VecX y_start_;          // that state
  std::vector<BodyState> start_states_;
  std::vector<TorqueFreeMotion> rotations_;
  bool watches_events_ = false;  // the system has events: steps are bounded (restart)
  double span_ = 0.0;            // |t_end - t0|, s
  double max_step_ = 0.0;        // s; +infinity without events
  mutable std::vector<BodyState> scratch_states_;  // sized once: dense_output does not allocate
};

}  // namespace tumble
