// Joints and force elements in the scenario: what the reader and the preparation refuse, each
// with the file, line, column and key (the contract's error format), and the trajectory's joint
// and element columns.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "run_tumble.hpp"
#include "scenario_run.hpp"

namespace tumble {
namespace {

const std::string kBat =
    "tumble: 1\n"                                                                              // 1
    "bodies:\n"                                                                                // 2
    "  bat: {shape: cylinder, radius: 0.03, length: 0.8, mass: 1, position: [0, 0, -0.5]}\n";  // 3
const std::string kSimulateTenthSecond = "simulate: {duration: 0.1}\n";

using test::expect_error;

TEST(JointScenario, AJointNamesKnownBodiesAndATypeItHas) {
  expect_error(
      kBat + "joints:\n  knob: {type: hing, body: bat, at: [0, 0, 0]}\n" + kSimulateTenthSecond, 5,
      16, "joints.knob.type", "unknown joint type 'hing'; did you mean 'hinge'?");
  expect_error(
      kBat + "joints:\n  knob: {type: ball, body: bta, at: [0, 0, 0]}\n" + kSimulateTenthSecond, 5,
      28, "joints.knob.body", "no body 'bta' in bodies (the bodies are bat)");
  expect_error(kBat + "joints:\n  knob: {type: ball, body: bat, at: [0, 0, 0], axis: [0, 1, 0]}\n" +
                   kSimulateTenthSecond,
               5, 48, "joints.knob.axis",
               "only a hinge, a prismatic or a cylindrical joint has axis (this joint is a ball)");
  expect_error(kBat +
                   "joints:\n  knob: {type: hinge, body: bat, at: [0, 0, 0], axis: [0, 0, 0]}\n" +
                   kSimulateTenthSecond,
               5, 55, "joints.knob.axis", "the axis must not be zero");
}

TEST(JointScenario, TheJointListedAfterTheOthersThatJoinItsBodiesClosesALoop) {
  const Scenario scenario = test::load_inline_scenario(
      kBat +
          "joints:\n  knob: {type: ball, body: bat, at: [0, 0, 0]}\n"
          "  again: {type: hinge, bodies: [bat, ground], at: [0, 0, -1], axis: [1, 0, 0]}\n" +
          kSimulateTenthSecond,
      "loop");
  ASSERT_EQ(scenario.joints.size(), 2U);
  EXPECT_FALSE(scenario.joints[0].closes_loop);
  EXPECT_TRUE(scenario.joints[1].closes_loop);
}

TEST(JointScenario, ALockActsAfterTheStart) {
  expect_error(kBat +
                   "joints:\n  knob: {type: hinge, body: bat, at: [0, 0, 0], axis: [0, 1, 0], "
                   "lock: {at: 0}}\n" +
                   kSimulateTenthSecond,
               5, 77, "joints.knob.lock.at", "a joint rigid from the start is a fixed joint");
}

TEST(JointScenario, GivenVelocitiesMustBeOnesTheJointsAllow) {
  // A hinge about y lets the bat turn about y only.
  expect_error(
      "tumble: 1\nbodies:\n"
      "  bat: {shape: cylinder, radius: 0.03, length: 0.8, mass: 1, position: [0, 0, -0.5],\n"
      "        angular_velocity: [1, 2, 0]}\n"
      "joints:\n  knob: {type: hinge, body: bat, at: [0, 0, 0], axis: [0, 1, 0]}\n" +
          kSimulateTenthSecond,
      4, 27, "bodies.bat.angular_velocity", "they give [0, 2, 0]");
  // Turning at 2 rad/s about the knob moves the COM at 1 m/s along -x, not +x.
  expect_error(
      "tumble: 1\nbodies:\n"
      "  bat: {shape: cylinder, radius: 0.03, length: 0.8, mass: 1, position: [0, 0, -0.5],\n"
      "        angular_velocity: [0, 2, 0], velocity: [1, 0, 0]}\n"
      "joints:\n  knob: {type: hinge, body: bat, at: [0, 0, 0], axis: [0, 1, 0]}\n" +
          kSimulateTenthSecond,
      4, 48, "bodies.bat.velocity", "they give [-1, 0, 0]");
}

TEST(JointScenario, ASpeedMotorRunningFromTheStartFixesTheInitialRate) {
  expect_error(kBat +
                   "joints:\n  knob: {type: hinge, body: bat, at: [0, 0, 0], axis: [0, 1, 0], "
                   "motor: {speed: 3}}\n" +
                   kSimulateTenthSecond,
               5, 66, "joints.knob.motor", "the motor drives the hinge at 3 rad/s from the start");
}

TEST(JointScenario, TheTextbookFormulationIsForFreeBodies) {
  expect_error(kBat + "joints:\n  knob: {type: ball, body: bat, at: [0, 0, 0]}\n" +
                   "simulate: {duration: 1, formulation: textbook}\n",
               6, 38, "simulate.formulation", "the textbook formulation integrates free bodies");
}

TEST(JointScenario, ForceElementsNameTheirBodiesAndNonNegativeConstants) {
  expect_error(kBat +
                   "forces:\n  - {type: spring, bodies: [ground, bat], at: [[0, 0, 1]], "
                   "stiffness: 10}\n" +
                   kSimulateTenthSecond,
               5, 47, "forces[0].at", "give two points, one on each body; got 1");
  expect_error(kBat +
                   "forces:\n  - {type: torsional_spring, bodies: [ground, bat], "
                   "stiffness: -1}\n" +
                   kSimulateTenthSecond,
               5, 64, "forces[0].stiffness", "stiffness must be >= 0");
  expect_error(kBat + "forces:\n  - {type: torsional_spring, body: bat, stiffness: 1}\n" +
                   kSimulateTenthSecond,
               5, 30, "forces[0].body", "joins two bodies: bodies: [a, b]");
  expect_error(kBat + "forces:\n  - {type: impulse, body: bat, value: [1, 0, 0], time: 0}\n" +
                   kSimulateTenthSecond,
               5, 56, "forces[0].time", "an impulse acts after the start");
}

TEST(JointScenario, TheTrajectoryHasReactionAndWorkColumns) {
  const std::string dir =
      (std::filesystem::temp_directory_path() / "tumble_joint_cli_columns").string();
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/bat.yaml";
  std::ofstream(path) << kBat
                      << "joints:\n  knob: {type: hinge, body: bat, at: [0, 0, 0], axis: [0, 1, "
                         "0]}\n"
                         "forces:\n  - {type: impulse, name: hit, body: bat, at: [0, 0, -0.6], "
                         "value: [1, 0, 0], time: 0.05}\n"
                      << kSimulateTenthSecond;
  const auto result = test::run_tumble("run " + test::quote_for_shell(path) + " --out " +
                                       test::quote_for_shell(dir));
  ASSERT_EQ(result.status, 0) << result.out;
  EXPECT_NE(result.out.find("impulse hit: KE 0 -> "), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("reaction impulse at knob"), std::string::npos) << result.out;
  std::ifstream csv(dir + "/bat.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_NE(header.find(",Lz,knob.Fx,knob.Fy,knob.Fz,knob.Mx,knob.My,knob.Mz,hit.P,hit.W"),
            std::string::npos)
      << header;
}

// Values each finite whose products overflow would fail at the first step with NaN rows: they
// are refused when the run is prepared, at the body.
TEST(PreparedRun, InitialValuesThatOverflowAreRefusedAtTheBody) {
  test::expect_error(R"(tumble: 1
bodies:
  ball: {shape: sphere, radius: 0.1, mass: 1e-300}
simulate: {duration: 1}
)",
                     3, 3, "bodies.ball", "an inertia that double precision cannot invert");
  test::expect_error(R"(tumble: 1
bodies:
  ball: {shape: sphere, radius: 0.1, mass: 1, angular_velocity: [0, 0, 1e308]}
simulate: {duration: 1}
)",
                     3, 65, "bodies.ball.angular_velocity",
                     "its kinetic energy or momentum overflows double precision");
  test::expect_error(R"(tumble: 1
bodies:
  ball: {shape: sphere, radius: 0.1, mass: 1, velocity: [1e160, 0, 0]}
simulate: {duration: 1}
)",
                     3, 57, "bodies.ball.velocity", "overflows double precision");
}

}  // namespace
}  // namespace tumble
