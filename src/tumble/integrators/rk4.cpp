#include "tumble/integrators/rk4.hpp"

namespace tumble {

StepOutcome Rk4::step(double t_stop) {
  const step_control::FixedStepEnd end = begin_step(t_stop);
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

  return accept_step(end);
}

}  // namespace tumble
