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
// The same laws hold against the other surfaces in one direction, with rho the centre's distance
// from the axis it swings about (in a pipe's bore, on a log, over a torus's tube), and against a
// point (a cone's apex) in both; a flat face is neutral. Two capsules that cross rock as a plank
// on a cylinder.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
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

// The ball (the second body, the other fixed) rolling steadily at speed v, its centre on a
// circle of radius rho about a horizontal axis, at the top (`up` -1: the circle's centre below)
// or the bottom (+1): its centre accelerates at v^2 / rho towards that axis, its spin is steady
// and the push on it is m (g + up v^2 / rho), straight up (`on_ball` -1 where the contact's force
// is the other's).
void expect_steady_roll(const ModalEquations& equations, double v, double rho, double up,
                        double on_ball = 1.0) {
  const VecX rates = equations.rates<double>(VecX::Zero(equations.layout().size()));
  // The ball's speeds' rates: vx vy vz after its six positions, then its angular acceleration.
  EXPECT_NEAR((Vec3(rates.segment<3>(6)) - Vec3(0, 0, up * v * v / rho)).norm(), 0.0,
              1e-12 * v * v / rho);
  EXPECT_NEAR(Vec3(rates.segment<3>(9)).norm(), 0.0, 1e-12 * v / kr);
  const std::vector<Vec3> forces = equations.contact_forces();
  ASSERT_EQ(forces.size(), 1U);
  EXPECT_NEAR((on_ball * forces[0] - Vec3(0, 0, km * (kG + up * v * v / rho))).norm(), 0.0,
              1e-12 * km * kG);
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
    expect_steady_roll(*equations, v, rho, -1.0, ball_first ? 1.0 : -1.0);
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

// A ball (radius r = 0.05, mass m = 0.2) with friction `mu` (inf: rolling; 0: frictionless)
// against a fixed body `other` (a line of its yaml after its name), its centre at `ball_at`,
// moving at `velocity` and turning at `spin` (world axes).
std::string ball_against(const std::string& other, const std::string& ball_at, double mu,
                         const std::string& velocity = "0, 0, 0",
                         const std::string& spin = "0, 0, 0") {
  return "tumble: 1\n"
         "gravity: [0, 0, -" +
         std::to_string(kG) +
         "]\n"
         "bodies:\n"
         "  other: {" +
         other +
         ", mass: 5}\n"
         "  ball: {shape: sphere, radius: 0.05, mass: 0.2, position: [" +
         ball_at + "], velocity: [" + velocity + "], angular_velocity: [" + spin +
         "]}\n"
         "joints:\n"
         "  stand: {type: fixed, bodies: [ground, other], at: [0, 0, 0]}\n"
         "contacts:\n"
         "  - {name: touch, type: bodies, bodies: [ball, other], friction: " +
         (mu > 1e300 ? std::string("inf") : std::to_string(mu)) +
         ", restitution: 0}\n"
         "simulate: {duration: 1}\n";
}

// A pipe (a tube of bore a = 0.3) lying along x, the ball inside it.
const std::string kPipe =
    "shape: tube, inner_radius: 0.3, outer_radius: 0.35, length: 2, orientation: {axis: [0, 1, "
    "0], angle: 90 deg}";

// At the bottom of the pipe's bore the ball's centre is on a circle of radius rho = a - r about
// the pipe's axis: it swings across the pipe as in a bowl, at omega^2 = 5 g / (7 rho) rolling
// (g / rho frictionless), and along the pipe nothing holds it back. The bore is the tube's inner
// cylinder (pair_core.hpp), its point sliding round at a / rho of the centre's motion.
TEST(ModesOfTouchingBodies, ABallInAPipeSwingsAcrossItAtTheClosedFormsFrequency) {
  const double rho = 0.3 - kr;
  for (const double mu : {1e301, 0.0}) {
    SCOPED_TRACE(mu);
    const ScenarioModes modes = modes_of_scenario(
        load_scenario_text(ball_against(kPipe, "0, 0, -0.25", mu), "pipe.yaml", {}));
    const std::vector<double> found = oscillating_frequencies(modes.analysis);
    ASSERT_EQ(found.size(), 1U);
    expect_relative(found[0], mu > 0.0 ? std::sqrt(5 * kG / (7 * rho)) : std::sqrt(kG / rho));
    for (const Mode& mode : modes.analysis.modes) EXPECT_NE(mode.kind, Mode::Kind::Growing);
    const std::vector<Vec3> forces = modes.equations->contact_forces();
    ASSERT_EQ(forces.size(), 1U);
    EXPECT_NEAR((forces[0] - Vec3(0, 0, km * kG)).norm(), 0.0, 1e-12 * km * kG);
  }
}

// examples/modes/ball_in_a_pipe.yaml: a marble (r = 0.01) in a pipe of bore a = 0.15, as above.
TEST(ModesOfTouchingBodies, TheMarbleInAPipeExampleSwingsAtTheClosedFormsFrequency) {
  const double rho = 0.15 - 0.01, g = 9.81;
  for (const char* mu : {"0.3", "0"}) {
    SCOPED_TRACE(mu);
    const ScenarioModes modes =
        test::modes_of(test::example("modes/ball_in_a_pipe.yaml"), {{"mu", mu}});
    const std::vector<double> found = oscillating_frequencies(modes.analysis);
    ASSERT_EQ(found.size(), 1U);
    expect_relative(found[0],
                    std::string(mu) == "0" ? std::sqrt(g / rho) : std::sqrt(5 * g / (7 * rho)));
  }
}

// Rolling round the bore at v through its bottom (across the pipe, along y), the ball turning at
// v / r about x: its centre goes round the pipe's axis on the circle of radius rho = a - r, its
// spin is steady (the push passes through its centre, no friction), and the bore pushes
// m (g + v^2 / rho). The contact point runs round the bore at a / rho of the centre's speed: the
// rolling rows' rates take that motion, and without it the centre would seem to be dragged.
TEST(ModesOfTouchingBodies, RollingRoundAPipesBoreItsCentreTurnsUpAtVSquaredOverRho) {
  const double v = 1.2, rho = 0.3 - kr;
  const std::shared_ptr<const ModalEquations> equations = modal_equations_of(load_scenario_text(
      ball_against(kPipe, "0, 0, -0.25", 1e301, "0, 1.2, 0", "-1.2 / 0.05, 0, 0"), "pipe.yaml",
      {}));
  expect_steady_roll(*equations, v, rho, 1.0);
}

// Balanced on top of a round surface of radius R in one direction (a log lying along x: a
// capsule's or a cylinder's side; a torus's tube, across it), the ball's centre moves on a
// circle of radius rho = R + r: it falls away at lambda^2 = 5 g / (7 rho) rolling, g / rho
// frictionless, and along the log (round the torus) nothing holds it. On a cone's apex (R = 0)
// it falls away so in both directions.
TEST(ModesOfTouchingBodies, ABallBalancedOnARoundTopFallsAwayAtTheClosedFormsRate) {
  struct Top {
    const char* name;
    std::string other, ball_at;
    double rho;
    std::size_t falls;  // how many ways it falls away
  };
  const std::vector<Top> tops = {
      {"a capsule log",
       "shape: capsule, radius: 0.1, length: 1, orientation: {axis: [0, 1, 0], angle: 90 deg}",
       "0.1, 0, 0.15", 0.1 + kr, 1},
      {"a cylinder log",
       "shape: cylinder, radius: 0.1, length: 1, orientation: {axis: [0, 1, 0], angle: 90 deg}",
       "-0.2, 0, 0.15", 0.1 + kr, 1},
      {"a torus's tube", "shape: torus, radius: 0.5, tube_radius: 0.1", "0, 0.5, 0.15", 0.1 + kr,
       1},
      // The apex 3h/4 = 0.3 above the cone's COM.
      {"a cone's apex", "shape: cone, radius: 0.2, height: 0.4", "0, 0, 0.35", kr, 2},
  };
  for (const Top& top : tops) {
    for (const double mu : {1e301, 0.0}) {
      SCOPED_TRACE(testing::Message() << top.name << ", mu " << mu);
      const ScenarioModes modes = modes_of_scenario(
          load_scenario_text(ball_against(top.other, top.ball_at, mu), "top.yaml", {}));
      const std::vector<double> found = growth_rates(modes.analysis);
      ASSERT_EQ(found.size(), top.falls);
      for (const double lambda : found) {
        expect_relative(lambda,
                        mu > 0.0 ? std::sqrt(5 * kG / (7 * top.rho)) : std::sqrt(kG / top.rho));
      }
      test::expect_undamped_twins(modes.analysis);
      const std::vector<Vec3> forces = modes.equations->contact_forces();
      ASSERT_EQ(forces.size(), 1U);
      EXPECT_NEAR((forces[0] - Vec3(0, 0, km * kG)).norm(), 0.0, 1e-12 * km * kG);
    }
  }
}

// Rolling over the top of a log (a capsule's or a cylinder's side, a torus's tube) at v across
// it (along y), turning at v / r about x: as over a dome, its centre turns down at v^2 / rho
// (rho = R + r), its spin is steady and the push is m (g - v^2 / rho). The contact point runs
// over the log at R / rho of the centre's speed (round the cylinder's side: its point slides
// round; over a capsule or a torus: its core's point is still and the normal turns), which the
// rows' rates take.
TEST(ModesOfTouchingBodies, RollingOverALogItsCentreTurnsDownAtVSquaredOverRho) {
  const double v = 0.4, rho = 0.1 + kr;
  const std::vector<std::pair<std::string, std::string>> logs = {
      {"shape: capsule, radius: 0.1, length: 1, orientation: {axis: [0, 1, 0], angle: 90 deg}",
       "0.1, 0, 0.15"},
      {"shape: cylinder, radius: 0.1, length: 1, orientation: {axis: [0, 1, 0], angle: 90 deg}",
       "-0.2, 0, 0.15"},
      {"shape: torus, radius: 0.5, tube_radius: 0.1", "0, 0.5, 0.15"},
  };
  for (const auto& [log, ball_at] : logs) {
    SCOPED_TRACE(log);
    const std::shared_ptr<const ModalEquations> equations = modal_equations_of(load_scenario_text(
        ball_against(log, ball_at, 1e301, "0, 0.4, 0", "-0.4 / 0.05, 0, 0"), "log.yaml", {}));
    expect_steady_roll(*equations, v, rho, -1.0);
  }
}

// On a flat face the ball rests with nothing to bring it back or send it away: no mode grows or
// oscillates, and the face carries its weight. On a box's face, and on the middle of a standing
// cylinder's end, over its axis (where the distance from the axis has no derivative, and the face
// needs none).
TEST(ModesOfTouchingBodies, ABallOnAFlatFaceRestsWithNoRestoringForce) {
  const std::vector<std::pair<std::string, std::string>> faces = {
      {"shape: box, size: [1, 1, 0.2]", "0.1, 0.2, 0.15"},
      {"shape: cylinder, radius: 0.3, length: 0.2", "0, 0, 0.15"},
  };
  for (const auto& [face, ball_at] : faces) {
    SCOPED_TRACE(face);
    const ScenarioModes modes =
        modes_of_scenario(load_scenario_text(ball_against(face, ball_at, 0.5), "face.yaml", {}));
    for (const Mode& mode : modes.analysis.modes) EXPECT_EQ(mode.kind, Mode::Kind::Neutral);
    const std::vector<Vec3> forces = modes.equations->contact_forces();
    ASSERT_EQ(forces.size(), 1U);
    EXPECT_NEAR((forces[0] - Vec3(0, 0, km * kG)).norm(), 0.0, 1e-12 * km * kG);
  }
}

// Over a box's edge the push turns as the ball rolls off the edge's side and not as it rolls
// onto the face, and on a ring's axis it touches all round the ring: neither has a
// linearisation, and each is refused by name.
TEST(ModesOfTouchingBodies, OverASeamOrAllRoundACircleTheContactIsRefusedByName) {
  struct Refused {
    std::string other, ball_at, why;
  };
  const std::vector<Refused> refused = {
      {"shape: box, size: [1, 1, 0.2]", "0, 0.5, 0.15",
       "contact touch: the sphere's centre is over a seam of the surface it touches"},
      {"shape: cylinder, radius: 0.1, length: 0.2", "0.1, 0, 0.15",
       "contact touch: the sphere's centre is over a seam of the surface it touches"},
      // A ring of radius 0.03 lying flat, the ball resting in it: its centre sqrt(r^2 - 0.03^2)
      // = 0.04 above the ring's plane.
      {"shape: ring, radius: 0.03", "0, 0, 0.04",
       "contact touch: the sphere's centre is on the axis of the circle it touches"},
  };
  for (const Refused& r : refused) {
    SCOPED_TRACE(r.other);
    try {
      modes_of_scenario(
          load_scenario_text(ball_against(r.other, r.ball_at, 0.5), "refused.yaml", {}));
      ADD_FAILURE() << "no NotSteady";
    } catch (const NotSteady& e) {
      EXPECT_NE(std::string(e.what()).find(r.why), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace tumble
