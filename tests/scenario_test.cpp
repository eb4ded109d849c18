// The scenario reader against the contract (scenario-v1): the prism example, expressions and
// parameters, --set, composite bodies by the parallel axis theorem, and one test per class of
// invalid input, each checking the message text and that FILE:LINE:COL points at the offending
// key or value.
#include "tumble/scenario/scenario.hpp"
#include "tumble/scenario/scenario_document.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "test_constants.hpp"
#include "tumble/integrators/tolerances.hpp"

namespace tumble {
namespace {

namespace fs = std::filesystem;

using test::kPi;

// A folder of its own for each test, so that the scenarios it writes do not collide.
fs::path test_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() / "tumble_scenario_test" /
                       (std::string(info->test_suite_name()) + "." + info->name());
  fs::create_directories(dir);
  return dir;
}

fs::path write_in_test_dir(const std::string& name, const std::string& text) {
  const fs::path path = test_dir() / name;
  std::ofstream(path) << text;
  return path;
}

Scenario load_text(const std::string& text, const std::vector<ParameterOverride>& overrides = {},
                   const std::string& name = "scenario.yaml") {
  return load_scenario(write_in_test_dir(name, text).string(), overrides);
}

struct Expected {
  int line;
  int column;
  std::string key;
  std::string message;  // a part of why()
};

// Loads the text, expecting a ScenarioError at the place and with the key and message given.
void expect_load_error(const std::string& text, const Expected& expected,
                       const std::vector<ParameterOverride>& overrides = {}) {
  const fs::path path = write_in_test_dir("invalid.yaml", text);
  try {
    load_scenario(path.string(), overrides);
    ADD_FAILURE() << "no error; expected one at " << expected.line << ":" << expected.column
                  << " about " << expected.key;
  } catch (const ScenarioError& error) {
    EXPECT_EQ(error.where().file, path.string());
    EXPECT_EQ(error.where().line, expected.line) << error.what();
    EXPECT_EQ(error.where().column, expected.column) << error.what();
    EXPECT_EQ(error.key(), expected.key) << error.what();
    EXPECT_NE(error.why().find(expected.message), std::string::npos)
        << "expected '" << expected.message << "' in\n"
        << error.what();
    const std::string prefix = path.string() + ":" + std::to_string(expected.line) + ":" +
                               std::to_string(expected.column) + ": " +
                               (expected.key.empty() ? "" : expected.key + ": ");
    EXPECT_EQ(std::string(error.what()).rfind(prefix, 0), 0u) << error.what();
  }
}

// A valid scenario's head: one sphere; tests append or replace lines after it.
const std::string kHead = "tumble: 1\n";
const std::string kSphere = "bodies:\n  ball: {shape: sphere, radius: 0.1, mass: 2}\n";
const std::string kSimulate = "simulate: {duration: 1}\n";

// ---------------------------------------------------------------------------------------------
// What valid input gives

TEST(Scenario, TheContractsPrismExampleParses) {
  const Scenario s = load_text(R"(tumble: 1                    # format version, required
name: tumbling prism
parameters: {a: 4, b: 1, c: 2}
gravity: [0, 0, 0]           # default [0, 0, -9.81]
bodies:
  prism:
    shape: box
    size: [a, b, c]
    mass: 12                 # or density: (kg/m^3), not both
    inertia: [5, 20, 17]
    position: [0, 0, 0]      # COM, world, m
    orientation: identity
    velocity: [0, 0, 0]      # COM velocity, world
    angular_velocity: [0, 0.01, 1]   # world frame, rad/s
simulate:
  duration: 20
  integrator: dopri5         # the ode45 method; see below
  rtol: 1e-8                 # defaults as ode45: rtol 1e-3, atol 1e-6
  atol: 1e-10
  output_every: 0.05         # trajectory rows, from dense output; default: every accepted step
output:
  trajectory: prism.csv      # relative to the output directory; no absolute paths, no '..'
)");
  EXPECT_EQ(s.name, "tumbling prism");
  EXPECT_EQ(s.parameters, (std::map<std::string, double>{{"a", 4}, {"b", 1}, {"c", 2}}));
  EXPECT_EQ(s.gravity_W, Vec3::Zero());
  ASSERT_EQ(s.bodies.size(), 1u);
  const BodySpec& prism = s.bodies[0];
  EXPECT_EQ(prism.name, "prism");
  EXPECT_EQ(prism.shape.kind, ShapeKind::Box);
  EXPECT_EQ(prism.shape.size, Vec3(4, 1, 2));
  EXPECT_TRUE(prism.parts.empty());
  EXPECT_EQ(prism.mass_properties.mass, 12.0);
  EXPECT_EQ(prism.mass_properties.com, Vec3::Zero());
  EXPECT_TRUE(prism.inertia_overridden);
  EXPECT_EQ(prism.mass_properties.inertia_about_com, Mat3(Vec3(5, 20, 17).asDiagonal()));
  EXPECT_EQ(prism.position_W, Vec3::Zero());
  EXPECT_EQ(prism.R_WB, Mat3::Identity());
  EXPECT_EQ(prism.velocity_W, Vec3::Zero());
  EXPECT_EQ(prism.angular_velocity_W, Vec3(0, 0.01, 1));
  EXPECT_EQ(prism.where.line, 6);
  EXPECT_EQ(prism.where.column, 3);
  EXPECT_TRUE(s.loads.empty());
  EXPECT_EQ(s.simulate.duration, 20.0);
  EXPECT_EQ(s.simulate.integrator, "dopri5");
  EXPECT_EQ(s.simulate.formulation, "body");
  EXPECT_EQ(s.simulate.rtol, 1e-8);
  EXPECT_EQ(s.simulate.atol, 1e-10);
  EXPECT_TRUE(s.simulate.rtol_given);
  EXPECT_TRUE(s.simulate.atol_given);
  EXPECT_EQ(s.simulate.output_every, 0.05);
  EXPECT_EQ(s.simulate.step, 0.0);
  EXPECT_EQ(s.output.trajectory, "prism.csv");
}

TEST(Scenario, FormatTwoTakesAutoWhereNoIntegratorIsGivenAndReadsAsFormatOneOtherwise) {
  // Format 1's default is the contract's dopri5 (DefaultsComeFromTheStructsAndTheFileName).
  const Scenario two = load_text("tumble: 2\n" + kSphere + kSimulate);
  EXPECT_EQ(two.format_version, 2);
  EXPECT_EQ(two.simulate.integrator, "auto");
  EXPECT_EQ(two.simulate.rtol, 1e-3);
  EXPECT_EQ(two.simulate.atol, 1e-6);
  const Scenario chosen =
      load_text("tumble: 2\n" + kSphere + "simulate: {duration: 1, integrator: dopri5}\n");
  EXPECT_EQ(chosen.simulate.integrator, "dopri5");
  const Scenario one = load_text(kHead + kSphere + kSimulate);
  EXPECT_EQ(one.format_version, 1);
  EXPECT_EQ(one.simulate.integrator, "dopri5");
}

TEST(Scenario, TheBoxFormulaGivesThePrismsInertiaWithoutAnOverride) {
  // The chapter's prism: a 4 x 1 x 2 box of 12 kg has I_G = M/12 (b^2 + c^2, ...) = diag(5, 20,
  // 17).
  const Scenario s =
      load_text(kHead + "bodies:\n  prism: {shape: box, size: [4, 1, 2], mass: 12}\n" + kSimulate);
  EXPECT_FALSE(s.bodies[0].inertia_overridden);
  EXPECT_TRUE(s.bodies[0].mass_properties.inertia_about_com.isApprox(
      Mat3(Vec3(5, 20, 17).asDiagonal()), 1e-15));
}

TEST(Scenario, DefaultsComeFromTheStructsAndTheFileName) {
  const Scenario s = load_text(kHead + kSphere + kSimulate, {}, "spin_test.yaml");
  EXPECT_EQ(s.name, "spin_test");
  EXPECT_EQ(s.gravity_W, Vec3(0, 0, -9.81));
  EXPECT_EQ(s.output.trajectory, "spin_test.csv");
  EXPECT_EQ(s.simulate.integrator, "dopri5");
  EXPECT_EQ(s.simulate.rtol, 1e-3);
  EXPECT_EQ(s.simulate.atol, 1e-6);
  EXPECT_FALSE(s.simulate.rtol_given);
  EXPECT_FALSE(s.simulate.atol_given);
  EXPECT_EQ(s.simulate.max_steps, 10'000'000);
  EXPECT_EQ(s.bodies[0].R_WB, Mat3::Identity());
  // A sphere: I = 2/5 m r^2 about every axis.
  EXPECT_NEAR(s.bodies[0].mass_properties.inertia_about_com(0, 0), 0.4 * 2 * 0.01, 1e-15);
}

TEST(Scenario, RtolWithoutAtolSetsAtolInOde45sRatio) {
  const Scenario s = load_text(kHead + kSphere + "simulate: {duration: 1, rtol: 1e-8}\n");
  EXPECT_TRUE(s.simulate.rtol_given);
  EXPECT_FALSE(s.simulate.atol_given);
  EXPECT_DOUBLE_EQ(s.simulate.atol, 1e-11);
}

TEST(Scenario, EveryNumberMayBeAnExpressionOverTheParameters) {
  const Scenario s = load_text(kHead +
                               "parameters:\n"
                               "  L: 2\n"
                               "  half: L/2\n"  // uses an earlier parameter
                               "  tilt: 30 deg\n"
                               "bodies:\n"
                               "  rod:\n"
                               "    shape: cylinder\n"
                               "    radius: 0.1*half\n"
                               "    length: L\n"
                               "    mass: 3\n"
                               "    position: [\"sqrt(2)*L/2\", pi/4, 30deg]\n"
                               "    orientation: {axis: [0, 0, 1], angle: tilt}\n"
                               "    angular_velocity: [2*pi, -e, 1e-3]\n" +
                               kSimulate);
  EXPECT_DOUBLE_EQ(s.parameters.at("half"), 1.0);
  EXPECT_DOUBLE_EQ(s.parameters.at("tilt"), kPi / 6);
  const BodySpec& rod = s.bodies[0];
  EXPECT_DOUBLE_EQ(rod.shape.radius, 0.1);
  EXPECT_EQ(rod.shape.length, 2.0);
  EXPECT_DOUBLE_EQ(rod.position_W.x(), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(rod.position_W.y(), kPi / 4);
  EXPECT_DOUBLE_EQ(rod.position_W.z(), kPi / 6);
  EXPECT_NEAR(rod.R_WB(0, 0), std::cos(kPi / 6), 1e-15);
  EXPECT_NEAR(rod.R_WB(1, 0), std::sin(kPi / 6), 1e-15);
  EXPECT_DOUBLE_EQ(rod.angular_velocity_W.x(), 2 * kPi);
  EXPECT_DOUBLE_EQ(rod.angular_velocity_W.y(), -std::numbers::e);
  EXPECT_EQ(rod.angular_velocity_W.z(), 1e-3);
}

TEST(Scenario, UnitsAfterANumberConvertItToSI) {
  // rpm to rad/s (x pi/30), cm and mm to m, ms to s, deg to rad; a unit's name is reserved.
  const Scenario s = load_text(kHead +
                               "parameters: {spin: 1500 rpm, r: 15 cm, w: (2 + 3) mm, t: 20 ms}\n"
                               "bodies:\n"
                               "  wheel: {shape: disk, radius: r, mass: 2, angular_velocity: [0, "
                               "0, spin], position: [w, 0, 0]}\n"
                               "simulate: {duration: 1, output_every: t}\n");
  EXPECT_DOUBLE_EQ(s.parameters.at("spin"), 1500 * kPi / 30);
  EXPECT_DOUBLE_EQ(s.parameters.at("r"), 0.15);
  EXPECT_DOUBLE_EQ(s.bodies[0].position_W.x(), 0.005);
  EXPECT_DOUBLE_EQ(s.simulate.output_every, 0.02);
  for (const char* unit : {"rpm", "cm", "mm", "ms", "deg"}) {
    try {
      load_text(kHead + "parameters: {" + unit + ": 2}\n" + kSphere + kSimulate);
      ADD_FAILURE() << unit << " was accepted as a parameter's name";
    } catch (const ScenarioError& error) {
      EXPECT_NE(error.why().find("is reserved"), std::string::npos) << error.what();
    }
  }
}

TEST(Scenario, AnAngleOfMoreThanATurnWrittenAsABareNumberIsReadInRadiansWithAWarning) {
  // `th: 25` is 25 rad (1432 degrees): accepted, as the contract says, and the warning says so
  // where it is; written with deg or pi, or within a turn, no warning.
  const auto body = [](const std::string& angle) {
    return kHead +
           "parameters: {th: 25}\nbodies:\n  ball: {shape: sphere, radius: 0.1, mass: 2,\n" +
           "    orientation: {axis: [0, 0, 1], angle: " + angle + "}}\n" + kSimulate;
  };
  const Scenario bare = load_text(body("th"));
  ASSERT_EQ(bare.warnings.size(), 1u);
  EXPECT_NE(bare.warnings[0].find(":5:"), std::string::npos) << bare.warnings[0];
  EXPECT_NE(bare.warnings[0].find("bodies.ball.orientation.angle"), std::string::npos)
      << bare.warnings[0];
  EXPECT_NE(bare.warnings[0].find("read in radians (1432 degrees"), std::string::npos)
      << bare.warnings[0];
  EXPECT_EQ(load_text(body("7")).warnings.size(), 1u);
  for (const char* fine : {"25 deg", "4*pi", "6", "-6.2"}) {
    EXPECT_TRUE(load_text(body(fine)).warnings.empty()) << fine;
  }
}

TEST(Scenario, SetOverridesAParameterAndTheValuesThatUseIt) {
  const std::string text = kHead +
                           "parameters: {a: 4, b: 1, c: 2, m: 3*a}\n"
                           "bodies:\n"
                           "  prism: {shape: box, size: [a, b, c], mass: m}\n" +
                           kSimulate;
  const Scenario plain = load_text(text);
  EXPECT_EQ(plain.bodies[0].mass_properties.mass, 12.0);
  // VALUE is an expression over the parameters above it; the last --set of a name wins.
  const Scenario set = load_text(text, {{"a", "2"}, {"c", "a/3"}, {"a", "3"}, {"c", "a-2"}});
  EXPECT_EQ(set.parameters.at("a"), 3.0);
  EXPECT_EQ(set.parameters.at("c"), 1.0);
  EXPECT_EQ(set.bodies[0].shape.size, Vec3(3, 1, 1));
  EXPECT_EQ(set.bodies[0].mass_properties.mass, 9.0);  // m = 3 a follows the new a
}

TEST(Scenario, UnknownSetNameIsACommandLineErrorListingTheParameters) {
  const fs::path path =
      write_in_test_dir("p.yaml", kHead + "parameters: {a: 4, b: 1, c: 2}\n" + kSphere + kSimulate);
  try {
    load_scenario(path.string(), {{"zz", "3"}});
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()),
              "--set zz: no parameter zz in " + path.string() + "; its parameters are a, b, c");
  }
  const fs::path none = write_in_test_dir("none.yaml", kHead + kSphere + kSimulate);
  EXPECT_THROW(
      {
        try {
          load_scenario(none.string(), {{"a", "1"}});
        } catch (const std::invalid_argument& error) {
          EXPECT_NE(std::string(error.what()).find("it has no parameters"), std::string::npos);
          throw;
        }
      },
      std::invalid_argument);
}

TEST(Scenario, ABadSetValueIsACommandLineError) {
  try {
    load_text(kHead + "parameters: {a: 4}\n" + kSphere + kSimulate, {{"a", "2*("}});
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("--set a=2*(: expression '2*('"), std::string::npos)
        << error.what();
  }
}

TEST(Scenario, TwoSpheresOnARodFollowTheParallelAxisTheorem) {
  // A dumbbell along x: spheres (M, r) at x = +-d on a rod (m_r, L). About the COM (the middle):
  //   I_xx = 2 (2/5 M r^2)                         (a rod has none about its own axis)
  //   I_yy = I_zz = 2 (2/5 M r^2 + M d^2) + m_r L^2 / 12.
  const double M = 3, r = 0.2, d = 1.5, m_r = 0.6, L = 2.6;
  const Scenario s = load_text(kHead +
                               "parameters: {M: 3, r: 0.2, d: 1.5}\n"
                               "bodies:\n"
                               "  dumbbell:\n"
                               "    position: [1, 2, 3]\n"
                               "    parts:\n"
                               "      - {name: left, shape: sphere, radius: r, mass: M, "
                               "position: [-d, 0, 0]}\n"
                               "      - {name: right, shape: sphere, radius: r, mass: M, "
                               "position: [d, 0, 0]}\n"
                               "      - {shape: rod, length: 2.6, mass: 0.6}\n" +
                               kSimulate);
  const BodySpec& body = s.bodies[0];
  ASSERT_EQ(body.parts.size(), 3u);
  EXPECT_EQ(body.parts[0].name, "left");
  EXPECT_EQ(body.parts[2].name, "parts[2]");
  EXPECT_EQ(body.parts[2].shape.kind, ShapeKind::Rod);
  EXPECT_EQ(body.shape.kind, ShapeKind::Point);
  EXPECT_FALSE(body.inertia_overridden);
  EXPECT_DOUBLE_EQ(body.mass_properties.mass, 2 * M + m_r);
  EXPECT_LT(body.mass_properties.com.norm(), 1e-15);
  const double sphere = 0.4 * M * r * r;
  const Vec3 expected(2 * sphere, 2 * (sphere + M * d * d) + m_r * L * L / 12,
                      2 * (sphere + M * d * d) + m_r * L * L / 12);
  EXPECT_TRUE(body.mass_properties.inertia_about_com.isApprox(Mat3(expected.asDiagonal()), 1e-14))
      << body.mass_properties.inertia_about_com;
  EXPECT_EQ(body.position_W, Vec3(1, 2, 3));
}

TEST(Scenario, ACompositesFramePlacesItsOffsetCentreOfMass) {
  // Point masses 1 kg at the origin and 3 kg at (0, 0, 2) of the body frame: COM at z = 1.5 in
  // the body; the frame turned 90 deg about x puts it at position + R_WB com = (0, -1.5, 0) + p.
  // A cylinder (m, R, h) laid along x by a part orientation has I_xx = m R^2 / 2.
  const Scenario s = load_text(kHead +
                               "bodies:\n"
                               "  lumps:\n"
                               "    position: [5, 0, 0]\n"
                               "    orientation: {axis: [1, 0, 0], angle: 90 deg}\n"
                               "    parts:\n"
                               "      - {shape: point, mass: 1}\n"
                               "      - {shape: point, mass: 3, position: [0, 0, 2]}\n"
                               "      - {shape: cylinder, radius: 0.5, length: 1, mass: 2,\n"
                               "         orientation: {axis: [0, 1, 0], angle: 90 deg}}\n" +
                               kSimulate);
  const BodySpec& body = s.bodies[0];
  EXPECT_DOUBLE_EQ(body.mass_properties.mass, 6.0);
  EXPECT_TRUE(body.mass_properties.com.isApprox(Vec3(0, 0, 1.0), 1e-15))
      << body.mass_properties.com.transpose();  // (3 * 2) / 6
  const Vec3 com_W = body.position_W + body.R_WB * body.mass_properties.com;
  EXPECT_TRUE(com_W.isApprox(Vec3(5, -1, 0), 1e-15)) << com_W.transpose();
  // About x: the cylinder's own m R^2 / 2 = 0.25, plus the points' and the cylinder's offsets
  // from z = 1: 1 * 1 + 3 * 1 + 2 * 1 = 6.
  EXPECT_NEAR(body.parts[2].mass_properties.inertia_about_com(0, 0), 0.25, 1e-15);
  EXPECT_NEAR(body.mass_properties.inertia_about_com(0, 0), 0.25 + 6, 1e-14);
}

TEST(Scenario, DensityMultipliesTheShapesMeasure) {
  const Scenario s = load_text(kHead +
                               "bodies:\n"
                               "  ball: {shape: sphere, radius: 0.5, density: 1000}\n"
                               "  sheet: {shape: plate, size: [2, 3], density: 4}\n" +
                               kSimulate);
  EXPECT_NEAR(s.bodies[0].mass_properties.mass, 1000 * 4.0 / 3.0 * kPi * 0.125, 1e-10);
  EXPECT_NEAR(s.bodies[1].mass_properties.mass, 24.0, 1e-12);
  EXPECT_EQ(s.bodies[1].shape.size, Vec3(2, 3, 0));
}

TEST(Scenario, AMeshIsFoundBesideTheScenario) {
  write_in_test_dir("cube.obj",
                    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
                    "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n");
  const Scenario s = load_text(
      kHead + "bodies:\n  cube: {shape: mesh, file: cube.obj, density: 600}\n" + kSimulate);
  const BodySpec& cube = s.bodies[0];
  EXPECT_EQ(fs::path(cube.shape.mesh_file), test_dir() / "cube.obj");
  EXPECT_NEAR(cube.mass_properties.mass, 600.0, 1e-9);
  EXPECT_TRUE(cube.mass_properties.inertia_about_com.isApprox(Mat3::Identity() * 100.0, 1e-12))
      << cube.mass_properties.inertia_about_com;  // m (1 + 1) / 12
}

TEST(Scenario, OrientationsInEveryForm) {
  const Scenario s = load_text(kHead +
                               "parameters: {h: sqrt(0.5)}\n"
                               "bodies:\n"
                               "  a: {shape: sphere, radius: 1, mass: 1, orientation: identity}\n"
                               "  b: {shape: sphere, radius: 1, mass: 1,\n"
                               "      orientation: {quaternion: [2, 0, 0, 2]}}\n"
                               "  c: {shape: sphere, radius: 1, mass: 1,\n"
                               "      orientation: {matrix: [[0, -1, 0], [1, 0, 0], [0, 0, 1]]}}\n"
                               "  d: {shape: sphere, radius: 1, mass: 1,\n"
                               "      orientation: {axis: [0, 0, 7], angle: pi/2}}\n"
                               "  e: {shape: sphere, radius: 1, mass: 1,\n"
                               "      orientation: {quaternion: [h, 0, 0, h]}}\n" +
                               kSimulate);
  Mat3 quarter_turn_z;
  quarter_turn_z << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  EXPECT_EQ(s.bodies[0].R_WB, Mat3::Identity());
  for (int i = 1; i < 5; ++i) {
    EXPECT_TRUE(s.bodies[static_cast<std::size_t>(i)].R_WB.isApprox(quarter_turn_z, 1e-15))
        << s.bodies[static_cast<std::size_t>(i)].name << "\n"
        << s.bodies[static_cast<std::size_t>(i)].R_WB;
  }
}

TEST(Scenario, AFullInertiaOverrideIsKeptAsGiven) {
  const Scenario s = load_text(kHead +
                               "bodies:\n"
                               "  b:\n"
                               "    shape: box\n"
                               "    size: [1, 1, 1]\n"
                               "    mass: 1\n"
                               "    inertia: [[2, 0.1, 0], [0.1, 3, 0], [0, 0, 4]]\n" +
                               kSimulate);
  Mat3 expected;
  expected << 2, 0.1, 0, 0.1, 3, 0, 0, 0, 4;
  EXPECT_EQ(s.bodies[0].mass_properties.inertia_about_com, expected);
  EXPECT_TRUE(s.bodies[0].inertia_overridden);
}

TEST(Scenario, ForcesAndTorquesAreNamedByTypeAndListPosition) {
  const Scenario s = load_text(kHead + kSphere +
                               "forces:\n"
                               "  - {type: torque, body: ball, value: [0, 0, 0.2], frame: body}\n"
                               "  - {type: force, body: ball, at: [0.1, 0, 0], value: [0, -5, 0],"
                               " from: 0.1, to: 0.2}\n"
                               "  - {type: force, name: push, body: ball, value: [1, 0, 0]}\n" +
                               kSimulate);
  ASSERT_EQ(s.loads.size(), 3u);
  const LoadSpec& torque = s.loads[0];
  EXPECT_EQ(torque.kind, LoadSpec::Kind::Torque);
  EXPECT_EQ(torque.name, "torque1");
  EXPECT_EQ(torque.body, "ball");
  EXPECT_TRUE(torque.body_frame);
  EXPECT_EQ(torque.value, Vec3(0, 0, 0.2));
  EXPECT_EQ(torque.from, -std::numeric_limits<double>::infinity());
  EXPECT_EQ(torque.to, std::numeric_limits<double>::infinity());
  EXPECT_EQ(torque.where.line, 5);
  const LoadSpec& force = s.loads[1];
  EXPECT_EQ(force.kind, LoadSpec::Kind::Force);
  EXPECT_EQ(force.name, "force2");
  EXPECT_FALSE(force.body_frame);
  EXPECT_TRUE(force.has_point);
  EXPECT_EQ(force.at_W, Vec3(0.1, 0, 0));
  EXPECT_EQ(force.from, 0.1);
  EXPECT_EQ(force.to, 0.2);
  EXPECT_EQ(s.loads[2].name, "push");
  EXPECT_FALSE(s.loads[2].has_point);
}

TEST(Scenario, FixedStepIntegratorsTakeTheirStep) {
  const Scenario s = load_text(kHead + kSphere +
                               "simulate: {duration: 2, integrator: rkmk4, step: 1e-3, "
                               "formulation: textbook, max_steps: 5000, output_every: 0.1}\n");
  EXPECT_EQ(s.simulate.integrator, "rkmk4");
  EXPECT_EQ(s.simulate.step, 1e-3);
  EXPECT_EQ(s.simulate.formulation, "textbook");
  EXPECT_EQ(s.simulate.max_steps, 5000);
  EXPECT_EQ(s.simulate.where.line, 4);
  EXPECT_EQ(s.simulate.where.column, 37);  // the integrator's value
}

// ---------------------------------------------------------------------------------------------
// Invalid input: one test per class, each pointing at the key or value at fault

TEST(ScenarioError, WhatReadsFileLineColumnKeyWhy) {
  const ScenarioError error({"a.yaml", 3, 7}, "bodies.b.mass", "mass must be > 0");
  EXPECT_STREQ(error.what(), "a.yaml:3:7: bodies.b.mass: mass must be > 0");
  EXPECT_STREQ(ScenarioError({"a.yaml", 0, 0}, "", "cannot be read").what(),
               "a.yaml:0:0: cannot be read");
}

TEST(ScenarioError, UnknownKeySuggestsTheClosestValidKey) {
  expect_load_error(kHead +
                        "bodies:\n"
                        "  prism:\n"
                        "    shape: box\n"
                        "    size: [4, 1, 2]\n"
                        "    mass: 12\n"
                        "    angular_velocty: [0, 0.01, 1]\n" +
                        kSimulate,
                    {7, 5, "bodies.prism.angular_velocty",
                     "unknown key 'angular_velocty'; did you mean 'angular_velocity'?"});
  expect_load_error(kHead + kSphere + "simulte: {duration: 1}\n",
                    {4, 1, "simulte", "unknown key 'simulte'; did you mean 'simulate'?"});
  expect_load_error(kHead + kSphere + "simulate: {duration: 1, rtoll: 1e-6}\n",
                    {4, 25, "simulate.rtoll", "did you mean 'rtol'?"});
  expect_load_error(kHead + "bodies:\n  b: {shpe: sphere, radius: 1, mass: 1}\n" + kSimulate,
                    {3, 7, "bodies.b.shpe", "unknown key 'shpe'; did you mean 'shape'?"});
  // A key with no near match lists the valid ones.
  expect_load_error(kHead + kSphere + kSimulate + "output: {movie: a.mp4}\n",
                    {5, 10, "output.movie",
                     "unknown key 'movie' (output takes: trajectory, animation, events, plots)"});
}

TEST(ScenarioError, ADimensionOfAnotherShapeIsAnUnknownKey) {
  expect_load_error(
      kHead + "bodies:\n  b: {shape: box, size: [1, 1, 1], radius: 2, mass: 1}\n" + kSimulate,
      {3, 36, "bodies.b.radius", "'radius' is not a dimension of a box, which takes size"});
}

TEST(ScenarioError, WrongTypesAreErrors) {
  expect_load_error(kHead + "bodies: prism\n" + kSimulate,
                    {2, 9, "bodies", "expected a mapping of bodies by name"});
  expect_load_error(
      kHead + "bodies:\n  b: {shape: sphere, radius: 1, mass: 1, position: [1, 2]}\n" + kSimulate,
      {3, 52, "bodies.b.position", "expected a list of 3 numbers [x, y, z], got a list of 2"});
  expect_load_error(
      kHead + "bodies:\n  b: {shape: sphere, radius: [1], mass: 1}\n" + kSimulate,
      {3, 30, "bodies.b.radius", "expected a number or an expression, got a list of 1"});
  expect_load_error(kHead + kSphere + "simulate: {duration: 1, integrator: [rk4]}\n",
                    {4, 37, "simulate.integrator", "expected a word or text, got a list of 1"});
}

TEST(ScenarioError, AMissingRequiredKeyIsReportedAtItsParent) {
  expect_load_error(kHead + kSphere + "simulate:\n  rtol: 1e-6\n",
                    {4, 1, "simulate.duration", "missing required key 'duration'"});
  expect_load_error(
      kHead + "bodies:\n  b:\n    shape: cylinder\n    radius: 1\n    mass: 1\n" + kSimulate,
      {3, 3, "bodies.b.length", "missing required key 'length' (a cylinder's length"});
  expect_load_error(kHead + "bodies:\n  b: {shape: sphere, radius: 1}\n" + kSimulate,
                    {3, 3, "bodies.b.mass",
                     "missing required key 'mass' (kg, > 0; or density: in "
                     "kg/m^3)"});
  expect_load_error(kHead + kSimulate, {1, 1, "bodies", "missing required key 'bodies'"});
  expect_load_error("bodies: {}\n", {1, 1, "tumble", "missing required key 'tumble'"});
  expect_load_error(kHead + kSphere, {1, 1, "simulate", "missing required key 'simulate'"});
}

TEST(ScenarioError, MassMustBePositive) {
  expect_load_error(
      kHead + "bodies:\n  b:\n    shape: sphere\n    radius: 0.1\n    mass: -2\n" + kSimulate,
      {6, 11, "bodies.b.mass", "mass must be > 0 (kg), got -2"});
  expect_load_error(kHead + "bodies:\n  b: {shape: sphere, radius: 0.1, density: 0}\n" + kSimulate,
                    {3, 44, "bodies.b.density", "density must be > 0 (kg/m^3), got 0"});
}

TEST(ScenarioError, MassAndDensityTogetherAreAnError) {
  expect_load_error(
      kHead + "bodies:\n  b: {shape: sphere, radius: 0.1, mass: 1, density: 5}\n" + kSimulate,
      {3, 44, "bodies.b.density", "give mass or density, not both"});
}

TEST(ScenarioError, ANonPositiveDefiniteInertiaIsAnError) {
  expect_load_error(
      kHead + "bodies:\n  b: {shape: sphere, radius: 1, mass: 1, inertia: [1, 0, 1]}\n" + kSimulate,
      {3, 51, "bodies.b.inertia", "inertia is not positive definite"});
  // A free rod has no inertia about its axis: the error says so and gives the fixes (held by a
  // hinge across it, it is a valid slender body: slender_body_test.cpp).
  expect_load_error(
      kHead + "bodies:\n  stick: {shape: rod, length: 1, mass: 1}\n" + kSimulate,
      {3, 18, "bodies.stick.shape",
       "a rod has no inertia about its own axis: free, nothing would say how it turns "
       "about that line; hold it with a hinge across it"});
  // Two points alone lie on one line.
  expect_load_error(kHead +
                        "bodies:\n  pair:\n    parts:\n"
                        "      - {shape: point, mass: 1}\n"
                        "      - {shape: point, mass: 1, position: [1, 0, 0]}\n" +
                        kSimulate,
                    {4, 5, "bodies.pair.parts",
                     "parts on one line have no inertia about it: free, nothing would say how it "
                     "turns about that line"});
}

TEST(ScenarioError, TheTriangleInequalityOfPrincipalMomentsIsChecked) {
  expect_load_error(kHead +
                        "bodies:\n  b:\n    shape: sphere\n    radius: 1\n    mass: 1\n"
                        "    inertia: [1, 1, 3]\n" +
                        kSimulate,
                    {7, 14, "bodies.b.inertia", "break the triangle inequality: 3 > 1 + 1 by 1"});
}

TEST(ScenarioError, ImpossibleDimensionsAreErrors) {
  expect_load_error(kHead + "bodies:\n  b: {shape: sphere, radius: -1, mass: 1}\n" + kSimulate,
                    {3, 30, "bodies.b.radius", "radius must be > 0 (m), got -1"});
  expect_load_error(kHead + "bodies:\n  b: {shape: box, size: [1, 0, 2], mass: 1}\n" + kSimulate,
                    {3, 29, "bodies.b.size[1]", "size[1] must be > 0 (m), got 0"});
  expect_load_error(
      kHead +
          "bodies:\n  pipe: {shape: tube, inner_radius: 0.2, outer_radius: 0.1, "
          "length: 1, mass: 1}\n" +
          kSimulate,
      {3, 37, "bodies.pipe.inner_radius", "inner_radius 0.2 must be less than outer_radius 0.1"});
}

TEST(ScenarioError, AZeroAxisIsAnError) {
  expect_load_error(kHead +
                        "bodies:\n  b:\n    shape: sphere\n    radius: 1\n    mass: 1\n"
                        "    orientation: {axis: [0, 0, 0], angle: 1}\n" +
                        kSimulate,
                    {7, 25, "bodies.b.orientation.axis", "axis [0, 0, 0] has no direction"});
}

TEST(ScenarioError, ANonOrthonormalMatrixIsAnError) {
  expect_load_error(kHead +
                        "bodies:\n  b:\n    shape: sphere\n    radius: 1\n    mass: 1\n"
                        "    orientation:\n      matrix: [[1, 0, 0], [0, 1, 0.01], [0, 0, 1]]\n" +
                        kSimulate,
                    {8, 15, "bodies.b.orientation.matrix",
                     "matrix is not orthonormal: max|R^T R - I| = 0.01 exceeds 1e-09"});
  expect_load_error(
      kHead +
          "bodies:\n  b:\n    shape: sphere\n    radius: 1\n    mass: 1\n"
          "    orientation:\n      matrix: [[1, 0, 0], [0, 1, 0], [0, 0, -1]]\n" +
          kSimulate,
      {8, 15, "bodies.b.orientation.matrix", "matrix has determinant -1: a reflection"});
}

TEST(ScenarioError, AZeroQuaternionIsAnError) {
  expect_load_error(
      kHead +
          "bodies:\n  b:\n    shape: sphere\n    radius: 1\n    mass: 1\n"
          "    orientation: {quaternion: [0, 0, 0, 0]}\n" +
          kSimulate,
      {7, 31, "bodies.b.orientation.quaternion", "quaternion [0, 0, 0, 0] is no rotation"});
}

TEST(ScenarioError, OneFormOfOrientationAtATime) {
  expect_load_error(kHead +
                        "bodies:\n  b:\n    shape: sphere\n    radius: 1\n    mass: 1\n"
                        "    orientation: {axis: [0, 0, 1], angle: 1, quaternion: [1, 0, 0, 0]}\n" +
                        kSimulate,
                    {7, 46, "bodies.b.orientation.quaternion",
                     "give one form of orientation, not both 'axis' and 'quaternion'"});
  expect_load_error(
      kHead +
          "bodies:\n  b:\n    shape: sphere\n    radius: 1\n    mass: 1\n"
          "    orientation: sideways\n" +
          kSimulate,
      {7, 18, "bodies.b.orientation", "expected identity, {axis: [x, y, z], angle: rad}"});
}

TEST(ScenarioError, ABadExpressionNamesItAndMuParsersMessage) {
  expect_load_error(
      kHead + "bodies:\n  b:\n    shape: sphere\n    radius: 1\n    mass: \"2*(3\"\n" + kSimulate,
      {6, 11, "bodies.b.mass", "expression '2*(3': Missing parenthesis"});
}

TEST(ScenarioError, AnUnknownParameterInAnExpressionListsTheParameters) {
  expect_load_error(
      kHead +
          "parameters: {L: 2}\nbodies:\n  b:\n    shape: sphere\n    radius: 1\n"
          "    mass: 3*Q\n" +
          kSimulate,
      {7, 11, "bodies.b.mass",
       "expression '3*Q': Unexpected token \"Q\" found at position 2.; the parameters "
       "defined here are L"});
  // A parameter may use only those above it.
  expect_load_error(kHead + "parameters:\n  a: 2*b\n  b: 1\n" + kSphere + kSimulate,
                    {3, 6, "parameters.a", "Unexpected token \"b\""});
}

// Every key that takes an expression refuses an assignment, located at the key (an expression
// only reads its names: red-team finding).
TEST(ScenarioError, AnExpressionThatAssignsIsLocated) {
  const std::string refused = "'=' would assign a value; an expression only reads its names";
  expect_load_error(kHead + "parameters:\n  a: 2\n  b: a = 3\n" + kSphere + kSimulate,
                    {4, 6, "parameters.b", "expression 'a = 3': " + refused});
  expect_load_error(kHead +
                        "parameters: {a: 2}\nbodies:\n  b:\n    shape: sphere\n    radius: 1\n"
                        "    mass: \"1 + (q = 2)\"\n" +
                        kSimulate,
                    {7, 11, "bodies.b.mass", "expression '1 + (q = 2)': " + refused});
  expect_load_error(kHead + kSphere + "simulate: {duration: \"a += 1\"}\n",
                    {4, 22, "simulate.duration", "expression 'a += 1': " + refused});
  // A comparison with == is a number, 1 or 0, as before.
  const Scenario scenario =
      load_text(kHead + "parameters: {a: 2, b: a == 2}\n" + kSphere + kSimulate);
  EXPECT_EQ(scenario.parameters.at("b"), 1.0);
}

// A comma outside a function's brackets gives two values, of which muParser would keep the last.
TEST(ScenarioError, AnExpressionOfTwoValuesIsLocated) {
  expect_load_error(
      kHead + "bodies:\n  b:\n    shape: sphere\n    radius: \"1, 2\"\n    mass: 1\n" + kSimulate,
      {5, 13, "bodies.b.radius", "expression '1, 2' gives 2 values"});
}

// A million parameters are read in seconds: each is defined in O(1) (a search of every earlier
// name took 31 s for 200,000 and would take minutes here, past the test's time limit).
TEST(ScenarioError, AMillionParametersAreReadInLinearTime) {
#ifdef TUMBLE_SANITIZER_BUILD
  // Read in some 15 s in Release, several times that under a sanitizer, which finds nothing here
  // that the Release run and the smaller tests above do not.
  GTEST_SKIP() << "a Release test: its size is what it checks";
#endif
  constexpr int kCount = 1'000'000;
  std::string text = kHead + "parameters:\n";
  text.reserve(20 * kCount);
  for (int i = 0; i < kCount; ++i) {
    text += i % 1000 == 999 ? fmt::format("  p{}: p{} + 1\n", i, i - 1)
                            : fmt::format("  p{}: {}\n", i, i);
  }
  const Scenario scenario =
      load_text(text + "bodies:\n  ball: {shape: sphere, radius: 0.1, mass: p999999 - p999997}\n" +
                kSimulate);
  EXPECT_EQ(scenario.parameters.size(), static_cast<std::size_t>(kCount));
  EXPECT_EQ(scenario.parameters.at("p999"), 999.0);
  EXPECT_EQ(scenario.parameters.at("p999999"), 999999.0);
  EXPECT_EQ(scenario.bodies[0].mass_properties.mass, 2.0);
}

TEST(ScenarioError, AReservedParameterNameIsAnError) {
  expect_load_error(kHead + "parameters: {pi: 3}\n" + kSphere + kSimulate,
                    {2, 14, "parameters.pi", "'pi' is reserved"});
}

TEST(ScenarioError, AYamlSyntaxErrorIsReportedAtTheParsersMark) {
  expect_load_error(kHead + "bodies:\n  b: {shape: sphere, radius: 1, mass: 1\n" + kSimulate,
                    {4, 9, "", "YAML syntax error: end of map flow not found"});
}

TEST(ScenarioError, OnlyFormatVersionsOneAndTwoAreRead) {
  expect_load_error("tumble: 3\n" + kSphere + kSimulate,
                    {1, 9, "tumble", "unsupported format version 3; this tumble reads 1 and 2"});
  expect_load_error("tumble: 1.5\n" + kSphere + kSimulate,
                    {1, 9, "tumble", "unsupported format version 1.5; this tumble reads 1 and 2"});
}

TEST(ScenarioError, AMissingFileCannotBeRead) {
  const std::string path = (test_dir() / "no_such.yaml").string();
  try {
    load_scenario(path, {});
    ADD_FAILURE() << "no error";
  } catch (const ScenarioError& error) {
    EXPECT_EQ(error.where().file, path);
    EXPECT_EQ(error.where().line, 0);
    EXPECT_EQ(error.where().column, 0);
    EXPECT_EQ(std::string(error.what()),
              path + ":0:0: cannot be read: no such file (check the path)");
  }
  EXPECT_THROW(load_scenario(test_dir().string(), {}), ScenarioError);
  expect_load_error("", {1, 1, "", "the file is empty"});
}

TEST(ScenarioError, AnUnknownForceTypeListsTheTypes) {
  expect_load_error(
      kHead + kSphere + "forces:\n  - {type: forse, body: ball, value: [1, 0, 0]}\n" + kSimulate,
      {5, 12, "forces[0].type",
       "unknown type 'forse'; did you mean 'force'? (the types are force, torque, impulse, "
       "spring, torsional_spring)"});
  expect_load_error(
      kHead + kSphere +
          "forces:\n  - {type: torque, body: ball, value: [1, 0, 0], at: [1, 0, 0]}\n" + kSimulate,
      {5, 50, "forces[0].at", "a torque has no point of application"});
}

TEST(ScenarioError, AForceMustNameABody) {
  expect_load_error(
      kHead + kSphere + "forces:\n  - {type: force, body: bal, value: [1, 0, 0]}\n" + kSimulate,
      {5, 25, "forces[0].body",
       "no body 'bal' in bodies; did you mean 'ball'? (the bodies are ball)"});
  expect_load_error(
      kHead + kSphere + "forces:\n  - {type: force, body: ground, value: [1, 0, 0]}\n" + kSimulate,
      {5, 25, "forces[0].body", "a load on ground does nothing"});
}

TEST(ScenarioError, AScheduleMustEndAfterItStarts) {
  expect_load_error(
      kHead + kSphere +
          "forces:\n  - {type: force, body: ball, value: [1, 0, 0], from: 2, to: 1}\n" + kSimulate,
      {5, 62, "forces[0].to", "to (1 s) must be later than from (2 s)"});
}

TEST(ScenarioError, AnUnknownIntegratorListsTheIntegrators) {
  expect_load_error(kHead + kSphere + "simulate: {duration: 1, integrator: ode45}\n",
                    {4, 37, "simulate.integrator",
                     "unknown integrator 'ode45' (the integrators are dopri5, dop853, rk4, rkmk4, "
                     "radau5, trbdf2, auto, exact)"});
  expect_load_error(kHead + kSphere + "simulate: {duration: 1, integrator: dopri45}\n",
                    {4, 37, "simulate.integrator", "did you mean 'dopri5'?"});
}

TEST(ScenarioError, Rk4NeedsAStep) {
  expect_load_error(kHead + kSphere + "simulate: {duration: 1, integrator: rk4}\n",
                    {4, 37, "simulate.integrator", "rk4 takes a fixed step: give simulate.step"});
  expect_load_error(kHead + kSphere + "simulate: {duration: 1, integrator: rk4, step: -1}\n",
                    {4, 48, "simulate.step", "step must be > 0 (s), got -1"});
}

TEST(ScenarioError, ExactIsForTorqueFreeBodies) {
  expect_load_error(
      kHead + kSphere + "forces:\n  - {type: torque, body: ball, value: [0, 0, 1]}\n" +
          "simulate: {duration: 1, integrator: exact}\n",
      {6, 37, "simulate.integrator",
       "exact is for torque-free free bodies; remove forces and joints or choose dopri5"});
}

TEST(ScenarioError, TextThatIsNotUtf8IsRefused) {
  // A Latin-1 e-acute (0xE9) in the scenario's name would reach the page's title.
  expect_load_error(kHead + "name: caf\xE9\n" + kSphere + kSimulate,
                    {2, 7, "name", "the text is not valid UTF-8 (byte 0xE9 at its position 4)"});
  expect_load_error(
      kHead + "bodies:\n  ball\xFF: {shape: sphere, radius: 0.1, mass: 2}\n" + kSimulate,
      {3, 3, "bodies", "not valid UTF-8"});
  // UTF-8 itself is fine.
  const fs::path path =
      write_in_test_dir("utf8.yaml", kHead + "name: caf\xC3\xA9 \xE2\x80\x94 \xF0\x9F\x8E\xB2\n" +
                                         kSphere + kSimulate);
  EXPECT_EQ(load_scenario(path.string(), {}).name, "caf\xC3\xA9 \xE2\x80\x94 \xF0\x9F\x8E\xB2");
}

TEST(ScenarioError, ASecondYamlDocumentIsRefused) {
  // Located at its '---'. The parser is asked for two documents at most: on some inputs
  // yaml-cpp's LoadAll finds empty documents without end (tests/data/fuzz/, FuzzRegressions).
  expect_load_error(kHead + kSphere + kSimulate + "---\ntumble: 1\n",
                    {5, 1, "", "the file holds 2 YAML documents (separated by ---)"});
}

TEST(ScenarioError, AnUnclosedQuoteIsLocatedWhereItOpens) {
  // The quote runs on and swallows bodies: and simulate:, which the parser takes as its text.
  expect_load_error(kHead + "name: \"tumbling\n" + kSphere + kSimulate,
                    {2, 7, "", "this quoted text is not closed on its line"});
  // A quoted text with ': ' in it, closed on its line, is a name like any other.
  const fs::path path =
      write_in_test_dir("colon.yaml", kHead + "name: \"Cubli: jumping\"\n" + kSphere + kSimulate);
  EXPECT_EQ(load_scenario(path.string(), {}).name, "Cubli: jumping");
}

TEST(ScenarioError, ManyKeysAreReadInLinearTime) {
  // 200,000 keys in one mapping, the last repeating the first: the duplicate is found (a check
  // of each key against every earlier one would take minutes here), then 200,000 unknown keys
  // are refused at the first.
  std::string many = kHead + kSphere + kSimulate + "output:\n";
  for (int i = 0; i < 200000; ++i) many += "  k" + std::to_string(i) + ": 1\n";
  expect_load_error(many + "  k0: 2\n",
                    {200006, 3, "output.k0", "duplicate key 'k0' (first given on line 6)"});
  expect_load_error(many, {6, 3, "output.k0", "unknown key 'k0'"});
}

TEST(ScenarioError, OutputBeyondTheRowBudgetIsRefusedBeforeTheRun) {
  // duration / output_every rows (and t0) past simulate.max_rows: the estimate and the fix.
  expect_load_error(kHead + kSphere + "simulate: {duration: 1, output_every: 1e-300}\n",
                    {4, 39, "simulate.output_every",
                     "duration / output_every is about 1e+300 rows, more than simulate.max_rows = "
                     "1000000: write less often (output_every: 1e-06 gives 1000000 rows)"});
  expect_load_error(kHead + kSphere + "simulate: {duration: 1e9, output_every: 0.01}\n",
                    {4, 41, "simulate.output_every", "about 1e+11 rows"});
  // Raised on purpose, it is the budget.
  const fs::path path = write_in_test_dir(
      "raised.yaml",
      kHead + kSphere + "simulate: {duration: 1, output_every: 1e-6, max_rows: 2e6}\n");
  EXPECT_EQ(load_scenario(path.string(), {}).simulate.max_rows, 2000000);
  // A fixed step's steps are known: past max_steps, or a row each past max_rows.
  expect_load_error(kHead + kSphere + "simulate: {duration: 1e9, integrator: rk4, step: 0.01}\n",
                    {4, 50, "simulate.step",
                     "duration / step is 1e+11 steps, more than "
                     "simulate.max_steps = 10000000"});
  expect_load_error(kHead + kSphere + "simulate: {duration: 1e4, integrator: rk4, step: 0.001}\n",
                    {4, 50, "simulate.step",
                     "one row per step is 1e+07 rows, more than "
                     "simulate.max_rows = 1000000: give output_every"});
}

TEST(ScenarioWarnings, AnRtolBelowWhatRoundOffAllowsIsRaisedToItWithANote) {
  // Below 100 eps each step's error estimate is round-off: the steps would shrink without end.
  // The reader raises it to 100 eps (the methods' floor) and says so at the key; atol, not
  // given, follows the raised rtol.
  const Scenario scenario =
      load_text(kHead + kSphere + "simulate:\n  duration: 1\n  rtol: 1e-15\n");
  EXPECT_EQ(scenario.simulate.rtol, tolerances::kMinRtol);
  EXPECT_EQ(scenario.simulate.atol, tolerances::kMinRtol * tolerances::kAtolPerRtol);
  ASSERT_EQ(scenario.warnings.size(), 1u);
  EXPECT_NE(scenario.warnings[0].find(":6:9: simulate.rtol: rtol 1e-15 is below what round-off "
                                      "allows (100 eps = 2.220446e-14"),
            std::string::npos)
      << scenario.warnings[0];
  EXPECT_NE(scenario.warnings[0].find("raised to 2.220446e-14"), std::string::npos);
}

TEST(ScenarioError, RtolAndAtolHaveTheIntegratorsRanges) {
  expect_load_error(kHead + kSphere + "simulate:\n  duration: 1\n  rtol: 1.5\n",
                    {6, 9, "simulate.rtol", "rtol must be in (0, 1) (e.g. 1e-8; below 2.2e-14"});
  expect_load_error(kHead + kSphere + "simulate:\n  duration: 1\n  rtol: 0\n",
                    {6, 9, "simulate.rtol", "got 0"});
  expect_load_error(kHead + kSphere + "simulate:\n  duration: 1\n  atol: 0\n",
                    {6, 9, "simulate.atol", "atol must be > 0 and finite"});
  expect_load_error(kHead + kSphere + "simulate:\n  duration: 0\n",
                    {5, 13, "simulate.duration", "duration must be > 0 (s), got 0"});
}

TEST(ScenarioError, TheTrajectoryMustStayInTheOutputDirectory) {
  expect_load_error(kHead + kSphere + kSimulate + "output:\n  trajectory: /tmp/run.csv\n",
                    {6, 15, "output.trajectory", "'/tmp/run.csv' is an absolute path"});
  expect_load_error(kHead + kSphere + kSimulate + "output:\n  trajectory: runs/../../run.csv\n",
                    {6, 15, "output.trajectory", "leaves the output directory through '..'"});
}

TEST(ScenarioError, GroundIsNotABodyName) {
  expect_load_error(
      kHead + "bodies:\n  ground: {shape: box, size: [9, 9, 1], mass: 1}\n" + kSimulate,
      {3, 3, "bodies.ground", "'ground' is the reserved name of the fixed world"});
}

TEST(ScenarioError, APointIsNoBodyOnItsOwn) {
  expect_load_error(
      kHead + "bodies:\n  dot: {shape: point, mass: 1}\n" + kSimulate,
      {3, 16, "bodies.dot.shape",
       "a point has no inertia at all: free, nothing would say how it turns about its "
       "COM"});
  expect_load_error(kHead + "bodies:\n  b: {shape: cube, size: [1, 1, 1], mass: 1}\n" + kSimulate,
                    {3, 14, "bodies.b.shape", "unknown shape 'cube'; did you mean 'box'?"});
}

TEST(ScenarioError, APointNeedsAMassNotADensity) {
  expect_load_error(
      kHead + "bodies:\n  b:\n    parts:\n      - {shape: point, density: 3}\n" + kSimulate,
      {5, 24, "bodies.b.parts[0].density", "a point has no size"});
}

TEST(ScenarioError, ACompositeTakesItsMassFromItsParts) {
  expect_load_error(kHead +
                        "bodies:\n  b:\n    mass: 3\n    parts:\n"
                        "      - {shape: sphere, radius: 1, mass: 1}\n" +
                        kSimulate,
                    {4, 5, "bodies.b.mass", "a composite body's mass is the sum of its parts'"});
}

TEST(ScenarioError, AMissingMeshFileIsAnError) {
  expect_load_error(kHead + "bodies:\n  b: {shape: mesh, file: nowhere.obj, mass: 1}\n" + kSimulate,
                    {3, 26, "bodies.b.file", "cannot read mesh file 'nowhere.obj'"});
}

TEST(ScenarioError, DuplicateKeysAreErrors) {
  expect_load_error(
      kHead + "bodies:\n  b: {shape: sphere, radius: 1, mass: 1, mass: 2}\n" + kSimulate,
      {3, 42, "bodies.b.mass", "duplicate key 'mass' (first given on line 3)"});
}

// A force and a contact both named floor would both write floor.P and floor.W: two columns of one
// name, of which a plot or an expression could only ever find the first.
TEST(ScenarioError, BodiesJointsForcesAndContactsShareOneSetOfNames) {
  const std::string crate =
      "bodies:\n  crate: {shape: box, size: [0.4, 0.3, 0.2], mass: 2, position: [0, 0, 0.1]}\n";
  const std::string spring =
      "  - {type: spring, name: floor, bodies: [ground, crate], stiffness: 1, "
      "at: [[0, 0, 0], [0, 0, 0]]}\n";
  expect_load_error(
      kHead + crate + "forces:\n" + spring +
          "contacts:\n  - {name: floor, type: plane, body: crate, "
          "plane: {point: [0, 0, 0], normal: [0, 0, 1]}}\n" +
          kSimulate,
      {7, 6, "contacts[0].name", "'floor' already names a spring (line 5, column 5)"});
  expect_load_error(kHead + crate +
                        "forces:\n  - {type: torque, name: crate, body: crate, value: [0, "
                        "0, 1]}\n" +
                        kSimulate,
                    {5, 20, "forces[0].name", "'crate' already names a body (line 3, column 3)"});
  // A default name counts too: the second force's "force2" is taken by the first's own name.
  expect_load_error(kHead + crate +
                        "forces:\n  - {type: force, name: force2, body: crate, value: [1, 0, 0]}\n"
                        "  - {type: force, body: crate, value: [1, 0, 0]}\n" +
                        kSimulate,
                    {6, 5, "forces[1]", "'force2' already names a force (line 5, column 5)"});
  expect_load_error(
      kHead + crate + "joints:\n  crate: {type: ball, body: crate, at: [0, 0, 0]}\n" + kSimulate,
      {5, 3, "joints.crate", "'crate' already names a body (line 3, column 3)"});
}

// A name heads CSV columns and shows in messages and on the animation page: a NUL byte or a
// terminal's escape in it would cut the header short or rewrite the user's screen.
TEST(ScenarioError, AControlCharacterInANameIsRefusedAndShownEscaped) {
  expect_load_error(
      kHead + "bodies:\n  \"ba\\0ll\": {shape: sphere, radius: 0.1, mass: 2}\n" + kSimulate,
      {3, 3, "bodies.ba\\x00ll", "body name 'ba\\x00ll' holds a control character"});
  expect_load_error(kHead + kSphere +
                        "forces:\n  - {type: force, name: \"f\\e[2J\", body: ball, "
                        "value: [1, 0, 0]}\n" +
                        kSimulate,
                    {5, 19, "forces[0].name", "force name 'f\\x1B[2J' holds a control character"});
}

}  // namespace
}  // namespace tumble

namespace tumble {
namespace {

// A read with a ParameterTrace notes each number that uses a followed parameter, or one defined
// from it (in the file or by --set), with its key path and text; numbers that do not are not
// noted.
TEST(Scenario, ATraceNotesWhereTheFollowedParametersReach) {
  const char* const text = R"(tumble: 1
parameters: {a: 1, b: 2 * a, c: 3, d: 0}
bodies:
  block:
    shape: box
    size: [b, 1, c]
    mass: 2
    velocity: [a, c, d]
    angular_velocity: [0, 0, 0]
simulate: {duration: a + 1}
)";
  const ScenarioDocument document = ScenarioDocument::from_text(text, "trace.yaml");
  ParameterTrace trace{{"a"}, {}};
  const Scenario scenario = document.read({{"d", "c - a"}}, true, &trace);
  EXPECT_EQ(trace.followed, (std::vector<std::string>{"a", "b", "d"}));
  std::vector<std::string> paths, expressions;
  for (const ParameterTrace::Use& use : trace.uses) {
    paths.push_back(use.path);
    expressions.push_back(use.expression);
  }
  EXPECT_EQ(paths, (std::vector<std::string>{"parameters.b", "parameters.d", "bodies.block.size[0]",
                                             "bodies.block.velocity[0]", "bodies.block.velocity[2]",
                                             "simulate.duration"}));
  EXPECT_EQ(expressions, (std::vector<std::string>{"2 * a", "c - a", "b", "a", "d", "a + 1"}));
  EXPECT_EQ(scenario.bodies[0].velocity_W, Vec3(1, 3, 2));
}

// A chain of parameters, each defined from the one above, is followed link by link (the trace
// looks names up by hash as its list grows: a search of the list would make a long chain
// quadratic); a parameter off the chain is not.
TEST(Scenario, ATraceFollowsAChainOfParameters) {
  constexpr int kCount = 1000;
  std::string text = "tumble: 1\nparameters:\n  p0: 1\n  q: 2\n";
  for (int i = 1; i < kCount; ++i) text += fmt::format("  p{}: p{} + 1\n", i, i - 1);
  text += fmt::format(
      "bodies:\n  ball: {{shape: sphere, radius: 0.1, mass: q, velocity: [p{}, 0, "
      "q]}}\nsimulate: {{duration: 1}}\n",
      kCount - 1);
  const ScenarioDocument document = ScenarioDocument::from_text(text, "chain.yaml");
  ParameterTrace trace{{"p0"}, {}};
  const Scenario scenario = document.read({}, true, &trace);
  ASSERT_EQ(trace.followed.size(), static_cast<std::size_t>(kCount));
  for (int i = 0; i < kCount; ++i) EXPECT_EQ(trace.followed[i], fmt::format("p{}", i));
  ASSERT_EQ(trace.uses.size(), static_cast<std::size_t>(kCount));
  EXPECT_EQ(trace.uses.back().path, "bodies.ball.velocity[0]");
  EXPECT_EQ(trace.uses.front().path, "parameters.p1");
  EXPECT_EQ(scenario.bodies[0].velocity_W, Vec3(kCount, 0, 2));
}

}  // namespace
}  // namespace tumble
