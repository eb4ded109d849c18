#pragma once
// Jacobi elliptic functions sn, cn, dn, the amplitude am and its inverse F(phi | k) for a fixed
// modulus 0 <= k < 1, by the arithmetic-geometric mean (AGM). The complementary modulus k' is an
// input of its own, so that the functions stay accurate to round-off as k -> 1 (near the
// separatrix of the free rigid body, where 1 - k^2 is the small quantity and cannot be recovered
// from a rounded k).
//
// Sources: Abramowitz & Stegun, Handbook of Mathematical Functions, 16.4 (descending AGM scale for
// sn, cn, dn) and 17.5-17.6 (AGM for K and the ascending Landen transformation for F);
// DLMF 22.20(ii) and 19.8(i); R. Bulirsch, "Numerical calculation of elliptic integrals and
// elliptic functions", Numer. Math. 7 (1965) 78-90 (sn, cn, dn by the Gauss transformation).
#include <array>

namespace tumble {

// sn, cn, dn of one argument u, and the amplitude am(u) (rad; continuous and increasing in u, so
// am(u + 4K) = am(u) + 2 pi): sn = sin(am), cn = cos(am).
struct JacobiValues {
  double sn;
  double cn;
  double dn;
  double am;
};

// sn, cn and dn alone.
struct JacobiFunctions {
  double sn;
  double cn;
  double dn;
};

class JacobiElliptic {
 public:
  // k2 = k^2 and kp2 = k'^2 = 1 - k^2, both in [0, 1], kp2 > 0 (the separatrix k = 1 has no
  // finite period and is handled by the caller with sech / tanh). The pair is taken as given:
  // k2 + kp2 may differ from 1 by round-off.
  JacobiElliptic(double k2, double kp2);

  // Complete elliptic integral of the first kind K(k) = pi / (2 AGM(1, k')).
  double quarter_period() const { return quarter_period_; }
  double k2() const { return k2_; }
  double kp2() const { return kp2_; }

  // sn, cn, dn, am at any real u; does not allocate.
  JacobiValues calc(double u) const;
  // sn, cn, dn at any real u, by Bulirsch's Gauss transformation (one sine and cosine, no arc
  // sines): a fifth of calc's time, as accurate (tests/torque_free_test.cpp); no am.
  JacobiFunctions calc_functions(double u) const;
  // The incomplete integral F(phi | k) = int_0^phi dtheta / sqrt(1 - k^2 sin^2 theta) at any
  // real phi (rad): the inverse of am, so calc(calc_inverse_amplitude(phi)).am == phi to
  // round-off.
  double calc_inverse_amplitude(double phi) const;

 private:
  // AGM scale a_n, b_n, c_n (A&S 16.4.2): a_0 = 1, b_0 = k', c_0 = k, converged after steps_.
  static constexpr int kMaxSteps = 40;
  std::array<double, kMaxSteps + 1> a_{};
  std::array<double, kMaxSteps + 1> b_{};
  std::array<double, kMaxSteps + 1> c_{};
  std::array<double, kMaxSteps + 1> one_minus_ratio_{};  // 1 - c_n / a_n, without cancellation
  int steps_ = 0;
  // Bulirsch's scale (the AGM of 1 and k' to sqrt(eps), which the last step squares):
  // gauss_a_[i] = a_{i-1}, gauss_b_[i] = b_{i-1} for i = 1..gauss_steps_, and gauss_scale_ the
  // last mean, which the argument is multiplied by.
  std::array<double, kMaxSteps + 1> gauss_a_{};
  std::array<double, kMaxSteps + 1> gauss_b_{};
  int gauss_steps_ = 0;
  double gauss_scale_ = 1.0;
  double k2_;
  double kp2_;
  double quarter_period_;
};

}  // namespace tumble
