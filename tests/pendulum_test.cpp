// Bodies held by a hinge, against the chapter's worked examples 3 and 5 (equations.md): the
// compound pendulum's period (the bat in the ASTM test), the reaction at its pivot, the centre of
// percussion, and the inverted mast on a torsional spring. Each at several parameter values,
// integrated at rtol 1e-10, atol 1e-12: the tolerances below are a few hundred times that, the
// global error of a few periods of an adaptive method run at that accuracy.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <boost/math/special_functions/ellint_1.hpp>
#include <cmath>

#include "scenario_run.hpp"
#include "test_constants.hpp"

namespace tumble {
namespace {

using test::kG;
using test::kPi;
using test::Row;
using test::run_inline_scenario;
using test::upward_zero_crossings;

// The upward zero crossings of a swing angle about y, read from each row's COM by angle_of (its
// rate is omega_W.y, with the sign convention of the scenarios below).
template <typename AngleOf>
std::vector<double> upward_crossings_of(const std::vector<Row>& rows, AngleOf angle_of) {
  std::vector<double> t, theta, rate;
  for (const Row& row : rows) {
    t.push_back(row.t);
    theta.push_back(angle_of(row.states[0].r_G));
    rate.push_back(row.states[0].omega_W.y());
  }
  return upward_zero_crossings(t, theta, rate);
}

struct Cylinder {
  double mass, radius, length;
  double transverse_inertia() const { return mass * (3 * radius * radius + length * length) / 12; }
};

// A cylinder hanging from a hinge about y at the origin, its COM at distance L, started at angle
// theta0 from the vertical. theta = atan2(-x_G, -z_G) grows with a turn about +y.
std::string bat_scenario(const Cylinder& c, double L, double theta0, double duration,
                         double output_every, const std::string& extra = "") {
  return fmt::format(
      "tumble: 1\n"
      "bodies:\n"
      "  bat: {{shape: cylinder, radius: {}, length: {}, mass: {}, position: [{}, 0, {}],\n"
      "        orientation: {{axis: [0, 1, 0], angle: {}}}}}\n"
      "joints:\n"
      "  knob: {{type: hinge, bodies: [ground, bat], at: [0, 0, 0], axis: [0, 1, 0]}}\n"
      "{}"
      "simulate: {{duration: {}, rtol: 1e-10, atol: 1e-12, output_every: {}}}\n",
      c.radius, c.length, c.mass, -L * std::sin(theta0), -L * std::cos(theta0), theta0, extra,
      duration, output_every);
}

struct PendulumCase {
  Cylinder body;
  double L, theta0;
};

TEST(CompoundPendulum, PeriodIsTheExactEllipticPeriod) {
  // Small swings: T = 2 pi sqrt(I_O / (M g L)) (equations.md, 5); any amplitude:
  // T = 4 sqrt(I_O / (M g L)) K(sin(theta0 / 2)).
  for (const PendulumCase& c :
       {PendulumCase{{0.9, 0.03, 0.84}, 0.6, 0.05}, PendulumCase{{2.0, 0.05, 1.0}, 0.3, 1.0},
        PendulumCase{{0.5, 0.02, 0.5}, 0.25, 2.5}}) {
    const double I_O = c.body.transverse_inertia() + c.body.mass * c.L * c.L;
    const double T_small = 2 * kPi * std::sqrt(I_O / (c.body.mass * kG * c.L));
    const double T_exact = 2 / kPi * T_small * boost::math::ellint_1(std::sin(c.theta0 / 2));
    const auto run = run_inline_scenario(
        bat_scenario(c.body, c.L, c.theta0, 2.6 * T_exact, T_exact / 2000), "pendulum");
    const std::vector<double> up = upward_crossings_of(
        run.rows, [](const Vec3& r_G) { return std::atan2(-r_G.x(), -r_G.z()); });
    ASSERT_GE(up.size(), 2u);
    EXPECT_NEAR(up[1] - up[0], T_exact, 1e-8 * T_exact) << "theta0 " << c.theta0;
    if (c.theta0 < 0.1) {
      EXPECT_NEAR(T_exact, T_small, 2e-4 * T_small);  // theta0^2 / 16
    }
    EXPECT_LT(run.result.conservation.max_relative_energy_drift, 1e-8);
  }
}

TEST(CompoundPendulum, PivotReactionIsMassTimesCOMAccelerationMinusWeight) {
  // About the fixed pivot O (6.7.7): I_O alpha = M_O = r_G x M g, so in the plane
  // alpha = -M g L sin(theta) / I_O; a_G = alpha x r_G + omega x (omega x r_G); and the pivot
  // carries the rest of M a_G: R = M a_G - M g, with no moment about the hinge axis.
  const Cylinder c{1.3, 0.04, 0.9};
  for (const double theta0 : {0.3, 2.0}) {
    const double L = 0.45;
    const double I_O = c.transverse_inertia() + c.mass * L * L;
    const auto run = run_inline_scenario(bat_scenario(c, L, theta0, 3.0, 0.01), "pivot_reaction");
    const Vec3 g_W(0, 0, -kG);
    double worst = 0.0, worst_moment = 0.0;
    for (const Row& row : run.rows) {
      const BodyState& s = row.states[0];
      const Vec3 r = s.r_G;
      const double theta = std::atan2(-r.x(), -r.z());
      const Vec3 alpha(0, -c.mass * kG * L * std::sin(theta) / I_O, 0);
      const Vec3 a_G = alpha.cross(r) + s.omega_W.cross(s.omega_W.cross(r));
      const Vec3 expected = c.mass * a_G - c.mass * g_W;
      ASSERT_EQ(row.extras.joints.size(), 1u);
      worst = std::max(worst, (row.extras.joints[0].F_W - expected).norm());
      worst_moment = std::max(worst_moment, std::abs(row.extras.joints[0].M_J_W.y()));
    }
    EXPECT_LT(worst, 1e-8 * c.mass * kG) << theta0;
    EXPECT_LT(worst_moment, 1e-10 * c.mass * kG * L) << theta0;
  }
}

TEST(CompoundPendulum, ABlowAtTheCentreOfPercussionLeavesNoReactionAtTheKnob) {
  // Impulse P (along x) at distance d below the pivot of the bat at rest: I_O omega = P d, the
  // COM moves off at v = omega L, and the knob supplies R = M v - P = P (M L d / I_O - 1): zero at
  // d = I_O / (M L) (equations.md, 5).
  const Cylinder c{0.9, 0.03, 0.84};
  const double L = 0.55, P = 1.7;
  const double I_O = c.transverse_inertia() + c.mass * L * L;
  const double d_cop = I_O / (c.mass * L);
  for (const double d : {d_cop, 0.5 * d_cop, 0.9, 1.4 * d_cop}) {
    const auto run = run_inline_scenario(
        bat_scenario(c, L, 0.0, 0.05, 0.01,
                     fmt::format("forces:\n  - {{type: impulse, name: hit, body: bat, at: [0, 0, "
                                 "{}], value: [{}, 0, 0], time: 0.02}}\n",
                                 -d, P)),
        "percussion");
    ASSERT_EQ(run.jumps.size(), 1u);
    const JointReaction& R = run.jumps[0].reaction_impulses[0];
    const double expected = P * (c.mass * L * d / I_O - 1);
    EXPECT_NEAR(R.F_W.x(), expected, 1e-12 * P) << d;
    EXPECT_NEAR(R.F_W.z(), 0.0, 1e-12 * P) << d;
    // It leaves the bat turning at omega = P d / I_O: KE = (P d)^2 / (2 I_O), all of it the
    // impulse's work.
    const double KE = P * P * d * d / (2 * I_O);
    EXPECT_EQ(run.jumps[0].kinetic_energy_before, 0.0);
    EXPECT_NEAR(run.jumps[0].kinetic_energy_after, KE, 1e-12 * KE);
    EXPECT_NEAR(run.rows.back().extras.elements[0].work, KE, 1e-12 * KE);
  }
  EXPECT_NEAR(d_cop,
              kG * std::pow(2 * kPi * std::sqrt(I_O / (c.mass * kG * L)), 2) / (4 * kPi * kPi),
              1e-12 * d_cop);  // the ASTM test's d = g T^2 / (4 pi^2) is the same number
}

TEST(CompoundPendulum, AShortBlowAtTheCentreOfPercussionLoadsTheKnobOnlyCentripetally) {
  // A force F for tau seconds at d = I_O / (M L), no gravity: the tangential reaction
  // M L alpha - F vanishes, leaving the centripetal M omega^2 L <= M L (F d tau / I_O)^2 and the
  // part of F along the bat once it has turned phi <= F d tau^2 / (2 I_O): F phi, half as much
  // again at the centre of percussion (M L d = I_O).
  const Cylinder c{0.9, 0.03, 0.84};
  const double L = 0.55, F = 800.0, tau = 1e-4;
  const double I_O = c.transverse_inertia() + c.mass * L * L;
  const double d = I_O / (c.mass * L);
  const auto run = run_inline_scenario(
      "gravity: [0, 0, 0]\n" +
          bat_scenario(c, L, 0.0, 0.0104, 1e-5,
                       fmt::format("forces:\n  - {{type: force, body: bat, at: [0, 0, {}], "
                                   "value: [{}, 0, 0], from: 0.01, to: {}}}\n",
                                   -d, F, 0.01 + tau)),
      "short_blow");
  const double bound = 1.5 * c.mass * L * std::pow(F * d * tau / I_O, 2);
  double largest = 0.0;
  for (const Row& row : run.rows) {
    if (row.t > 0.01 && row.t < 0.01 + tau) {
      largest = std::max(largest, row.extras.joints[0].F_W.norm());
    }
  }
  EXPECT_LE(largest, bound * (1 + 1e-6));
  EXPECT_GT(largest, 0.0);
  EXPECT_LT(bound, 1e-3 * F);  // so the check above says the knob feels next to nothing
}

// ---- The inverted mast (equations.md, 3) ----------------------------------------------------

// The mast upright at t = 0 (where its spring is unstretched), turning at omega0 about y.
std::string mast_scenario(double M, double length, double radius, double k, double omega0,
                          double duration, double output_every) {
  return fmt::format(
      "tumble: 1\n"
      "bodies:\n"
      "  mast: {{shape: cylinder, radius: {}, length: {}, mass: {}, position: [0, 0, {}],\n"
      "         angular_velocity: [0, {}, 0]}}\n"
      "joints:\n"
      "  base: {{type: hinge, body: mast, at: [0, 0, 0], axis: [0, 1, 0]}}\n"
      "forces:\n"
      "  - {{type: torsional_spring, name: spring, bodies: [ground, mast], stiffness: {}}}\n"
      "simulate: {{duration: {}, rtol: 1e-10, atol: 1e-14, output_every: {}}}\n",
      radius, length, M, 0.5 * length, omega0, k, duration, output_every);
}

TEST(InvertedMast, SmallOscillationFrequency) {
  // I_O theta'' + k theta - M g (L/2) sin(theta) = 0: omega_n = sqrt((k - M g L / 2) / I_O), with
  // I_O = M L^2 / 3 for a slender mast (here the cylinder's own I_O, radius included). At an
  // amplitude of 1e-4 rad the frequency shifts by ~1e-8.
  const double M = 3.0, length = 2.0, radius = 0.01;
  const double I_O = M * (3 * radius * radius + length * length) / 12 + M * length * length / 4;
  const double k_tip = M * kG * length / 2;
  for (const double ratio : {1.5, 3.0, 10.0}) {
    const double k = ratio * k_tip;
    const double omega_n = std::sqrt((k - k_tip) / I_O);
    const double T = 2 * kPi / omega_n;
    const auto run = run_inline_scenario(
        mast_scenario(M, length, radius, k, 1e-4 * omega_n, 2.6 * T, T / 2000), "mast");
    const std::vector<double> up =
        upward_crossings_of(run.rows, [](const Vec3& r_G) { return std::atan2(r_G.x(), r_G.z()); });
    ASSERT_GE(up.size(), 2u);
    EXPECT_NEAR(up[1] - up[0], T, 1e-7 * T) << "k / (M g L / 2) = " << ratio;
    // Elastic energy is part of E: with it E holds.
    EXPECT_LT(run.result.conservation.max_relative_energy_drift, 1e-8);
  }
}

TEST(InvertedMast, FallsWhenTheSpringIsTooWeak) {
  // k < M g L / 2: theta grows as (omega0 / lambda) sinh(lambda t), lambda =
  // sqrt((M g L / 2 - k) / I_O),
  // while small (checked where theta ~ 1e-3: the nonlinear part is ~theta^2 / 6 of it), and the
  // mast falls past horizontal.
  const double M = 3.0, length = 2.0, radius = 0.01;
  const double I_O = M * (3 * radius * radius + length * length) / 12 + M * length * length / 4;
  const double k_tip = M * kG * length / 2;
  for (const double ratio : {0.0, 0.5, 0.9}) {
    const double lambda = std::sqrt((1 - ratio) * k_tip / I_O);
    const double omega0 = 1e-6 * lambda;
    const double t1 = std::asinh(1e3) / lambda;
    const auto run = run_inline_scenario(
        mast_scenario(M, length, radius, ratio * k_tip, omega0, t1 + 12 / lambda, t1 / 100),
        "fall");
    const Row& at_t1 = run.rows[100];
    ASSERT_NEAR(at_t1.t, t1, 1e-12 * t1);
    const double theta1 = std::atan2(at_t1.states[0].r_G.x(), at_t1.states[0].r_G.z());
    EXPECT_NEAR(theta1, omega0 / lambda * std::sinh(lambda * t1), 1e-6 * theta1) << ratio;
    // It leaves upright for good: far past the 1e-3 rad of the linear range (with a spring it
    // comes to rest about the tipped equilibrium k theta = M g (L/2) sin(theta)).
    double largest = 0.0;
    for (const Row& row : run.rows) {
      largest =
          std::max(largest, std::abs(std::atan2(row.states[0].r_G.x(), row.states[0].r_G.z())));
    }
    EXPECT_GT(largest, 0.5) << ratio;
  }
}

}  // namespace
}  // namespace tumble
