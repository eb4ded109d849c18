#include "tumble/integrators/auto_switching.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace tumble {

AutoSwitching::AutoSwitching(const StepControl& control)
    : control_(control), explicit_(control), implicit_(control) {}

void AutoSwitching::start(OdeSystem& system, double t0, const VecX& y0, double t_end) {
  system_ = &system;
  t_end_ = t_end;
  implicit_available_ = system.gives_jacobian();
  explicit_.start(system, t0, y0, t_end);
  implicit_started_ = implicit_active_ = switch_armed_ = false;
  stiff_steps_ = calm_steps_ = 0;
  armed_h_lambda_ = 0.0;
  stiff_without_jacobian_at_ = -1.0;
  switch_count_ = 0;
  step_bound_ = std::numeric_limits<double>::infinity();
  mirror_active();
}

void AutoSwitching::restart(double t, const VecX& y) {
  if (system_ == nullptr) throw std::logic_error("auto: restart() before start()");
  if (implicit_active_ && !switch_armed_ && !system_->gives_jacobian_at(t, y)) {
    switch_armed_ = true;  // the jump left radau5 without a Jacobian: DOP853 takes over
    armed_h_lambda_ = MethodSwitch::kModesWithoutJacobian;
  }
  if (switch_armed_) {
    take_switch(t, y, true);
  } else {
    active().restart(t, y);
    // The jump's state is new: the tests count from it.
    stiff_steps_ = calm_steps_ = 0;
  }
  mirror_active();
}

std::unique_ptr<Integrator> AutoSwitching::clone_onto(OdeSystem& system) const {
  auto copy = std::make_unique<AutoSwitching>(*this);
  copy->explicit_ = static_cast<const Dop853&>(*explicit_.clone_onto(system));
  copy->implicit_ = static_cast<const Radau5&>(*implicit_.clone_onto(system));
  copy->system_ = &system;
  return copy;
}

StepOutcome AutoSwitching::step(double t_stop) {
  if (system_ == nullptr) throw std::logic_error("auto: step() before start()");
  if (switch_armed_) take_switch(t_, y_, false);
  Integrator& method = active();
  method.bound_next_step(step_bound_);
  const long rejected_before = method.stats().rejected_steps;
  const StepOutcome outcome = method.step(t_stop);
  if (outcome == StepOutcome::Ok) watch_stiffness(method.stats().rejected_steps > rejected_before);
  mirror_active();
  return outcome;
}

void AutoSwitching::watch_stiffness(bool retried) {
  const double h_lambda = active().last_step_h_lambda();
  if (!implicit_active_) {
    // Hairer's counters (DOP853's IASTI and NONSTI), with the band below the edge read as the
    // header says.
    const bool held = h_lambda > kExplicitStabilityEdge || (retried && h_lambda > kNearEdge);
    if (held) {
      calm_steps_ = 0;
      if (++stiff_steps_ < kStiffSteps) return;
      stiff_steps_ = 0;
      if (implicit_available_ && system_->gives_jacobian_at(explicit_.t(), explicit_.y())) {
        switch_armed_ = true;
        armed_h_lambda_ = h_lambda;
      } else if (stiff_without_jacobian_at_ < 0.0) {
        stiff_without_jacobian_at_ = explicit_.t();
      }
    } else if (h_lambda <= kNearEdge && calm_steps_ < kCalmStepsForgive &&
               ++calm_steps_ == kCalmStepsForgive) {
      stiff_steps_ = 0;
    }
    return;
  }
  // radau5: DOP853 would be stable at its steps, with room to spare, for fifteen in a row.
  if (h_lambda <= 0.5 * kExplicitStabilityEdge) {
    if (++calm_steps_ < kStiffSteps) return;
    switch_armed_ = true;
    armed_h_lambda_ = h_lambda;
  } else {
    calm_steps_ = 0;
  }
}

void AutoSwitching::take_switch(double t, const VecX& y, bool after_jump) {
  switch_armed_ = false;
  stiff_steps_ = calm_steps_ = 0;
  if (t == t_end_) {  // a restart at the run's end (an event there): no step is left to switch
    active().restart(t, y);
    return;
  }
  if (!implicit_active_ && !system_->gives_jacobian_at(t, y)) {
    // A jump since the test fired put the system in modes without a Jacobian: DOP853 goes on.
    if (stiff_without_jacobian_at_ < 0.0) stiff_without_jacobian_at_ = t;
    if (after_jump) explicit_.restart(t, y);
    return;
  }
  if (switch_count_ < kKeptSwitches) {
    switches_[switch_count_] = MethodSwitch{t, !implicit_active_, armed_h_lambda_};
  }
  ++switch_count_;
  if (implicit_active_) {
    implicit_active_ = false;
    explicit_.restart(t, y);
    return;
  }
  implicit_active_ = true;
  if (implicit_started_) {
    implicit_.restart(t, y);
  } else {
    implicit_.start(*system_, t, y, t_end_);
    implicit_started_ = true;
  }
}

void AutoSwitching::mirror_active() {
  const Integrator& method = active();
  t_ = method.t();
  t_previous_ = method.t_previous();
  h_ = method.step_size();
  y_ = method.y();
  y_previous_ = method.y_previous();
}

IntegratorStats AutoSwitching::stats() const {
  IntegratorStats sum = explicit_.stats();
  if (implicit_started_) {
    const IntegratorStats implicit = implicit_.stats();
    sum.accepted_steps += implicit.accepted_steps;
    sum.rejected_steps += implicit.rejected_steps;
    sum.rhs_evaluations += implicit.rhs_evaluations;
  }
  return sum;
}

// The tests' counters, the switches so far, then each method's memory (radau5's once started:
// a load starts it first, as the run did, to size its workspace).
void AutoSwitching::archive_memory(StateArchive& archive) {
  archive.flag("implicit_started", implicit_started_);
  archive.flag("implicit_active", implicit_active_);
  archive.require("implicit_active", implicit_started_ || !implicit_active_,
                  "0 unless radau5 has started");
  archive.flag("switch_armed", switch_armed_);
  archive.require("switch_armed", !switch_armed_ || implicit_active_ || implicit_available_,
                  "0: this run's system gives no Jacobian for radau5 to switch to");
  archive.integer("stiff_steps", stiff_steps_);
  archive.require("stiff_steps", stiff_steps_ >= 0 && stiff_steps_ < kStiffSteps,
                  "a count below the stiff steps' 15");
  archive.integer("calm_steps", calm_steps_);
  archive.require("calm_steps", calm_steps_ >= 0 && calm_steps_ <= kStiffSteps,
                  "a count from 0 to 15");
  archive.number("armed_h_lambda", armed_h_lambda_);
  archive.number("stiff_without_jacobian_at", stiff_without_jacobian_at_);
  archive.count("switch_count", switch_count_);
  for (std::size_t i = 0; i < switches().size(); ++i) {
    archive.enter("switch" + std::to_string(i));
    archive.number("t", switches_[i].t);
    archive.flag("to_implicit", switches_[i].to_implicit);
    archive.number("h_lambda", switches_[i].h_lambda);
    archive.leave();
  }
  archive.enter("dop853");
  explicit_.archive_memory(archive);
  archive.leave();
  if (implicit_started_) {
    if (archive.loading()) {
      if (!implicit_available_) {
        archive.fail("implicit_started", "0: this run's system gives no Jacobian for radau5");
      }
      implicit_.start(*system_, explicit_.t(), explicit_.y(), t_end_);
    }
    archive.enter("radau5");
    implicit_.archive_memory(archive);
    archive.leave();
  }
  archive.number("step_bound", step_bound_);
  archive.require("step_bound", step_bound_ > 0.0, "a bound on the step, > 0 (inf: none)");
  if (archive.loading()) mirror_active();
}

}  // namespace tumble
