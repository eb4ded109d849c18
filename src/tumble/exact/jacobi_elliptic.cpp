#include "tumble/exact/jacobi_elliptic.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace tumble {

namespace {

// Bulirsch's means stop where they agree to this (its square is below round-off).
constexpr double kGaussAgreement = 1e-9;
// Below this |u| (after the reduction by periods), sn = u, cn = dn = 1 to round-off.
constexpr double kTinyArgument = 1e-100;

}  // namespace

// AGM of 1 and k' (A&S 17.6.1-17.6.2):
//   a_{n+1} = (a_n + b_n) / 2,  b_{n+1} = sqrt(a_n b_n),  c_{n+1} = (a_n - b_n) / 2,
// with c_{n+1} evaluated as c_n^2 / (4 a_{n+1}) (equal in exact arithmetic, free of the
// cancellation in a_n - b_n). It converges quadratically; stop once c_n / a_n is below round-off.
// Then K = pi / (2 a_N) (A&S 17.6.4).
JacobiElliptic::JacobiElliptic(double k2, double kp2) : k2_(k2), kp2_(kp2) {
  if (!(k2 >= 0.0 && k2 <= 1.0 && kp2 > 0.0 && kp2 <= 1.0)) {
    throw std::invalid_argument("JacobiElliptic: need 0 <= k^2 <= 1 and 0 < k'^2 <= 1, got k^2 = " +
                                std::to_string(k2) + ", k'^2 = " + std::to_string(kp2));
  }
  a_[0] = 1.0;
  b_[0] = std::sqrt(kp2);
  c_[0] = std::sqrt(k2);
  int n = 0;
  while (c_[n] > 0.5 * std::numeric_limits<double>::epsilon() * a_[n]) {
    if (n == kMaxSteps) throw std::logic_error("JacobiElliptic: AGM did not converge");
    a_[n + 1] = 0.5 * (a_[n] + b_[n]);
    b_[n + 1] = std::sqrt(a_[n] * b_[n]);
    c_[n + 1] = c_[n] * c_[n] / (4.0 * a_[n + 1]);
    ++n;
  }
  // 1 - c_n / a_n = (a_n - c_n) / a_n = b_n^2 / (a_n (a_n + c_n)) since a_n^2 = b_n^2 + c_n^2:
  // accurate where c_n / a_n is within round-off of 1 (k' -> 0).
  for (int i = 0; i <= n; ++i) one_minus_ratio_[i] = b_[i] * b_[i] / (a_[i] * (a_[i] + c_[i]));
  steps_ = n;
  quarter_period_ = std::numbers::pi / (2.0 * a_[n]);
  // Bulirsch's scale: the same means, stopped where they agree to sqrt(eps) (the step after would
  // square that), each pair kept.
  double a = 1.0, b_squared = kp2, mean = 1.0;
  for (int i = 1; i <= kMaxSteps; ++i) {
    gauss_steps_ = i;
    gauss_a_[i] = a;
    gauss_b_[i] = std::sqrt(b_squared);
    mean = 0.5 * (a + gauss_b_[i]);
    if (std::abs(a - gauss_b_[i]) <= kGaussAgreement * a) break;
    b_squared = gauss_b_[i] * a;
    a = mean;
  }
  gauss_scale_ = mean;
}

// Descending AGM scale (A&S 16.4.3): phi_N = 2^N a_N u, then for n = N, ..., 1
//   sin(2 phi_{n-1} - phi_n) = (c_n / a_n) sin(phi_n),
// and am(u) = phi_0. The argument is first reduced to |u| <= 2K with am(u + 4K m) = am(u) + 2 pi m.
// dn from dn^2 = k'^2 + k^2 cn^2: a sum of two non-negative terms, accurate to round-off even
// where dn is as small as k' (near the separatrix), unlike 1 - k^2 sn^2.
JacobiValues JacobiElliptic::calc(double u) const {
  const double period = 4.0 * quarter_period_;
  const double m = std::nearbyint(u / period);
  const double u_reduced = u - m * period;
  double phi = std::ldexp(a_[steps_] * u_reduced, steps_);
  for (int n = steps_; n >= 1; --n) {
    // asin(y), y = (c_n / a_n) sin(phi). Near k = 1, c_n / a_n and |sin(phi)| are both close to
    // 1 and asin(y) = pi/2 - 2 asin(sqrt((1 - y) / 2)) loses nothing only if 1 - |y| is formed
    // without cancellation: 1 - |y| = e |s| + cos^2(phi) / (1 + |s|), e = 1 - c_n / a_n.
    const double s = std::sin(phi);
    const double y = c_[n] / a_[n] * s;
    double asin_y;
    if (std::abs(y) < 0.5) {
      asin_y = std::asin(y);
    } else {
      const double c = std::cos(phi);
      const double one_minus_abs_y =
          one_minus_ratio_[n] * std::abs(s) + c * c / (1.0 + std::abs(s));
      asin_y = std::copysign(
          0.5 * std::numbers::pi - 2.0 * std::asin(std::sqrt(0.5 * one_minus_abs_y)), y);
    }
    phi = 0.5 * (phi + asin_y);
  }
  JacobiValues v;
  v.sn = std::sin(phi);
  v.cn = std::cos(phi);
  v.dn = std::sqrt(kp2_ + k2_ * v.cn * v.cn);
  v.am = phi + 2.0 * std::numbers::pi * m;
  return v;
}

// Bulirsch's algorithm (his sncndn): with v = a_N u, s = sin v, c = cos v, it climbs back up the
// means from the ratio c / s by Gauss's transformation, each step
//   x <- x * r,  r <- r * dn,  dn <- (b_{i-1} + x) / (a_{i-1} + x),  x <- r / a_{i-1}
// (x, r: Bulirsch's a and c), sums of positive terms that lose nothing as k -> 1 (where the
// descending scale's arc sines near 1 need the care taken in calc), and ends with
// sn = 1 / sqrt(r^2 + 1), cn = r sn.
JacobiFunctions JacobiElliptic::calc_functions(double u) const {
  const double period = 4.0 * quarter_period_;
  const double u_reduced = u - std::nearbyint(u / period) * period;
  // Near a zero of sn the ratio c / s squared would overflow: there sn = u, cn = dn = 1 to
  // round-off.
  if (std::abs(u_reduced) < kTinyArgument) return {u_reduced, 1.0, 1.0};
  double r = gauss_scale_;
  const double v = u_reduced * r;
  const double s = std::sin(v);
  const double c = std::cos(v);
  JacobiFunctions f{s, c, 1.0};
  if (s == 0.0) return f;
  double x = c / s;
  r *= x;
  for (int i = gauss_steps_; i >= 1; --i) {
    x *= r;
    r *= f.dn;
    f.dn = (gauss_b_[i] + x) / (gauss_a_[i] + x);
    x = r / gauss_a_[i];
  }
  const double magnitude = 1.0 / std::sqrt(r * r + 1.0);
  f.sn = s >= 0.0 ? magnitude : -magnitude;
  f.cn = r * f.sn;
  return f;
}

// Ascending Landen transformation (A&S 17.5.8 with 17.6; DLMF 19.8(i)): phi_0 = phi,
//   tan(phi_{n+1} - phi_n) = (b_n / a_n) tan(phi_n),
// with phi_{n+1} - phi_n taken in the same quadrant as phi_n (atan2 below), and then
// F(phi | k) = phi_N / (2^N a_N). It inverts the descending recursion of calc step by step.
// phi is first reduced to |phi| <= pi with F(phi + 2 pi m) = F(phi) + 4 K m.
double JacobiElliptic::calc_inverse_amplitude(double phi) const {
  const double m = std::nearbyint(phi / (2.0 * std::numbers::pi));
  double phi_n = phi - 2.0 * std::numbers::pi * m;
  for (int n = 0; n < steps_; ++n) {
    double delta = std::atan2(b_[n] * std::sin(phi_n), a_[n] * std::cos(phi_n));
    // atan2 returns (-pi, pi]; shift by whole turns to the branch nearest phi_n, where the
    // increment lies (it has the quadrant of phi_n).
    delta += 2.0 * std::numbers::pi * std::nearbyint((phi_n - delta) / (2.0 * std::numbers::pi));
    phi_n += delta;
  }
  return std::ldexp(phi_n, -steps_) / a_[steps_] + 4.0 * quarter_period_ * m;
}

}  // namespace tumble
