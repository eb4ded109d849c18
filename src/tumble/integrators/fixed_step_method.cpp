#include "tumble/integrators/fixed_step_method.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "tumble/integrators/hermite.hpp"

namespace tumble {

FixedStepMethod::FixedStepMethod(std::string_view method_name, const StepControl& control)
    : method_name_(method_name) {
  step_control::validate_fixed(method_name_, control);
  h_ = control.fixed_step;
}

void FixedStepMethod::prepare(OdeSystem& /*system*/, Eigen::Index /*n*/) {}

void FixedStepMethod::finish_dense_output(VecX& /*y_out*/) const {}

void FixedStepMethod::start(OdeSystem& system, double t0, const VecX& y0, double t_end) {
  step_control::validate_start(method_name_, system, t0, y0, t_end);
  system_ = &system;
  const Eigen::Index n = y0.size();
  for (VecX* v : {&f_previous_, &f_current_, &k2_, &k3_, &k4_, &y_stage_, &y_new_}) {
    v->setZero(n);
  }
  prepare(system, n);
  direction_ = t_end > t0 ? 1.0 : -1.0;
  stats_ = IntegratorStats{};
  restart(t0, y0);
}

void FixedStepMethod::restart(double t, const VecX& y) {
  if (system_ == nullptr) {
    throw std::logic_error(std::string(method_name_) + ": restart() before start()");
  }
  if (y.size() != f_current_.size()) {
    throw std::invalid_argument(std::string(method_name_) + ": restart() with a wrong-size y");
  }
  t_ = t_previous_ = t_grid_ = t;
  grid_steps_ = 0;
  y_ = y;
  y_previous_ = y;
  system_->derivative(t_, y_, f_current_);
  ++stats_.rhs_evaluations;
}

void FixedStepMethod::archive_memory(StateArchive& archive) {
  archive_common(archive);
  archive_direction(archive, direction_);
  archive.number("t_grid", t_grid_);
  archive.require("t_grid", std::isfinite(t_grid_), "a finite time");
  archive.integer("grid_steps", grid_steps_);
  archive.require("grid_steps", grid_steps_ >= 0, "a count, not negative");
  archive_sized(archive, "f_previous", f_previous_);
  archive_sized(archive, "f_current", f_current_);
}

step_control::FixedStepEnd FixedStepMethod::begin_step(double t_stop) const {
  if (system_ == nullptr) {
    throw std::logic_error(std::string(method_name_) + ": step() before start()");
  }
  step_control::require_ahead(method_name_, t_, t_stop, direction_);
  return step_control::next_fixed_step_end(t_grid_, grid_steps_, h_, direction_, t_stop);
}

StepOutcome FixedStepMethod::accept_step(const step_control::FixedStepEnd& end) {
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

void FixedStepMethod::dense_output(double t, VecX& y_out) const {
  if (t_ == t_previous_) {  // no step since start or restart
    y_out = y_;
    return;
  }
  hermite_interpolate(t_previous_, y_previous_, f_previous_, t_, y_, f_current_, t, y_out);
  finish_dense_output(y_out);
}

}  // namespace tumble
