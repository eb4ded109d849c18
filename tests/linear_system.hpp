#pragma once
// y' = A y with its Jacobian: the linear system the implicit methods' tests solve in closed form.
#include <cmath>
#include <complex>
#include <utility>

#include "tumble/integrators/ode_system.hpp"

namespace tumble::test {

// y' = A y with its Jacobian A: y(t) = exp(A (t - t0)) y0, from A's eigen-decomposition.
class Linear : public OdeSystem {
 public:
  explicit Linear(MatX a) : a_(std::move(a)) {}
  Eigen::Index dimension() const override { return a_.rows(); }
  void derivative(double /*t*/, const VecX& y, VecX& dydt) const override {
    dydt.noalias() = a_ * y;
  }
  bool jacobian(double /*t*/, const VecX& /*y*/, MatX& dfdy) const override {
    dfdy = a_;
    return true;
  }
  bool gives_jacobian() const override { return true; }
  // exp(A t) y0 for a 2 x 2 A, from its eigenvalues tau +- d (tau = tr(A)/2, d^2 = tau^2 -
  // det(A), complex where the motion oscillates): with C = (e^((tau+d)t) + e^((tau-d)t))/2 and
  // S = (e^((tau+d)t) - e^((tau-d)t))/(2d), exp(A t) = (C - tau S) I + S A (each exponential
  // on its own, so that a fast decay underflows to zero rather than meeting an overflow).
  VecX exact(double t, const VecX& y0) const {
    using Complex = std::complex<double>;
    const double tau = 0.5 * a_.trace();
    const Complex d = std::sqrt(Complex(tau * tau - a_.determinant()));
    const Complex plus = std::exp((tau + d) * t), minus = std::exp((tau - d) * t);
    const double C = std::real(0.5 * (plus + minus));
    const double S = std::real((plus - minus) / (2.0 * d));
    return (C - tau * S) * y0 + S * (a_ * y0);
  }

 private:
  MatX a_;
};

// y' = -y without its Jacobian: an explicit method's system, which the implicit methods refuse.
class DecayWithoutJacobian : public OdeSystem {
 public:
  Eigen::Index dimension() const override { return 1; }
  void derivative(double /*t*/, const VecX& y, VecX& dydt) const override { dydt[0] = -y[0]; }
};

// Two modes, rates -1 and -1e6 s^-1, coupled in the state's axes: A = P diag(-1, -1e6) P^-1.
inline MatX two_rates() {
  Eigen::Matrix2d p;
  p << 1.0, 1.0, 1.0, -2.0;
  const Eigen::Matrix2d d = Eigen::Vector2d(-1.0, -1e6).asDiagonal();
  return p * d * p.inverse();
}

// x'' = -x.
inline MatX oscillator() {
  MatX a(2, 2);
  a << 0.0, 1.0, -1.0, 0.0;
  return a;
}

}  // namespace tumble::test
