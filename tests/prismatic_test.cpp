// The prismatic joint (a slider) against closed forms: a block on a tilted slider with a spring
// along it oscillates at sqrt(k / m) whatever the tilt, about a rest point shifted down the slope
// by m g sin(theta) / k; a speed motor holds its rate exactly and does the work of lifting the
// block; a force motor accelerates it at F / m; a lock stops it, with the kinetic energy lost as
// the lock's work; the rail's reaction has no component along the rail; a pendulum on a cart that
// rolls on a rail keeps the horizontal momentum and the energy.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "scenario_run.hpp"
#include "test_constants.hpp"

namespace tumble {
namespace {

using test::Row;
using test::run_inline_scenario;

using test::kDeg;
using test::kG;

// A 2 kg block on a slider through its COM along u = (cos th, 0, -sin th) (down the slope for
// th > 0), started at the spring's rest length with speed v0 along u; the spring runs from a
// ground point 1 m up the rail to the block's COM. `bodies` lists the slider's bodies.
std::string spring_slider(double theta, double k, double v0, const char* bodies,
                          double duration = 5) {
  return fmt::format(R"(tumble: 1
parameters: {{th: {}, k: {}, v0: {}}}
gravity: [0, 0, -{}]
bodies:
  block:
    shape: box
    size: [0.2, 0.1, 0.1]
    mass: 2
    position: [0, 0, 0]
    velocity: [v0*cos(th), 0, -v0*sin(th)]
joints:
  slide: {{type: prismatic, bodies: {}, at: [0, 0, 0], axis: [cos(th), 0, -sin(th)]}}
forces:
  - {{type: spring, name: spring, bodies: [ground, block], at: [[-cos(th), 0, sin(th)], [0, 0, 0]],
     stiffness: k}}
simulate: {{duration: {}, integrator: dop853, rtol: 1e-11, atol: 1e-13, output_every: 0.01}}
)",
                     theta, k, v0, kG, bodies, duration);
}

TEST(Prismatic, ASpringOnATiltedSliderOscillatesAtSqrtKOverMAboutTheShiftedRest) {
  const double m = 2.0, k = 50.0, v0 = 0.3;
  const double omega = std::sqrt(k / m);
  for (const double theta : {0.0, 30 * kDeg, 75 * kDeg, 90 * kDeg}) {
    const auto run = run_inline_scenario(spring_slider(theta, k, v0, "[ground, block]"), "slide");
    const Vec3 u(std::cos(theta), 0, -std::sin(theta));
    const double shift = m * kG * std::sin(theta) / k;
    for (const Row& row : run.rows) {
      const double t = row.t;
      // x'' = -(k/m) x + g sin(th): x = shift (1 - cos wt) + (v0 / w) sin wt.
      const double x = shift * (1 - std::cos(omega * t)) + v0 / omega * std::sin(omega * t);
      const double v = shift * omega * std::sin(omega * t) + v0 * std::cos(omega * t);
      const Vec3& r = row.states[0].r_G;
      // rtol 1e-11 over ~8 periods: the phase error stays well below 1e-9 of the 0.4 m amplitude.
      EXPECT_NEAR(r.dot(u), x, 1e-9) << "theta " << theta / kDeg << " t " << t;
      EXPECT_NEAR(row.states[0].v_G.dot(u), v, 1e-9) << "theta " << theta / kDeg << " t " << t;
      // The joint holds by construction: no motion off the rail, no turning.
      EXPECT_LT((r - r.dot(u) * u).norm(), 1e-14);
      EXPECT_LT(row.states[0].omega_W.norm(), 1e-14);
      // The rail pushes only across itself: its reaction carries the weight's part across it.
      const JointReaction& rail = row.extras.joints[0];
      EXPECT_NEAR(rail.F_W.dot(u), 0.0, 1e-12 * m * kG);
      const Vec3 across = -m * Vec3(0, 0, -kG) + m * kG * std::sin(theta) * u;
      EXPECT_NEAR((rail.F_W - across).norm(), 0.0, 1e-11 * m * kG);
      // Gravity and the spring keep E.
      EXPECT_NEAR(row.quantities.total_energy, run.rows.front().quantities.total_energy,
                  1e-10 * m * kG);
    }
  }
}

TEST(Prismatic, TheBodiesInEitherOrderGiveTheSameMotion) {
  // [block, ground]: ground is the joint's second body, so the tree takes the joint reversed.
  const auto ground_first =
      run_inline_scenario(spring_slider(0.4, 50, 0.3, "[ground, block]", 2), "ground_first");
  const auto block_first =
      run_inline_scenario(spring_slider(0.4, 50, 0.3, "[block, ground]", 2), "block_first");
  ASSERT_EQ(ground_first.rows.size(), block_first.rows.size());
  for (std::size_t i = 0; i < ground_first.rows.size(); ++i) {
    EXPECT_NEAR((ground_first.rows[i].states[0].r_G - block_first.rows[i].states[0].r_G).norm(),
                0.0, 1e-12);
    // What the first body exerts on the second: the reactions are opposite.
    EXPECT_NEAR(
        (ground_first.rows[i].extras.joints[0].F_W + block_first.rows[i].extras.joints[0].F_W)
            .norm(),
        0.0, 1e-11);
  }
}

// A block on a slider up a slope of th along u = (cos th, 0, sin th), with a motor on it.
std::string motor_slider(double theta, const std::string& motor, const std::string& velocity,
                         const std::string& extra = "") {
  return fmt::format(R"(tumble: 1
parameters: {{th: {}}}
gravity: [0, 0, -{}]
bodies:
  block:
    shape: box
    size: [0.2, 0.1, 0.1]
    mass: 2
    position: [0, 0, 0]
    velocity: {}
joints:
  slide: {{type: prismatic, body: block, at: [0, 0, 0], axis: [cos(th), 0, sin(th)],
          motor: {}{}}}
simulate: {{duration: 3, integrator: dopri5, rtol: 1e-10, atol: 1e-12, output_every: 0.01}}
)",
                     theta, kG, velocity, motor, extra);
}

TEST(Prismatic, ASpeedMotorHoldsItsRateExactlyAndDoesTheWorkOfLifting) {
  const double m = 2.0, speed = 0.5, theta = 30 * kDeg;
  const auto run = run_inline_scenario(
      motor_slider(theta, "{speed: 0.5}", "[0.5*cos(th), 0, 0.5*sin(th)]"), "lift");
  const Vec3 u(std::cos(theta), 0, std::sin(theta));
  for (const Row& row : run.rows) {
    EXPECT_NEAR(row.states[0].v_G.dot(u), speed, 1e-15);
    EXPECT_NEAR(row.states[0].r_G.dot(u), speed * row.t, 1e-13 * (1 + row.t));
    // The motor pushes with m g sin(th) and works at that times the speed: the lift's m g h.
    const ElementWork& motor = row.extras.elements[0];
    EXPECT_NEAR(motor.power, m * kG * std::sin(theta) * speed, 1e-12);
    EXPECT_NEAR(motor.work, m * kG * speed * row.t * std::sin(theta), 1e-11 * (1 + row.t));
  }
}

TEST(Prismatic, AForceMotorAcceleratesTheBlockAtForceOverMass) {
  // Level rail, F = 3 N: x = F t^2 / (2 m), and the motor's work is F x.
  const double m = 2.0, F = 3.0;
  const auto run = run_inline_scenario(motor_slider(0.0, "{force: 3}", "[0, 0, 0]"), "push");
  for (const Row& row : run.rows) {
    const double x = F * row.t * row.t / (2 * m);
    EXPECT_NEAR(row.states[0].r_G.x(), x, 1e-12 * (1 + x));
    EXPECT_NEAR(row.extras.elements[0].work, F * x, 1e-11 * (1 + x));
  }
}

TEST(Prismatic, ALockStopsTheSliderAndItsWorkIsTheKineticEnergyLost) {
  const double m = 2.0, v0 = 0.8, t_lock = 1.0;
  const auto run = run_inline_scenario(
      motor_slider(0.0, "{force: 0}", "[0.8, 0, 0]", ", lock: {at: 1}"), "lock");
  for (const Row& row : run.rows) {
    // The row at t_lock is the state just before the lock (a breakpoint's row is the step's end).
    if (row.t <= t_lock) {
      EXPECT_NEAR(row.states[0].r_G.x(), v0 * row.t, 1e-13);
    } else {
      EXPECT_NEAR(row.states[0].r_G.x(), v0 * t_lock, 1e-13);
      EXPECT_EQ(row.states[0].v_G.norm(), 0.0);
    }
  }
  ASSERT_EQ(run.jumps.size(), 1u);
  EXPECT_DOUBLE_EQ(run.jumps[0].t, t_lock);
  EXPECT_NEAR(run.jumps[0].kinetic_energy_before, 0.5 * m * v0 * v0, 1e-13);
  EXPECT_NEAR(run.jumps[0].kinetic_energy_after, 0.0, 1e-15);
  // Elements: the motor, then the lock.
  EXPECT_NEAR(run.rows.back().extras.elements[1].work, -0.5 * m * v0 * v0, 1e-13);
}

TEST(Prismatic, APendulumOnACartKeepsTheHorizontalMomentumAndTheEnergy) {
  // The cart slides on a level rail (no force along it), the rod hangs from a hinge on the cart:
  // a tree ground -> slider -> cart -> hinge -> rod. Started with the rod at 40 degrees.
  const auto run = run_inline_scenario(R"(tumble: 1
parameters: {L: 0.6, a: 40 deg}
gravity: [0, 0, -9.81]
bodies:
  cart:
    shape: box
    size: [0.3, 0.2, 0.1]
    mass: 1.5
    position: [0, 0, 0]
  rod:
    shape: cylinder
    radius: 0.01
    length: L
    mass: 0.5
    position: [L/2*sin(a), 0, -L/2*cos(a)]
    orientation: {axis: [0, 1, 0], angle: -a}
joints:
  rail: {type: prismatic, body: cart, at: [0, 0, 0], axis: [1, 0, 0]}
  pin: {type: hinge, bodies: [cart, rod], at: [0, 0, 0], axis: [0, 1, 0]}
simulate: {duration: 4, integrator: dop853, rtol: 1e-11, atol: 1e-13, output_every: 0.01}
)",
                                       "cart_pole");
  const Row& first = run.rows.front();
  // Held in joint coordinates, px and E are kept to the integration's accuracy: rtol 1e-11 over
  // about three swings, against the rod's momentum and energy scales m sqrt(g L) and m g L.
  const double p_scale = 0.5 * std::sqrt(kG * 0.6), E_scale = 0.5 * kG * 0.6;
  double swing = 0.0;
  for (const Row& row : run.rows) {
    EXPECT_NEAR(row.quantities.linear_momentum.x(), 0.0, 100 * 1e-11 * p_scale);
    EXPECT_NEAR(row.quantities.total_energy, first.quantities.total_energy, 100 * 1e-11 * E_scale);
    EXPECT_NEAR(row.extras.joints[0].F_W.x(), 0.0, 1e-11);
    swing = std::max(swing, std::abs(row.states[0].r_G.x()));
  }
  // The cart does move: the rod's swing drives it back and forth.
  EXPECT_GT(swing, 0.01);
}

TEST(Prismatic, ItsKeysAreChecked) {
  test::expect_error(R"(tumble: 1
bodies:
  block: {shape: box, size: [0.2, 0.1, 0.1], mass: 2}
joints:
  slide: {type: prismatic, body: block, at: [0, 0, 0], axis: [1, 0, 0], motor: {torque: 1}}
simulate: {duration: 1}
)",
                     5, 81, "joints.slide.motor.torque", "force");
  test::expect_error(R"(tumble: 1
bodies:
  block: {shape: box, size: [0.2, 0.1, 0.1], mass: 2}
joints:
  slide: {type: prismatic, body: block, at: [0, 0, 0]}
simulate: {duration: 1}
)",
                     5, 3, "joints.slide.axis", "the direction the slider moves along");
  test::expect_error(R"(tumble: 1
bodies:
  block: {shape: box, size: [0.2, 0.1, 0.1], mass: 2, velocity: [0.2, 0, 0]}
joints:
  slide: {type: prismatic, body: block, at: [0, 0, 0], axis: [1, 0, 0], motor: {speed: 1}}
simulate: {duration: 1}
)",
                     5, 73, "joints.slide.motor", "drives the slider at 1 m/s from the start");
}

}  // namespace
}  // namespace tumble
