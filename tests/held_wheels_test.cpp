// Round bodies that a joint holds, rolling: examples/cart_on_a_ramp.yaml, a frame on four disks,
// each on a hinge across the ramp. Energy (or Newton-Euler on the frame and each wheel: the
// ramp's friction F = I_w a / R^2 spins each wheel up) gives the acceleration along the ramp
//     a = g sin(alpha) M / (M + 4 I_w / R^2),   M the whole mass, I_w = m R^2 / 2,
// with no slip (each wheel turns at v / R about its axle) and E conserved. Four wheels on a plane
// are one normal force more than the cart's freedoms off the ramp need: the least-norm forces
// the redundant rows' solve takes share the load evenly, M g cos(alpha) / 4 at each wheel (the
// moment of the friction about the COM is the wheels' spin-up, 4 I_w a / R: the front and rear
// wheels press alike).
//
// The example runs at rtol 1e-12: the tests allow 1e-10 of each closed-form value (the run's
// error in the speed is ~1e-12 of it).
//
// And a disk as a pendulum's bob (a round body on a hinge, in the hinge's plane) swinging down
// onto a frictionless wall where it hangs vertically, its rim's point level with its centre
// striking: one freedom, so the impact reverses the angular speed times e, and the energy left
// is e^2 of the strike's kinetic energy above the bottom (as for a sphere's bob,
// contact_joint_test.cpp).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "test_files.hpp"

namespace tumble {
namespace {

TEST(HeldWheels, ACartRollsDownARampAtTheClosedFormsAcceleration) {
  const test::ScenarioRun run =
      test::run_scenario(load_scenario(test::example("cart_on_a_ramp.yaml"), {}));
  const double alpha = 15.0 * std::numbers::pi / 180.0, g = 9.81, R = 0.1;
  const double m_wheel = 0.5, M = 4.0 + 4 * m_wheel, I_w = m_wheel * R * R / 2;
  const double a = g * std::sin(alpha) * M / (M + 4 * I_w / (R * R));
  const Vec3 down_W(std::cos(alpha), 0.0, -std::sin(alpha));  // down the ramp
  const Vec3 axle_W(0.0, 1.0, 0.0);
  const double N_each = M * g * std::cos(alpha) / 4;
  const test::Row& first = run.rows.front();
  const Vec3 r0 = first.states[0].r_G;
  const double E0 = first.quantities.total_energy;
  ASSERT_GT(run.rows.size(), 100u);
  for (const test::Row& row : run.rows) {
    const double t = row.t;
    const BodyState& frame = row.states[0];
    const double s = (frame.r_G - r0).dot(down_W), v = frame.v_G.dot(down_W);
    EXPECT_NEAR(s, a * t * t / 2, 1e-10 * a) << "t " << t;
    EXPECT_NEAR(v, a * t, 1e-10 * a) << "t " << t;
    EXPECT_NEAR(frame.omega_W.norm(), 0.0, 1e-10) << "t " << t;  // the frame does not pitch
    for (std::size_t w = 1; w <= 4; ++w) {
      // No slip: each wheel turns about its axle at v / R (forwards: about +y).
      EXPECT_NEAR(row.states[w].omega_W.dot(axle_W), v / R, 1e-10 * a / R) << "t " << t;
      const ContactOutput& contact = row.extras.contacts[w - 1];
      EXPECT_EQ(contact.mode, 2) << "wheel " << w << ", t " << t;
      EXPECT_NEAR(contact.normal_force, N_each, 1e-10 * N_each) << "wheel " << w << ", t " << t;
      EXPECT_NEAR(contact.slip_speed, 0.0, 1e-10 * a) << "wheel " << w << ", t " << t;
    }
    EXPECT_NEAR(row.quantities.total_energy, E0, 1e-10 * M * a * a) << "t " << t;
  }
  // Each wheel rolls from the start and never changes mode.
  for (const ContactEventRecord& event : run.contact_events) {
    EXPECT_EQ(event.t, 0.0) << event.what;
    EXPECT_EQ(event.what, "rolls on its rim");
  }
}

TEST(HeldWheels, ADiskOnAPendulumStrikingAWallReboundsWithEOfItsAngularSpeed) {
  const double r = 0.05, l = 0.5, m = 1.0;
  for (const double e : {0.3, 0.6, 1.0}) {
    const test::ScenarioRun run = test::run_inline_scenario(fmt::format(R"(tumble: 1
parameters: {{r: {}, l: {}, m: {}, rest: {}, a: 60 deg}}
gravity: [0, 0, -{}]
bodies:
  bob:
    shape: disk
    radius: r
    mass: m
    position: [-l*sin(a), 0, l - l*cos(a)]
    orientation: {{axis: [1, 0, 0], angle: 90 deg}}   # in the hinge's plane (x-z)
joints:
  pivot: {{type: hinge, body: bob, at: [0, 0, l], axis: [0, 1, 0]}}
contacts:
  - {{name: wall, type: plane, body: bob, plane: {{point: [r, 0, 0], normal: [-1, 0, 0]}},
     friction: 0, restitution: rest}}
simulate: {{duration: 0.7, integrator: dop853, rtol: 1e-11, atol: 1e-13, output_every: 0.002}}
)",
                                                                        r, l, m, e, test::kG),
                                                            "disk_pendulum");
    ASSERT_GE(run.contact_events.size(), 1u);
    EXPECT_EQ(run.contact_events[0].what.rfind("impact on its rim", 0), 0u)
        << run.contact_events[0].what;
    const double t_strike = run.contact_events[0].t;
    const double E0 = run.rows.front().quantities.total_energy;  // PE 0 at the bottom
    const double E_scale = m * test::kG * l;
    for (const test::Row& row : run.rows) {
      const BodyState& bob = row.states[0];
      EXPECT_LE(bob.r_G.x(), 1e-12) << "the rim is through the wall at t " << row.t;
      if (row.t < t_strike) {
        EXPECT_NEAR(row.quantities.total_energy, E0, 1e-9 * E_scale) << "e " << e;
      } else if (row.t > t_strike && row.t < t_strike + 0.2) {
        EXPECT_NEAR(row.quantities.total_energy, e * e * E0, 1e-9 * E_scale) << "e " << e;
        EXPECT_LT(bob.v_G.x(), 0.0) << "e " << e;
      }
    }
  }
}

}  // namespace
}  // namespace tumble
