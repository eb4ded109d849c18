#include "tumble/simulation/exact_integrator.hpp"

#include <stdexcept>

namespace tumble {

std::unique_ptr<Integrator> ExactIntegrator::clone_onto(OdeSystem& system) const {
  auto copy = std::make_unique<ExactIntegrator>(*this);
  copy->formulation_ = dynamic_cast<const Formulation*>(&system);
  if (copy->formulation_ == nullptr) {
    throw std::invalid_argument("the exact integrator needs a rigid-body formulation");
  }
  return copy;
}

void ExactIntegrator::start(OdeSystem& system, double t0, const VecX& y0, double /*t_end*/) {
  formulation_ = dynamic_cast<const Formulation*>(&system);
  if (formulation_ == nullptr) {
    throw std::invalid_argument("the exact integrator needs a rigid-body formulation");
  }
  if (!formulation_->model().loads.empty()) {
    throw std::invalid_argument(
        "the exact integrator is for torque-free bodies: no force or torque may act");
  }
  stats_ = {};
  scratch_states_.resize(formulation_->body_count());
  y_previous_ = y0;
  restart(t0, y0);
}

void ExactIntegrator::restart(double t, const VecX& y) {
  t_ = t_previous_ = t_start_ = t;
  y_ = y;
  start_states_.clear();
  rotations_.clear();
  for (std::size_t i = 0; i < formulation_->body_count(); ++i) {
    const BodyState s = formulation_->unpack(y, i);
    start_states_.push_back(s);
    rotations_.emplace_back(formulation_->model().bodies[i].I_G_B, s.R_WB, s.omega_W);
  }
}

StepOutcome ExactIntegrator::step(double t_stop) {
  t_previous_ = t_;
  y_previous_ = y_;
  t_ = t_stop;
  h_ = t_ - t_previous_;
  dense_output(t_, y_);
  ++stats_.accepted_steps;
  return StepOutcome::Ok;
}

void ExactIntegrator::dense_output(double t, VecX& y_out) const {
  const double tau = t - t_start_;
  const Vec3& g = formulation_->model().gravity_W;
  for (std::size_t i = 0; i < start_states_.size(); ++i) {
    const BodyState& s0 = start_states_[i];
    BodyState& s = scratch_states_[i];
    s.r_G = s0.r_G + s0.v_G * tau + 0.5 * g * tau * tau;
    s.v_G = s0.v_G + g * tau;
    s.R_WB = rotations_[i].R_WB(tau);
    s.omega_W = rotations_[i].omega_W(tau);
  }
  formulation_->pack(scratch_states_, y_out);
}

}  // namespace tumble
