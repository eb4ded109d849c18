// Tests of the exact Euler-Poinsot solution (src/tumble/exact/torque_free.*):
//   - the AGM Jacobi functions against Boost.Math;
//   - the chapter's prism and its two stable variants against 40-digit reference states;
//   - the tumbling prism's first flip time (root of omega_B.z);
//   - properties for random bodies on every branch: Euler's equations and dR/dt = R [omega_B]x by
//     finite differences, orthonormality, conservation of E and L_W, the initial data;
//   - degenerate motions (rest, steady spin, spherical and axisymmetric bodies);
//   - a brute-force RK4 integration of Euler's equations and the quaternion kinematics;
//   - no heap allocation in the evaluation; input errors name the bad input.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <new>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "allocation_counter.hpp"
#include "test_constants.hpp"
#include "test_math.hpp"
#include "tumble/exact/jacobi_elliptic.hpp"
#include "tumble/exact/torque_free.hpp"
#include "tumble/math/rotation.hpp"

namespace tumble {
namespace {

using test::kEps;
constexpr double kInf = std::numeric_limits<double>::infinity();

using test::max_abs;

// ---------------------------------------------------------------------------------------------
// Jacobi elliptic functions

// The AGM evaluation against Boost.Math (an independent implementation) for moduli from 0 to
// 1 - 1e-12. Both are accurate to a few ulps of the argument u, so |difference| <= 64 eps (1 + |u|)
// allows for the phase round-off of both.
TEST(JacobiElliptic, AgreesWithBoost) {
  for (const double k : {0.0, 1e-8, 0.3, 0.7, 0.95, 0.999999}) {
    const double k2 = k * k;
    const JacobiElliptic jac(k2, (1.0 - k) * (1.0 + k));
    EXPECT_NEAR(jac.quarter_period(), boost::math::ellint_1(k), 8 * kEps * jac.quarter_period());
    for (const double u : {-37.5, -3.1, -0.2, 0.0, 0.4, 1.3, 2.9, 11.0, 123.4}) {
      double cn_boost, dn_boost;
      const double sn_boost = boost::math::jacobi_elliptic(k, u, &cn_boost, &dn_boost);
      const JacobiValues v = jac.calc(u);
      const double tol = 64 * kEps * (1.0 + std::abs(u));
      EXPECT_NEAR(v.sn, sn_boost, tol) << "k " << k << " u " << u;
      EXPECT_NEAR(v.cn, cn_boost, tol) << "k " << k << " u " << u;
      EXPECT_NEAR(v.dn, dn_boost, tol) << "k " << k << " u " << u;
      // Bulirsch's Gauss transformation, the other algorithm, to the same bound.
      const JacobiFunctions f = jac.calc_functions(u);
      EXPECT_NEAR(f.sn, sn_boost, tol) << "k " << k << " u " << u;
      EXPECT_NEAR(f.cn, cn_boost, tol) << "k " << k << " u " << u;
      EXPECT_NEAR(f.dn, dn_boost, tol) << "k " << k << " u " << u;
      // am is the inverse of F: a round trip returns u to the same phase round-off.
      EXPECT_NEAR(jac.calc_inverse_amplitude(v.am), u, tol) << "k " << k << " u " << u;
      if (std::abs(v.am) < 1.5) {
        EXPECT_NEAR(jac.calc_inverse_amplitude(v.am), boost::math::ellint_1(k, v.am), tol);
      }
    }
  }
}

// Near a zero of sn the Gauss transformation works with cot(a_N u), which squared would overflow
// for |u| below ~1e-154: there, and just above where it takes over, sn = u and cn = dn = 1 to
// round-off (sn(u) = u - (1 + k^2) u^3 / 6 + ...).
TEST(JacobiElliptic, TinyArgumentsGiveTheSeriesTerms) {
  for (const double kp2 : {1.0, 0.3, 1e-12}) {
    const JacobiElliptic jac(1.0 - kp2, kp2);
    for (const double u : {1e-300, -1e-200, 1e-120, 2e-100, -1e-60, 1e-20}) {
      const JacobiFunctions f = jac.calc_functions(u);
      EXPECT_NEAR(f.sn, u, kEps * std::abs(u)) << "u " << u;
      EXPECT_EQ(f.cn, 1.0) << "u " << u;
      EXPECT_EQ(f.dn, 1.0) << "u " << u;
    }
  }
}

// Close to k = 1 (k'^2 = 1e-18), where Boost's (k, u) interface cannot resolve k' and the plain
// descending AGM loses half the digits in asin near 1. Reference values from mpmath (40 digits,
// ellipfun with m = 1 - 1e-18). The phase u is good to eps u, and |d(sn, cn, dn)/du| <= 1, so
// the absolute error bound is 8 eps (1 + u); dn near K (~1e-9) is checked to the same absolute
// bound, a relative 1e-6 there (the plain algorithm errs by ~1e-8 absolute).
TEST(JacobiElliptic, AccurateNearModulusOne) {
  const double kp2 = 1e-18;
  const JacobiElliptic jac(1.0 - kp2, kp2);
  EXPECT_NEAR(jac.quarter_period(), 22.10956019806630178, 4 * kEps * 22.1);
  struct JacobiReference {
    double u, sn, cn, dn;
  };
  for (const JacobiReference& r :
       {JacobiReference{3.0, 0.99505475368673045157, 0.099327927419433205411,
                        0.099327927419433210395},
        JacobiReference{10.0, 0.99999999587769276387, 0.0000907998593350639361,
                        0.000090799859340570552514},
        JacobiReference{20.7, 0.99999999999999999815, 1.9249518547904673638e-9,
                        2.1692025362471943569e-9},
        JacobiReference{22.1, 1.0, 9.5603436964878066392e-12, 1.0000456990415962857e-9},
        JacobiReference{30.0, 0.99999999999910780698, -1.3358091355375024824e-6,
                        1.3358095098424212355e-6}}) {
    const JacobiValues v = jac.calc(r.u);
    const double tol = 8 * kEps * (1.0 + r.u);
    EXPECT_NEAR(v.sn, r.sn, tol) << "u " << r.u;
    EXPECT_NEAR(v.cn, r.cn, tol) << "u " << r.u;
    EXPECT_NEAR(v.dn, r.dn, tol) << "u " << r.u;
    const JacobiFunctions f = jac.calc_functions(r.u);
    EXPECT_NEAR(f.sn, r.sn, tol) << "u " << r.u;
    EXPECT_NEAR(f.cn, r.cn, tol) << "u " << r.u;
    EXPECT_NEAR(f.dn, r.dn, tol) << "u " << r.u;
    // The inverse is ill-conditioned here (du = d(am) / dn, dn ~ 1e-9), but it is backward
    // stable: the functions at the recovered argument reproduce the values to round-off.
    const JacobiValues back = jac.calc(jac.calc_inverse_amplitude(v.am));
    EXPECT_NEAR(back.sn, v.sn, tol) << "u " << r.u;
    EXPECT_NEAR(back.cn, v.cn, tol) << "u " << r.u;
    EXPECT_NEAR(back.dn, v.dn, tol) << "u " << r.u;
  }
}

// ---------------------------------------------------------------------------------------------
// The chapter's prism against the 40-digit reference

struct RefState {
  double t;
  Vec3 omega_W, omega_B;
  Mat3 R_WB;
};
struct RefCase {
  std::string id;
  Vec3 I0_diag, omega0;
  double energy, L_norm;
  std::vector<RefState> states;
  std::vector<double> flip_times;
};

std::vector<RefCase> load_reference() {
  const YAML::Node root = YAML::LoadFile(TUMBLE_TEST_DATA_DIR "/free-prism-40digit.json");
  std::vector<RefCase> cases;
  for (const YAML::Node& c : root["cases"]) {
    RefCase rc;
    rc.id = c["id"].as<std::string>();
    for (int i = 0; i < 3; ++i) {
      rc.I0_diag(i) = c["I0_diag"][i].as<double>();
      rc.omega0(i) = c["omega0"][i].as<double>();
    }
    // The *_str fields carry 35 digits; strtod rounds them to the nearest double.
    rc.energy = std::stod(c["energy_str"].as<std::string>());
    rc.L_norm = std::stod(c["L_norm_str"].as<std::string>());
    for (const YAML::Node& s : c["states"]) {
      RefState rs;
      rs.t = s["t"].as<double>();
      for (int i = 0; i < 3; ++i) {
        rs.omega_W(i) = std::stod(s["omega_spatial_str"][i].as<std::string>());
        rs.omega_B(i) = std::stod(s["omega_body_str"][i].as<std::string>());
      }
      for (int i = 0; i < 9; ++i)
        rs.R_WB(i / 3, i % 3) = std::stod(s["R_str"][i].as<std::string>());
      rc.states.push_back(rs);
    }
    if (c["k_axis_flip"]) {
      for (const YAML::Node& t : c["k_axis_flip"]["times"]) rc.flip_times.push_back(t.as<double>());
    }
    cases.push_back(rc);
  }
  return cases;
}

// Error budget: the state at time t depends on the phase lambda t + tau_0 and on the precession
// angle psi(t) ~ |omega| t; each is formed to a relative round-off of a few eps, i.e. an absolute
// phase error of about C eps |omega| t with |omega| ~ 1 rad/s here and C ~ 10 (the argument
// reduction, psi's series, the AGM). R and omega move at rates <= |omega| ~ 1 per unit phase, so
// |error| <~ 10 eps t = 2.2e-15 t, plus a floor of ~1e-15 from the evaluation itself. Asserted:
// 2e-15 * max(t, 50), i.e. 1e-13, 4e-13 and 4e-12 at t = 20, 200 and 2000 (measured: 2.3e-15,
// 2.8e-14 and 4.8e-13 at worst, the last two the tumbling case, whose saddle passages amplify
// phase errors; 1.2e-15, 2.6e-14 and 6.8e-13 when psi was a table and a quadrature).
TEST(TorqueFreeMotion, MatchesFortyDigitReference) {
  std::printf("case        t      |d omega_B|   |d omega_W|   |d R|\n");
  for (const RefCase& c : load_reference()) {
    const TorqueFreeMotion motion(c.I0_diag.asDiagonal().toDenseMatrix(), Mat3::Identity(),
                                  c.omega0);
    EXPECT_NEAR(motion.kinetic_energy(), c.energy, 4 * kEps * c.energy) << c.id;
    EXPECT_NEAR(motion.angular_momentum_W().norm(), c.L_norm, 4 * kEps * c.L_norm) << c.id;
    for (const RefState& s : c.states) {
      const double e_omega_B = max_abs(Vec3(motion.omega_B(s.t) - s.omega_B));
      const double e_omega_W = max_abs(Vec3(motion.omega_W(s.t) - s.omega_W));
      const double e_R = max_abs(Mat3(motion.R_WB(s.t) - s.R_WB));
      std::printf("%-10s %6.0f  %.3e     %.3e     %.3e\n", c.id.c_str(), s.t, e_omega_B, e_omega_W,
                  e_R);
      const double tol = 2e-15 * std::max(s.t, 50.0);
      EXPECT_LE(e_omega_B, tol) << c.id << " t " << s.t;
      EXPECT_LE(e_omega_W, tol) << c.id << " t " << s.t;
      EXPECT_LE(e_R, tol) << c.id << " t " << s.t;
    }
  }
}

// The tumbling prism (spin about the intermediate axis) reverses its body-frame spin omega_B.z
// first at t_flip = 9.6640948340752253 s by this solution (toms748 to 1 ulp); the 40-digit
// reference gives 9.664094834075236 (rounded to double), 1.1e-14 s away. Flips recur every half
// period 2K/lambda = 19.328189668150472 s.
double first_flip_time_of_unstable_prism() {
  const TorqueFreeMotion motion(Vec3(5.0, 20.0, 17.0).asDiagonal().toDenseMatrix(),
                                Mat3::Identity(), Vec3(0.0, 0.01, 1.0));
  const auto omega_z = [&motion](double t) { return motion.omega_B(t).z(); };
  std::uintmax_t iterations = 100;
  const auto bracket = boost::math::tools::toms748_solve(
      omega_z, 9.0, 10.5, boost::math::tools::eps_tolerance<double>(53), iterations);
  return 0.5 * (bracket.first + bracket.second);
}

TEST(TorqueFreeMotion, UnstablePrismFlipTime) {
  const double t_flip = first_flip_time_of_unstable_prism();
  std::printf("first flip of omega_B.z: t = %.17g s\n", t_flip);
  EXPECT_LT(std::abs(t_flip - 9.664), 5e-4);  // the chapter's 4 digits
  // The reference's root (40-digit solution, rounded to double). omega_B.z crosses zero with slope
  // ~ lambda a_3 ~ 0.2 rad/s^2 and is accurate to ~1e-15 rad/s, so the root is good to ~1e-14 s.
  const std::vector<RefCase> reference = load_reference();
  const RefCase& unstable = reference.at(0);
  ASSERT_EQ(unstable.id, "unstable");
  EXPECT_NEAR(t_flip, unstable.flip_times.at(0), 1e-13);
  EXPECT_NEAR(t_flip, 9.664094834075236, 1e-13);
  // omega_B is periodic with 4K/lambda, twice the spacing of the flips.
  const TorqueFreeMotion motion(Vec3(5.0, 20.0, 17.0).asDiagonal().toDenseMatrix(),
                                Mat3::Identity(), Vec3(0.0, 0.01, 1.0));
  EXPECT_NEAR(motion.period(), 2.0 * (unstable.flip_times.at(1) - unstable.flip_times.at(0)),
              1e-12);
}

// ---------------------------------------------------------------------------------------------
// Properties for random bodies

struct Draw {
  std::string label;
  Mat3 I_G_B;
  Mat3 R_WB0;
  Vec3 omega_W0;
};

Mat3 random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return exp_so3(Vec3(n(rng), n(rng), n(rng)) * 2.0);
}

// Fourth-order central difference of f at t (error h^4/30 |f^(5)| + 1.5 eps_f / h).
template <class F>
auto central_difference(const F& f, double t, double h) {
  using Value = decltype(f(t));  // evaluate into a plain object, not a dangling expression
  return Value(((f(t - 2 * h) - f(t + 2 * h)) + 8.0 * (f(t + h) - f(t - h))) / (12.0 * h));
}

// Checks every property at 40 sample times in [-20, 100] / |omega|. `rate` below bounds the
// frequencies of the motion (rad/s) and scales the finite-difference step and tolerances.
void check_properties(const Draw& d) {
  SCOPED_TRACE(d.label);
  const TorqueFreeMotion motion(d.I_G_B, d.R_WB0, d.omega_W0);
  const Mat3 I_inv = d.I_G_B.inverse();
  const Vec3 omega_B0 = d.R_WB0.transpose() * d.omega_W0;
  const double w = std::max(d.omega_W0.norm(), 1e-300);
  Eigen::SelfAdjointEigenSolver<Mat3> eig(d.I_G_B);
  const double ratio = eig.eigenvalues().maxCoeff() / eig.eigenvalues().minCoeff();
  // Frequencies of omega_B and R are at most (I_max / I_min) |omega|.
  const double rate = ratio * w;
  const double E0 = motion.kinetic_energy();
  const Vec3 L0 = motion.angular_momentum_W();

  // Initial data to round-off. For a diagonal I_G_B the principal axes are exact and omega_B(0)
  // is a_i times a Jacobi function at the fitted phase: a few eps |omega| (1e-15 ~ 4.5 eps).
  // Otherwise omega passes through the eigenvector matrix and back, two more 3-term products
  // of ~3 eps each: 2e-15 |omega|. On a periodic orbit the fitted phase tau_0 = F(phi | k) is
  // itself a number rounded to eps |tau_0|, with |tau_0| up to 2K = lambda T / 2: omega(0) moves
  // along the orbit by up to eps (T / 2) |omega_dot(0)| more (Euler's equations give omega_dot).
  // Near the separatrix K is ~20 and this term leads (about 7e-15 |omega| there).
  const bool diagonal = d.I_G_B.isDiagonal(0.0);
  const Vec3 omega_dot_B0 = I_inv * Vec3((d.I_G_B * omega_B0).cross(omega_B0));
  const double phase_rounding =
      std::isfinite(motion.period()) ? kEps * 0.5 * motion.period() * omega_dot_B0.norm() : 0.0;
  EXPECT_LE(max_abs(Vec3(motion.omega_B(0.0) - omega_B0)),
            (diagonal ? 1e-15 : 2e-15) * w + phase_rounding);
  EXPECT_LE(max_abs(Mat3(motion.R_WB(0.0) - d.R_WB0)), 1e-15);
  EXPECT_NEAR(E0, 0.5 * omega_B0.dot(d.I_G_B * omega_B0), 4 * kEps * E0);

  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> time(-20.0, 100.0);
  const double h = 2e-3 / rate;  // finite-difference step: 2e-3 rad of the fastest motion
  for (int i = 0; i < 40; ++i) {
    const double t = i == 0 ? 0.0 : time(rng) / std::max(w, 1e-3);
    const Vec3 om = motion.omega_B(t);
    const Mat3 R = motion.R_WB(t);
    // Orthonormal to round-off: R is a product of four rotations each orthonormal to ~2 eps.
    EXPECT_LE(orthonormality_error(R), 1e-14) << "t " << t;
    EXPECT_GT(R.determinant(), 0.0);
    // Conserved to round-off: E and L_W are sums of O(1) products of quantities each good to a few
    // eps relative (relative to |L| and E; 1e-14 ~ 45 eps).
    EXPECT_NEAR(0.5 * om.dot(d.I_G_B * om), E0, 1e-14 * E0) << "t " << t;
    EXPECT_LE((R * (d.I_G_B * om) - L0).norm(), 1e-14 * L0.norm()) << "t " << t;
    EXPECT_LE((motion.omega_W(t) - R * om).norm(), 4 * kEps * w);

    // Euler's equations: I omega' = -omega x I omega. The difference quotient errs by
    // h^4/30 |omega^(5)| <~ (2e-3)^4 / 30 |omega| rate = 5e-13 |omega| rate from truncation, and
    // by 1.5 e_f / h from the evaluation error e_f, which grows with the phase (e_f <~ 1e-14
    // |omega| at |t| <= 100 / |omega|): <~ 1e-11 |omega| rate. Bound: 1e-10 |omega| rate
    // (measured: 1.5e-11 at worst). |omega'| itself is up to |omega| rate, so a wrong solution
    // fails by O(1).
    const auto omega_of_t = [&motion](double s) { return Vec3(motion.omega_B(s)); };
    const Vec3 omega_dot_fd = central_difference(omega_of_t, t, h);
    const Vec3 omega_dot = I_inv * (-om.cross(d.I_G_B * om));
    EXPECT_LE((omega_dot_fd - omega_dot).norm(), 1e-10 * w * rate) << "t " << t;

    // Kinematics dR/dt = R [omega_B]x, the same error budget with |R| = 1 (and R's own rate).
    const auto R_of_t = [&motion](double s) { return Mat3(motion.R_WB(s)); };
    const Mat3 R_dot_fd = central_difference(R_of_t, t, h);
    EXPECT_LE(max_abs(Mat3(R_dot_fd - R * hat(om))), 1e-10 * rate) << "t " << t;
  }
}

// Random principal moments in every order on the diagonal, or rotated to a full tensor.
Mat3 inertia_from(const Vec3& moments, const Mat3& Q) {
  return Q * moments.asDiagonal() * Q.transpose();
}

TEST(TorqueFreeMotion, RandomBodiesSatisfyEulerAndKinematics) {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> moment(1.0, 10.0);
  std::normal_distribution<double> n(0.0, 1.0);
  const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  int on_each_side[2] = {0, 0};
  for (int draw = 0; draw < 24; ++draw) {
    Vec3 sorted(moment(rng), moment(rng), moment(rng));
    std::sort(sorted.data(), sorted.data() + 3);
    const int* order = orders[draw % 6];
    const Vec3 moments(sorted(order[0]), sorted(order[1]), sorted(order[2]));
    const Mat3 Q = draw % 2 == 0 ? Mat3::Identity() : random_rotation(rng);
    const Mat3 I = inertia_from(moments, Q);
    const Vec3 omega_B(n(rng), n(rng), n(rng));
    const Mat3 R0 = random_rotation(rng);
    // Which side of the separatrix: 2 E I_mid vs |L|^2.
    const double two_E = omega_B.dot(I * omega_B);
    const double side = two_E * sorted(1) - (I * omega_B).squaredNorm();
    ++on_each_side[side > 0 ? 1 : 0];
    check_properties({"random draw " + std::to_string(draw), I, R0, R0 * omega_B});
  }
  // Both sides of the separatrix were visited.
  EXPECT_GT(on_each_side[0], 3);
  EXPECT_GT(on_each_side[1], 3);
}

// The chapter's prism spun about its intermediate axis with a tilt of 1e-160 rad/s about its
// largest: k'^2 ~ 1e-320, a subnormal number, yet not zero, so the orbit is a periodic one with
// K ~ 370 (a period of 2,460 s). Its precession's series then takes 4,097 samples and 1,192
// terms: the extreme the transform must carry, exactly (Euler's equations, the kinematics and the
// invariants, as for any body).
TEST(TorqueFreeMotion, AnOrbitWhoseModulusUnderflowsIsStillExact) {
  const Mat3 I = Vec3(5.0, 20.0, 17.0).asDiagonal();
  const TorqueFreeMotion motion(I, Mat3::Identity(), Vec3(0.0, 1e-160, 1.0));
  EXPECT_TRUE(std::isfinite(motion.period()));
  EXPECT_GT(motion.period(), 2000.0);
  check_properties({"k'^2 underflowing", I, Mat3::Identity(), Vec3(0.0, 1e-160, 1.0)});
}

// 2 E I_mid / |L|^2 = 1 +- 1e-6 (k'^2 ~ 1e-6, K ~ 8): the orbit lingers near the saddle.
TEST(TorqueFreeMotion, NearSeparatrix) {
  std::mt19937_64 rng(99);
  for (const double offset : {1e-6, -1e-6}) {
    for (int order = 0; order < 2; ++order) {
      const Vec3 I_P(2.0, 3.5, 6.0);
      // Choose w_3 so that D = L^2 - 2 E I_2 = I1 (I1 - I2) w1^2 + I3 (I3 - I2) w3^2 hits
      // offset * |L|^2 (approximately: |L|^2 from the unperturbed w3).
      const double w1 = 0.8, w2 = -0.6;
      const double w3_sep =
          std::sqrt(I_P(0) * (I_P(1) - I_P(0)) * w1 * w1 / (I_P(2) * (I_P(2) - I_P(1))));
      const Vec3 L_sep = I_P.cwiseProduct(Vec3(w1, w2, w3_sep));
      const double w3 =
          std::sqrt((offset * L_sep.squaredNorm() + I_P(0) * (I_P(1) - I_P(0)) * w1 * w1) /
                    (I_P(2) * (I_P(2) - I_P(1))));
      const Mat3 Q = order == 0 ? Mat3::Identity() : random_rotation(rng);
      const Mat3 I = inertia_from(I_P, Q);
      const Vec3 omega_B = Q * Vec3(w1, w2, w3);
      const double E = 0.5 * omega_B.dot(I * omega_B);
      const double r = 2.0 * E * I_P(1) / (I * omega_B).squaredNorm();
      EXPECT_NEAR(r, 1.0 - offset, 1e-7);  // the draw is where it was meant to be
      const Mat3 R0 = random_rotation(rng);
      check_properties({"near separatrix " + std::to_string(offset), I, R0, R0 * omega_B});
      const TorqueFreeMotion motion(I, R0, R0 * omega_B);
      EXPECT_TRUE(std::isfinite(motion.period()));
      EXPECT_GT(motion.period(), 10.0);  // K ~ ln(4/k') ~ 9: long period
    }
  }
}

// Exactly on the separatrix: I = diag(2, 5, 6) gives D = 6 (w3^2 - w1^2), zero for w1 = +-w3.
TEST(TorqueFreeMotion, OnSeparatrix) {
  std::mt19937_64 rng(5);
  // R0 a signed permutation, so that omega_B0 = R0^T (R0 omega) is exact and D stays 0.
  Mat3 R0;
  R0 << 0, 0, 1,  //
      -1, 0, 0,   //
      0, -1, 0;
  for (const Vec3& omega_B : {Vec3(0.5, 0.3, 0.5), Vec3(-0.5, 0.3, 0.5), Vec3(0.5, -0.9, -0.5)}) {
    for (const Vec3& moments : {Vec3(2, 5, 6), Vec3(6, 5, 2)}) {
      // Permute omega with the moments so D stays zero.
      const Vec3 om = moments.x() == 2 ? omega_B : Vec3(omega_B.z(), omega_B.y(), omega_B.x());
      const Mat3 I = moments.asDiagonal();
      const TorqueFreeMotion motion(I, R0, R0 * om);
      EXPECT_EQ(motion.period(), kInf);
      check_properties({"on separatrix", I, R0, R0 * om});
      // A random R0 rounds omega_B0 off the separatrix by ~eps: a periodic orbit with k'^2 ~
      // 1e-16 and a period of a few hundred seconds, the hardest case for the elliptic functions.
      const Mat3 R_random = random_rotation(rng);
      check_properties({"within round-off of the separatrix", I, R_random, R_random * om});
      // The motion is asymptotic to a steady spin about the intermediate axis, where omega_B
      // points along +-e_2 with |omega_B| = |L| / I_2.
      const Vec3 late = motion.omega_B(200.0);
      EXPECT_NEAR(std::abs(late.y()), motion.angular_momentum_W().norm() / 5.0, 1e-12);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Degenerate motions

// Steady spin R(t) = exp(t [omega_W]x) R0. The exponential of a large angle is good to
// eps * |omega| t, so 1e-13 over |omega| t <= 60 rad.
void expect_steady(const TorqueFreeMotion& motion, const Mat3& R0, const Vec3& omega_W0,
                   double tol) {
  const Vec3 omega_B0 = R0.transpose() * omega_W0;
  for (const double t : {0.0, 0.3, 7.0, 30.0, -12.0}) {
    EXPECT_LE(max_abs(Vec3(motion.omega_B(t) - omega_B0)), tol) << "t " << t;
    EXPECT_LE(max_abs(Mat3(motion.R_WB(t) - exp_so3(t * omega_W0) * R0)), tol) << "t " << t;
    EXPECT_LE(max_abs(Vec3(motion.omega_W(t) - omega_W0)), tol) << "t " << t;
  }
}

TEST(TorqueFreeMotion, AtRestStaysPut) {
  const Mat3 R0 = rotation_from_axis_angle(Vec3(1, 2, 3), 0.7);
  const TorqueFreeMotion motion(Vec3(1, 2, 3).asDiagonal().toDenseMatrix(), R0, Vec3::Zero());
  EXPECT_EQ(motion.period(), kInf);
  EXPECT_EQ(motion.kinetic_energy(), 0.0);
  for (const double t : {0.0, 1.0, 1e6}) {
    EXPECT_EQ(motion.omega_B(t), Vec3::Zero());
    EXPECT_EQ(motion.R_WB(t), R0);  // exp(0) = I exactly
  }
}

TEST(TorqueFreeMotion, SteadySpinAboutEachPrincipalAxis) {
  std::mt19937_64 rng(11);
  const Vec3 moments(3.0, 7.0, 4.0);  // axis 1 is the intermediate one
  // R0 a signed permutation, so that omega_B0 = R0^T omega_W0 lies exactly on the axis.
  Mat3 R0_exact;
  R0_exact << 0, 1, 0,  //
      0, 0, -1,         //
      -1, 0, 0;
  for (int axis = 0; axis < 3; ++axis) {
    const Mat3 R0 = R0_exact;
    const Vec3 omega_W0 = R0 * (1.3 * Vec3::Unit(axis));
    const TorqueFreeMotion motion(moments.asDiagonal().toDenseMatrix(), R0, omega_W0);
    EXPECT_EQ(motion.period(), kInf);  // exact steady spin, even about the unstable axis
    expect_steady(motion, R0, omega_W0, 1e-13);
  }
  // Rotated inertia tensor: the principal axes are only known to round-off, so the spin about
  // the maximum and minimum axes is a tiny stable wobble (amplitude ~ eps) about the steady
  // motion; the bound grows with the 60 rad of phase.
  for (const int column : {0, 2}) {  // eigenvalues ascend: column 0 = minimum, 2 = maximum axis
    const Mat3 Q = random_rotation(rng);
    const Mat3 I = inertia_from(Vec3(3.0, 7.0, 4.0), Q);
    Eigen::SelfAdjointEigenSolver<Mat3> eig(I);
    const Mat3 R0 = random_rotation(rng);
    const Vec3 omega_W0 = R0 * (1.3 * eig.eigenvectors().col(column));
    const TorqueFreeMotion motion(I, R0, omega_W0);
    expect_steady(motion, R0, omega_W0, 1e-12);
  }
}

TEST(TorqueFreeMotion, SphericalBody) {
  std::mt19937_64 rng(3);
  const Mat3 R0 = random_rotation(rng);
  const Vec3 omega_W0(0.4, -1.1, 0.25);
  const TorqueFreeMotion motion(2.5 * Mat3::Identity(), R0, omega_W0);
  EXPECT_EQ(motion.period(), kInf);
  expect_steady(motion, R0, omega_W0, 1e-13);
}

// Two equal moments (symmetry axis e_s, I_s; transverse I_t): omega_B precesses uniformly about
// e_s at Omega = (I_s - I_t) / I_t * omega_s (Landau & Lifshitz §33):
// omega_B(t) = Rot(e_s, Omega t) omega_B0. Both oblate (I_s largest) and prolate.
TEST(TorqueFreeMotion, AxisymmetricBodyPrecessesUniformly) {
  std::mt19937_64 rng(17);
  struct Body {
    Vec3 moments;
    int symmetry_axis;
  };
  for (const Body& b : {Body{Vec3(2, 2, 5), 2}, Body{Vec3(5, 2, 5), 1}, Body{Vec3(3, 1, 1), 0}}) {
    const Mat3 I = b.moments.asDiagonal();
    const Vec3 omega_B0(0.7, -0.4, 0.9);
    const Mat3 R0 = random_rotation(rng);
    const TorqueFreeMotion motion(I, R0, R0 * omega_B0);
    const Vec3 e_s = Vec3::Unit(b.symmetry_axis);
    const double I_s = b.moments(b.symmetry_axis);
    const double I_t = b.moments((b.symmetry_axis + 1) % 3);
    const double Omega = (I_s - I_t) / I_t * omega_B0.dot(e_s);
    EXPECT_NEAR(motion.period(), 2.0 * std::numbers::pi / std::abs(Omega), 1e-13 * motion.period());
    for (const double t : {0.5, 3.0, 40.0}) {
      const Vec3 expected = rotation_from_axis_angle(e_s, Omega * t) * omega_B0;
      // Phase Omega t good to a few eps * Omega t (< 60 rad).
      EXPECT_LE(max_abs(Vec3(motion.omega_B(t) - expected)), 1e-13) << "t " << t;
    }
    check_properties({"axisymmetric", I, R0, R0 * omega_B0});
  }
}

// ---------------------------------------------------------------------------------------------
// Brute force: classical RK4 on (q, omega_B) with
//   omega_B' = I^-1 (-omega_B x I omega_B),  q' = q (0, omega_B) / 2,
// h = 1e-4 s to t = 10 s. RK4's global error is ~ T h^4 |f^(5)| ~ 10 * 1e-16 * rate^5: below
// 1e-14 for rates ~ 1. The 1e5 steps add round-off between sqrt(1e5) eps (random walk, 7e-15)
// and 1e5 eps (systematic, 2e-11); the tumbling prism's saddle amplifies either by ~10.
// Bound: 1e-11 (measured: 7.5e-14 at worst), so the test tells a correct solution from a wrong
// one (whose errors are O(1)) with room for round-off growth.
TEST(TorqueFreeMotion, AgreesWithBruteForceRK4) {
  std::mt19937_64 rng(23);
  const Mat3 Q = random_rotation(rng);
  const std::vector<Draw> draws = {
      {"unstable prism", Vec3(5, 20, 17).asDiagonal().toDenseMatrix(), Mat3::Identity(),
       Vec3(0.0, 0.01, 1.0)},
      {"general body", inertia_from(Vec3(1.5, 2.5, 4.0), Q), random_rotation(rng),
       Vec3(0.6, -0.8, 0.5)},
  };
  for (const Draw& d : draws) {
    SCOPED_TRACE(d.label);
    const Mat3 I_inv = d.I_G_B.inverse();
    const auto omega_dot = [&](const Vec3& om) { return Vec3(I_inv * (-om.cross(d.I_G_B * om))); };
    const auto q_dot = [](const Eigen::Vector4d& q, const Vec3& om) {
      // (w, x, y, z) times the pure quaternion (0, om), halved.
      Eigen::Vector4d r;
      r << -q(1) * om.x() - q(2) * om.y() - q(3) * om.z(),
          q(0) * om.x() + q(2) * om.z() - q(3) * om.y(),
          q(0) * om.y() + q(3) * om.x() - q(1) * om.z(),
          q(0) * om.z() + q(1) * om.y() - q(2) * om.x();
      return Eigen::Vector4d(0.5 * r);
    };
    const Quat q0 = quaternion_from_rotation(d.R_WB0);
    Eigen::Vector4d q(q0.w(), q0.x(), q0.y(), q0.z());
    Vec3 om = d.R_WB0.transpose() * d.omega_W0;
    const double h = 1e-4;
    const int steps = 100000;
    for (int i = 0; i < steps; ++i) {
      const Vec3 k1w = omega_dot(om);
      const Eigen::Vector4d k1q = q_dot(q, om);
      const Vec3 om2 = om + 0.5 * h * k1w;
      const Eigen::Vector4d q2 = q + 0.5 * h * k1q;
      const Vec3 k2w = omega_dot(om2);
      const Eigen::Vector4d k2q = q_dot(q2, om2);
      const Vec3 om3 = om + 0.5 * h * k2w;
      const Eigen::Vector4d q3 = q + 0.5 * h * k2q;
      const Vec3 k3w = omega_dot(om3);
      const Eigen::Vector4d k3q = q_dot(q3, om3);
      const Vec3 om4 = om + h * k3w;
      const Eigen::Vector4d q4 = q + h * k3q;
      const Vec3 k4w = omega_dot(om4);
      const Eigen::Vector4d k4q = q_dot(q4, om4);
      om += h / 6.0 * (k1w + 2.0 * k2w + 2.0 * k3w + k4w);
      q += h / 6.0 * (k1q + 2.0 * k2q + 2.0 * k3q + k4q);
    }
    const Mat3 R_rk4 = rotation_from_quaternion(Quat(q(0), q(1), q(2), q(3)));
    const TorqueFreeMotion motion(d.I_G_B, d.R_WB0, d.omega_W0);
    const double t = h * steps;
    const double e_omega = max_abs(Vec3(motion.omega_B(t) - om));
    const double e_R = max_abs(Mat3(motion.R_WB(t) - R_rk4));
    std::printf("RK4 h = 1e-4 vs exact at t = 10 (%s): |d omega_B| %.2e, |d R| %.2e\n",
                d.label.c_str(), e_omega, e_R);
    EXPECT_LE(e_omega, 1e-11);
    EXPECT_LE(e_R, 1e-11);
  }
}

// ---------------------------------------------------------------------------------------------
// Evaluation does not allocate (it runs at every output row); construction may.
TEST(TorqueFreeMotion, EvaluationDoesNotAllocate) {
  const std::vector<TorqueFreeMotion> motions = {
      TorqueFreeMotion(Vec3(5, 20, 17).asDiagonal().toDenseMatrix(), Mat3::Identity(),
                       Vec3(0.0, 0.01, 1.0)),
      TorqueFreeMotion(Vec3(2, 5, 6).asDiagonal().toDenseMatrix(), Mat3::Identity(),
                       Vec3(0.5, 0.3, 0.5)),                                // separatrix
      TorqueFreeMotion(Mat3::Identity(), Mat3::Identity(), Vec3(1, 2, 3)),  // steady
  };
  double sink = 0;
  test::AllocationCounter allocations;
  for (const TorqueFreeMotion& m : motions) {
    for (int i = 0; i < 200; ++i) {
      const double t = 0.37 * i;
      sink += m.omega_B(t).sum() + m.R_WB(t).sum() + m.omega_W(t).sum();
    }
  }
  EXPECT_EQ(allocations.count(), 0);
  EXPECT_TRUE(std::isfinite(sink));
}

// ---------------------------------------------------------------------------------------------
// Input errors name the input and the fix.
TEST(TorqueFreeMotion, RejectsBadInput) {
  const auto message_of = [](const Mat3& I, const Mat3& R, const Vec3& w) -> std::string {
    try {
      TorqueFreeMotion motion(I, R, w);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no exception";
  };
  Mat3 asymmetric = Mat3::Identity();
  asymmetric(0, 1) = 0.5;
  EXPECT_NE(message_of(asymmetric, Mat3::Identity(), Vec3::Ones()).find("I_G_B must be symmetric"),
            std::string::npos);
  EXPECT_NE(message_of(Vec3(1, -1, 2).asDiagonal().toDenseMatrix(), Mat3::Identity(), Vec3::Ones())
                .find("positive definite"),
            std::string::npos);
  EXPECT_NE(message_of(Mat3::Identity(), 2.0 * Mat3::Identity(), Vec3::Ones())
                .find("R_WB0 must be a rotation"),
            std::string::npos);
  EXPECT_NE(message_of(Mat3::Identity(), Mat3::Identity(), Vec3(0, kInf, 0)).find("finite"),
            std::string::npos);
}

}  // namespace
}  // namespace tumble
