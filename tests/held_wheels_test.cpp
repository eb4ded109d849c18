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
//
// And examples/edge_mill.yaml: a millstone on a bearing at the end of an axle that a ball joint
// holds at the height of the stone's centre, rolling round the pivot. Steady at any turning rate
// Omega: the stone spins about the axle at -Omega d / R, and the moment of momentum about the
// pivot along the axle, I_a ws, turns with it; its rate Omega I_a ws across the axle is what the
// weights' moments and the ground's N d leave, so that
//     N = (m + m_a / 2) g + I_a Omega^2 / R,   I_a = m R^2 / 2,
// with no friction (none is needed: the ball joint takes the centripetal force, and of the
// forces the redundant rows leave open the solve takes those with the least friction).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "scenario_run.hpp"
#include "test_files.hpp"
#include "tumble/modes/scenario_modes.hpp"

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

TEST(HeldWheels, AnEdgeMillsGroundPushesWithTheWeightsShareAndTheGyroscopicTerm) {
  const double R = 0.5, m = 10.0, d = 1.0, m_axle = 2.0, g = 9.81, I_a = m * R * R / 2;
  for (const double Omega : {2.0, 5.0}) {
    const test::ScenarioRun run = test::run_scenario(
        load_scenario(test::example("edge_mill.yaml"), {{"Omega", std::to_string(Omega)}}));
    const double N = (m + m_axle / 2) * g + I_a * Omega * Omega / R;
    const double spin = -Omega * d / R;
    ASSERT_GT(run.rows.back().t, 10 * 2 * std::numbers::pi / Omega - 0.01);  // ten circuits
    for (const test::Row& row : run.rows) {
      const ContactOutput& ground = row.extras.contacts[0];
      ASSERT_EQ(ground.mode, 2) << row.t;
      // The run's tolerance (rtol 1e-12) on forces of ~100 N and speeds of ~Omega d: 1e-9.
      EXPECT_NEAR(ground.normal_force, N, 1e-9 * N) << "Omega " << Omega << ", t " << row.t;
      EXPECT_LT(ground.friction_W.norm(), 1e-9 * N) << "Omega " << Omega << ", t " << row.t;
      // Steady: the stone's centre d from the pivot at its height, turning at Omega about the
      // vertical, spinning at -Omega d / R about the axle.
      const BodyState& stone = row.states[1];
      const Vec3 from_pivot = stone.r_G - Vec3(0.0, 0.0, R);
      EXPECT_NEAR(from_pivot.z(), 0.0, 1e-9 * d) << row.t;
      EXPECT_NEAR(from_pivot.norm(), d, 1e-9 * d) << row.t;
      EXPECT_NEAR(stone.omega_W.z(), Omega, 1e-9 * Omega) << row.t;
      EXPECT_NEAR(stone.omega_W.dot(from_pivot / d), spin, 1e-9 * Omega) << row.t;
    }
  }
}

// `tumble modes` takes the edge mill at any turning rate as the steady motion it is: its
// contact's rows repeat, along the axle, what the ball joint holds, and the linearisation holds
// the independent ones (docs/modes.md); the ground's force it reports (the rows' least-norm
// forces: no friction) is the closed form's N, and the steadiness leaves no rate above round-off.
TEST(HeldWheels, AnEdgeMillIsASteadyMotionForModesAtAnyTurningRate) {
  const double R = 0.5, m = 10.0, m_axle = 2.0, g = 9.81, I_a = m * R * R / 2;
  for (const double Omega : {0.5, 2.0, 5.0}) {
    const ScenarioModes modes = modes_of_scenario(
        load_scenario(test::example("edge_mill.yaml"), {{"Omega", std::to_string(Omega)}}));
    EXPECT_FALSE(modes.linearisation.equilibrium()) << Omega;
    EXPECT_LT(modes.linearisation.largest_rate, 1e-12 * Omega) << Omega;
    const std::vector<Vec3> forces = modes.equations->contact_forces();
    ASSERT_EQ(forces.size(), 1u);
    const double N = (m + m_axle / 2) * g + I_a * Omega * Omega / R;
    EXPECT_NEAR(forces[0].z(), N, 1e-12 * N) << Omega;
    EXPECT_LT(forces[0].head<2>().norm(), 1e-12 * N) << Omega;
    // No mode grows: rolling at another rate is another steady motion (a neutral family), and
    // the stone's angle on its bearing is a symmetry (the stone is round), not a coordinate
    // that nothing restores: stable, not marginal.
    EXPECT_EQ(modes.analysis.verdict, ModalAnalysis::Verdict::Stable)
        << Omega << ": " << modes.analysis.verdict_text;
  }
}

}  // namespace
}  // namespace tumble
