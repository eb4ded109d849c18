#pragma once
// DOP853: Dormand and Prince's explicit Runge-Kutta method of order 8 with Hairer and Wanner's
// step control and 7th-order continuous extension, for tight tolerances.
//
// Method (E. Hairer, S. P. Norsett and G. Wanner, "Solving Ordinary Differential Equations I",
// 2nd ed., Springer 1993, section II.10, and their code DOP853): twelve stages k_1..k_12 (k_12 at
// t + h), the 8th-order solution y_new = y + h sum b_i k_i, and two local error estimates,
// e5 = sum er_i k_i (5th order) and e3 = sum b_i k_i - bhh1 k_1 - bhh2 k_9 - bhh3 k_12 (3rd
// order), combined as
//   err = |h| E5 / sqrt(n (E5 + 0.01 E3)),  E_p = sum_i (e_p,i / sk_i)^2,
//   sk_i = atol + rtol max(|y_i|, |y_new_i|),
// accepted when err <= 1. After acceptance k_13 = f(t + h, y_new) is the next step's k_1.
//
// Step control (Hairer's code, with beta = 0): fac = clamp(err^(1/8) / 0.9, 1/6, 1/0.333),
// h_new = h / fac; after a rejection the step does not grow in the next accepted step; a rejected
// step already at 16 eps(t) is a StepSizeUnderflow; a step within 1 % of t_stop is stretched onto
// it. The first step is Hairer's starting-step algorithm (one extra f evaluation) unless
// StepControl::initial_step > 0. The default bound on |h| is the whole span |t_end - t0|, as in
// Hairer's code (not ode45's tenth: the 8th-order method wants long steps; outputs come from the
// continuous extension), unless StepControl::max_step > 0.
//
// Continuous extension: with s = (t - t_n) / h, s1 = 1 - s, Delta = y_{n+1} - y_n,
//   r2 = Delta, r3 = h k_1 - Delta, r4 = Delta - h k_13 - r3,
//   r5..r8 = h sum_{i in 1,6..16} d_{j,i} k_i,
//   y(s) = y_n + s (r2 + s1 (r3 + s (r4 + s1 (r5 + s (r6 + s1 (r7 + s r8)))))),
// which needs three more stages k_14..k_16. They are evaluated lazily, on the first
// dense_output() call inside a step, so steps that no output or event looks into cost 12
// evaluations, not 15. Hence dense_output() is const but fills a mutable cache and counts the
// three evaluations in the (mutable) statistics:
//   rhs_evaluations = 2 (start) + 11 (accepted + rejected) + accepted
//                     + 3 (steps with dense output) + 1 per restart.
// Projection costs nothing extra: k_13 is evaluated after system.project() on the new state.
#include <array>

#include "tumble/integrators/integrator.hpp"

namespace tumble {

class Dop853 final : public Integrator {
 public:
  // Throws std::invalid_argument for tolerances or step bounds that make no sense;
  // StepControl::fixed_step is ignored.
  explicit Dop853(const StepControl& control);

  std::string_view name() const override { return "dop853"; }
  int order() const override { return 8; }
  bool adaptive() const override { return true; }

  void start(OdeSystem& system, double t0, const VecX& y0, double t_end) override;
  void restart(double t, const VecX& y) override;
  std::unique_ptr<Integrator> clone_onto(OdeSystem& system) const override {
    auto copy = std::make_unique<Dop853>(*this);
    copy->system_ = &system;
    return copy;
  }
  void archive_memory(StateArchive& archive) override;
  StepOutcome step(double t_stop) override;
  void dense_output(double t, VecX& y_out) const override;
  // Hairer's stiffness estimate (DOP853's, and dopri5's in Hairer-Wanner II, section IV.2): the
  // last step's two evaluations at its end, k_12 at the last stage's argument and k_13 at the new
  // state, give |lambda| ~ |k_13 - k_12| / |y_new - Y_12| along their difference, a direction in
  // which the stages' own error has grown where stability holds the step; here both norms are
  // taken in the step error's scale (sk_i). Compared with 6.1, the edge of DOP853's stability
  // region on the negative real axis. 0 right after a start or restart.
  double last_step_h_lambda() const override;

 private:
  static constexpr int kStages = 13;  // k_1..k_12 and k_13 = f(t + h, y_new)
  using Stages = std::array<VecX, kStages>;

  // Hairer's starting step (Hairer-Norsett-Wanner I, II.4, and DOP853's HINIT), from f0 in the
  // accepted stages' k_13.
  double initial_step();
  // k_14..k_16 and r5..r8 of the last accepted step.
  void prepare_dense_output() const;

  // The stages of the last accepted step and of the step being tried (which may be rejected or
  // fail without touching the accepted ones, so the lazy continuous extension stays valid).
  const Stages& accepted_stages() const { return stages_[accepted_]; }
  Stages& trial_stages() { return stages_[1 - accepted_]; }

  StepControl control_;
  OdeSystem* system_ = nullptr;
  double direction_ = 1.0;  // +1 forward in time, -1 backward
  double h_max_ = 0.0;      // s, bound on |h|
  std::array<Stages, 2> stages_;
  int accepted_ = 0;  // which of stages_ holds the last accepted step
  VecX y_stage_;      // argument of f at the inner stages
  VecX increment_;    // sum b_i k_i
  VecX y_new_;        // the 8th-order solution of the step being tried
  VecX error5_;       // the 5th-order error estimate (without h)
  VecX error3_;       // the 3rd-order error estimate (without h)
  VecX atols_;        // the absolute tolerance per component (step_control::absolute_tolerances)

  // Lazy continuous extension of the last accepted step.
  mutable bool dense_ready_ = false;
  mutable std::array<VecX, 3> dense_stages_;  // k_14, k_15, k_16
  mutable std::array<VecX, 4> dense_terms_;   // r5, r6, r7, r8
  mutable VecX dense_y_stage_;
};

}  // namespace tumble
