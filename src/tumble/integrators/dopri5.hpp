#pragma once
// Dormand-Prince 5(4) with MATLAB ode45's step-size control and defaults: the workhorse method.
//
// Method (J. R. Dormand and P. J. Prince, "A family of embedded Runge-Kutta formulae", J. Comput.
// Appl. Math. 6 (1980) 19-26): seven stages k_1..k_7, of which k_7 = f(t + h, y_new) is the next
// step's k_1 (first same as last, FSAL), the 5th-order solution y_new = y + h sum b_i k_i, and
// the local error estimate e = h sum (b_i - bhat_i) k_i against the embedded 4th-order one.
//
// Step control (Shampine and Reichelt, "The MATLAB ODE Suite", 1997, and ode45.m):
//   err = max_i |e_i| / max(|y_i|, |y_new_i|, atol / rtol), accepted when err <= rtol;
//   first rejection in a step: h *= max(0.1, 0.8 (rtol / err)^(1/5)); later ones: h *= 0.5;
//   after an acceptance with no rejection in that step: h /= max(0.2, 1.25 (err / rtol)^(1/5));
//   |h| <= max_step (default a tenth of |t_end - t0|); a rejected step already at the minimum
//   16 eps(t) is a StepSizeUnderflow; a step within 10 % of t_stop is stretched onto it.
// The first step is ode45's (step_size_control.hpp) unless StepControl::initial_step > 0.
// Deviation from ode45, for stops that are not the end (breakpoints): after a step shortened to
// land on t_stop the next step is at least the step the controller had proposed before clipping.
//
// Continuous extension: Shampine's 4th-order interpolant (L. F. Shampine, "Some practical
// Runge-Kutta formulas", Math. Comp. 46 (1986) 135-150; Hairer-Norsett-Wanner I, II.6), with
// s = (t - t_n) / h, s1 = 1 - s, Delta = y_{n+1} - y_n, D = sum d_i k_i:
//   y(s) = y_n + s^2 (3 - 2 s) Delta + h [s s1^2 k_1 - s^2 s1 k_7 + s^2 s1^2 D],
// no extra evaluations of f.
//
// Projection: after each accepted step system.project() puts y_new back on the manifold. FSAL's
// k_1 and the continuous extension (which ends exactly on the projected state) must belong to the
// state the next step starts from: when the projection only renormalised unit quaternions, k_7
// is rescaled to f at the projected state exactly (OdeSystem's contract on quaternions, no
// evaluation); any other change (constraints) costs one evaluation of f. So
//   rhs_evaluations = 1 (start) + 6 (accepted + rejected)
//                     + (steps whose projection moved y beyond renormalising) + 1 per restart.
#include <array>

#include "tumble/integrators/integrator.hpp"

namespace tumble {

class Dopri5 final : public Integrator {
 public:
  // Throws std::invalid_argument for tolerances or step bounds that make no sense;
  // StepControl::fixed_step is ignored.
  explicit Dopri5(const StepControl& control);

  std::string_view name() const override { return "dopri5"; }
  int order() const override { return 5; }
  bool adaptive() const override { return true; }

  void start(OdeSystem& system, double t0, const VecX& y0, double t_end) override;
  void restart(double t, const VecX& y) override;
  std::unique_ptr<Integrator> clone_onto(OdeSystem& system) const override {
    auto copy = std::make_unique<Dopri5>(*this);
    copy->system_ = &system;
    return copy;
  }
  void archive_memory(StateArchive& archive) override;
  StepOutcome step(double t_stop) override;
  void dense_output(double t, VecX& y_out) const override;

 private:
  static constexpr int kStages = 7;
  using Stages = std::array<VecX, kStages>;

  // The stages of the last accepted step (for FSAL and the continuous extension) and those of
  // the step being tried, which may be rejected or fail without touching the accepted ones.
  const Stages& accepted_stages() const { return stages_[accepted_]; }
  Stages& trial_stages() { return stages_[1 - accepted_]; }

  StepControl control_;
  OdeSystem* system_ = nullptr;
  double direction_ = 1.0;  // +1 forward in time, -1 backward
  double h_max_ = 0.0;      // s, bound on |h|
  std::array<Stages, 2> stages_;
  int accepted_ = 0;  // which of stages_ holds the last accepted step
  VecX y_stage_;      // argument of f at the inner stages
  VecX y_new_;        // the 5th-order solution of the step being tried
  VecX error_;        // its local error estimate
  VecX thresholds_;   // atol_i / rtol per component (step_control::absolute_tolerances)
};

}  // namespace tumble
