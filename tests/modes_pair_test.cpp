// tumble modes with two bodies touching: a ball (radius r, mass m, I = 2 m r^2 / 5) on a sphere
// or inside a shell, its point at the contact held to the other body's (rolling), or only along
// the normal (frictionless). Against closed forms to 1e-9 relative (the Jacobian is exact to
// round-off). Its centre moves on a circle of radius rho about the other's centre (rho = R - r in
// a bowl, R + r on a dome); rolling ties its spin to that motion, omega r = rho theta', so its
// kinetic energy is (7/10) m rho^2 theta'^2:
//  - in a fixed bowl it swings as a pendulum of length rho in 5g/7: omega^2 = 5 g / (7 rho), or
//    frictionless (its spin free) g / rho; on a dome it falls away at lambda^2 = 5 g / (7 rho) or
//    g / rho; off the top by theta it rolls down at (5/7) g sin(theta), pressed on by m g
//    cos(theta), held by the friction (2/7) m g sin(theta);
//  - in a bowl of mass M on a level rail (it slides along x, without friction), the momentum
//    along the rail, (M + m) X' + m rho theta', stays zero: with X' = -m rho theta' / (M + m) the
//    kinetic energy is (1/2) m rho^2 (7/5 - m / (M + m)) theta'^2, so across the rail the ball
//    swings at omega^2 = g / (rho (7/5 - m / (M + m))), along it (the bowl held) at 5 g / (7 rho).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "modes_checks.hpp"
#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "tumble/inertia/shapes.hpp"
#include "tumble/modes/not_steady.hpp"
#include "tumble/modes/scenario_modes.hpp"

namespace tumble {
namespace {

using test::expect_relative;
using test::kG;

constexpr double kR = 0.5, kr = 0.05, km = 0.2, kM = 2.0;

// A ball with friction `mu` against a fixed sphere (`bowl` false: on its top, the ball at theta
// from it) or inside a fixed shell (at theta from its bottom). The contact names the ball first,
// which makes it the contact's body (whose force contact_forces gives), or, `ball_first` false,
// second: two spheres' contact is then the dome's, the ball's motion on its other side (a shell
// is always the other side).
std::string ball_on(bool bowl, double mu, const std::string& theta = "0", bool ball_first = true) {
  const std::string body = bowl ? "shape: shell" : "shape: sphere";
  const std::string rho = bowl ? "(R - r)" : "(R + r)";
  const std::string height = bowl ? "R - " + rho + "*cos(theta)" : rho + "*cos(theta)";
  return "tumble: 1\n"
         "parameters: {R: 0.5, r: 0.05, m: 0.2, theta: " +
         theta + "}\ngravity: [0, 0, -" + std::to_string(kG) +
         "]\n"
         "bodies:\n"
         "  other: {" +
         body + ", radius: R, mass: 2, position: [0, 0, " + (bowl ? "R" : "0") +
         "]}\n"
         "  ball: {shape: sphere, radius: r, mass: m, position: [" +
         rho + "*sin(theta), 0, " + height +
         "]}\n"
         "joints:\n"
         "  stand: {type: fixed, bodies: [ground, other], at: [0, 0, 0]}\n"
         "contacts:\n"
         "  - {name: touch, type: bodies, bodies: " +
         (ball_first ? "[ball, other]" : "[other, ball]") +
         ", friction: " + (mu > 1e300 ? std::string("inf") : std::to_string(mu)) +
         ", restitution: 0}\n"
         "simulate: {duration: 1}\n";
}

std::vector<double> oscillating_frequencies(const ModalAnalysis& analysis) {
  std::vector<double> found;
  for (const Mode& mode : analysis.modes) {
    if (mode.kind == Mode::Kind::Oscillating) found.push_back(mode.natural_frequency);
  }
  return found;
}

std::vector<double> growth_rates(const ModalAnalysis& analysis) {
  std::vector<double> found;
  for (const Mode& mode : analysis.modes) {
    EXPECT_NE(mode.kind, Mode::Kind::Oscillating);
    if (mode.kind == Mode::Kind::Growing) found.push_back(mode.growth_rate);
  }
  return found;
}

TEST(ModesOfTouchingBodies, ABallInABowlSwingsAtTheClosedFormsFrequencyRollingOrFrictionless) {
  const double rho = kR - kr;
  for (const double mu : {1e301, 0.0}) {
    SCOPED_TRACE(mu);
    const ScenarioModes modes =
        modes_of_scenario(load_scenario_text(ball_on(true, mu), "bowl.yaml", {}));
    const double expected = mu > 0.0 ? std::sqrt(5 * kG / (7 * rho)) : std::sqrt(kG / rho);
    const std::vector<double> found = oscillating_frequencies(modes.analysis);
    ASSERT_EQ(found.size(), 2U);  // across and along x
    for (const double omega : found) expect_relative(omega, expected);
    // The bowl carries the ball's weight, straight up.
    const std::vector<Vec3> forces = modes.equations->contact_forces();
    ASSERT_EQ(forces.size(), 1U);
    EXPECT_NEAR((forces[0] - Vec3(0, 0, km * kG)).norm(), 0.0, 1e-12 * km * kG);
  }
}

TEST(ModesOfTouchingBodies, ABallOnTopOfADomeFallsAwayAtTheClosedFormsRate) {
  const double rho = kR + kr;
  for (const bool ball_first : {true, false}) {
    for (const double mu : {1e301, 0.0}) {
      SCOPED_TRACE(testing::Message()
                   << mu << (ball_first ? ", the ball first" : ", the dome first"));
      const ScenarioModes modes = modes_of_scenario(
          load_scenario_text(ball_on(false, mu, "0", ball_first), "dome.yaml", {}));
      const double expected = mu > 0.0 ? std::sqrt(5 * kG / (7 * rho)) : std::sqrt(kG / rho);
      const std::vector<double> found = growth_rates(modes.analysis);
      ASSERT_EQ(found.size(), 2U);
      for (const double lambda : found) expect_relative(lambda, expected);
      test::expect_undamped_twins(modes.analysis);
    }
  }
}

TEST(ModesOfTouchingBodies, OffTheTopOfADomeItRollsDownAtFiveSeventhsOfGSinTheta) {
  // Not an equilibrium: the equations themselves, at theta = 30 degrees on the dome's side.
  const double theta = std::acos(std::sqrt(3.0) / 2.0);
  const std::shared_ptr<const ModalEquations> equations =
      modal_equations_of(load_scenario_text(ball_on(false, 1e301, "30 deg"), "dome.yaml", {}));
  const VecX rates = equations->rates<double>(VecX::Zero(equations->layout().size()));
  const Vec3 n(std::sin(theta), 0, std::cos(theta));
  const Vec3 down(std::cos(theta), 0, -std::sin(theta));
  // The ball's speeds' rates: vx vy vz after its six positions; its angular acceleration (body
  // axes, the last three) a / r, about y.
  EXPECT_NEAR((Vec3(rates.segment<3>(6)) - 5.0 / 7.0 * kG * std::sin(theta) * down).norm(), 0.0,
              1e-12 * kG);
  expect_relative(rates(10), 5.0 / 7.0 * kG * std::sin(theta) / kr);
  const std::vector<Vec3> forces = equations->contact_forces();
  ASSERT_EQ(forces.size(), 1U);
  expect_relative(forces[0].dot(n), km * kG * std::cos(theta));
  EXPECT_NEAR(
      (forces[0] - forces[0].dot(n) * n + 2.0 / 7.0 * km * kG * std::sin(theta) * down).norm(), 0.0,
      1e-12 * km * kG);
}

TEST(ModesOfTouchingBodies, RollingOverTheTopOfADomeItsCentreTurnsDownAtVSquaredOverRho) {
  // Over the top at v, rolling (omega r = v), its centre on the circle of radius rho = R + r: it
  // accelerates only towards the dome's centre, at v^2 / rho, its spin steady, the dome pushing
  // m (g - v^2 / rho). The contact point moves over both (at v R / rho over the dome): what the
  // rows' rates take from that motion is in these numbers, as it is in any steady motion's.
  const double v = 1.5, rho = kR + kr;
  for (const bool ball_first : {true, false}) {
    SCOPED_TRACE(ball_first ? "the ball first" : "the dome first");
    const std::string yaml = test::replaced(
        ball_on(false, 1e301, "0", ball_first), "mass: m, position: [",
        "mass: m, velocity: [1.5, 0, 0], angular_velocity: [0, 1.5 / r, 0], position: [");
    const std::shared_ptr<const ModalEquations> equations =
        modal_equations_of(load_scenario_text(yaml, "dome.yaml", {}));
    const VecX rates = equations->rates<double>(VecX::Zero(equations->layout().size()));
    EXPECT_NEAR((Vec3(rates.segment<3>(6)) - Vec3(0, 0, -v * v / rho)).norm(), 0.0,
                1e-12 * v * v / rho);
    EXPECT_NEAR(Vec3(rates.segment<3>(9)).norm(), 0.0, 1e-12 * v / kr);
    const std::vector<Vec3> forces = equations->contact_forces();
    ASSERT_EQ(forces.size(), 1U);
    const double on_ball = ball_first ? 1.0 : -1.0;
    EXPECT_NEAR((on_ball * forces[0] - Vec3(0, 0, km * (kG - v * v / rho))).norm(), 0.0,
                1e-12 * km * kG);
  }
}

TEST(ModesOfTouchingBodies, InABowlOnARailTheBallSwingsFasterAcrossTheRailAsTheBowlRecoils) {
  const std::string yaml =
      "tumble: 1\n"
      "parameters: {R: 0.5, r: 0.05, m: 0.2, M: 2}\n"
      "gravity: [0, 0, -" +
      std::to_string(kG) +
      "]\n"
      "bodies:\n"
      "  bowl: {shape: shell, radius: R, mass: M, position: [0, 0, R]}\n"
      "  ball: {shape: sphere, radius: r, mass: m, position: [0, 0, r]}\n"
      "joints:\n"
      "  rail: {type: prismatic, body: bowl, at: [0, 0, R], axis: [1, 0, 0]}\n"
      "contacts:\n"
      "  - {name: inside, type: bodies, bodies: [bowl, ball], friction: inf, "
      "restitution: 0}\n"
      "simulate: {duration: 1}\n";
  const ScenarioModes modes = modes_of_scenario(load_scenario_text(yaml, "rail.yaml", {}));
  const double rho = kR - kr;
  std::vector<double> found = oscillating_frequencies(modes.analysis);
  ASSERT_EQ(found.size(), 2U);
  std::sort(found.begin(), found.end());
  expect_relative(found[0], std::sqrt(5 * kG / (7 * rho)));
  expect_relative(found[1], std::sqrt(kG / (rho * (7.0 / 5.0 - km / (kM + km)))));
}

// A capsule (radius r_a, length L, mass m) lying across a fixed capsule rail of radius R, rolling
// on it: in the plane of its axis and the vertical it is a plank whose flat underside is r_a below
// its centre, rocking on a circle of radius R. Its potential m g ((R + r_a) cos(theta) + R theta
// sin(theta)) has m g (R - r_a) for its second derivative, and its kinetic energy is
// (I_t + m r_a^2) theta'^2 / 2 to leading order: it rocks at omega^2 = m g (R - r_a) / (I_t + m
// r_a^2), I_t its inertia about a diameter. Rolling along the rail and turning about the
// vertical through the contact are free (no restoring force). Lying along the rail instead is a
// line contact, refused.
std::string capsule_across_a_rail(const std::string& along) {
  return "tumble: 1\n"
         "gravity: [0, 0, -" +
         std::to_string(kG) +
         "]\n"
         "bodies:\n"
         "  rail: {shape: capsule, radius: 0.05, length: 3, mass: 10, orientation: {axis: [1, "
         "0, 0], angle: 90 deg}}\n"
         "  log: {shape: capsule, radius: 0.04, length: 0.4, mass: 1, position: [0, 0, 0.09], "
         "orientation: {axis: [" +
         along +
         "], angle: 90 deg}}\n"
         "joints:\n"
         "  footing: {type: fixed, bodies: [ground, rail], at: [0, 0, 0]}\n"
         "contacts:\n"
         "  - {name: on_rail, type: bodies, bodies: [log, rail], friction: 0.5}\n"
         "simulate: {duration: 1}\n";
}

TEST(ModesOfTouchingBodies, ACapsuleAcrossACapsuleRailRocksAsAPlankOnACylinder) {
  const ScenarioModes modes =
      modes_of_scenario(load_scenario_text(capsule_across_a_rail("0, 1, 0"), "across.yaml", {}));
  const double m = 1, r_a = 0.04, R = 0.05;
  Shape log;
  log.kind = ShapeKind::Capsule;
  log.radius = r_a;
  log.length = 0.4;
  const double I_t = shape_mass_properties(log, m).inertia_about_com(0, 0);
  const std::vector<double> found = oscillating_frequencies(modes.analysis);
  ASSERT_EQ(found.size(), 1U);
  expect_relative(found[0], std::sqrt(m * kG * (R - r_a) / (I_t + m * r_a * r_a)));
  // The rail carries the log's weight, straight up.
  const std::vector<Vec3> forces = modes.equations->contact_forces();
  ASSERT_EQ(forces.size(), 1U);
  EXPECT_NEAR((forces[0] - Vec3(0, 0, m * kG)).norm(), 0.0, 1e-12 * m * kG);
  // Along the rail: a line, refused.
  try {
    modes_of_scenario(load_scenario_text(capsule_across_a_rail("1, 0, 0"), "along.yaml", {}));
    ADD_FAILURE() << "no NotSteady";
  } catch (const NotSteady& e) {
    EXPECT_NE(std::string(e.what()).find("contact on_rail: its two capsules lie along each other"),
              std::string::npos)
        << e.what();
  }
}

TEST(ModesOfTouchingBodies, ABallOnABoxIsRefusedNamingWhatIsLinearised) {
  const std::string yaml =
      "tumble: 1\n"
      "bodies:\n"
      "  block: {shape: box, size: [1, 1, 0.2], mass: 5, position: [0, 0, 0]}\n"
      "  ball: {shape: sphere, radius: 0.05, mass: 0.2, position: [0, 0, "
      "0.15]}\n"
      "joints:\n"
      "  stand: {type: fixed, bodies: [ground, block], at: [0, 0, 0]}\n"
      "contacts:\n"
      "  - {name: on_block, type: bodies, bodies: [ball, block], friction: "
      "0.5}\n"
      "simulate: {duration: 1}\n";
  try {
    modes_of_scenario(load_scenario_text(yaml, "box.yaml", {}));
    ADD_FAILURE() << "no NotSteady";
  } catch (const NotSteady& e) {
    EXPECT_NE(std::string(e.what()).find("contact on_block: its two bodies touch; tumble modes "
                                         "linearises two bodies touching where the other is a "
                                         "sphere or a shell"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace tumble
