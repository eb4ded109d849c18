#include "tumble/simulation/exact_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <Eigen/Eigenvalues>

namespace tumble {

namespace {

// The formulation the system runs (the system itself, or the one under the scenario's events).
const Formulation& formulation_of(const OdeSystem& system) {
  const Formulation* formulation = system.rigid_body_formulation();
  if (formulation == nullptr) {
    throw std::invalid_argument("the exact integrator needs a rigid-body formulation");
  }
  return *formulation;
}

}  // namespace

std::unique_ptr<Integrator> ExactIntegrator::clone_onto(OdeSystem& system) const {
  auto copy = std::make_unique<ExactIntegrator>(*this);
  copy->formulation_ = &formulation_of(system);
  return copy;
}

void ExactIntegrator::start(OdeSystem& system, double t0, const VecX& y0, double t_end) {
  formulation_ = &formulation_of(system);
  watches_events_ = !system.events().empty();
  span_ = std::abs(t_end - t0);
  if (!fits(formulation_->model())) {
    throw std::invalid_argument(
        "the exact integrator is for free bodies on which no force or torque acts");
  }
  stats_ = {};
  scratch_states_.resize(formulation_->body_count());
  y_previous_ = y0;
  restart(t0, y0);
}

bool ExactIntegrator::fits(const Model& model) {
  return model.bodies_are_free() && model.loads.empty();
}

void ExactIntegrator::restart(double t, const VecX& y) {
  t_ = t_previous_ = t;
  y_ = y;
  begin_closed_form(t, y);
}

void ExactIntegrator::archive_memory(StateArchive& archive) {
  archive_common(archive);
  archive.number("t_start", t_start_);
  archive.require("t_start", std::isfinite(t_start_), "a finite time");
  archive_sized(archive, "y_start", y_start_);
  if (archive.loading()) begin_closed_form(t_start_, VecX(y_start_));
}

void ExactIntegrator::begin_closed_form(double t, const VecX& y) {
  t_start_ = t;
  y_start_ = y;
  start_states_.clear();
  rotations_.clear();
  for (std::size_t i = 0; i < formulation_->body_count(); ++i) {
    const BodyState s = formulation_->unpack(y, i);
    start_states_.push_back(s);
    rotations_.emplace_back(formulation_->model().bodies[i].I_G_B, s.R_WB, s.omega_W);
  }
  // The driver looks for the events' sign changes at the steps' ends: with events, a step turns
  // no body by more than an eighth of a turn (|omega| <= |L| / I_min, L constant) and lasts no
  // more than a tenth of the run (ode45's largest step, for the COM's parabola), so that no
  // function of the row turns and turns back within one unseen. Without, one step to the stop.
  max_step_ = std::numeric_limits<double>::infinity();
  if (!watches_events_) return;
  max_step_ = span_ > 0.0 ? span_ / 10.0 : max_step_;
  for (std::size_t i = 0; i < rotations_.size(); ++i) {
    const Mat3& I_G_B = formulation_->model().bodies[i].I_G_B;
    const double I_min =
        Eigen::SelfAdjointEigenSolver<Mat3>(I_G_B, Eigen::EigenvaluesOnly).eigenvalues().minCoeff();
    const double omega_max = rotations_[i].angular_momentum_W().norm() / I_min;
    if (omega_max > 0.0) max_step_ = std::min(max_step_, 0.25 * std::numbers::pi / omega_max);
  }
}

StepOutcome ExactIntegrator::step(double t_stop) {
  t_previous_ = t_;
  y_previous_ = y_;
  // Lands on t_stop when the bound would leave less than a hundredth of a step to it.
  t_ = t_stop - t_ > 1.01 * max_step_ ? t_ + max_step_ : t_stop;
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
    rotations_[i].calc_rotation(tau, s.R_WB, s.omega_W);
  }
  formulation_->pack(scratch_states_, y_out);
}

}  // namespace tumble
