#include "tumble/integrators/rk4.hpp"

#include <stdexcept>

#include "tumble/integrators/hermite.hpp"
#include "tumble/integrators/step_size_control.hpp"

namespace tumble {

Rk4::Rk4(const StepControl& control) {
  step_control::validate_fixed(name(), control);
  h_ = control.fixed_step;
}

void Rk4::start(OdeSystem& system, double t0, const VecX& y0, double t_end) {
  step_control::validate_start(name(), system, t0, y0, t_end);
  system_ = &system;
  const Eigen::Index n = y0.size();
  f_previous_.setZero(n);
  f_current_.setZero(n);
  k2_.setZero(n);
  k3_.setZero(n);
  k4_.setZero(n);
  y_stage_.setZero(n);
  y_new_.setZero(n);
  direction_ = t_end > t0 ? 1.0 : -1.0;
  stats_ = IntegratorStats{};
  restart(t0, y0);
}

void Rk4::restart(double t, const VecX& y) {
  if (system_ == nullptr) throw std::logic_error("rk4: restart() before start()");
  if (y.size() != f_current_.size())
    throw std::invalid_argument("rk4: restart() with a wrong-size y");
  t_ = t_previous_ = t_grid_ = t;
  grid_steps_ = 0;
  y_ = y;
  y_previous_ = y;
  system_->derivative(t_, y_, f_current_);
  ++stats_.rhs_evaluations;
}

StepOutcome Rk4::step(double t_stop) {
  if (system_ == nullptr) throw std::logic_error("rk4: step() before start()");
  step_control::require_ahead(name(), t_, t_stop, direction_);
  const step_control::FixedStepEnd end =
      step_control::next_fixed_step_end(t_grid_, grid_steps_, h_, direction_, t_stop);
  const double h = end.t_new - t_;
  const double t_half = t_ + 0.5 * h;

  const VecX& k1 = f_current_;
  y_stage_ = y_ + (0.5 * h) * k1;
  system_->derivative(t_half, y_stage_, k2_);
  y_stage_ = y_ + (0.5 * h) * k2_;
  system_->derivative(t_half, y_stage_, k3_);
  y_stage_ = y_ + h * k3_;
  system_->derivative(end.t_new, y_stage_, k4_);
  stats_.rhs_evaluations += 3;
  y_new_ = y_ + (h / 6.0) * (k1 + 2.0 * k2_ + 2.0 * k3_ + k4_);
  if (!y_new_.allFinite()) return StepOutcome::NonFiniteState;

  y_previous_.swap(y_);
  y_.swap(y_new_);
  system_->project(end.t_new, y_);
  f_previous_.swap(f_current_);
  system_->derivative(end.t_new, y_, f_current_);
  ++stats_.rhs_evaluations;
  t_previous_ = t_;
  t_ = end.t_new;
  if (end.lands) {
    t_grid_ = end.t_new;
    grid_steps_ = 0;
  } else {
    ++grid_steps_;
  }
  ++stats_.accepted_steps;
  return StepOutcome::Ok;
}

void Rk4::dense_output(double t, VecX& y_out) const {
  if (t_ == t_previous_) {  // no step since start or restart
    y_out = y_;
    return;
  }
  hermite_interpolate(t_previous_, y_previous_, f_previous_, t_, y_, f_current_, t, y_out);
}

}  // namespace tumble
