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
// (A disk as a pendulum's bob striking a wall: contact_joint_test.cpp, with the sphere's.)
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scenario_run.hpp"
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

}  // namespace
}  // namespace tumble
