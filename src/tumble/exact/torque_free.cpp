// The exact torque-free motion of a rigid body (Euler-Poinsot).
//
// Notation. Body axes B; principal axes P (I_G_B = Q diag(I_1, I_2, I_3) Q^T, I_1 <= I_2 <= I_3,
// Q proper); working axes K, a signed permutation of P chosen below so that the angular momentum
// circulates about K's third axis with L_3 > 0. J_1, J_2, J_3 are the moments along K's axes and
// w = omega_K. World W; L = |L_W|; E the kinetic energy.
//
// 1. Angular velocity (Landau & Lifshitz, Mechanics, 3rd ed., §37, eqs. 37.10-37.12; Whittaker,
//    Analytical Dynamics, §69). Euler's equations J_1 w_1' = (J_2 - J_3) w_2 w_3 (cyclic) with
//    2E = sum J_i w_i^2, L^2 = sum J_i^2 w_i^2 are solved, when J_2 lies between J_1 and J_3 and
//    sign(L^2 - 2 E J_2) = sign(J_3 - J_2) (the orbit encircles axis 3), by
//      w_1 = a_1 cn(tau), w_2 = a_2 sn(tau), w_3 = a_3 dn(tau),  tau = lambda t + tau_0,
//    where, with the cancellation-free forms of the two positive combinations
//      A_1 = 2 E J_3 - L^2 = J_1 (J_3 - J_1) w_1^2 + J_2 (J_3 - J_2) w_2^2,
//      A_3 = L^2 - 2 E J_1 = J_2 (J_2 - J_1) w_2^2 + J_3 (J_3 - J_1) w_3^2,
//      D   = L^2 - 2 E J_2 = J_1 (J_1 - J_2) w_1^2 + J_3 (J_3 - J_2) w_3^2,
//    a_1^2 = A_1 / (J_1 (J_3 - J_1)), a_2^2 = A_1 / (J_2 (J_3 - J_2)), a_3^2 = A_3 / (J_3 (J_3 -
//    J_1)), lambda^2 = (J_3 - J_2) A_3 / (J_1 J_2 J_3), k^2 = (J_2 - J_1) A_1 / ((J_3 - J_2) A_3)
//    and k'^2 = 1 - k^2 = (J_3 - J_1) D / ((J_3 - J_2) A_3) (the last identity follows by
//    expanding; it keeps k' accurate near the separatrix D = 0). Substituting cn' = -sn dn, sn' =
//    cn dn, dn' = -k^2 sn cn into Euler's equations fixes the signs: with a_3 > 0 and lambda > 0,
//    sign(a_2) = sign(a_1) sign(J_3 - J_2). The same formulas hold for J_1 > J_2 > J_3 (all
//    differences change sign together), which is how the orbits about the minimum axis are done.
//    On the separatrix D = 0 (k = 1): sn = tanh, cn = dn = sech.
//    The phase tau_0 comes from the amplitude am(tau_0) = atan2(w_2 / a_2, w_1 / a_1) at t = 0,
//    inverted with F(phi | k) (the components that change sign fix the phase; dn follows).
//
// 2. Orientation (the construction of Celledoni, Fasso, Safstrom & Zanna, "The exact computation
//    of the free rigid body motion and its use in splitting methods", SIAM J. Sci. Comput. 30(4),
//    2008, section 2; also van Zon & Schofield, J. Comput. Phys. 225, 2007):
//      R_WK(t) = R_WL Rz(psi(t)) P(l(t)),  l = L_K / L,
//    where P(l) is the rotation taking l to e_3 about the axis l x e_3 (never singular, since
//    l_3 > 0 on the whole orbit):
//      P = I + [v]x + [v]x^2 / (1 + l_3),  v = l x e_3,
//    and R_WL = R_WK(0) P(l(0))^T is the fixed rotation with R_WL e_3 = L_W / L.
//    Derivation of psi' (ours; the same steps as in the references): R_WK^T dR_WK/dt = [w]x gives
//    w = psi' P^T e_3 + vee(P^T P') = psi' l + vee(P^T P'). Dotting with l (l.w = 2E/L) and using
//    l' = l x w, l.vee(P^T P') = (P' P^T)_{21} = (l_1 l_2' - l_2 l_1') / (1 + l_3)
//    = (l_3 2E/L - w_3) / (1 + l_3), so
//      psi' = (2E/L + w_3) / (1 + l_3) = (2E + L w_3) / (L + J_3 w_3),
//    a function of dn(tau) alone, hence of period 2K in tau. (With Euler angles about L instead of
//    the minimal rotation one gets Landau's phi' = L (J_1 w_1^2 + J_2 w_2^2)/(J_1^2 w_1^2 +
//    J_2^2 w_2^2), eq. 37.15; the two differ by the rate of atan2(l_1, l_2).) The test checks
//    dR/dt = R [omega_B]x by finite differences.
//    psi is integrated once, as a series: psi' is even in tau and of period 2K, so
//      psi'(tau) = c_0 + sum_n c_n cos(n pi tau / K),  G(tau) = int_0^tau psi' dtau
//                = c_0 tau + sum_n c_n K / (n pi) sin(n pi tau / K),
//    and psi(t) = (G(tau(t)) - G(tau_0)) / lambda. The c_n are the trapezoidal rule's on M + 1
//    samples over a half period (a cosine transform, by FFT), which for a periodic analytic
//    function is exact but for the aliasing of the coefficients beyond M; M doubles until the upper
//    half of the c_n is at round-off, and that half is dropped, with the lower half's trailing
//    terms at round-off. psi' is analytic in a strip about the real axis, so its c_n fall
//    geometrically: 65 samples and 21 terms for the chapter's prism, 257 and 82 for an orbit within
//    round-off of the separatrix (where K grows as ln(4 / k')), 4,097 and 1,192 where k'^2
//    underflows to a subnormal number (K ~ 370). Each evaluation is then one sum by
//    Clenshaw's recurrence, not a quadrature. On the separatrix itself psi' is not periodic: it
//    tends to 2E/L as |tau| -> infinity (sech(44) < 2e-19), and G is tabulated at panel
//    boundaries over |tau| <= 44 (adaptive Gauss-Kronrod, to round-off), completed inside a panel
//    by a 15-point Gauss-Legendre rule and extended linearly.
#include "tumble/exact/torque_free.hpp"

#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unsupported/Eigen/FFT>

#include "tumble/exact/jacobi_elliptic.hpp"
#include "tumble/math/rotation.hpp"

namespace tumble {

// Outside the anonymous namespace: Impl, declared in the header, holds one.
enum class TorqueFreeMotionKind {
  kSteady,      // omega_B constant: at rest, spherical body, or spin about a principal axis
  kPeriodic,    // off the separatrix: elliptic functions with 0 <= k < 1
  kSeparatrix,  // D = 0 exactly: sech / tanh
};

namespace {

// The cosine series of psi' (periodic orbits): samples over a half period, at least and at most.
constexpr int kLeastSamples = 32;
constexpr int kMostSamples = 1 << 16;
// A coefficient within this many round-offs of the largest sample is at the transform's noise.
constexpr double kSeriesNoise = 8.0;

// Panel width (in tau) of the psi table (the separatrix). psi' is a rational function of dn(tau),
// analytic in a strip about the real axis (dn has its poles at i K', K' >= pi/2), and varies on a
// scale >= 1 in tau (dn ~ sech near the separatrix), so a 15-point Gauss-Legendre rule on a panel
// of width 0.5 is exact to round-off. Checked while writing this: against adaptive 61-point
// Gauss-Kronrod the panel integrals differ by <= 2.2e-16 for k'^2 from 0.5 down to 1e-30 and
// J_3 a_3 / L from 0.3 to 1 - 1e-6.
constexpr double kPanelWidth = 0.5;
// Half-width of the tabulated range on the separatrix: beyond it sech(tau) < 2e-19.
constexpr double kSeparatrixHalfRange = 44.0;

// The rotation taking the unit vector l (l_3 > -1) to e_3 about l x e_3.
Mat3 rotation_to_e3(const Vec3& l) {
  const double c = 1.0 / (1.0 + l.z());
  Mat3 P;
  P << 1.0 - l.x() * l.x() * c, -l.x() * l.y() * c, -l.x(),  //
      -l.x() * l.y() * c, 1.0 - l.y() * l.y() * c, -l.y(),   //
      l.x(), l.y(), l.z();
  return P;
}

Mat3 rotation_about_z(double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  Mat3 Rz;
  Rz << c, -s, 0.0,  //
      s, c, 0.0,     //
      0.0, 0.0, 1.0;
  return Rz;
}

// Neumaier's compensated sum: the rounding of each addition is kept and added back at the end,
// so that a sum of many terms is as accurate as its terms.
class CompensatedSum {
 public:
  void add(double x) {
    const double t = sum_ + x;
    compensation_ += std::abs(sum_) >= std::abs(x) ? (sum_ - t) + x : (x - t) + sum_;
    sum_ = t;
  }
  double value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0, compensation_ = 0;
};

std::string format_matrix(const Mat3& M) {
  std::ostringstream os;
  os.precision(17);
  os << "[" << M.row(0) << "; " << M.row(1) << "; " << M.row(2) << "]";
  return os.str();
}

}  // namespace

struct TorqueFreeMotion::Impl {
  TorqueFreeMotionKind kind = TorqueFreeMotionKind::kSteady;
  Mat3 R_WB0;
  Vec3 omega_B0;
  Vec3 omega_W0;
  Vec3 L_W;           // angular momentum about the COM, world (kg m^2 / s)
  double energy = 0;  // rotational kinetic energy (J)

  // Working axes: omega_K = S_KB omega_B; moments J (kg m^2) along them.
  Mat3 S_KB;
  Vec3 J;
  double L_norm = 0;    // |L| (kg m^2 / s)
  double energy_K = 0;  // E from the working-frame components (consistent with L_norm)
  Vec3 amplitude;       // a_1, a_2, a_3 (rad/s), signed as in the header comment
  double lambda = 0;    // rate of the elliptic argument (1/s)
  double tau0 = 0;      // elliptic argument at t = 0
  std::optional<JacobiElliptic> jacobi;
  double period = std::numeric_limits<double>::infinity();

  Mat3 R_WL;  // fixed: R_WL e_3 = L_W / L

  // Periodic orbits: psi' = mean_psi_rate + sum_n c_n cos(n pi tau / K); G's periodic part
  // sum_n psi_sine[n - 1] sin(n pi tau / K), psi_sine[n - 1] = c_n K / (n pi).
  double mean_psi_rate = 0;
  std::vector<double> psi_sine;
  // The separatrix: G at tau = table_begin + j * panel_width, j = 0..panels.
  double table_begin = 0;
  double panel_width = 0;
  std::vector<double> G_table;
  double G_tau0 = 0;

  // Angular velocity in working axes at elliptic argument tau.
  Vec3 calc_omega_K(double tau) const {
    if (kind == TorqueFreeMotionKind::kSeparatrix) {
      const double sech = 1.0 / std::cosh(tau);
      return Vec3(amplitude.x() * sech, amplitude.y() * std::tanh(tau), amplitude.z() * sech);
    }
    const JacobiFunctions v = jacobi->calc_functions(tau);
    return Vec3(amplitude.x() * v.cn, amplitude.y() * v.sn, amplitude.z() * v.dn);
  }

  // psi' = (2E + L w_3) / (L + J_3 w_3), as a function of tau (rad/s).
  double calc_psi_rate(double tau) const {
    const double w3 = kind == TorqueFreeMotionKind::kSeparatrix
                          ? amplitude.z() / std::cosh(tau)
                          : amplitude.z() * jacobi->calc_functions(tau).dn;
    return (2.0 * energy_K + L_norm * w3) / (L_norm + J.z() * w3);
  }

  // G(tau) = int_0^tau psi'(s) ds (periodic case: the series) or int_{-44}^tau (separatrix: the
  // table).
  double calc_G(double tau) const {
    if (kind == TorqueFreeMotionKind::kPeriodic) {
      // tau = whole periods + r, r in [0, 2K): the mean rate carries the periods exactly, and the
      // sines are taken at theta = pi r / K in [0, 2 pi).
      const double K = jacobi->quarter_period();
      const double turns = std::floor(tau / (2.0 * K));
      const double r = tau - turns * 2.0 * K;
      const double theta = std::numbers::pi * r / K;
      // Clenshaw: u_n = b_n + 2 cos(theta) u_{n+1} - u_{n+2}; the sum is u_1 sin(theta).
      const double two_cos = 2.0 * std::cos(theta);
      double u1 = 0, u2 = 0;
      for (auto b = psi_sine.rbegin(); b != psi_sine.rend(); ++b) {
        const double u0 = *b + two_cos * u1 - u2;
        u2 = u1;
        u1 = u0;
      }
      return mean_psi_rate * (turns * 2.0 * K + r) + u1 * std::sin(theta);
    }
    const int panels = static_cast<int>(G_table.size()) - 1;
    const double span = panel_width * panels;
    const auto rate = [this](double s) { return calc_psi_rate(s); };
    double r = tau - table_begin;
    if (r <= 0.0 || r >= span) {
      // Beyond the table psi' = 2E/L to round-off.
      const double rate_far = 2.0 * energy_K / L_norm;
      return r <= 0.0 ? rate_far * r : G_table.back() + rate_far * (r - span);
    }
    r = std::clamp(r, 0.0, span);
    const int j = std::min(static_cast<int>(r / panel_width), panels - 1);
    const double panel_start = table_begin + j * panel_width;
    return G_table[j] + boost::math::quadrature::gauss<double, 15>::integrate(rate, panel_start,
                                                                              table_begin + r);
  }

  // The cosine series of psi' over the period 2K (module comment, 2.).
  void build_psi_series() {
    const double K = jacobi->quarter_period();
    // samples[j] = psi'(j K / M), j = 0..M; each doubling adds the midpoints.
    std::vector<double> samples = {calc_psi_rate(0.0), calc_psi_rate(K)};
    std::vector<double> coefficients;
    std::vector<std::complex<double>> spectrum;
    for (int M = 1; M < kMostSamples;) {
      std::vector<double> finer(2 * static_cast<std::size_t>(M) + 1);
      for (int j = 0; j <= M; ++j) finer[2 * j] = samples[j];
      for (int j = 0; j < M; ++j) finer[2 * j + 1] = calc_psi_rate((2 * j + 1) * K / (2 * M));
      samples = std::move(finer);
      M *= 2;
      if (M < kLeastSamples) continue;
      // The trapezoidal rule over the whole period, folded onto the half (psi' is even):
      //   c_n = (1 / M) (f_0 + (-1)^n f_M + 2 sum_{j=1}^{M-1} f_j cos(n pi j / M)),
      // c_0 half of that: the real part of the discrete Fourier transform of the samples' even
      // extension over the 2M points of the period, by FFT (Eigen's module: O(M log M); the
      // sum written out, O(M^2), took 0.13 s for an orbit whose k'^2 underflows to 1e-320).
      double largest_sample = 0;
      for (const double f : samples) largest_sample = std::max(largest_sample, std::abs(f));
      std::vector<double> period_samples(2 * static_cast<std::size_t>(M));
      for (int j = 0; j <= M; ++j) period_samples[j] = samples[j];
      for (int j = 1; j < M; ++j) period_samples[2 * M - j] = samples[j];
      Eigen::FFT<double>().fwd(spectrum, period_samples);
      coefficients.resize(static_cast<std::size_t>(M) + 1);
      for (int n = 0; n <= M; ++n) coefficients[n] = spectrum[n].real() / M;
      const double noise = kSeriesNoise * std::numeric_limits<double>::epsilon() * largest_sample;
      double tail = 0;
      for (int n = M / 2 + 1; n <= M; ++n) tail = std::max(tail, std::abs(coefficients[n]));
      if (tail > noise) continue;
      // The terms up to the last above the noise (each one costs every evaluation a step).
      int terms = M / 2;
      while (terms > 0 && std::abs(coefficients[terms]) <= noise) --terms;
      mean_psi_rate = 0.5 * coefficients[0];
      psi_sine.resize(static_cast<std::size_t>(terms));
      for (int n = 1; n <= terms; ++n) {
        psi_sine[n - 1] = coefficients[n] * K / (n * std::numbers::pi);
      }
      return;
    }
    throw std::logic_error("TorqueFreeMotion: psi's series did not converge in " +
                           std::to_string(kMostSamples) +
                           " samples (k'^2 = " + std::to_string(jacobi->kp2()) + ")");
  }

  void build_psi_table(double begin, double span) {
    const int panels = std::max(1, static_cast<int>(std::ceil(span / kPanelWidth)));
    table_begin = begin;
    panel_width = span / panels;
    G_table.assign(panels + 1, 0.0);
    const auto rate = [this](double s) { return calc_psi_rate(s); };
    CompensatedSum sum;
    for (int j = 0; j < panels; ++j) {
      const double a = begin + j * panel_width;
      // 31-point Kronrod on a panel is already at round-off (see kPanelWidth); Boost's error
      // estimate is floored at 2 eps |result|, so a relative tolerance of 1e-14 accepts it without
      // subdividing, while a rougher integrand would still be bisected (up to 4 levels).
      double error = 0;
      const double piece = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
          rate, a, a + panel_width, 4, 1e-14, &error);
      if (!(error <= 1e-13 * std::abs(piece) + 1e-300)) {
        throw std::logic_error("TorqueFreeMotion: psi quadrature did not converge (panel error " +
                               std::to_string(error) + ", integral " + std::to_string(piece) + ")");
      }
      sum.add(piece);
      G_table[j + 1] = sum.value();
    }
  }

  double calc_psi(double t) const { return (calc_G(tau0 + lambda * t) - G_tau0) / lambda; }
};

TorqueFreeMotion::TorqueFreeMotion(const Mat3& I_G_B, const Mat3& R_WB0, const Vec3& omega_W0) {
  if (!I_G_B.allFinite() || !R_WB0.allFinite() || !omega_W0.allFinite()) {
    throw std::invalid_argument(
        "TorqueFreeMotion: I_G_B, R_WB0 and omega_W0 must be finite; got I_G_B = " +
        format_matrix(I_G_B) + ", R_WB0 = " + format_matrix(R_WB0));
  }
  const double I_scale = I_G_B.cwiseAbs().maxCoeff();
  if ((I_G_B - I_G_B.transpose()).cwiseAbs().maxCoeff() > 1e-12 * I_scale) {
    throw std::invalid_argument("TorqueFreeMotion: I_G_B must be symmetric; got " +
                                format_matrix(I_G_B) + ". Symmetrise the inertia tensor.");
  }
  if (orthonormality_error(R_WB0) > 1e-9 || R_WB0.determinant() < 0.0) {
    throw std::invalid_argument(
        "TorqueFreeMotion: R_WB0 must be a rotation (orthonormal to 1e-9, "
        "det +1); got " +
        format_matrix(R_WB0) + ". Use nearest_rotation() on it.");
  }
  const Mat3 I_sym = 0.5 * (I_G_B + I_G_B.transpose());
  Eigen::SelfAdjointEigenSolver<Mat3> eigen(I_sym);
  if (eigen.info() != Eigen::Success || !(eigen.eigenvalues().x() > 0.0)) {
    throw std::invalid_argument("TorqueFreeMotion: I_G_B must be positive definite; got " +
                                format_matrix(I_G_B) + " with smallest principal moment " +
                                std::to_string(eigen.eigenvalues().x()) + " kg m^2.");
  }
  Vec3 I_principal = eigen.eigenvalues();  // ascending
  Mat3 Q = eigen.eigenvectors();           // columns: principal axes in body axes
  if (I_sym(0, 1) == 0.0 && I_sym(0, 2) == 0.0 && I_sym(1, 2) == 0.0) {
    // Already principal: take the moments and axes exactly (the iterative solver rescales and
    // would perturb them by round-off, hiding exact separatrices, symmetries and steady spins).
    std::array<int, 3> order = {0, 1, 2};
    std::sort(order.begin(), order.end(),
              [&I_sym](int a, int b) { return I_sym(a, a) < I_sym(b, b); });
    Q.setZero();
    for (int i = 0; i < 3; ++i) {
      I_principal(i) = I_sym(order[i], order[i]);
      Q(order[i], i) = 1.0;
    }
  }
  if (Q.determinant() < 0.0) Q.col(2) = -Q.col(2);

  auto impl = std::make_shared<Impl>();
  impl->R_WB0 = R_WB0;
  impl->omega_W0 = omega_W0;
  impl->omega_B0 = R_WB0.transpose() * omega_W0;
  impl->L_W = R_WB0 * (I_sym * impl->omega_B0);
  impl->energy = 0.5 * impl->omega_B0.dot(I_sym * impl->omega_B0);

  const Vec3 w_P = Q.transpose() * impl->omega_B0;
  // Steady motion: omega_B is an eigenvector of I_G_B (every pair of non-zero components has equal
  // moments); then omega is constant in both frames and R_WB(t) = exp(t [omega_W]x) R_WB0.
  bool steady = true;
  for (int i = 0; i < 3; ++i) {
    for (int j = i + 1; j < 3; ++j) {
      if (I_principal(i) != I_principal(j) && w_P(i) != 0.0 && w_P(j) != 0.0) steady = false;
    }
  }
  if (steady) {
    impl->kind = TorqueFreeMotionKind::kSteady;
    impl_ = std::move(impl);
    return;
  }

  // Side of the separatrix: D > 0 encircles the maximum axis (working = principal axes), D < 0
  // the minimum axis (working axes (e_3, e_2, -e_1): a proper rotation, so Euler's equations keep
  // their form), D = 0 is the separatrix.
  const double I1 = I_principal.x(), I2 = I_principal.y(), I3 = I_principal.z();
  const double D = I1 * (I1 - I2) * w_P.x() * w_P.x() + I3 * (I3 - I2) * w_P.z() * w_P.z();
  Mat3 S_KP = Mat3::Identity();
  Vec3 J = I_principal;
  if (D < 0.0) {
    S_KP << 0, 0, 1,  //
        0, 1, 0,      //
        -1, 0, 0;
    J = Vec3(I3, I2, I1);
  }
  Vec3 w = S_KP * w_P;  // exact: a signed permutation
  // A half turn about e_1 makes w_3 > 0 (w_3 != 0 on every non-steady orbit, see D).
  if (w.z() < 0.0) {
    S_KP.row(1) = -S_KP.row(1);
    S_KP.row(2) = -S_KP.row(2);
    w = Vec3(w.x(), -w.y(), -w.z());
  }
  impl->S_KB = S_KP * Q.transpose();
  impl->J = J;
  impl->L_norm = J.cwiseProduct(w).norm();
  impl->energy_K = 0.5 * w.dot(J.cwiseProduct(w));

  const double J1 = J.x(), J2 = J.y(), J3 = J.z();
  const double A1 = J1 * (J3 - J1) * w.x() * w.x() + J2 * (J3 - J2) * w.y() * w.y();
  const double A3 = J2 * (J2 - J1) * w.y() * w.y() + J3 * (J3 - J1) * w.z() * w.z();
  impl->lambda = std::sqrt((J3 - J2) * A3 / (J1 * J2 * J3));
  const double k2 = std::clamp((J2 - J1) * A1 / ((J3 - J2) * A3), 0.0, 1.0);
  const double kp2 = std::clamp((J3 - J1) * D / ((J3 - J2) * A3), 0.0, 1.0);
  // k'^2 can underflow for a D of a few denormals: that orbit is the separatrix to round-off.
  const bool on_separatrix = D == 0.0 || kp2 == 0.0;
  double a1 = std::sqrt(A1 / (J1 * (J3 - J1)));
  if (on_separatrix) a1 = std::copysign(a1, w.x());  // w_1 = a_1 sech keeps its sign
  const double a2 = std::copysign(std::sqrt(A1 / (J2 * (J3 - J2))), a1 * (J3 - J2));
  const double a3 = std::sqrt(A3 / (J3 * (J3 - J1)));
  impl->amplitude = Vec3(a1, a2, a3);

  if (on_separatrix) {
    impl->kind = TorqueFreeMotionKind::kSeparatrix;
    // sinh(tau_0) = sn / cn = (w_2 / a_2) / (w_1 / a_1).
    impl->tau0 = std::asinh((w.y() / a2) / (w.x() / a1));
    impl->build_psi_table(-kSeparatrixHalfRange, 2.0 * kSeparatrixHalfRange);
  } else {
    impl->kind = TorqueFreeMotionKind::kPeriodic;
    impl->jacobi.emplace(k2, kp2);
    impl->tau0 = impl->jacobi->calc_inverse_amplitude(std::atan2(w.y() / a2, w.x() / a1));
    const double K = impl->jacobi->quarter_period();
    impl->period = 4.0 * K / impl->lambda;
    impl->build_psi_series();
  }
  impl->G_tau0 = impl->calc_G(impl->tau0);

  // R_WK(0) = R_WB0 S_KB^T; P(l(0)) from the same evaluation as at later times, so that
  // R_WB(0) = R_WB0 up to the round-off of the products.
  const Vec3 L_K0 = J.cwiseProduct(impl->calc_omega_K(impl->tau0));
  impl->R_WL = R_WB0 * impl->S_KB.transpose() * rotation_to_e3(L_K0.normalized()).transpose();
  impl_ = std::move(impl);
}

Vec3 TorqueFreeMotion::omega_B(double t) const {
  const Impl& m = *impl_;
  if (m.kind == TorqueFreeMotionKind::kSteady) return m.omega_B0;
  return m.S_KB.transpose() * m.calc_omega_K(m.tau0 + m.lambda * t);
}

Mat3 TorqueFreeMotion::R_WB(double t) const {
  Mat3 R;
  Vec3 omega;
  calc_rotation(t, R, omega);
  return R;
}

Vec3 TorqueFreeMotion::omega_W(double t) const {
  Mat3 R;
  Vec3 omega;
  calc_rotation(t, R, omega);
  return omega;
}

void TorqueFreeMotion::calc_rotation(double t, Mat3& R_WB_out, Vec3& omega_W_out) const {
  const Impl& m = *impl_;
  if (m.kind == TorqueFreeMotionKind::kSteady) {
    R_WB_out = exp_so3(t * m.omega_W0) * m.R_WB0;
    omega_W_out = m.omega_W0;
    return;
  }
  const Vec3 omega_K = m.calc_omega_K(m.tau0 + m.lambda * t);
  const Vec3 L_K = m.J.cwiseProduct(omega_K);
  R_WB_out = m.R_WL * rotation_about_z(m.calc_psi(t)) * rotation_to_e3(L_K.normalized()) * m.S_KB;
  omega_W_out = R_WB_out * (m.S_KB.transpose() * omega_K);
}

Vec3 TorqueFreeMotion::angular_momentum_W() const {
  return impl_->L_W;
}

double TorqueFreeMotion::kinetic_energy() const {
  return impl_->energy;
}

double TorqueFreeMotion::period() const {
  return impl_->period;
}

}  // namespace tumble
