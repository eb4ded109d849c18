// tumble modes with bodies touching planes: the contacts' constraints reduce the linearisation
// (rolling: the point does not move; frictionless: it stays on the plane), and the modes are
// those on the constraints' tangent space. Against closed forms to 1e-9 relative (the Jacobian
// is exact to round-off), and, where there is none, against the integrated motion.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "modes_checks.hpp"
#include "run_tumble.hpp"
#include "scenario_run.hpp"
#include "test_files.hpp"
#include "tumble/modes/scenario_modes.hpp"

namespace tumble {
namespace {

using test::example;
using test::expect_relative;
using test::replaced;

ScenarioModes modes_of_text(const std::string& yaml,
                            const std::vector<ParameterOverride>& sets = {}) {
  return modes_of_scenario(load_scenario_text(yaml, "inline.yaml", sets));
}

std::size_t count_of(const ModalAnalysis& analysis, Mode::Kind kind) {
  std::size_t count = 0;
  for (const Mode& mode : analysis.modes) count += mode.kind == kind ? 1 : 0;
  return count;
}

// The modes live on the constraints' tangent space T, which the flow keeps: A T lies in T.
void expect_tangent_space_kept(const Linearisation& lin) {
  const MatX& T = lin.tangent;
  const MatX AT = lin.A * T;
  const double leak = (AT - T * (T.transpose() * AT)).cwiseAbs().maxCoeff();
  EXPECT_LE(leak, 1e-10 * (1.0 + lin.A.cwiseAbs().maxCoeff()));
}

// A disk (or a ring) rolling upright along x at spin Omega: the lean obeys
// (I_d + M r^2) phi'' = (M g r - (I_a + M r^2) I_a Omega^2 / I_d) phi
// (examples/modes/rolling_disk), the heading and the spin are neutral families (a steady turn,
// another speed).
TEST(ModesContact, RollingDiskWobblesAboveItsCriticalSpinAndFallsBelow) {
  const double M = 2, r = 0.3, g = 9.81;
  const std::string disk = test::read_file(example("modes/rolling_disk.yaml"));
  for (const bool ring : {false, true}) {
    const double I_a = ring ? M * r * r : M * r * r / 2;
    const double I_d = ring ? M * r * r / 2 : M * r * r / 4;
    const std::string yaml = ring ? replaced(disk, "shape: disk", "shape: ring") : disk;
    // Uniform disk: critical at Omega^2 = g / (3 r), 3.30 rad/s; the ring at g / (4 r), 2.86.
    for (const double Omega : {10.0, 4.0, 3.0, 2.0}) {
      const ScenarioModes modes = modes_of_text(yaml, {{"Omega", std::to_string(Omega)}});
      const Linearisation& lin = modes.linearisation;
      ASSERT_EQ(lin.symmetries.size(), 1U);  // its spin about its axis
      expect_relative(std::abs(lin.symmetry_rates(0)), Omega);
      ASSERT_EQ(lin.neutral_symmetries.size(), 1U);  // the heading
      expect_tangent_space_kept(lin);
      const double lambda_squared =
          (M * g * r - (I_a + M * r * r) * I_a * Omega * Omega / I_d) / (I_d + M * r * r);
      const ModalAnalysis& analysis = modes.analysis;
      ASSERT_EQ(analysis.modes.size(), lambda_squared < 0 ? 3U : 4U);
      EXPECT_EQ(count_of(analysis, Mode::Kind::Neutral), 2U);
      if (lambda_squared < 0) {
        EXPECT_EQ(analysis.verdict, ModalAnalysis::Verdict::Stable) << Omega;
        EXPECT_EQ(analysis.modes[0].kind, Mode::Kind::Oscillating);
        expect_relative(analysis.modes[0].damped_frequency, std::sqrt(-lambda_squared));
      } else {
        EXPECT_EQ(analysis.verdict, ModalAnalysis::Verdict::Unstable) << Omega;
        expect_relative(analysis.modes[0].growth_rate, std::sqrt(lambda_squared));
        expect_relative(analysis.modes[1].growth_rate, -std::sqrt(lambda_squared));
      }
    }
  }
}

// At rest on its rim: rolling, it pivots about the contact point, (I_d + M r^2) phi'' = M g r phi;
// on ice its COM only moves vertically, I_d phi'' = M g r phi (to first order).
TEST(ModesContact, DiskOnItsRimFallsAboutTheContactOrItsCentre) {
  const double M = 2, r = 0.3, g = 9.81, I_d = M * r * r / 4;
  const std::string disk = test::read_file(example("modes/rolling_disk.yaml"));
  for (const bool ice : {false, true}) {
    const std::string yaml = ice ? replaced(disk, "friction: 0.8", "friction: 0") : disk;
    const ScenarioModes modes = modes_of_text(yaml, {{"Omega", "0"}});
    EXPECT_TRUE(modes.linearisation.equilibrium());
    expect_tangent_space_kept(modes.linearisation);
    EXPECT_EQ(modes.analysis.verdict, ModalAnalysis::Verdict::Unstable);
    const double lambda = std::sqrt(M * g * r / (ice ? I_d : I_d + M * r * r));
    expect_relative(modes.analysis.modes[0].growth_rate, lambda);
  }
}

// A cube balanced on a vertex, its COM above it: a body pivoted at that point, tipping either way
// at lambda^2 = M g d / I_P (d = a sqrt(3) / 2, I_P = M a^2 / 6 + M d^2); its turn about the
// vertical is neutral.
TEST(ModesContact, CubeOnAVertexTipsLikeAnInvertedPendulum) {
  const double M = 1.5, a = 0.2, g = 9.81;
  const double d = a * std::sqrt(3.0) / 2;
  const double lambda = std::sqrt(M * g * d / (M * a * a / 6 + M * d * d));
  const ScenarioModes modes = modes_of_text(R"(tumble: 1
parameters: {a: 0.2, M: 1.5, g: 9.81}
gravity: [0, 0, -g]
bodies:
  cube:
    shape: box
    size: [a, a, a]
    mass: M
    position: [0, 0, a*sqrt(3)/2]
    orientation: {axis: [1, -1, 0], angle: acos(1/sqrt(3))}
contacts:
  - {name: floor, type: plane, body: cube, plane: {point: [0, 0, 0], normal: [0, 0, 1]},
     friction: 1}
simulate: {duration: 1}
)");
  EXPECT_TRUE(modes.linearisation.equilibrium());
  EXPECT_EQ(modes.analysis.verdict, ModalAnalysis::Verdict::Unstable);
  ASSERT_EQ(modes.analysis.modes.size(), 5U);  // two tips, each growing and decaying; the spin
  expect_relative(modes.analysis.modes[0].growth_rate, lambda);
  expect_relative(modes.analysis.modes[1].growth_rate, lambda);
  expect_relative(modes.analysis.modes[2].growth_rate, 0.0 - lambda);
  expect_relative(modes.analysis.modes[3].growth_rate, 0.0 - lambda);
  EXPECT_EQ(modes.analysis.modes[4].kind, Mode::Kind::Neutral);
}

// A top spinning upright on its apex (sticking: a fixed point): I_t xi'' - i I_a w xi' - M g l xi =
// 0 for its lean xi = theta_x + i theta_y (examples/modes/sleeping_top.yaml). It sleeps when (I_a
// w)^2 > 4 I_t M g l, nutating and precessing at (I_a w +- sqrt(D)) / (2 I_t); below, it grows at
// sqrt(-D) / (2 I_t) while turning at I_a w / (2 I_t).
TEST(ModesContact, TopSleepsOnItsApexAboveTheCriticalSpin) {
  const double r = 0.05, h = 0.04, M = 0.1, g = 9.81, l = 3 * h / 4;
  const double I_a = 3 * M * r * r / 10;
  const double I_t = 3 * M * r * r / 20 + 3 * M * h * h / 80 + M * l * l;
  for (const double w : {100.0, 60.0, 40.0, 0.0}) {
    const ScenarioModes modes = modes_of_scenario(
        load_scenario(example("modes/sleeping_top.yaml"), {{"w", std::to_string(w)}}));
    expect_tangent_space_kept(modes.linearisation);
    const double D = std::pow(I_a * w, 2) - 4 * I_t * M * g * l;
    const ModalAnalysis& analysis = modes.analysis;
    if (D > 0) {
      EXPECT_EQ(analysis.verdict, ModalAnalysis::Verdict::Stable) << w;
      ASSERT_EQ(count_of(analysis, Mode::Kind::Oscillating), 2U);
      expect_relative(analysis.modes[0].damped_frequency, (I_a * w - std::sqrt(D)) / (2 * I_t));
      expect_relative(analysis.modes[1].damped_frequency, (I_a * w + std::sqrt(D)) / (2 * I_t));
    } else {
      EXPECT_EQ(analysis.verdict, ModalAnalysis::Verdict::Unstable) << w;
      test::expect_undamped_twins(analysis);
      expect_relative(analysis.modes[0].growth_rate, std::sqrt(-D) / (2 * I_t));
      if (w > 0) {
        expect_relative(analysis.modes[0].damped_frequency, I_a * w / (2 * I_t));
      }
    }
  }
}

// A ball on a slope at rest is no equilibrium: it rolls down at (5/7) g sin(alpha), held by a
// friction force (2/7) M g sin(alpha) and N = M g cos(alpha).
TEST(ModesContact, BallOnASlopeRollsDownWithTheChaptersAcceleration) {
  const double M = 0.4, g = 9.81, alpha = 20.0 * std::numbers::pi / 180.0;
  const Scenario scenario = load_scenario_text(R"(tumble: 1
parameters: {r: 0.1, M: 0.4, g: 9.81, alpha: 20 deg}
gravity: [0, 0, -g]
bodies:
  ball: {shape: sphere, radius: r, mass: M, position: [-r*sin(alpha), 0, r*cos(alpha)]}
contacts:
  - {name: slope, type: plane, body: ball,
     plane: {point: [0, 0, 0], normal: [-sin(alpha), 0, cos(alpha)]}, friction: 0.5}
simulate: {duration: 1}
)",
                                               "inline.yaml", {});
  const std::shared_ptr<const ModalEquations> equations = modal_equations_of(scenario);
  const VecX rates = equations->rates<double>(VecX::Zero(equations->layout().size()));
  const Vec3 n(-std::sin(alpha), 0, std::cos(alpha));
  const Vec3 down_slope(-std::cos(alpha), 0, -std::sin(alpha));
  // The ball's speeds' rates: vx vy vz after its six positions.
  const Vec3 a_G = rates.segment<3>(6);
  EXPECT_NEAR((a_G - 5.0 / 7.0 * g * std::sin(alpha) * down_slope).norm(), 0.0, 1e-12 * g);
  // Its angular acceleration (body axes, the last three) is a_G / r, about the slope's horizontal.
  expect_relative(rates.segment<3>(9).norm(), 5.0 / 7.0 * g * std::sin(alpha) / 0.1);
  const std::vector<Vec3> forces = equations->contact_forces();
  ASSERT_EQ(forces.size(), 1U);
  expect_relative(forces[0].dot(n), M * g * std::cos(alpha));
  expect_relative((forces[0] - forces[0].dot(n) * n).norm(), 2.0 / 7.0 * M * g * std::sin(alpha));
  EXPECT_THROW(
      {
        try {
          linearise(*equations);
        } catch (const NotSteady& e) {
          EXPECT_NE(std::string(e.what()).find("ball.wy changes at -23.96"), std::string::npos)
              << e.what();
          throw;
        }
      },
      NotSteady);
}

// The coin of examples/rolling_coin.yaml, rolling in a circle: steady as a turn about the vertical
// at Omega^2 = g tan(theta) / (3 rho / 2 + r sin(theta) / 4) and a spin s about its axis. Its
// wobble has no closed form here: it is held to the integrated motion, pushed off by 1e-5 of its
// precession, whose height then oscillates at the wobble's frequency. The push also moves it to a
// neighbouring steady circle, whose wobble is slower by about 3.5 times the push (3.5e-7), and
// the wobble's amplitude (2.4e-9 m) stays a thousand times the integration's error (atol 1e-12
// m): 2e-6 bounds both.
TEST(ModesContact, CoinRollingInACircleWobblesAsItsIntegratedMotionDoes) {
  const double r = 0.0125, theta = 15.0 * std::numbers::pi / 180.0, rho = 0.1, g = 9.81;
  const double Omega = std::sqrt(g * std::tan(theta) / (1.5 * rho + 0.25 * r * std::sin(theta)));
  const double s = -Omega * (rho + r * std::sin(theta)) / r;
  const ScenarioModes modes = test::modes_of(example("rolling_coin.yaml"));
  const Linearisation& lin = modes.linearisation;
  ASSERT_EQ(lin.symmetries.size(), 2U);
  expect_relative(lin.symmetry_rates(0), s);
  expect_relative(lin.symmetry_rates(1), Omega);
  expect_tangent_space_kept(lin);
  EXPECT_EQ(modes.analysis.verdict, ModalAnalysis::Verdict::Stable);
  ASSERT_EQ(modes.analysis.modes[0].kind, Mode::Kind::Oscillating);
  const double wobble = modes.analysis.modes[0].damped_frequency;

  Scenario pushed = load_scenario(example("rolling_coin.yaml"), {{"lean", "1.00001"}});
  pushed.simulate.output_every = 0.002;
  pushed.simulate.duration = 1.5;
  const test::ScenarioRun run = test::run_scenario(std::move(pushed));
  std::vector<double> t, z, vz;
  double low = 1e300, high = -1e300;
  for (const test::Row& row : run.rows) {
    low = std::min(low, row.states[0].r_G.z());
    high = std::max(high, row.states[0].r_G.z());
  }
  for (const test::Row& row : run.rows) {
    t.push_back(row.t);
    z.push_back(row.states[0].r_G.z() - (low + high) / 2);
    vz.push_back(row.states[0].v_G.z());
  }
  const std::vector<double> up = test::upward_zero_crossings(t, z, vz);
  ASSERT_GE(up.size(), 5U);
  const double period = (up.back() - up.front()) / static_cast<double>(up.size() - 1);
  EXPECT_NEAR(2 * std::numbers::pi / period, wobble, 2e-6 * wobble);
}

TEST(ModesContact, RefusesWhatHasNoLinearisationAndSaysWhy) {
  const auto expect_refused = [](const std::string& path, const std::string& why,
                                 const std::vector<ParameterOverride>& sets = {}) {
    try {
      test::modes_of(path, sets);
      ADD_FAILURE() << path << ": no NotSteady";
    } catch (const NotSteady& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  expect_refused(example("box_slides_to_rest.yaml"), "rests on an edge or a face");
  expect_refused(example("ramp_race.yaml"), "rests along a line of its side");
  expect_refused(example("backspin_disk.yaml"), "slides at");
  // The coin needs mu >= 0.18 to hold its circle.
  const std::string coin = test::read_file(example("rolling_coin.yaml"));
  try {
    modes_of_text(replaced(coin, "friction: 0.5", "friction: 0.1"));
    ADD_FAILURE() << "no NotSteady";
  } catch (const NotSteady& e) {
    EXPECT_NE(std::string(e.what()).find("more than mu N"), std::string::npos) << e.what();
  }
  // A pendulum swinging through its lowest point on a frictionless floor: the hinge holds the
  // bob's height there to first order (its contact's row repeats the joint's), but its
  // centripetal acceleration w^2 L lifts it off the floor, which no force of the floor's holds.
  const char* const swinging = R"(tumble: 1
gravity: [0, 0, -9.81]
bodies:
  bob: {shape: sphere, radius: 0.05, mass: 1, position: [0, 0, -0.5], angular_velocity: [0, 2, 0]}
joints:
  pin: {type: hinge, body: bob, at: [0, 0, 0], axis: [0, 1, 0]}
contacts:
  - {name: floor, type: plane, body: bob, friction: 0,
     plane: {point: [0, 0, -0.55], normal: [0, 0, 1]}}
simulate: {duration: 1}
)";
  try {
    modes_of_text(swinging);
    ADD_FAILURE() << "no NotSteady";
  } catch (const NotSteady& e) {
    EXPECT_NE(std::string(e.what()).find("otherwise than the contact would hold it"),
              std::string::npos)
        << e.what();
  }
}

TEST(ModesContact, CommandWritesTheRollingDisksModes) {
  const std::filesystem::path out = test::fresh_test_dir("ModesContact", "Command");
  const test::CommandResult result =
      test::run_tumble("modes " + example("modes/rolling_disk.yaml") + " --out " + out.string());
  EXPECT_EQ(result.status, 0) << result.out;
  EXPECT_NE(result.out.find("contact ground: rolling or sticking"), std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("verdict: stable"), std::string::npos) << result.out;
  EXPECT_TRUE(std::filesystem::exists(out / "rolling_disk_modes.csv"));
}

}  // namespace
}  // namespace tumble
