// Distance joints (a massless rod between a point of each body, loop_rows.hpp): the conical
// pendulum's steady circling and its rod's pull, a slider-crank whose connecting rod is massless
// against its closed-form kinematics and inverse dynamics, the rod pendulum's linearisation, and
// the located errors of rods that cannot be.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "modes_checks.hpp"
#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "test_files.hpp"

namespace tumble {
namespace {

using test::kPi;

// examples/conical_pendulum.yaml: the ball's centre on its circle, at the steady rate, with the
// rod's pull T = m g / cos(alpha) towards the ceiling point, over ten turns.
TEST(RodJoint, AConicalPendulumCirclesAtItsSteadyRateWithItsRodsPull) {
  const test::ScenarioRun run =
      test::run_scenario(load_scenario(test::example("conical_pendulum.yaml"), {}));
  const double L = 1.0, alpha = 30.0 * kPi / 180.0, g = 9.81, zO = 2.0, m = 1.5;
  const double Omega = std::sqrt(g / (L * std::cos(alpha))), T = m * g / std::cos(alpha);
  const Vec3 O(0.0, 0.0, zO);
  ASSERT_GT(run.rows.size(), 3000U);
  EXPECT_NEAR(run.rows.back().t, 10.0 * 2.0 * kPi / Omega, 1e-12);
  const double E0 = run.rows.front().quantities.total_energy;
  for (const test::Row& row : run.rows) {
    const BodyState& ball = row.states.at(0);
    const double phase = Omega * row.t;
    const Vec3 circle(L * std::sin(alpha) * std::cos(phase), L * std::sin(alpha) * std::sin(phase),
                      zO - L * std::cos(alpha));
    // rtol 1e-11 over ten turns (some 250 steps, each erring by up to rtol): the phase drifts
    // by well under 100 rtol (6e-11 here).
    EXPECT_LT((ball.r_G - circle).norm(), 1e-9 * L) << "t " << row.t;
    // The rod's pull, what the ceiling exerts on the ball through it, against the closed form;
    // and against Newton's second law along the rod at the row's own state, whose velocity
    // terms are the centripetal m v^2 / L: -F.u = m (v^2 / L + g.u) with u from O to the ball.
    const JointReaction& rod = row.extras.joints.at(0);
    const Vec3 u = (ball.r_G - O) / L;
    EXPECT_NEAR((rod.F_W - (-T * u)).norm(), 0.0, 1e-9 * T) << "t " << row.t;
    // (round-off: the row's own state)
    EXPECT_NEAR(-rod.F_W.dot(u), m * (ball.v_G.squaredNorm() / L + g * -u.z()), 1e-13 * T);
    EXPECT_LE(rod.F_W.cross(u).norm(), 1e-12 * T);  // along the rod
    EXPECT_EQ(rod.M_J_W.norm(), 0.0);
    // Fixed to the ball's centre, the rod leaves its spin alone: none but round-off's (the rod's
    // end 1e-17 m off the centre under its 17 N pull turns the ball at 1e-13 rad/s^2: a few
    // 1e-12 rad/s over the run's 19 s).
    EXPECT_LE(ball.omega_W.norm(), 1e-11);
    EXPECT_NEAR(row.quantities.total_energy, E0, 1e-10 * std::abs(E0));
    EXPECT_LE(row.extras.loops.gap, 1e-13 * L);
    EXPECT_LE(row.extras.loops.speed, 1e-12 * Omega * L);
  }
}

// examples/slider_crank.yaml with its connecting rod massless: a distance joint from the crank
// pin to the wrist pin in place of the rod's body and its two hinges. The piston's position is
// the closed form's (the crank turns at its speed), and with the rod's mass gone the motor's
// power is w dE/dtheta of the crank and the piston alone; the rod's pull on the piston is along
// it and gives the piston its acceleration, m x'' (the guide takes no force along x).
TEST(RodJoint, ASliderCrankWithAMasslessRodFollowsItsClosedFormAndTakesItsTorque) {
  std::string text = test::read_file(test::example("slider_crank.yaml"));
  const std::size_t rod_from = text.find("  rod:\n");
  text.erase(rod_from, text.find("  piston:\n") - rod_from);
  const std::size_t big_end = text.find("  big_end:");
  text.erase(big_end, text.find("  guide:") - big_end);
  const std::size_t wrist_pin = text.find("  wrist_pin:");
  text.erase(wrist_pin, text.find("simulate:") - wrist_pin);
  text = test::replaced(
      text, "simulate:",
      "  rod: {type: distance, bodies: [crank, piston], at: [[\"r*cos(theta0)\", 0, \"-yA\"], "
      "[xB, 0, 0]]}\nsimulate:");
  const test::ScenarioRun run = test::run_inline_scenario(text, "slider_crank_massless_rod");
  ASSERT_EQ(run.scenario.joints.back().type, JointType::Distance);
  ASSERT_TRUE(run.scenario.joints.back().closes_loop);
  const double r = 0.1, l = 0.35, w = 20.0, theta0 = 30.0 * kPi / 180.0, g = 9.81;
  const double m_crank = 0.5, m_piston = 2.0;
  ASSERT_GT(run.rows.size(), 1000U);
  double largest_power = 0.0, largest_pull = 0.0;
  for (const test::Row& row : run.rows) {
    largest_power = std::max(largest_power, std::abs(row.extras.elements.at(0).power));
    largest_pull = std::max(largest_pull, row.extras.joints.at(2).F_W.norm());
  }
  for (const test::Row& row : run.rows) {
    const double theta = theta0 + w * row.t;
    // The closed form (the rod's terms are zero with its mass).
    const double s = std::sqrt(l * l - r * r * std::sin(theta) * std::sin(theta));
    const double x = r * std::cos(theta) + s;
    const double x1 = -r * std::sin(theta) - r * r * std::sin(theta) * std::cos(theta) / s;
    const double x2 =
        -r * std::cos(theta) -
        r * r * (std::cos(theta) * std::cos(theta) - std::sin(theta) * std::sin(theta)) / s -
        std::pow(r * r * std::sin(theta) * std::cos(theta), 2) / (s * s * s);
    const BodyState& piston = row.states.at(1);
    EXPECT_NEAR(piston.r_G.x(), x, 1e-10 * l) << "t " << row.t;
    const double dKE = w * w * m_piston * x1 * x2;
    const double dPE = -g * m_crank * r / 2.0 * std::cos(theta);
    EXPECT_NEAR(row.extras.elements.at(0).power, w * (dKE + dPE), 1e-9 * largest_power)
        << "t " << row.t;
    // The crank pin (turning about +y from +x towards -z) and the rod's pull along it.
    const Vec3 A(r * std::cos(theta), 0.0, -r * std::sin(theta));
    const Vec3 u = (piston.r_G - A).normalized();
    const JointReaction& rod = row.extras.joints.at(2);
    EXPECT_LE(rod.F_W.cross(u).norm(), 1e-9 * largest_pull) << "t " << row.t;
    EXPECT_NEAR(rod.F_W.x(), m_piston * w * w * x2, 1e-9 * largest_pull) << "t " << row.t;
    EXPECT_LE(row.extras.loops.gap, 1e-12 * l);
  }
}

// A ball hung at rest from its centre by a rod: it swings as a point pendulum of the rod's
// length in either direction, omega^2 = g / L exactly (the rod leaves the ball's turning alone,
// so its inertia does not enter), and its three turns are neutral.
TEST(RodJoint, ARodPendulumsModesAreThoseOfAPointPendulum) {
  const std::string yaml = R"(tumble: 1
name: rod pendulum
gravity: [0, 0, -9.81]
bodies:
  ball: {shape: sphere, radius: 0.1, mass: 2, position: [0, 0, -0.8]}
joints:
  rod: {type: distance, body: ball, at: [[0, 0, 0], [0, 0, -0.8]]}
simulate: {duration: 1}
)";
  const ScenarioModes modes = modes_of_scenario(test::load_inline_scenario(yaml, "rod_pendulum"));
  EXPECT_TRUE(modes.linearisation.equilibrium());
  std::vector<double> swings;
  for (const Mode& mode : modes.analysis.modes) {
    if (mode.kind == Mode::Kind::Oscillating) {
      swings.push_back(mode.natural_frequency);
    } else {
      EXPECT_EQ(mode.kind, Mode::Kind::Neutral);
    }
  }
  ASSERT_EQ(swings.size(), 2U);
  for (const double omega : swings) test::expect_relative(omega, std::sqrt(9.81 / 0.8));
}

TEST(RodJoint, RodsThatCannotBeAreLocatedErrors) {
  const std::string head = R"(tumble: 1
gravity: [0, 0, -9.81]
bodies:
  ball: {shape: sphere, radius: 0.1, mass: 2, position: [0, 0, -0.8]}
joints:
)";
  const std::string tail = "simulate: {duration: 1}\n";
  // Each on line 6: "  rod: {type: distance, body: ball, at: " and what follows.
  struct Case {
    std::string rest;
    int column;
    std::string key, why;
  };
  const std::vector<Case> cases = {
      {"[[0, 0, -0.8], [0, 0, -0.8]]}", 41, "joints.rod.at", "a rod's ends are 0 m apart"},
      {"[0, 0, 0]}", 41, "joints.rod.at", "give two points, one on each body; got 3"},
      {"[[0, 0, 0], [0, 0, -0.8]], motor: {speed: 1}}", 68, "joints.rod.motor",
       "a distance joint takes no motor"},
      {"[[0, 0, 0], [0, 0, -0.8]], lock: {at: 1}}", 68, "joints.rod.lock",
       "a distance joint (a rod) takes no lock"},
  };
  for (const Case& c : cases) {
    test::expect_error(head + "  rod: {type: distance, body: ball, at: " + c.rest + "\n" + tail, 6,
                       c.column, c.key, c.why);
  }
  test::expect_error(head + "  rod: {type: distanse, body: ball}\n" + tail, 6, 15,
                     "joints.rod.type", "did you mean 'distance'?");
  // A rod across a hinge of a floating pair takes the hinge's freedom: the pair is rigid, a
  // structure whose reactions no motion decides (its six freedoms as a whole are its own).
  test::expect_error(R"(tumble: 1
gravity: [0, 0, -9.81]
bodies:
  a: {shape: sphere, radius: 0.1, mass: 1, position: [0, 0, 0]}
  b: {shape: sphere, radius: 0.1, mass: 1, position: [1, 0, 0]}
joints:
  h: {type: hinge, bodies: [a, b], at: [0.5, 0, 0], axis: [0, 0, 1]}
  rod: {type: distance, bodies: [a, b], at: [[0, 0.2, 0], [1, 0.2, 0]]}
)" + tail,
                     8, 3, "joints.rod", "leave nothing free to move");
}

}  // namespace
}  // namespace tumble
