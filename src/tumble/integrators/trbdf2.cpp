#include "tumble/integrators/trbdf2.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "tumble/integrators/hermite.hpp"
#include "tumble/integrators/step_size_control.hpp"

namespace tumble {

namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
// Newton iterations a stage may take before the step is tried again shorter.
constexpr int kMostIterations = 6;
// A contraction rate at or above this diverges; above the second, the next step takes J anew.
constexpr double kDiverging = 0.9;
constexpr double kSlowRate = 0.1;
// Bounds on h_new / h; the step-size safety factor.
constexpr double kMostGrowth = 5.0, kMostShrink = 5.0;
constexpr double kSafety = 0.9;

// The method's coefficients from their definitions (the class comment).
struct Tableau {
  double gamma = 0.0, d = 0.0, w = 0.0;
  double b_hat[3] = {0.0, 0.0, 0.0};  // the embedded order-3 weights
};

Tableau derive_tableau() {
  Tableau t;
  t.gamma = 2.0 - std::sqrt(2.0);
  t.d = t.gamma / 2.0;
  t.w = (1.0 - t.d) / 2.0;  // sum b = 1
  // sum b_hat c = 1/2 and sum b_hat c^2 = 1/3 on c = (0, gamma, 1): b_hat_2 gamma (1 - gamma) =
  // 1/6, then b_hat_3 from the first, b_hat_1 from sum b_hat = 1.
  t.b_hat[1] = 1.0 / (6.0 * t.gamma * (1.0 - t.gamma));
  t.b_hat[2] = 0.5 - t.gamma * t.b_hat[1];
  t.b_hat[0] = 1.0 - t.b_hat[1] - t.b_hat[2];
  return t;
}

const Tableau& tableau() {
  static const Tableau t = derive_tableau();
  return t;
}

}  // namespace

TrBdf2::TrBdf2(const StepControl& control) : ImplicitMethod("trbdf2", control) {}

void TrBdf2::start(OdeSystem& system, double t0, const VecX& y0, double t_end) {
  start_implicit(system, t0, y0, t_end);
  const Eigen::Index n = y0.size();
  for (VecX* v : {&f_previous_, &base_, &stage2_, &stage3_, &f2_, &f3_, &f_iterate_, &residual_,
                  &delta_, &scale_}) {
    v->setZero(n);
  }
  lu_ = Eigen::PartialPivLU<MatX>(n);
  f_previous_ = f0_;
  theta_ = 0.0;
}

void TrBdf2::restart(double t, const VecX& y) {
  restart_implicit(t, y);
  f_previous_ = f0_;
}

void TrBdf2::factor(double h) {
  const Eigen::Index n = jacobian_.rows();
  lu_.compute(MatX::Identity(n, n) - (h * tableau().d) * jacobian_);
  factored_h_ = h;
  ++factorisations_;
}

TrBdf2::Newton TrBdf2::solve_stage(double t_stage, double h, const VecX& base, VecX& stage) {
  const double hd = h * tableau().d;
  scale_ = atol_.array() + control_.rtol * y_.array().abs();
  const double enough = newton_enough();
  faccon_ = std::pow(std::max(faccon_, kEpsilon), 0.8);
  double previous = 0.0;
  for (int iteration = 1; iteration <= kMostIterations; ++iteration) {
    system_->derivative(t_stage, stage, f_iterate_);
    ++stats_.rhs_evaluations;
    if (!f_iterate_.allFinite()) return Newton::Failed;
    residual_ = base + hd * f_iterate_ - stage;
    delta_.noalias() = lu_.solve(residual_);
    const double size = rms(delta_, scale_);
    if (!std::isfinite(size)) return Newton::Failed;
    if (iteration > 1) {
      const double rate = size / previous;
      if (!(rate < kDiverging)) return Newton::Failed;
      theta_ = std::max(theta_, rate);
      faccon_ = rate / (1.0 - rate);
    }
    stage += delta_;
    if (faccon_ * size <= enough) return Newton::Converged;
    previous = std::max(size, kEpsilon);
  }
  return Newton::Failed;
}

StepOutcome TrBdf2::step(double t_stop) {
  if (system_ == nullptr) throw std::logic_error("trbdf2: step() before start()");
  step_control::require_ahead(name(), t_, t_stop, direction_);
  const Tableau& c = tableau();
  const double h_min = step_control::minimum_step(t_);
  double h_abs = step_control::first_try(h_, h_max_, step_bound_, h_min);
  bool rejected = false;
  for (;;) {
    const step_control::ClippedStep clipped =
        step_control::clip_to_stop(t_, h_abs, t_stop, direction_, kLandingStretch);
    h_abs = clipped.h_abs;
    const double h = direction_ * h_abs;
    if (need_jacobian_) take_jacobian();
    if (h != factored_h_) factor(h);
    theta_ = 0.0;
    const double hd = h * c.d;

    // The trapezoidal stage from an Euler predictor, then the BDF2 stage from the line through
    // y_n and Y_2 carried on to t_n + h.
    base_ = y_ + hd * f0_;
    stage2_ = y_ + (c.gamma * h) * f0_;
    bool solved = solve_stage(t_ + c.gamma * h, h, base_, stage2_) == Newton::Converged;
    if (solved) {
      f2_ = (stage2_ - base_) / hd;
      base_ = y_ + (h * c.w) * (f0_ + f2_);
      stage3_ = y_ + (stage2_ - y_) / c.gamma;
      solved = solve_stage(clipped.t_new, h, base_, stage3_) == Newton::Converged;
    }
    if (!solved) {
      ++stats_.rejected_steps;
      if (h_abs <= h_min) {
        h_ = h_abs;
        return StepOutcome::StepSizeUnderflow;
      }
      h_abs = std::max(h_min, 0.5 * h_abs);
      // With a Jacobian kept from an earlier state, take it anew here before shortening more.
      if (!jacobian_current_) need_jacobian_ = true;
      rejected = true;
      continue;
    }
    f3_ = (stage3_ - base_) / hd;

    // est = h sum (b_hat - b)_i f_i, filtered through (I - h d J)^-1.
    residual_ =
        h * ((c.b_hat[0] - c.w) * f0_ + (c.b_hat[1] - c.w) * f2_ + (c.b_hat[2] - c.d) * f3_);
    delta_.noalias() = lu_.solve(residual_);
    scale_ = atol_.array() + control_.rtol * y_.array().abs().max(stage3_.array().abs());
    const double err = std::max(rms(delta_, scale_), 1e-10);
    if (!std::isfinite(err) || !stage3_.allFinite()) {
      ++stats_.rejected_steps;
      if (!step_control::shorten_after_blow_up(h_abs, h_min)) {
        h_ = h_abs;
        return StepOutcome::NonFiniteState;
      }
      rejected = true;
      continue;
    }
    const double growth =
        std::clamp(kSafety * std::pow(err, -1.0 / 3.0), 1.0 / kMostShrink, kMostGrowth);
    if (err > 1.0) {
      ++stats_.rejected_steps;
      if (h_abs <= h_min) {
        h_ = h_abs;
        return StepOutcome::StepSizeUnderflow;
      }
      h_abs = std::max(h_min, h_abs * growth);
      rejected = true;
      continue;
    }

    // Accepted.
    double h_next = h_abs * growth;
    if (rejected) h_next = std::min(h_next, h_abs);
    const bool keep_jacobian = theta_ <= kSlowRate;
    if (keep_jacobian && h_next >= h_abs && h_next <= kKeepSizeBelow * h_abs && !clipped.lands) {
      h_next = h_abs;
    }
    y_previous_.swap(y_);
    y_.swap(stage3_);
    system_->project(clipped.t_new, y_);
    f_previous_.swap(f0_);
    t_previous_ = t_;
    t_ = clipped.t_new;
    system_->derivative(t_, y_, f0_);
    ++stats_.rhs_evaluations;
    jacobian_current_ = false;
    need_jacobian_ = !keep_jacobian;
    h_ = std::min(h_next, h_max_);
    ++stats_.accepted_steps;
    return StepOutcome::Ok;
  }
}

void TrBdf2::dense_output(double t, VecX& y_out) const {
  if (t_ == t_previous_) {  // no step since start or restart
    y_out = y_;
    return;
  }
  hermite_interpolate(t_previous_, y_previous_, f_previous_, t_, y_, f0_, t, y_out);
}

// Everything the next step depends on: the Jacobian it may keep, the factorisation's step (made
// again from it), the slopes at both ends of the last step, Newton's memory.
void TrBdf2::archive_memory(StateArchive& archive) {
  archive_implicit(archive);
  archive_sized(archive, "f_previous", f_previous_);
  archive_newton_factor(archive);
  archive.number("theta", theta_);
  if (archive.loading() && factored_h_ != 0.0) factor(factored_h_);
}

}  // namespace tumble
