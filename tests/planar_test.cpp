// Planar statements (planar: true): the chapter's planar examples written in the x-y plane as
// the chapter draws them (examples/planar/) (y up, turning about z: points [x, y], angles and rates
// as numbers) against their 3D statements in examples/, which move in the x-z plane with gravity
// along -z and turn about y. The same problem: each body's COM (x, y) is the 3D one's (x, z), its
// rate about z is minus its 3D rate about y (z out of the x-y plane is -y of the x-z plane), and E
// is the same, row for row. The two runs are integrations of one motion in other coordinates, each
// within its tolerance of it: they agree to a thousand times the examples' rtol.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "scenario_run.hpp"

namespace tumble {
namespace {

struct PlanarCase {
  const char* example;  // examples/NAME.yaml and its planar statement examples/planar/NAME.yaml
  double rtol;          // the example's
};

void expect_same_motion(const PlanarCase& c) {
  const test::ScenarioRun planar = test::run_scenario(load_scenario(
      std::string(TUMBLE_SOURCE_DIR) + "/examples/planar/" + c.example + ".yaml", {}));
  const test::ScenarioRun spatial = test::run_scenario(
      load_scenario(std::string(TUMBLE_SOURCE_DIR) + "/examples/" + c.example + ".yaml", {}));
  ASSERT_EQ(planar.rows.size(), spatial.rows.size()) << c.example;
  const double tol = 1e3 * c.rtol;
  double length = 0.0, rate = 0.0, energy = 0.0;  // the scales the errors are measured against
  for (const test::Row& row : spatial.rows) {
    for (const BodyState& s : row.states) {
      length = std::max(length, s.r_G.norm());
      rate = std::max(rate, s.omega_W.norm());
    }
    energy = std::max(
        {energy, std::abs(row.quantities.kinetic_energy), std::abs(row.quantities.total_energy)});
  }
  for (std::size_t i = 0; i < planar.rows.size(); ++i) {
    const test::Row& p = planar.rows[i];
    const test::Row& s = spatial.rows[i];
    ASSERT_EQ(p.t, s.t);
    for (std::size_t b = 0; b < p.states.size(); ++b) {
      const BodyState& q = p.states[b];
      const BodyState& r = s.states[b];
      EXPECT_NEAR(q.r_G.x(), r.r_G.x(), tol * length) << c.example << " body " << b << " t " << p.t;
      EXPECT_NEAR(q.r_G.y(), r.r_G.z(), tol * length) << c.example << " body " << b << " t " << p.t;
      // Off the plane only by round-off (the contacts' and joints' solves mix the components).
      EXPECT_NEAR(q.r_G.z(), 0.0, 1e-12 * length);
      EXPECT_NEAR(q.omega_W.z(), -r.omega_W.y(), tol * rate) << c.example << " body " << b;
      EXPECT_NEAR(q.omega_W.x(), 0.0, 1e-12 * rate);
      EXPECT_NEAR(q.omega_W.y(), 0.0, 1e-12 * rate);
    }
    EXPECT_NEAR(p.quantities.total_energy, s.quantities.total_energy, tol * energy) << c.example;
  }
}

TEST(PlanarScenario, TheRampRaceIsItsSpatialStatement) {
  expect_same_motion({"ramp_race", 1e-10});
}

// The cylinder on a ramp too steep for its friction (mu below the critical (1/3) tan(theta)).
TEST(PlanarScenario, TheCylinderBelowItsCriticalFrictionIsItsSpatialStatement) {
  expect_same_motion({"ramp_too_steep", 1e-10});
}

// The mast and the bat are cylinders standing in the plane: in a planar statement a rod along x
// turned a quarter turn, with the cylinder's moments (a planar cylinder's axis is z: a wheel).
TEST(PlanarScenario, TheInvertedMastIsItsSpatialStatement) {
  expect_same_motion({"inverted_mast", 1e-8});
}

TEST(PlanarScenario, TheStruckBatIsItsSpatialStatement) {
  expect_same_motion({"bat_struck", 1e-8});
}

// The backspin disk: a wheel of the plane, thrown along +x; backspin turns it counter-clockwise.
TEST(PlanarScenario, TheBackspinDiskIsItsSpatialStatement) {
  expect_same_motion({"backspin_disk", 1e-10});
}

TEST(PlanarScenario, TheCubliIsItsSpatialStatement) {
  expect_same_motion({"cubli", 1e-8});
}

// A closed loop: B, the last hinge, is a constraint on the tree in both statements.
TEST(PlanarScenario, TheFourBarIsItsSpatialStatement) {
  expect_same_motion({"four_bar", 1e-10});
}

// The angle column runs on past each turn: the backspin disk, thrown at v0 with w0 = 60 rad/s
// counter-clockwise, turns by w0 t - mu g t^2 / R while it slides (friction mu M g at its rim
// slows the spin by 2 mu g / R) and so nearly ten turns before its slip stops at
// t_roll = (v0 + w0 R) / (3 mu g); then it rolls, x + R angle constant. At rtol 1e-10 the
// angle, some 60 rad, and the roll's onset, located to the integrator's precision, hold both to
// 1e-7.
TEST(PlanarScenario, TheAngleColumnCountsTheTurns) {
  const double R = 0.1, mu = 0.2, v0 = 2.0, w0 = 60.0, g = 9.81;
  const test::ScenarioRun run = test::run_inline_scenario(R"(tumble: 1
planar: true
parameters: {M: 0.2, R: 0.1, mu: 0.2, v0: 2, w0: 60, g: 9.81}
gravity: [0, -g]
bodies:
  disk: {shape: disk, radius: R, mass: M, position: [0, R], velocity: [v0, 0], angular_velocity: w0}
contacts:
  - {name: floor, type: plane, body: disk, plane: {point: [0, 0], normal: [0, 1]}, friction: mu}
simulate: {duration: 2, integrator: dop853, rtol: 1e-10, atol: 1e-12, output_every: 0.01}
)",
                                                          "angle");
  const double t_roll = (v0 + w0 * R) / (3 * mu * g);
  const double x_roll = v0 * t_roll - 0.5 * mu * g * t_roll * t_roll;
  const double angle_roll = w0 * t_roll - mu * g * t_roll * t_roll / R;
  ASSERT_GT(angle_roll, 2 * M_PI * 5);
  for (const test::Row& row : run.rows) {
    ASSERT_EQ(row.extras.planar_angles.size(), 1u);
    const double angle = row.extras.planar_angles[0];
    if (row.t < t_roll) {
      EXPECT_NEAR(angle, w0 * row.t - mu * g * row.t * row.t / R, 1e-7) << row.t;
    } else {
      EXPECT_NEAR(row.states[0].r_G.x() + R * angle, x_roll + R * angle_roll, 1e-7) << row.t;
    }
    EXPECT_EQ(row.extras.planar_rates[0], row.states[0].omega_W.z());
  }
}

// The planar backspin disk's own event: its centre reverses at t_rev = v0 / (mu g), while it
// still slides (vx = v0 - mu g t). The located time is as good as the integrated vx, which the
// contact's solved forces and the state's projections hold to about rtol (1e-10): asserted to
// ten times that.
TEST(PlanarScenario, TheBackspinDiskReversesWhenItsEventSays) {
  const test::ScenarioRun run = test::run_scenario(
      load_scenario(std::string(TUMBLE_SOURCE_DIR) + "/examples/planar/backspin_disk.yaml", {}));
  const double t_rev = 2.0 / (0.2 * 9.81);
  ASSERT_EQ(run.result.user_events.size(), 1u);
  EXPECT_EQ(run.result.user_events[0].name, "reverses");
  EXPECT_NEAR(run.result.user_events[0].t, t_rev, 1e-9 * t_rev);
}

// A planar statement says so where it is wrong: a point in 3D, a 3D spin, an orientation, a
// ball joint, a hinge's axis.
TEST(PlanarScenario, ThreeDimensionalKeysAreRefusedWhereWritten) {
  const std::string head =
      "tumble: 1\nplanar: true\nbodies:\n  b: {shape: sphere, radius: 1, "
      "mass: 1, ";
  const std::string tail = "}\nsimulate: {duration: 1}\n";
  test::expect_error(head + "position: [0, 1, 2]" + tail, 4, 52, "bodies.b.position",
                     "expected a list of 2 numbers [x, y] (the scenario is planar");
  test::expect_error(head + "angular_velocity: [0, 0, 1]" + tail, 4, 60,
                     "bodies.b.angular_velocity", "expected one number (the scenario is planar");
  test::expect_error(head + "orientation: identity" + tail, 4, 42, "bodies.b.orientation",
                     "give `angle:`");
  test::expect_error(
      head + "position: [1, 0]}\njoints:\n  j: {type: ball, body: b, at: [0, 0]" + tail, 6, 6,
      "joints.j", "a ball joint would let the bodies leave the plane");
  test::expect_error(head +
                         "position: [1, 0]}\njoints:\n  j: {type: hinge, body: b, at: [0, 0], "
                         "axis: [0, 0, 1]" +
                         tail,
                     6, 41, "joints.j.axis", "leave `axis:` out");
  test::expect_error(
      "tumble: 1\nbodies:\n  b: {shape: sphere, radius: 1, mass: 1, angle: 1}\n"
      "simulate: {duration: 1}\n",
      3, 42, "bodies.b.angle", "planar scenario's");
}

}  // namespace
}  // namespace tumble
