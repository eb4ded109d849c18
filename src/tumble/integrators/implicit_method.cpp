#include "tumble/integrators/implicit_method.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "tumble/integrators/step_size_control.hpp"

namespace tumble {

ImplicitMethod::ImplicitMethod(std::string_view name, const StepControl& control)
    : control_(control), name_(name) {
  step_control::validate_adaptive(name_, control_);
}

void ImplicitMethod::start_implicit(OdeSystem& system, double t0, const VecX& y0, double t_end) {
  step_control::validate_start(name_, system, t0, y0, t_end);
  const Eigen::Index n = y0.size();
  jacobian_.setZero(n, n);
  if (!system.jacobian(t0, y0, jacobian_)) {
    throw std::invalid_argument(fmt::format(
        "{}: this system gives no Jacobian df/dy, which an implicit method needs", name_));
  }
  system_ = &system;
  f0_.setZero(n);
  direction_ = t_end > t0 ? 1.0 : -1.0;
  const double span = std::abs(t_end - t0);
  h_max_ = control_.max_step > 0.0 ? control_.max_step : span;
  stats_ = IntegratorStats{};
  jacobian_evaluations_ = 1;  // the one taken above, at (t0, y0)
  factorisations_ = 0;
  // The estimate is held to the tolerances asked (radau5.hpp, trbdf2.hpp).
  step_control::absolute_tolerances(system, y0, control_.atol, atol_);

  t_ = t_previous_ = t0;
  y_ = y0;
  y_previous_ = y0;
  system_->derivative(t_, y_, f0_);
  ++stats_.rhs_evaluations;
  on_new_jacobian();
  jacobian_current_ = true;
  need_jacobian_ = false;
  factored_h_ = 0.0;
  faccon_ = 1.0;
  h_ = control_.initial_step > 0.0
           ? std::min(control_.initial_step, h_max_)
           : step_control::ode45_initial_step(y_, f0_, control_.rtol, atol_, h_max_, span, t0);
}

void ImplicitMethod::restart_implicit(double t, const VecX& y) {
  if (system_ == nullptr)
    throw std::logic_error(fmt::format("{}: restart() before start()", name_));
  if (y.size() != y_.size()) {
    throw std::invalid_argument(fmt::format("{}: restart() with a wrong-size y", name_));
  }
  t_ = t_previous_ = t;
  y_ = y;
  y_previous_ = y;
  system_->derivative(t_, y_, f0_);
  ++stats_.rhs_evaluations;
  jacobian_current_ = false;
  need_jacobian_ = true;
  faccon_ = 1.0;
}

void ImplicitMethod::take_jacobian() {
  if (!system_->jacobian(t_, y_, jacobian_)) {
    // The run fails here with the rows so far (the driver's runtime_error), not the program.
    throw std::runtime_error(fmt::format("{}: the system stopped giving a Jacobian", name_));
  }
  ++jacobian_evaluations_;
  on_new_jacobian();
  jacobian_current_ = true;
  need_jacobian_ = false;
  factored_h_ = 0.0;
}

// The Jacobian a step may keep and the step its factorisations are for (they are made again
// from both, as the run made them), f at the current state.
void ImplicitMethod::archive_implicit(StateArchive& archive) {
  archive_common(archive);
  archive_direction(archive, direction_);
  archive.number("h_max", h_max_);
  archive.require("h_max", h_max_ > 0.0, "the largest step, > 0");
  archive_sized(archive, "atol", atol_);
  VecX jacobian = jacobian_.reshaped();
  archive_sized(archive, "jacobian", jacobian);
  if (archive.loading()) {
    archive.require("jacobian", jacobian.allFinite(), "finite numbers");
    jacobian_ = jacobian.reshaped(jacobian_.rows(), jacobian_.cols());
    on_new_jacobian();
  }
  archive.flag("jacobian_current", jacobian_current_);
  archive.flag("need_jacobian", need_jacobian_);
  archive.number("factored_h", factored_h_);
  archive.require("factored_h", std::isfinite(factored_h_), "a finite step");
  archive_sized(archive, "f0", f0_);
}

void ImplicitMethod::archive_newton_factor(StateArchive& archive) {
  archive.number("faccon", faccon_);
  archive.require("faccon", std::isfinite(faccon_) && faccon_ >= 0.0, "a factor, not negative");
}

double ImplicitMethod::newton_enough() const {
  constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
  return std::max(10.0 * kEpsilon / control_.rtol, std::min(0.03, std::sqrt(control_.rtol)));
}

double ImplicitMethod::rms(const VecX& v, const VecX& sk) {
  return std::sqrt((v.array() / sk.array()).square().sum() / static_cast<double>(v.size()));
}

}  // namespace tumble
