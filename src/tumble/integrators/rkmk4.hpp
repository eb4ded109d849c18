#pragma once
// A Runge-Kutta-Munthe-Kaas method of order 4 on SO(3)^m x R^n: the unit quaternions at
// system.unit_quaternion_offsets() are advanced by exact rotations, so they stay unit to
// round-off; every other component takes the classical RK4 step (rk4.hpp).
//
// H. Munthe-Kaas, "High order Runge-Kutta methods on manifolds", Appl. Numer. Math. 29 (1999)
// 115-127; E. Hairer, C. Lubich and G. Wanner, "Geometric Numerical Integration", 2nd ed.,
// Springer 2006, section IV.8.2.
//
// A quaternion q with q' = q (x) (0, omega_B) / 2 moves by right multiplication, q = q_n (x)
// exp(Theta), with exp(Theta) = (cos(|Theta|/2), sin(|Theta|/2) Theta / |Theta|). Its rotation
// vector obeys
//   Theta' = dexp^{-1}_{-Theta}(omega_B) = omega_B + Theta x omega_B / 2
//            + Theta x (Theta x omega_B) / 12 + O(|Theta|^3 |omega_B|),
// (the body-frame, left-trivialised form: hence the + signs, where the spatial form has
// v - [u, v]/2 + [u, [u, v]]/12), truncated after the double cross product, which is all order 4
// needs (Munthe-Kaas: keep the terms of order < p - 1). With the RK4 tableau, stage by stage:
//   Theta_1 = 0, Theta_2 = h/2 K_1, Theta_3 = h/2 K_2, Theta_4 = h K_3,
//   Q_i = q_n (x) exp(Theta_i),  y_i = y_n + h sum_j a_ij F_j  (the other components),
//   (Q_i', F_i) = f(t + c_i h, (Q_i, y_i)),
//   omega_i = 2 vec(conj(Q_i) (x) Q_i') / |Q_i|^2  (omega_B read back from the system's q'),
//   K_i = dexp^{-1}_{-Theta_i}(omega_i),
//   q_{n+1} = q_n (x) exp(h/6 (K_1 + 2 K_2 + 2 K_3 + K_4)).
// For a constant omega_B every Theta_i is parallel to it, K_i = omega_B and the step is exact.
//
// Fixed step on a grid, landing on t_stop, project() and the evaluation count as rk4:
// 1 (start) + 4 per step + 1 per restart. Continuous extension: the cubic Hermite interpolant of
// all components (the quaternion's slope is the system's q'), then the quaternions normalised.
#include <Eigen/Dense>
#include <array>
#include <span>

#include "tumble/integrators/fixed_step_method.hpp"

namespace tumble {

class Rkmk4 final : public FixedStepMethod {
 public:
  // Throws std::invalid_argument unless control.fixed_step > 0; the tolerances are ignored.
  explicit Rkmk4(const StepControl& control) : FixedStepMethod("rkmk4", control) {}

  std::string_view name() const override { return "rkmk4"; }
  int order() const override { return 4; }
  std::unique_ptr<Integrator> clone_onto(OdeSystem& system) const override {
    auto copy = std::make_unique<Rkmk4>(*this);
    copy->system_ = &system;
    // The offsets are the system's own (a span into it), not this method's.
    copy->quaternion_offsets_ = system.unit_quaternion_offsets();
    return copy;
  }
  StepOutcome step(double t_stop) override;

 protected:
  void prepare(OdeSystem& system, Eigen::Index n) override;
  void finish_dense_output(VecX& y_out) const override;

 private:
  // K_i = dexp^{-1}_{-Theta}(omega_B) for every quaternion slot, omega_B read from (y, f) there.
  void calc_lie_algebra_slopes(const VecX& y, const VecX& f, const Eigen::Matrix3Xd& theta,
                               Eigen::Matrix3Xd& slopes) const;
  // y_out's quaternion slots = q_n (x) exp(theta) (other components untouched).
  void rotate_quaternions(const Eigen::Matrix3Xd& theta, VecX& y_out) const;

  std::span<const Eigen::Index> quaternion_offsets_;
  std::array<Eigen::Matrix3Xd, 4> slopes_;  // K_1..K_4, one column per quaternion slot
  Eigen::Matrix3Xd theta_;                  // Theta_i, one column per quaternion slot
};

}  // namespace tumble
