// The cylindrical joint (turns about and slides along one axis) against closed forms: a body on it
// under a constant force along the axis and a constant torque about it slides and turns
// independently, x = F t^2 / (2 m) and theta = T t^2 / (2 I), its joint passing no force along
// the axis and no moment about it; a pendulum on it, swinging about a horizontal axis and sliding
// along it on a spring, has the two frequencies sqrt(M g l / I_O) and sqrt(k / M) (`tumble
// modes`); a lock stops both freedoms, its work the kinetic energy lost.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "modes_checks.hpp"
#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "tumble/modes/scenario_modes.hpp"

namespace tumble {
namespace {

using test::Row;
using test::run_inline_scenario;

using test::kG;

// A 2 kg box on a horizontal shaft along x through its COM, pushed along the shaft by F and
// turned about it by T from rest; gravity across the shaft.
struct Shaft {
  static constexpr double m = 2, a = 0.5, b = 0.2, c = 0.3, F = 3, T = 0.5;
  static constexpr double I_x = m * (b * b + c * c) / 12;  // about the shaft, kg m^2
};

std::string shaft_scenario(const std::string& extra = "") {
  return fmt::format(R"(tumble: 1
gravity: [0, 0, -{g}]
bodies:
  box: {{shape: box, size: [{a}, {b}, {c}], mass: {m}, position: [0, 0, 0]}}
joints:
  shaft: {{type: cylindrical, body: box, at: [0, 0, 0], axis: [1, 0, 0]{extra}}}
forces:
  - {{type: force, name: push, body: box, value: [{F}, 0, 0]}}
  - {{type: torque, name: twist, body: box, value: [{T}, 0, 0]}}
simulate: {{duration: 2, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: 0.05}}
)",
                     fmt::arg("g", kG), fmt::arg("a", Shaft::a), fmt::arg("b", Shaft::b),
                     fmt::arg("c", Shaft::c), fmt::arg("m", Shaft::m), fmt::arg("F", Shaft::F),
                     fmt::arg("T", Shaft::T), fmt::arg("extra", extra));
}

TEST(CylindricalJoint, AForceAlongAndATorqueAboutItSlideAndTurnItApart) {
  const test::ScenarioRun run = run_inline_scenario(shaft_scenario(), "shaft");
  ASSERT_GT(run.rows.size(), 40U);
  for (const Row& row : run.rows) {
    const double t = row.t;
    const double travel = Shaft::F * t * t / (2 * Shaft::m);
    const double angle = Shaft::T * t * t / (2 * Shaft::I_x);
    const auto& q = row.extras.coordinates[0].values;  // angle, rate, travel, speed
    EXPECT_NEAR(q[0], angle, 1e-12 * std::max(1.0, angle)) << "t " << t;
    EXPECT_NEAR(q[1], Shaft::T * t / Shaft::I_x, 1e-12 * std::max(1.0, q[1])) << "t " << t;
    EXPECT_NEAR(q[2], travel, 1e-12 * std::max(1.0, travel)) << "t " << t;
    EXPECT_NEAR(q[3], Shaft::F * t / Shaft::m, 1e-12) << "t " << t;
    // The body's state says the same: its COM along the shaft, turned about it.
    const BodyState& s = row.states[0];
    EXPECT_NEAR(s.r_G.x(), travel, 1e-12 * std::max(1.0, travel));
    EXPECT_NEAR(s.omega_W.x(), Shaft::T * t / Shaft::I_x, 1e-12 * std::max(1.0, q[1]));
    // The shaft passes no force along itself and no moment about itself; it carries the weight.
    const JointReaction& reaction = row.extras.joints[0];
    const double weight = Shaft::m * kG;
    EXPECT_NEAR(reaction.F_W.x(), 0.0, 1e-12 * weight);
    EXPECT_NEAR(reaction.M_J_W.x(), 0.0, 1e-12 * weight);
    EXPECT_NEAR((reaction.F_W - Vec3(0, 0, weight)).norm(), 0.0, 1e-12 * weight);
  }
}

TEST(CylindricalJoint, ALockStopsBothFreedomsAndItsWorkIsTheKineticEnergyLost) {
  const test::ScenarioRun run =
      run_inline_scenario(shaft_scenario(", lock: {at: 1}"), "locked_shaft");
  const Row* before = nullptr;
  for (const Row& row : run.rows) {
    if (row.t < 1.0) before = &row;
    if (row.t <= 1.0) continue;
    // Locked: the box keeps its place on the shaft and its turn, whatever pushes it.
    EXPECT_NEAR(row.extras.coordinates[0].values[1], 0.0, 1e-12);
    EXPECT_NEAR(row.extras.coordinates[0].values[3], 0.0, 1e-12);
    EXPECT_NEAR(row.extras.coordinates[0].values[2], Shaft::F / (2 * Shaft::m), 1e-12);
  }
  ASSERT_NE(before, nullptr);
  ASSERT_EQ(run.jumps.size(), 1U);
  const JumpRecord& lock = run.jumps[0];
  EXPECT_EQ(lock.t, 1.0);
  // The kinetic energy at the lock: (m v^2 + I w^2) / 2 with v = F t / m, w = T t / I at t = 1.
  const double v = Shaft::F / Shaft::m, w = Shaft::T / Shaft::I_x;
  const double ke = 0.5 * (Shaft::m * v * v + Shaft::I_x * w * w);
  EXPECT_NEAR(lock.kinetic_energy_before, ke, 1e-12 * ke);
  EXPECT_NEAR(lock.kinetic_energy_after, 0.0, 1e-12 * ke);
  // The lock's work (the last ledger entry) is the kinetic energy it took.
  const ElementWork& lock_work = run.rows.back().extras.elements.back();
  EXPECT_NEAR(lock_work.work, -ke, 1e-12 * ke);
}

// A sphere of radius r on a rod of length l below a horizontal shaft along x: it swings about
// the shaft, and slides along it on a spring of stiffness k from a ground point on the shaft to
// the joint point. The two motions are apart: sqrt(M g l / I_O) and sqrt(k / M).
TEST(CylindricalJoint, APendulumSlidingOnASpringHasItsTwoFrequencies) {
  constexpr double M = 1.5, r = 0.1, l = 0.8, k = 40;
  const std::string yaml = fmt::format(R"(tumble: 1
gravity: [0, 0, -{g}]
bodies:
  bob: {{shape: sphere, radius: {r}, mass: {M}, position: [0, 0, -{l}]}}
joints:
  shaft: {{type: cylindrical, body: bob, at: [0, 0, 0], axis: [1, 0, 0]}}
forces:
  - {{type: spring, name: spring, bodies: [ground, bob], at: [[-1, 0, 0], [0, 0, 0]],
     stiffness: {k}}}
simulate: {{duration: 1}}
)",
                                       fmt::arg("g", kG), fmt::arg("r", r), fmt::arg("M", M),
                                       fmt::arg("l", l), fmt::arg("k", k));
  const ScenarioModes modes =
      modes_of_scenario(test::load_inline_scenario(yaml, "sliding_pendulum"));
  ASSERT_EQ(modes.linearisation.coordinates.size(), 4U);
  EXPECT_EQ(modes.linearisation.coordinates[0].name, "shaft.angle");
  EXPECT_EQ(modes.linearisation.coordinates[1].name, "shaft.travel");
  EXPECT_EQ(modes.linearisation.coordinates[2].name, "shaft.rate");
  EXPECT_EQ(modes.linearisation.coordinates[3].name, "shaft.speed");
  const double I_O = 2.0 / 5.0 * M * r * r + M * l * l;
  test::expect_oscillating_at(modes.analysis, {std::sqrt(M * kG * l / I_O), std::sqrt(k / M)},
                              1e-12);
  EXPECT_EQ(modes.analysis.verdict, ModalAnalysis::Verdict::Stable);
}

TEST(CylindricalJoint, ASpeedMotorIsRefusedWhereItsKeyIs) {
  test::expect_error(
      R"(tumble: 1
bodies:
  box: {shape: box, size: [1, 1, 1], mass: 1}
joints:
  shaft: {type: cylindrical, body: box, at: [0, 0, 0], axis: [1, 0, 0], motor: {speed: 1}}
simulate: {duration: 1}
)",
      5, 81, "joints.shaft.motor.speed", "a speed is prescribed on a hinge or a slider");
}

}  // namespace
}  // namespace tumble
