// Slender bodies (docs/scenario.md, Bodies): a point or a lone rod, whose inertia about the COM
// is singular, is a valid body where its joints allow it no turn about the axes it has no
// inertia about; elsewhere it is refused, at its shape, saying why.
//  - A point mass on a massless link (a point on a hinge), released from the horizontal: the
//    pendulum's exact solution, sin(theta/2) = k sn(K(k) - w0 t; k) with k = sin(theta0/2) and
//    w0 = sqrt(g/l) (theta from the bottom; e.g. Lawden, Elliptic Functions and Applications,
//    1989, ch. 5), over 1,000 periods T = 4 K(k) / w0.
//  - A uniform rod standing on a hinge at its foot with a torsional spring k (the chapter's mast,
//    equations.md): M L^2/3 theta'' = -(k - M g L/2) theta, so it swings at
//    omega_n = sqrt((k - M g L/2) / (M L^2/3)).
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cmath>
#include <complex>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "modes_checks.hpp"
#include "scenario_run.hpp"
#include "test_constants.hpp"

namespace tumble {
namespace {

using test::Row;
using test::run_inline_scenario;

using test::kG;

TEST(SlenderBody, APointOnAMasslessLinkFollowsThePendulumsExactSolutionOver1000Periods) {
  const double l = 0.8, m = 2.0, theta0 = M_PI / 2;
  const double k = std::sin(theta0 / 2), w0 = std::sqrt(kG / l);
  const double K = boost::math::ellint_1(k);
  const double T = 4 * K / w0;
  // The largest departure from the exact angle over 1,000 periods, and the period measured from
  // the first to the thousandth pass through the bottom.
  struct Result {
    double worst = 0.0, period = 0.0;
  };
  const auto run_at = [&](double rtol) {
    const auto run =
        run_inline_scenario(fmt::format(R"(tumble: 1
gravity: [0, 0, -{}]
bodies:
  bob: {{shape: point, mass: {}, position: [{}, 0, 0]}}
joints:
  pivot: {{type: hinge, body: bob, at: [0, 0, 0], axis: [0, 1, 0]}}
simulate: {{duration: {}, integrator: dop853, rtol: {}, atol: {}, output_every: {}}}
)",
                                        kG, m, l, 1000 * T + T / 8, rtol, rtol * 1e-2, T / 64),
                            "point_pendulum");
    Result result;
    std::vector<double> t, theta, rate;
    for (const Row& row : run.rows) {
      const Vec3& r = row.states[0].r_G;
      t.push_back(row.t);
      theta.push_back(std::atan2(r.x(), -r.z()));
      rate.push_back(-row.states[0].omega_W.y());  // d/dt atan2(x, -z) about +y is -omega_y
      const double exact = 2 * std::asin(k * boost::math::jacobi_sn(k, K - w0 * row.t));
      result.worst = std::max(result.worst, std::abs(theta.back() - exact));
      EXPECT_NEAR(r.norm(), l, 1e-12) << "the link keeps its length, t " << row.t;
    }
    const std::vector<double> up = test::upward_zero_crossings(t, theta, rate);
    EXPECT_GE(up.size(), 1000u);
    result.period = (up.back() - up.front()) / static_cast<double>(up.size() - 1);
    return result;
  };
  const Result coarse = run_at(1e-10), fine = run_at(1e-12);
  // The period, averaged over a thousand, is the exact one to a few rtol; the phase, whose error
  // grows with time as the local errors change the energy (and so the period), stays within
  // 1e-4 rad over the thousand periods at rtol 1e-10 and shrinks with rtol as an eighth-order
  // method's must (rtol 100 times smaller: at least 30 times smaller).
  EXPECT_NEAR(coarse.period, T, 1e-8 * T);
  EXPECT_NEAR(fine.period, T, 1e-10 * T);
  EXPECT_LT(coarse.worst, 1e-4);
  EXPECT_LT(fine.worst, coarse.worst / 30);
}

// A double pendulum of two equal point masses on massless links of equal length l: its normal
// modes have omega^2 = (g/l)(2 -+ sqrt 2), the lower link's angle from the vertical sqrt 2 and
// -sqrt 2 times the upper's (e.g. Goldstein, Classical Mechanics, 3rd ed., section 6.4). It was
// refused: the lower hinge sits on the upper bob, and was counted against it, though it turns
// only the lower one. Only the joint that moves a body is.
TEST(SlenderBody, ADoublePendulumOfPointsHasTheClassicNormalModes) {
  const double l = 0.7, m = 1.3;
  const Scenario scenario = test::load_inline_scenario(fmt::format(R"(tumble: 1
gravity: [0, 0, -{}]
bodies:
  bob1: {{shape: point, mass: {}, position: [0, 0, -{}]}}
  bob2: {{shape: point, mass: {}, position: [0, 0, -{}]}}
joints:
  upper: {{type: hinge, body: bob1, at: [0, 0, 0], axis: [0, 1, 0]}}
  lower: {{type: hinge, bodies: [bob1, bob2], at: [0, 0, -{}], axis: [0, 1, 0]}}
simulate: {{duration: 1}}
)",
                                                                   kG, m, l, m, 2 * l, l),
                                                       "double_pendulum_of_points");
  const ScenarioModes modes = modes_of_scenario(scenario);
  ASSERT_EQ(modes.analysis.modes.size(), 2U);
  for (const auto& [index, sign] : {std::pair{0, -1.0}, std::pair{1, +1.0}}) {
    const Mode& mode = modes.analysis.modes[static_cast<std::size_t>(index)];
    const double omega = std::sqrt(kG / l * (2 + sign * std::sqrt(2.0)));
    EXPECT_NEAR(mode.natural_frequency, omega, 1e-12 * omega);
    // The coordinates are the upper hinge's angle and the lower's relative to the upper link:
    // theta2 / theta1 = shape(1) / shape(0) + 1 = -+ sqrt 2.
    const std::complex<double> ratio = mode.shape(1) / mode.shape(0) + 1.0;
    EXPECT_NEAR(ratio.real(), -sign * std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(ratio.imag(), 0.0, 1e-12);
  }
}

// The zeros of the Laguerre polynomial L_n, from its recurrence
// (k + 1) L_{k+1} = (2k + 1 - x) L_k - k L_{k-1}: all real, in (0, 4n + 2), a scan's sign changes
// refined by bisection.
std::vector<double> laguerre_zeros(int n) {
  const auto L = [n](double x) {
    double previous = 1.0, current = 1.0 - x;
    for (int k = 1; k < n; ++k) {
      const double next = ((2 * k + 1 - x) * current - k * previous) / (k + 1);
      previous = current;
      current = next;
    }
    return current;
  };
  std::vector<double> zeros;
  const double step = 1e-3;
  for (double a = 0.0; a < 4 * n + 2; a += step) {
    double lo = a, hi = a + step;
    if ((L(lo) > 0) == (L(hi) > 0)) continue;
    for (int i = 0; i < 200 && lo < hi; ++i) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      ((L(mid) > 0) == (L(lo) > 0) ? lo : hi) = mid;
    }
    zeros.push_back(0.5 * (lo + hi));
  }
  return zeros;
}

// A chain of n equal point masses hanging on n massless links of equal length l: its modes have
// omega^2 = (g / l) x_k, x_k the zeros of the Laguerre polynomial L_n (the double pendulum's
// 2 -+ sqrt 2 are L_2's). Twenty links are forty coordinates, more than a dual number carries
// (kDualSeeds): the Jacobian is taken in two evaluations, its columns seeded in turn.
TEST(SlenderBody, AHangingChainOfTwentyPointsHasTheLaguerreZerosAsItsModes) {
  constexpr int n = 20;
  static_assert(2 * n > kDualSeeds);
  const double l = 0.25, m = 0.4;
  std::string yaml = fmt::format("tumble: 1\ngravity: [0, 0, -{}]\nbodies:\n", kG);
  std::string joints = "joints:\n";
  for (int i = 1; i <= n; ++i) {
    yaml += fmt::format("  p{}: {{shape: point, mass: {}, position: [0, 0, {}]}}\n", i, m, -i * l);
    joints +=
        fmt::format("  j{}: {{type: hinge, bodies: [{}, p{}], at: [0, 0, {}], axis: [0, 1, 0]}}\n",
                    i, i == 1 ? std::string("ground") : fmt::format("p{}", i - 1), i, -(i - 1) * l);
  }
  const ScenarioModes modes = modes_of_scenario(
      test::load_inline_scenario(yaml + joints + "simulate: {duration: 1}\n", "hanging_chain"));
  std::vector<double> omega_squared;
  for (const Mode& mode : modes.analysis.modes) {
    omega_squared.push_back(mode.natural_frequency * mode.natural_frequency);
  }
  std::sort(omega_squared.begin(), omega_squared.end());
  const std::vector<double> x = laguerre_zeros(n);
  ASSERT_EQ(x.size(), static_cast<std::size_t>(n));
  ASSERT_EQ(omega_squared.size(), x.size());
  // Each to 1e-11 of itself: the eigenvalues of a 40 x 40 system whose omega^2 span three decades
  // come out to a few hundred eps (3e-12 at worst, the highest mode).
  for (std::size_t k = 0; k < x.size(); ++k) {
    EXPECT_NEAR(omega_squared[k], kG / l * x[k], 1e-11 * kG / l * x[k]) << "mode " << k;
  }
}

// A chain of ten point masses on massless links, released from the horizontal: it runs, the
// links keep their lengths, and the energy stays what it was (nothing but gravity does work) to
// the tolerance asked for.
TEST(SlenderBody, AChainOfTenPointsOnHingesConservesItsEnergy) {
  const double l = 0.3, rtol = 1e-10;
  std::string yaml = fmt::format("tumble: 1\ngravity: [0, 0, -{}]\nbodies:\n", kG);
  std::string joints = "joints:\n";
  for (int i = 1; i <= 10; ++i) {
    yaml += fmt::format("  p{}: {{shape: point, mass: 0.5, position: [{}, 0, 0]}}\n", i, i * l);
    joints +=
        fmt::format("  j{}: {{type: hinge, bodies: [{}, p{}], at: [{}, 0, 0], axis: [0, 1, 0]}}\n",
                    i, i == 1 ? std::string("ground") : fmt::format("p{}", i - 1), i, (i - 1) * l);
  }
  const auto run = test::run_inline_scenario(
      yaml + joints +
          fmt::format("simulate: {{duration: 2, integrator: dop853, rtol: {}, atol: {}, "
                      "output_every: 0.01}}\n",
                      rtol, rtol * 1e-2),
      "chain_of_points");
  ASSERT_EQ(run.rows.size(), 201U);
  const double E0 = run.rows.front().quantities.total_energy;
  // The scale of E: the largest kinetic energy, about the potential energy released (J).
  double largest_ke = 0.0;
  for (const Row& row : run.rows) {
    largest_ke = std::max(largest_ke, row.quantities.kinetic_energy);
  }
  ASSERT_GT(largest_ke, 1.0);
  // Each accepted step's error is held to rtol of the state (atol is a hundredth of it), so the
  // energy can drift by about rtol of its scale a step, at most: the bound is the steps' sum.
  const auto steps = static_cast<double>(run.result.report.stats.accepted_steps);
  for (const Row& row : run.rows) {
    EXPECT_NEAR(row.quantities.total_energy, E0, steps * rtol * largest_ke) << "t " << row.t;
    for (int i = 1; i < 10; ++i) {
      const double link = (row.states[static_cast<std::size_t>(i)].r_G -
                           row.states[static_cast<std::size_t>(i - 1)].r_G)
                              .norm();
      EXPECT_NEAR(link, l, 1e-12) << "link " << i << " at t " << row.t;
    }
  }
}

TEST(SlenderBody, ARodOnAHingeWithATorsionalSpringSwingsAtTheMastsFrequency) {
  const double M = 1.5, L = 1.2, a = 1e-4;
  for (const double k : {15.0, 40.0}) {
    const double omega_n = std::sqrt((k - M * kG * L / 2) / (M * L * L / 3));
    const double period = 2 * M_PI / omega_n;
    const auto run = run_inline_scenario(fmt::format(R"(tumble: 1
gravity: [0, 0, -{}]
parameters: {{L: {}, a: {}}}
bodies:
  mast: {{shape: rod, length: L, mass: {}, position: [L/2*sin(a), 0, L/2*cos(a)],
          orientation: {{axis: [0, 1, 0], angle: a - 90 deg}}}}
joints:
  foot: {{type: hinge, body: mast, at: [0, 0, 0], axis: [0, 1, 0]}}
forces:
  - {{type: torsional_spring, bodies: [ground, mast], stiffness: {}, rest: -a}}
simulate: {{duration: {}, integrator: dop853, rtol: 1e-12, atol: 1e-15, output_every: {}}}
)",
                                                     kG, L, a, M, k, 10 * period, period / 2000),
                                         "mast");
    std::vector<double> t, angle, rate;
    for (const Row& row : run.rows) {
      t.push_back(row.t);
      angle.push_back(row.extras.coordinates[0].values[0] + a);  // from upright
      rate.push_back(row.extras.coordinates[0].values[1]);
    }
    const std::vector<double> up = test::upward_zero_crossings(t, angle, rate);
    ASSERT_GE(up.size(), 5u);
    const double measured = (up.back() - up.front()) / static_cast<double>(up.size() - 1);
    EXPECT_NEAR(measured, period, 1e-8 * period) << "k " << k;
  }
}

TEST(SlenderBody, AFreeRodOrOneOnABallJointOrTurnedAboutItsOwnLineIsRefusedAtItsShape) {
  const std::string head =
      "tumble: 1\nbodies:\n  rod: {shape: rod, length: 1, mass: 2, position: [0.5, 0, 0]}\n";
  const std::string simulate = "simulate: {duration: 1}\n";
  test::expect_error(
      head + simulate, 3, 16, "bodies.rod.shape",
      "a rod has no inertia about its own axis: free, nothing would say how it turns");
  test::expect_error(head + "joints:\n  pin: {type: ball, body: rod, at: [0, 0, 0]}\n" + simulate,
                     3, 16, "bodies.rod.shape", "on the ball joint 'pin'");
  test::expect_error(
      head + "joints:\n  pin: {type: hinge, body: rod, at: [0, 0, 0], axis: [1, 0, 0]}\n" +
          simulate,
      3, 16, "bodies.rod.shape", "the hinge 'pin' turns it about an axis it has no inertia");
  // A shaft along it, and a Hooke joint whose second axis lies along it.
  test::expect_error(
      head + "joints:\n  pin: {type: cylindrical, body: rod, at: [0, 0, 0], axis: [1, 0, 0]}\n" +
          simulate,
      3, 16, "bodies.rod.shape", "the cylindrical joint 'pin' turns it about an axis it has no");
  test::expect_error(head +
                         "joints:\n  pin: {type: universal, body: rod, at: [0, 0, 0], axes: [[0, "
                         "0, 1], [1, 0, 0]]}\n" +
                         simulate,
                     3, 16, "bodies.rod.shape",
                     "the universal joint 'pin' turns it about an axis it has no");
  // A point on a hinge through it.
  test::expect_error(
      "tumble: 1\nbodies:\n  bob: {shape: point, mass: 1}\njoints:\n  pin: {type: hinge, body: "
      "bob, at: [0, 0, 0], axis: [0, 1, 0]}\n" +
          simulate,
      3, 16, "bodies.bob.shape", "a point has no inertia at all: the hinge 'pin'");
}

}  // namespace
}  // namespace tumble

namespace tumble {
namespace {

// A point mass on a ball joint (the spherical pendulum), started on the conical pendulum's
// circle: at an angle theta from the downward vertical, turning about the vertical at
// Omega = sqrt(g / (L cos theta)), it keeps its height -L cos theta and its azimuth advances as
// Omega t. The point's turn about the line from the pivot through it moves no mass; it is held
// at the rate it was given. At dop853 rtol 1e-11 over five turns the height and the azimuth are
// held to 1e-8 (of L and in rad).
TEST(SlenderBody, APointOnABallJointCirclesAtTheConicalPendulumsRate) {
  const double L = 1.5, theta = 40.0 * M_PI / 180.0;
  const double omega = std::sqrt(kG / (L * std::cos(theta)));
  const double turn = 2 * M_PI / omega;
  const auto run = run_inline_scenario(
      fmt::format(R"(tumble: 1
gravity: [0, 0, -{}]
bodies:
  bob: {{shape: point, mass: 2, position: [{}, 0, {}], angular_velocity: [0, 0, {}]}}
joints:
  pivot: {{type: ball, body: bob, at: [0, 0, 0]}}
simulate: {{duration: {}, integrator: dop853, rtol: 1e-11, atol: 1e-13, output_every: {}}}
)",
                  kG, L * std::sin(theta), -L * std::cos(theta), omega, 5 * turn, turn / 40),
      "conical_pendulum");
  ASSERT_GT(run.rows.size(), 200u);
  for (const Row& row : run.rows) {
    const Vec3& r = row.states[0].r_G;
    EXPECT_NEAR(r.norm(), L, 1e-12) << row.t;
    EXPECT_NEAR(r.z(), -L * std::cos(theta), 1e-8 * L) << row.t;
    const double azimuth = std::atan2(r.y(), r.x());
    EXPECT_NEAR(std::remainder(azimuth - omega * row.t, 2 * M_PI), 0.0, 1e-8) << row.t;
    EXPECT_NEAR(row.quantities.total_energy, run.rows.front().quantities.total_energy,
                1e-9 * std::abs(run.rows.front().quantities.total_energy));
  }
}

// Released from rest level with its pivot, a point on a ball joint swings in the vertical plane
// as the point on a hinge does: the two runs agree to what their tolerances allow.
TEST(SlenderBody, APointOnABallJointSwingsAsOnAHinge) {
  const auto swing = [](const std::string& joint) {
    return run_inline_scenario(R"(tumble: 1
bodies:
  bob: {shape: point, mass: 2, position: [0.8, 0, 0]}
joints:
  pivot: )" + joint + R"(
simulate: {duration: 5, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: 0.05}
)",
                               "swing");
  };
  const test::ScenarioRun hinge = swing("{type: hinge, body: bob, at: [0, 0, 0], axis: [0, 1, 0]}");
  const test::ScenarioRun ball = swing("{type: ball, body: bob, at: [0, 0, 0]}");
  ASSERT_EQ(ball.rows.size(), hinge.rows.size());
  for (std::size_t i = 0; i < ball.rows.size(); ++i) {
    EXPECT_LT((ball.rows[i].states[0].r_G - hinge.rows[i].states[0].r_G).norm(), 1e-9)
        << ball.rows[i].t;
    EXPECT_NEAR(ball.rows[i].states[0].r_G.y(), 0.0, 1e-12);
  }
}

TEST(SlenderBody, APointOnItsOwnBallJointIsRefused) {
  test::expect_error(
      "tumble: 1\nbodies:\n  bob: {shape: point, mass: 1, position: [1, 0, 0]}\njoints:\n  pin: "
      "{type: ball, body: bob, at: [1, 0, 0]}\nsimulate: {duration: 1}\n",
      3, 16, "bodies.bob.shape", "it sits on the ball joint 'pin'");
}

}  // namespace
}  // namespace tumble
