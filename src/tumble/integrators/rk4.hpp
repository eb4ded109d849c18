#pragma once
// The classical fourth-order Runge-Kutta method with a fixed step, the reference method of the
// benchmarks and the vector-space twin of rkmk4.
//
//   k1 = f(t, y), k2 = f(t + h/2, y + h/2 k1), k3 = f(t + h/2, y + h/2 k2), k4 = f(t + h, y + h
//   k3), y_new = y + h/6 (k1 + 2 k2 + 2 k3 + k4),
// then system.project(t + h, y_new) and f(t + h, y_new), which is the continuous extension's end
// slope and the next step's k1: rhs_evaluations = 1 (start) + 4 accepted + 1 per restart.
//
// Steps lie on the grid t_grid + n h (computed, not accumulated, so long runs do not drift). A
// step that would pass t_stop, or end within a tiny fraction (1e-8) of h short of it, ends on
// t_stop exactly; the grid then restarts there. Continuous extension: the cubic Hermite
// interpolant from (y, f) at both ends of the step (hermite.hpp).
#include "tumble/integrators/fixed_step_method.hpp"

namespace tumble {

class Rk4 final : public FixedStepMethod {
 public:
  // Throws std::invalid_argument unless control.fixed_step > 0; the tolerances are ignored.
  explicit Rk4(const StepControl& control) : FixedStepMethod("rk4", control) {}

  std::string_view name() const override { return "rk4"; }
  int order() const override { return 4; }
  std::unique_ptr<Integrator> clone_onto(OdeSystem& system) const override {
    auto copy = std::make_unique<Rk4>(*this);
    copy->system_ = &system;
    return copy;
  }
  StepOutcome step(double t_stop) override;
};

}  // namespace tumble
