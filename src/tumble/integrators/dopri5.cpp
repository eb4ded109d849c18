#include "tumble/integrators/dopri5.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tumble/integrators/step_size_control.hpp"

namespace tumble {

namespace {

// Butcher tableau of DOPRI5 (Dormand and Prince 1980; Hairer-Norsett-Wanner I, Table II.5.2).
// Zero entries (a_i2 for i >= 3, b_2) are left out of the stage sums below.
constexpr double c2 = 1.0 / 5.0, c3 = 3.0 / 10.0, c4 = 4.0 / 5.0, c5 = 8.0 / 9.0;
constexpr double a21 = 1.0 / 5.0;
constexpr double a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
constexpr double a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
constexpr double a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0,
                 a54 = -212.0 / 729.0;
constexpr double a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0,
                 a64 = 49.0 / 176.0, a65 = -5103.0 / 18656.0;
// The 5th-order weights b_i (also the last stage row: FSAL).
constexpr double b1 = 35.0 / 384.0, b3 = 500.0 / 1113.0, b4 = 125.0 / 192.0, b5 = -2187.0 / 6784.0,
                 b6 = 11.0 / 84.0;
// e_i = b_i - bhat_i, the weights of the local error estimate.
constexpr double e1 = 71.0 / 57600.0, e3 = -71.0 / 16695.0, e4 = 71.0 / 1920.0,
                 e5 = -17253.0 / 339200.0, e6 = 22.0 / 525.0, e7 = -1.0 / 40.0;
// Shampine's dense-output weights d_i (Hairer's DOPRI5 code).
constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                 d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                 d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;

// A step within 10 % of the stop is stretched onto it (ode45).
constexpr double kLandingStretch = 1.1;

}  // namespace

Dopri5::Dopri5(const StepControl& control) : control_(control) {
  step_control::validate_adaptive(name(), control_);
}

void Dopri5::start(OdeSystem& system, double t0, const VecX& y0, double t_end) {
  step_control::validate_start(name(), system, t0, y0, t_end);
  system_ = &system;
  const Eigen::Index n = y0.size();
  for (Stages& stages : stages_) {
    for (VecX& k : stages) k.setZero(n);
  }
  y_stage_.setZero(n);
  y_new_.setZero(n);
  error_.setZero(n);
  direction_ = t_end > t0 ? 1.0 : -1.0;
  const double span = std::abs(t_end - t0);
  h_max_ = control_.max_step > 0.0 ? control_.max_step : 0.1 * span;
  stats_ = IntegratorStats{};

  t_ = t_previous_ = t0;
  y_ = y0;
  y_previous_ = y0;
  accepted_ = 0;
  system_->derivative(t_, y_, stages_[accepted_][kStages - 1]);
  ++stats_.rhs_evaluations;
  step_control::absolute_tolerances(system, y0, control_.atol, thresholds_);

  h_ = control_.initial_step > 0.0
           ? std::min(control_.initial_step, h_max_)
           : step_control::ode45_initial_step(y_, stages_[accepted_][kStages - 1], control_.rtol,
                                              thresholds_, h_max_, span, t0);
  thresholds_ /= control_.rtol;  // atol_i / rtol, as the error measure takes them
}

// The stages and the tolerances taken from y0 at the start.
void Dopri5::archive_memory(StateArchive& archive) {
  archive_common(archive);
  archive_stage_sets(archive, direction_, h_max_, accepted_, stages_);
  archive_sized(archive, "thresholds", thresholds_);
}

void Dopri5::restart(double t, const VecX& y) {
  if (system_ == nullptr) throw std::logic_error("dopri5: restart() before start()");
  if (y.size() != y_.size()) throw std::invalid_argument("dopri5: restart() with a wrong-size y");
  t_ = t_previous_ = t;
  y_ = y;
  y_previous_ = y;
  system_->derivative(t_, y_, stages_[accepted_][kStages - 1]);
  ++stats_.rhs_evaluations;
}

StepOutcome Dopri5::step(double t_stop) {
  if (system_ == nullptr) throw std::logic_error("dopri5: step() before start()");
  step_control::require_ahead(name(), t_, t_stop, direction_);

  Stages& k = trial_stages();
  k[0] = accepted_stages()[kStages - 1];  // FSAL: f at the current state
  const double rtol = control_.rtol;
  const double h_min = step_control::minimum_step(t_);
  double h_abs = step_control::first_try(h_, h_max_, step_bound_, h_min);
  bool rejected_before = false;

  for (;;) {
    const double h_proposed = h_abs;
    const step_control::ClippedStep clipped =
        step_control::clip_to_stop(t_, h_abs, t_stop, direction_, kLandingStretch);
    h_abs = clipped.h_abs;
    const double h = direction_ * h_abs;
    const double t_new = clipped.t_new;

    y_stage_ = y_ + (h * a21) * k[0];
    system_->derivative(t_ + c2 * h, y_stage_, k[1]);
    y_stage_ = y_ + h * (a31 * k[0] + a32 * k[1]);
    system_->derivative(t_ + c3 * h, y_stage_, k[2]);
    y_stage_ = y_ + h * (a41 * k[0] + a42 * k[1] + a43 * k[2]);
    system_->derivative(t_ + c4 * h, y_stage_, k[3]);
    y_stage_ = y_ + h * (a51 * k[0] + a52 * k[1] + a53 * k[2] + a54 * k[3]);
    system_->derivative(t_ + c5 * h, y_stage_, k[4]);
    y_stage_ = y_ + h * (a61 * k[0] + a62 * k[1] + a63 * k[2] + a64 * k[3] + a65 * k[4]);
    system_->derivative(t_new, y_stage_, k[5]);
    y_new_ = y_ + h * (b1 * k[0] + b3 * k[2] + b4 * k[3] + b5 * k[4] + b6 * k[5]);
    system_->derivative(t_new, y_new_, k[6]);
    stats_.rhs_evaluations += 6;

    error_ = h * (e1 * k[0] + e3 * k[2] + e4 * k[3] + e5 * k[4] + e6 * k[5] + e7 * k[6]);
    const double err = step_control::max_norm_error(error_, y_, y_new_, thresholds_);
    if (!std::isfinite(err) || !y_new_.allFinite()) {
      ++stats_.rejected_steps;
      if (!step_control::shorten_after_blow_up(h_abs, h_min)) {
        h_ = h_abs;
        return StepOutcome::NonFiniteState;
      }
      rejected_before = true;
      continue;
    }

    if (err > rtol) {
      ++stats_.rejected_steps;
      if (h_abs <= h_min) {
        h_ = h_abs;
        return StepOutcome::StepSizeUnderflow;
      }
      // ode45: the first failure scales by the error (never below a tenth); a repeated failure
      // means the asymptotic model does not hold, so it only halves.
      h_abs =
          rejected_before ? 0.5 * h_abs : h_abs * std::max(0.1, 0.8 * std::pow(rtol / err, 0.2));
      h_abs = std::max(h_min, h_abs);
      rejected_before = true;
      continue;
    }

    // Accepted. After a failure in this step ode45 keeps the step that worked; otherwise it grows
    // by the error model, at most five-fold.
    double h_next = h_abs;
    if (!rejected_before) {
      const double shrink = 1.25 * std::pow(err / rtol, 0.2);
      h_next = shrink > 0.2 ? h_abs / shrink : 5.0 * h_abs;
      if (clipped.lands) h_next = std::max(h_next, h_proposed);
    }

    y_previous_.swap(y_);
    y_.swap(y_new_);
    y_new_ = y_;  // the unprojected end point, to see whether project() moves it
    system_->project(t_new, y_);
    // FSAL: k7 = f(t_new, y) is the next step's k1. A projection that only renormalised the
    // quaternions rescales it exactly (OdeSystem's contract); any other change needs f again.
    if (y_ != y_new_ &&
        !rescale_quaternion_derivatives(system_->unit_quaternion_offsets(), y_new_, y_, k[6])) {
      system_->derivative(t_new, y_, k[6]);
      ++stats_.rhs_evaluations;
    }
    t_previous_ = t_;
    t_ = t_new;
    h_ = h_next;
    accepted_ = 1 - accepted_;
    ++stats_.accepted_steps;
    return StepOutcome::Ok;
  }
}

void Dopri5::dense_output(double t, VecX& y_out) const {
  if (t_ == t_previous_) {  // no step since start or restart
    y_out = y_;
    return;
  }
  // y(s) = (1 - w) y_n + w y_{n+1} + h [(s s1^2 + q d1) k1 + q (d3 k3 + ... + d6 k6)
  //        + (q d7 - s^2 s1) k7],  w = s^2 (3 - 2s), q = s^2 s1^2: the class comment's formula
  // with D expanded.
  const double h = t_ - t_previous_;
  const double s = (t - t_previous_) / h;
  const double s1 = 1.0 - s;
  const double w = s * s * (3.0 - 2.0 * s);
  const double q = s * s * s1 * s1;
  const Stages& k = accepted_stages();
  y_out = (1.0 - w) * y_previous_ + w * y_ + (h * (s * s1 * s1 + q * d1)) * k[0] +
          (h * q * d3) * k[2] + (h * q * d4) * k[3] + (h * q * d5) * k[4] + (h * q * d6) * k[5] +
          (h * (q * d7 - s * s * s1)) * k[6];
}

}  // namespace tumble
