// The universal (Hooke) joint against closed forms: a box with unequal moments hung below it by l,
// its first axis (x) fixed in ground and its second (y) in the box, swings at
// sqrt(M g l / I_1,O) and sqrt(M g l / I_2,O) about the two (I about the joint, `tumble modes`);
// in a large swing its energy is conserved to the tolerance while the joint holds: ground's first
// axis and the box's second stay at right angles and the joint point stays put, at every row to
// round-off; the same joint stated from the box's side moves the box the same way.
#include <gtest/gtest.h>

#include <algorithm>
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

struct Box {
  static constexpr double m = 3, a = 0.2, b = 0.5, c = 0.3, l = 0.6;
  // About the joint: x and y through O, the COM l below it.
  static constexpr double I_1O = m * (b * b + c * c) / 12 + m * l * l;
  static constexpr double I_2O = m * (a * a + c * c) / 12 + m * l * l;
};

// `bodies` and `axes` state the joint: [ground, box] with (x, y), or [box, ground] with (y, x).
std::string hung_box(double w1, double w2, const std::string& bodies, const std::string& axes) {
  return fmt::format(R"(tumble: 1
parameters: {{l: {l}, w1: {w1}, w2: {w2}}}
gravity: [0, 0, -{g}]
bodies:
  box:
    shape: box
    size: [{a}, {b}, {c}]
    mass: {m}
    position: [0, 0, -l]
    angular_velocity: [w1, w2, 0]
    velocity: [-w2*l, w1*l, 0]
joints:
  cross: {{type: universal, bodies: {bodies}, at: [0, 0, 0], axes: {axes}}}
simulate: {{duration: 5, integrator: dop853, rtol: 1e-10, atol: 1e-12, output_every: 0.01}}
)",
                     fmt::arg("l", Box::l), fmt::arg("w1", w1), fmt::arg("w2", w2),
                     fmt::arg("g", kG), fmt::arg("a", Box::a), fmt::arg("b", Box::b),
                     fmt::arg("c", Box::c), fmt::arg("m", Box::m), fmt::arg("bodies", bodies),
                     fmt::arg("axes", axes));
}

const std::string kFromGround = "[ground, box]";
const std::string kAxesFromGround = "[[1, 0, 0], [0, 1, 0]]";

TEST(UniversalJoint, ABoxHungOnItSwingsAboutEachAxisAtItsOwnFrequency) {
  const ScenarioModes modes = modes_of_scenario(
      test::load_inline_scenario(hung_box(0, 0, kFromGround, kAxesFromGround), "hung_box"));
  ASSERT_EQ(modes.linearisation.coordinates.size(), 4U);
  EXPECT_EQ(modes.linearisation.coordinates[0].name, "cross.angle1");
  EXPECT_EQ(modes.linearisation.coordinates[1].name, "cross.angle2");
  test::expect_oscillating_at(
      modes.analysis,
      {std::sqrt(Box::m * kG * Box::l / Box::I_1O), std::sqrt(Box::m * kG * Box::l / Box::I_2O)},
      1e-12);
  // Each mode turns about one axis only: the slower about x (the larger I_O), by angle1.
  const Mode& slow = *std::min_element(
      modes.analysis.modes.begin(), modes.analysis.modes.end(),
      [](const Mode& p, const Mode& q) { return p.natural_frequency < q.natural_frequency; });
  EXPECT_NEAR(std::abs(slow.shape(1)), 0.0, 1e-12);
  EXPECT_EQ(modes.analysis.verdict, ModalAnalysis::Verdict::Stable);
}

TEST(UniversalJoint, ALargeSwingKeepsItsEnergyAndTheCrossHoldsItsAxesSquare) {
  const test::ScenarioRun run =
      run_inline_scenario(hung_box(2.0, 1.5, kFromGround, kAxesFromGround), "large_swing");
  ASSERT_EQ(run.rows.size(), 501U);
  // Energy to the tolerance: rtol 1e-10 a step, over the run's few hundred steps.
  EXPECT_LT(run.result.conservation.scaled_energy_drift(), 1e-8);
  double largest_turn = 0.0;
  for (const Row& row : run.rows) {
    const BodyState& s = row.states[0];
    // Ground's first axis (x) and the box's second (its y) at right angles, and the joint point
    // (l above the COM in the box's axes) at the origin.
    EXPECT_NEAR(Vec3::UnitX().dot(s.R_WB.col(1)), 0.0, 1e-12) << "t " << row.t;
    EXPECT_NEAR((s.r_G + s.R_WB * Vec3(0, 0, Box::l)).norm(), 0.0, 1e-12) << "t " << row.t;
    largest_turn = std::max(largest_turn, std::abs(row.extras.coordinates[0].values[0]));
    // The columns are the angles' own: angle1 turns the box about x, so its y axis lies in the
    // plane across x at angle1 from y (while angle2 turns it about that y).
    const double angle1 = row.extras.coordinates[0].values[0];
    EXPECT_NEAR(s.R_WB.col(1).dot(Vec3(0, std::cos(angle1), std::sin(angle1))), 1.0, 1e-12);
  }
  EXPECT_GT(largest_turn, 0.5);  // a large swing
}

TEST(UniversalJoint, TheJointStatedFromTheBoxsSideMovesItTheSameWay) {
  const test::ScenarioRun from_ground =
      run_inline_scenario(hung_box(2.0, 1.5, kFromGround, kAxesFromGround), "from_ground");
  const test::ScenarioRun from_box = run_inline_scenario(
      hung_box(2.0, 1.5, "[box, ground]", "[[0, 1, 0], [1, 0, 0]]"), "from_box");
  ASSERT_EQ(from_ground.rows.size(), from_box.rows.size());
  for (std::size_t i = 0; i < from_ground.rows.size(); ++i) {
    const BodyState& p = from_ground.rows[i].states[0];
    const BodyState& q = from_box.rows[i].states[0];
    // Each run to rtol 1e-10: the two agree to a few times that.
    EXPECT_NEAR((p.r_G - q.r_G).norm(), 0.0, 1e-8) << "t " << from_ground.rows[i].t;
    EXPECT_NEAR((p.omega_W - q.omega_W).norm(), 0.0, 1e-7) << "t " << from_ground.rows[i].t;
    // Stated the other way, the first angle is the turn about the box's y.
    EXPECT_NEAR(from_box.rows[i].extras.coordinates[0].values[0],
                -from_ground.rows[i].extras.coordinates[0].values[2], 1e-7);
  }
}

// Without gravity, a torque T about the second axis turns the box about it alone, from rest:
// I_2,O theta_2'' = T (theta_1 stays 0: with theta_1' = 0 nothing drives it), and the motor's
// work T theta_2 is the kinetic energy.
TEST(UniversalJoint, ATorqueAboutTheSecondAxisTurnsTheBoxAboutItAlone) {
  constexpr double T = 0.7;
  std::string yaml = hung_box(0, 0, kFromGround, kAxesFromGround);
  const auto change = [&yaml](const std::string& from, const std::string& to) {
    yaml.replace(yaml.find(from), from.size(), to);
  };
  change("gravity: [0, 0, -9.81]", "gravity: [0, 0, 0]");
  change("axes: [[1, 0, 0], [0, 1, 0]]}",
         fmt::format("axes: [[1, 0, 0], [0, 1, 0]], motor: {{torque2: {}}}}}", T));
  const test::ScenarioRun run = run_inline_scenario(yaml, "driven_box");
  ASSERT_EQ(run.rows.size(), 501U);
  for (const Row& row : run.rows) {
    const double t = row.t;
    const double angle2 = T * t * t / (2 * Box::I_2O);
    const auto& q = row.extras.coordinates[0].values;  // angle1, rate1, angle2, rate2
    EXPECT_NEAR(q[0], 0.0, 1e-12) << "t " << t;
    EXPECT_NEAR(q[2], angle2, 1e-10 * std::max(1.0, angle2)) << "t " << t;
    EXPECT_NEAR(q[3], T * t / Box::I_2O, 1e-10 * std::max(1.0, q[3])) << "t " << t;
    // The motor's work (the ledger's last entry) is the kinetic energy it gave.
    const double work = row.extras.elements.back().work;
    EXPECT_NEAR(work, T * q[2], 1e-10 * std::max(1.0, work)) << "t " << t;
    EXPECT_NEAR(row.quantities.kinetic_energy, work, 1e-10 * std::max(1.0, work)) << "t " << t;
  }
}

TEST(UniversalJoint, AxesNotAtRightAnglesAreRefusedWhereTheyAre) {
  test::expect_error(hung_box(0, 0, kFromGround, "[[1, 0, 0], [0.1, 1, 0]]"), 13, 72,
                     "joints.cross.axes", "at right angles");
}

}  // namespace
}  // namespace tumble
