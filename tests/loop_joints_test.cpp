// Joints that close loops (multibody/loop_joints.hpp): each mechanism against its exact
// kinematics, its inverse dynamics or its conservation laws, and the loop held at every row.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "test_files.hpp"

namespace tumble {
namespace {

using test::kPi;

// The slider-crank's closed form in the plane of the motion, with X along the guide and Y = -z
// (the crank turns from X towards Y): the crank pin at r (cos theta, sin theta), the wrist pin at
// (x, 0) with x = r cos(theta) + s, s = sqrt(l^2 - r^2 sin^2(theta)). Derivatives by theta.
struct SliderCrankPose {
  double x = 0.0, x1 = 0.0, x2 = 0.0;  // the wrist pin, and its first two derivatives
  Eigen::Vector2d rod_G1, rod_G2;      // the rod's COM's first two derivatives
  double rod_turn1 = 0.0, rod_turn2 = 0.0;
};

// The largest kinetic energy over a run's rows, J: the scale of its energy's drift.
double largest_kinetic_energy(const test::ScenarioRun& run) {
  double largest = 0.0;
  for (const test::Row& row : run.rows) largest = std::max(largest, row.quantities.kinetic_energy);
  return largest;
}

SliderCrankPose slider_crank_pose(double r, double l, double theta) {
  const double u = r * std::sin(theta), u1 = r * std::cos(theta), u2 = -u;
  const double s = std::sqrt(l * l - u * u);
  const double s1 = -u * u1 / s;
  const double s2 = -(u1 * u1 + u * u2) / s - u * u * u1 * u1 / (s * s * s);
  SliderCrankPose p;
  p.x = r * std::cos(theta) + s;
  p.x1 = -u + s1;
  p.x2 = -u1 + s2;
  // The rod's COM is the middle of the crank pin and the wrist pin.
  p.rod_G1 = Eigen::Vector2d((-u + p.x1) / 2.0, u1 / 2.0);
  p.rod_G2 = Eigen::Vector2d((-u1 + p.x2) / 2.0, u2 / 2.0);
  // The rod's direction from the wrist pin to the crank pin, (-s, u): its angle's derivatives.
  p.rod_turn1 = (-s * u1 + u * s1) / (l * l);
  p.rod_turn2 = (-s * u2 + u * s2) / (l * l);
  return p;
}

TEST(LoopJoints, ASliderCrankDrivenAtASpeedFollowsItsClosedFormAndTakesItsTorque) {
  const test::ScenarioRun run =
      test::run_scenario(load_scenario(test::example("slider_crank.yaml"), {}));
  const double r = 0.1, l = 0.35, w = 20.0, theta0 = 30.0 * kPi / 180.0, g = 9.81;
  const double m_crank = 0.5, m_rod = 1.2, m_piston = 2.0, I_rod = m_rod * l * l / 12.0;
  const double x0 = slider_crank_pose(r, l, theta0).x;
  ASSERT_GT(run.rows.size(), 1000U);
  EXPECT_NEAR(run.rows.back().t, 10 * 2 * kPi / w, 1e-12);
  double largest_power = 0.0;
  for (const test::Row& row : run.rows) {
    largest_power = std::max(largest_power, std::abs(row.extras.elements.at(0).power));
  }
  for (const test::Row& row : run.rows) {
    const double theta = theta0 + w * row.t;
    const SliderCrankPose p = slider_crank_pose(r, l, theta);
    const double travel = row.extras.coordinates.at(2).values[0];  // guide.travel
    EXPECT_NEAR(x0 + travel, p.x, 1e-10 * l) << "t " << row.t;
    // The motor's power is the rate of the mechanism's energy: w dE/dtheta at theta' = w, with
    // KE = (w^2 / 2) (m_rod |G'|^2 + I_rod psi'^2 + m_piston x'^2) (the crank's own KE is
    // constant) and PE = -g (m_crank Y_crank + m_rod Y_rod) (gravity along +Y).
    const double dKE = w * w *
                       (m_piston * p.x1 * p.x2 + m_rod * p.rod_G1.dot(p.rod_G2) +
                        I_rod * p.rod_turn1 * p.rod_turn2);
    const double dPE = -g * (m_crank * r / 2.0 * std::cos(theta) + m_rod * p.rod_G1.y());
    EXPECT_NEAR(row.extras.elements.at(0).power, w * (dKE + dPE), 1e-9 * largest_power)
        << "t " << row.t;
    EXPECT_LE(row.extras.loops.gap, 1e-12 * l);
  }
}

// The same slider-crank with its guide listed last: the guide closes the loop, as a slider (two
// point rows across its axis, three turn rows) or as a cylindrical joint (two and two), and the
// wrist pin is a joint of the tree.
TEST(LoopJoints, ASliderCranksGuideMayCloseTheLoop) {
  const std::string text = test::read_file(test::example("slider_crank.yaml"));
  const std::size_t from = text.find("  guide:");
  const std::size_t to = text.find('\n', from) + 1;
  const std::string guide = text.substr(from, to - from);
  std::string reordered = text;
  reordered.erase(from, to - from);
  reordered = test::replaced(reordered, "simulate:", guide + "simulate:");
  for (const bool cylindrical : {false, true}) {
    const std::string yaml =
        cylindrical ? test::replaced(reordered, "{type: prismatic", "{type: cylindrical")
                    : reordered;
    const test::ScenarioRun run = test::run_inline_scenario(yaml, "slider_crank_guide_last");
    ASSERT_TRUE(run.scenario.joints.back().closes_loop);
    ASSERT_EQ(run.scenario.joints.back().name, "guide");
    const double r = 0.1, l = 0.35, w = 20.0, theta0 = 30.0 * kPi / 180.0;
    for (const test::Row& row : run.rows) {
      const double x = slider_crank_pose(r, l, theta0 + w * row.t).x;
      EXPECT_NEAR(row.states.at(2).r_G.x(), x, 1e-10 * l) << "t " << row.t;
      EXPECT_LE(row.extras.loops.gap, 1e-12 * l);
      EXPECT_LE(row.extras.loops.turn, 1e-12);
    }
  }
}

TEST(LoopJoints, TwoShaftsOnAHookeJointTurnAtTheJointsRatio) {
  const test::ScenarioRun run =
      test::run_scenario(load_scenario(test::example("hooke_shafts.yaml"), {}));
  const double beta = 30.0 * kPi / 180.0, w1 = 10.0;
  ASSERT_GT(run.rows.size(), 1000U);
  for (const test::Row& row : run.rows) {
    const double theta1 = row.extras.coordinates.at(0).values[0];  // bearing1.angle
    const double w2 = row.extras.coordinates.at(1).values[1];      // bearing2.rate
    const double sin_beta = std::sin(beta), sin_theta = std::sin(theta1);
    EXPECT_NEAR(w2, w1 * std::cos(beta) / (1.0 - sin_beta * sin_beta * sin_theta * sin_theta),
                1e-10 * w1)
        << "t " << row.t;
    EXPECT_NEAR(theta1, w1 * row.t, 1e-9);
  }
  // Over whole turns the output keeps up with the input: ten turns each.
  EXPECT_NEAR(run.rows.back().extras.coordinates.at(1).values[0], 20.0 * kPi, 1e-9);
}

TEST(LoopJoints, AFourBarFreeUnderGravityConservesEnergyWithItsLoopClosed) {
  std::string text = test::read_file(test::example("four_bar.yaml"));
  text = test::replaced(text, "duration: 10", "duration: 100");
  text = test::replaced(text, "rtol: 1e-10", "rtol: 1e-12");
  text = test::replaced(text, "atol: 1e-12", "atol: 1e-14");
  text = test::replaced(text, "output_every: 0.01", "output_every: 0.05");
  const test::ScenarioRun run = test::run_inline_scenario(text, "four_bar_100s");
  ASSERT_EQ(run.rows.size(), 2001U);
  const double E0 = run.rows.front().quantities.total_energy;
  const double largest_ke = largest_kinetic_energy(run);
  ASSERT_GT(largest_ke, 1.0);  // it moves
  const double scale = std::max(std::abs(E0), largest_ke);
  for (const test::Row& row : run.rows) {
    EXPECT_NEAR(row.quantities.total_energy, E0, 1e-9 * scale) << "t " << row.t;
    EXPECT_LT(row.extras.loops.gap, 1e-10);
    EXPECT_LT(row.extras.loops.speed, 1e-10);
  }
  // The crank turns all the way round (Grashof): the swing from 60 degrees reaches beyond it.
  double turned = 0.0;
  for (const test::Row& row : run.rows) {
    turned = std::max(turned, std::abs(row.extras.coordinates.at(0).values[0]));
  }
  EXPECT_GT(turned, kPi / 3.0);
}

// A torque motor at B, between the coupler and the rocker, for half a second: the same
// mechanism whether B closes the loop (the torque pair is a load on the coupler and the rocker)
// or O4 does (B is a joint of the tree, and the torque its generalised force). The two runs
// agree to their tolerance, and in each the motor's work is what the energy gained.
TEST(LoopJoints, ATorqueAcrossTheClosingJointMovesTheLinkageAsAcrossATreeJoint) {
  std::string text = test::read_file(test::example("four_bar.yaml"));
  text = test::replaced(text, "duration: 10", "duration: 2");
  text = test::replaced(text, "axis: [0, 1, 0]}\nsimulate:",
                        "axis: [0, 1, 0], motor: {torque: 3, from: 0.2, to: 0.7}}\nsimulate:");
  // O4 listed last: it closes the loop, and B is a joint of the tree.
  const std::size_t o4 = text.find("  O4:");
  const std::size_t b = text.find("  B:");
  std::string tree_b = text;
  tree_b.erase(o4, b - o4);
  tree_b = test::replaced(tree_b, "simulate:", text.substr(o4, b - o4) + "simulate:");
  const test::ScenarioRun closing = test::run_inline_scenario(text, "four_bar_motor_closing");
  const test::ScenarioRun in_tree = test::run_inline_scenario(tree_b, "four_bar_motor_in_tree");
  ASSERT_TRUE(closing.scenario.joints.at(3).closes_loop);  // B
  ASSERT_EQ(in_tree.scenario.joints.back().name, "O4");
  ASSERT_TRUE(in_tree.scenario.joints.back().closes_loop);
  ASSERT_EQ(closing.rows.size(), in_tree.rows.size());
  const double E0 = closing.rows.front().quantities.total_energy;
  const double scale = std::max(std::abs(E0), largest_kinetic_energy(closing));
  double work = 0.0;
  for (std::size_t i = 0; i < closing.rows.size(); ++i) {
    const test::Row& c = closing.rows[i];
    const test::Row& t = in_tree.rows[i];
    ASSERT_EQ(c.t, t.t);
    // The crank's angle O2 (joint 0 in both) and the rocker's place (rtol 1e-10 each).
    EXPECT_NEAR(c.extras.coordinates.at(0).values[0], t.extras.coordinates.at(0).values[0], 1e-8)
        << "t " << c.t;
    EXPECT_LT((c.states.at(2).r_G - t.states.at(2).r_G).norm(), 1e-8) << "t " << c.t;
    for (const test::Row* row : {&c, &t}) {
      // B.motor is the first element; E - E0 is its work (the hinges do none).
      EXPECT_NEAR(row->quantities.total_energy - E0, row->extras.elements.at(0).work, 1e-9 * scale)
          << "t " << row->t;
    }
    work = c.extras.elements.at(0).work;
  }
  EXPECT_GT(std::abs(work), 0.1 * scale);  // it did work
}

TEST(LoopJoints, ALockOnAFourBarStopsItAndGroundsItsMomentThroughTheLoop) {
  // The crank locks at t = 0.5 s: a four-bar with its crank held has no freedom left, so every
  // body stops at once. The ground's reaction impulses at O2 (with the lock's moment) and O4,
  // which carries the rocker's and through B the coupler's share, take all the angular momentum.
  std::string text = test::read_file(test::example("four_bar.yaml"));
  text = test::replaced(text, "axis: [0, 1, 0]}", "axis: [0, 1, 0], lock: {at: 0.5}}");
  text = test::replaced(text, "duration: 10", "duration: 1");
  const test::ScenarioRun run = test::run_inline_scenario(text, "four_bar_lock");
  ASSERT_EQ(run.jumps.size(), 1U);
  const JumpRecord& lock = run.jumps.front();
  EXPECT_EQ(lock.t, 0.5);
  ASSERT_GT(lock.kinetic_energy_before, 1.0);
  EXPECT_LT(lock.kinetic_energy_after, 1e-24 * lock.kinetic_energy_before);
  // O2 is joint 0 at the origin, O4 joint 2 at (0.6, 0, 0).
  const JointReaction& O2 = lock.reaction_impulses.at(0);
  const JointReaction& O4 = lock.reaction_impulses.at(2);
  const Vec3 moment = O2.M_J_W + O4.M_J_W + Vec3(0.6, 0.0, 0.0).cross(O4.F_W);
  const Vec3 change = lock.angular_momentum_after_W - lock.angular_momentum_before_W;
  EXPECT_LT((moment - change).norm(), 1e-12 * lock.angular_momentum_before_W.norm());
  for (const test::Row& row : run.rows) {
    EXPECT_LT(row.extras.loops.gap, 1e-12) << "t " << row.t;
    if (row.t >= 0.5) {
      EXPECT_LT(row.quantities.kinetic_energy, 1e-20) << "t " << row.t;
    }
  }
}

TEST(LoopJoints, AFourBarLockedJointByJointStaysStillThoughItsLoopHoldsFewerDirections) {
  // The crank locks at t = 0.5 s (the linkage stops), then the rocker at 0.75 s: with both held,
  // only the coupler's turn about A is left to B's rows, which hold one direction where they held
  // two. That is the tree's freedoms changing at a breakpoint, not a singular position: the run
  // goes on, at rest, with the loop closed.
  std::string text = test::read_file(test::example("planar/four_bar.yaml"));
  text = test::replaced(text, "at: [0, 0]}", "at: [0, 0], lock: {at: 0.5}}");
  text = test::replaced(text, "at: [0.6, 0]}", "at: [0.6, 0], lock: {at: 0.75}}");
  text = test::replaced(text, "duration: 10", "duration: 1");
  const test::ScenarioRun run = test::run_inline_scenario(text, "four_bar_locked_twice");
  ASSERT_EQ(run.jumps.size(), 2U);
  ASSERT_GT(run.jumps[0].kinetic_energy_before, 1.0);
  EXPECT_NEAR(run.rows.back().t, 1.0, 1e-12);
  for (const test::Row& row : run.rows) {
    EXPECT_LT(row.extras.loops.gap, 1e-12) << "t " << row.t;
    if (row.t >= 0.5) {
      EXPECT_LT(row.quantities.kinetic_energy, 1e-20) << "t " << row.t;
    }
  }
}

TEST(LoopJoints, AnImpulseOnAFourBarsCouplerIsSharedByTheLoopWithoutWork) {
  // Struck at rest: the impulse's work is J . v_P / 2, and it is the KE after only if the loop's
  // share of the blow does none (its impulses zero its rows' velocities, which were zero).
  std::string text = test::read_file(test::example("four_bar.yaml"));
  text = test::replaced(text, "gravity: [0, 0, -9.81]", "gravity: [0, 0, 0]");
  text = test::replaced(
      text, "joints:",
      "forces:\n  - {type: impulse, body: coupler, at: [0.35, 0, 0.34], value: [0, 0, -2], "
      "time: 0.2}\njoints:");
  text = test::replaced(text, "duration: 10", "duration: 1");
  const test::ScenarioRun run = test::run_inline_scenario(text, "four_bar_impulse");
  ASSERT_EQ(run.jumps.size(), 1U);
  const JumpRecord& blow = run.jumps.front();
  EXPECT_EQ(blow.kinetic_energy_before, 0.0);
  ASSERT_GT(blow.kinetic_energy_after, 0.01);
  // The row at the blow's instant shows the state after it: the coupler's point's velocity.
  const auto after = std::find_if(run.rows.begin(), run.rows.end(),
                                  [](const test::Row& row) { return row.t >= 0.2; });
  ASSERT_NE(after, run.rows.end());
  ASSERT_EQ(after->t, 0.2);
  const BodyState& coupler = after->states.at(1);
  const Vec3 v_P = coupler.v_G + coupler.omega_W.cross(Vec3(0.35, 0.0, 0.34) - coupler.r_G);
  EXPECT_NEAR(blow.kinetic_energy_after, Vec3(0.0, 0.0, -2.0).dot(v_P) / 2.0,
              1e-12 * blow.kinetic_energy_after);
  // Then no force acts but the joints': KE stays.
  for (const test::Row& row : run.rows) {
    if (row.t < 0.2) continue;
    EXPECT_NEAR(row.quantities.kinetic_energy, blow.kinetic_energy_after,
                1e-9 * blow.kinetic_energy_after)
        << "t " << row.t;
    EXPECT_LT(row.extras.loops.speed, 1e-12) << "t " << row.t;
  }
}

TEST(LoopJoints, AFourBarDrivenPastItsDeadCentreStopsThereSayingSo) {
  // The rocker driven at 1 rad/s swings B away from O2 until the crank and the coupler line up
  // (|O2 B| = crank + coupler = 0.8 m): there the loop loses a direction and the rocker cannot
  // go on. With B = O4 + 0.5 (sin(phi), 0, cos(phi)), |O2 B|^2 = 0.61 + 0.6 sin(phi), which
  // reaches 0.64 at sin(phi) = 0.05.
  std::string text = test::read_file(test::example("four_bar.yaml"));
  text = test::replaced(text, "at: [0.6, 0, 0], axis: [0, 1, 0]}",
                        "at: [0.6, 0, 0], axis: [0, 1, 0], motor: {speed: 1}}");
  text = test::replaced(text, "  rocker:\n", "  rocker:\n    angular_velocity: [0, 1, 0]\n");
  PreparedSimulation simulation = prepare_simulation(test::load_inline_scenario(text, "driven"));
  const SimulationResult result = run_simulation(
      simulation, [](double, std::span<const BodyState>, const SystemQuantities&) {});
  ASSERT_FALSE(result.report.completed);
  const double phi0 = std::atan2(0.6032015300873869 - 0.6, 0.4999897501000391);
  const double t_dead = std::asin(0.05) - phi0;
  // Located as the step that reaches it shrinks: within 1e-9 s before it.
  EXPECT_NEAR(result.report.t_reached, t_dead, 1e-9);
  EXPECT_NE(result.report.failure.find("'B'"), std::string::npos) << result.report.failure;
  EXPECT_NE(result.report.failure.find("dead centre"), std::string::npos) << result.report.failure;
}

TEST(LoopJoints, BricardsMechanismMovesWithTheFreedomTheCountMisses) {
  const test::ScenarioRun run =
      test::run_scenario(load_scenario(test::example("bricard.yaml"), {}));
  ASSERT_EQ(run.rows.size(), 1001U);
  EXPECT_EQ(run.rows.back().t, 10.0);
  const double E0 = run.rows.front().quantities.total_energy;
  const double largest_ke = largest_kinetic_energy(run);
  ASSERT_GT(largest_ke, 1.0);  // it moves: one freedom
  const double scale = std::max(std::abs(E0), largest_ke);
  for (const test::Row& row : run.rows) {
    EXPECT_NEAR(row.quantities.total_energy, E0, 1e-8 * scale) << "t " << row.t;
    EXPECT_LT(row.extras.loops.gap, 1e-13) << "t " << row.t;
    EXPECT_LT(row.extras.loops.turn, 1e-13) << "t " << row.t;
  }
}

// Six links joined in a ring by six parallel hinges: a planar hexagon with three freedoms of its
// own, whose six hinges state three constraints more than the ring needs (each link's plane).
// Thrown spinning about two axes, with two of its hinges flexing at the start, it falls freely.
constexpr const char* kHexagon = R"yaml(tumble: 1
name: hexagon of six links thrown spinning
parameters:
  a: 0.3
  c: a*sqrt(3)/2
  W: 4
  Wx: 1.5
gravity: [0, 0, -9.81]
bodies:
  l1: {shape: box, size: [a, 0.02, 0.01], mass: 1.0, position: [c, 0, 0],
       orientation: {axis: [0, 0, 1], angle: 90 deg}, angular_velocity: [Wx, 0, W],
       velocity: [0, c*W, 0]}
  l2: {shape: box, size: [a, 0.02, 0.01], mass: 1.1, position: ["c*cos(60 deg)", "c*sin(60 deg)", 0],
       orientation: {axis: [0, 0, 1], angle: 150 deg}, angular_velocity: [Wx, 0, W + 1]}
  l3: {shape: box, size: [a, 0.02, 0.01], mass: 1.2, position: ["c*cos(120 deg)", "c*sin(120 deg)", 0],
       orientation: {axis: [0, 0, 1], angle: 210 deg}, angular_velocity: [Wx, 0, W]}
  l4: {shape: box, size: [a, 0.02, 0.01], mass: 1.3, position: [-c, 0, 0],
       orientation: {axis: [0, 0, 1], angle: 270 deg}, angular_velocity: [Wx, 0, W - 2]}
  l5: {shape: box, size: [a, 0.02, 0.01], mass: 1.4, position: ["c*cos(240 deg)", "c*sin(240 deg)", 0],
       orientation: {axis: [0, 0, 1], angle: 330 deg}, angular_velocity: [Wx, 0, W]}
  l6: {shape: box, size: [a, 0.02, 0.01], mass: 1.5, position: ["c*cos(300 deg)", "c*sin(300 deg)", 0],
       orientation: {axis: [0, 0, 1], angle: 30 deg}, angular_velocity: [Wx, 0, W]}
joints:
  h12: {type: hinge, bodies: [l1, l2], at: ["a*cos(30 deg)", "a*sin(30 deg)", 0], axis: [0, 0, 1]}
  h23: {type: hinge, bodies: [l2, l3], at: [0, a, 0], axis: [0, 0, 1]}
  h34: {type: hinge, bodies: [l3, l4], at: ["a*cos(150 deg)", "a*sin(150 deg)", 0], axis: [0, 0, 1]}
  h45: {type: hinge, bodies: [l4, l5], at: ["a*cos(210 deg)", "a*sin(210 deg)", 0], axis: [0, 0, 1]}
  h56: {type: hinge, bodies: [l5, l6], at: [0, -a, 0], axis: [0, 0, 1]}
  h61: {type: hinge, bodies: [l6, l1], at: ["a*cos(330 deg)", "a*sin(330 deg)", 0], axis: [0, 0, 1]}
simulate:
  duration: 5
  integrator: dop853
  rtol: 1e-11
  atol: 1e-13
  output_every: 0.01
)yaml";

TEST(LoopJoints, AHexagonOfHingedLinksThrownSpinningKeepsItsMomentaAndItsHinges) {
  const test::ScenarioRun run = test::run_inline_scenario(kHexagon, "hexagon");
  ASSERT_EQ(run.rows.size(), 501U);
  const Vec3 g(0.0, 0.0, -test::kG);
  double M = 0.0;
  for (const RigidBody& body : run.bodies) M += body.mass;
  // Linear momentum less the weight's impulse, and angular momentum about the moving COM.
  const auto momenta = [&](const test::Row& row, Vec3& P, Vec3& L_G) {
    P = row.quantities.linear_momentum - M * g * row.t;
    Vec3 r_com = Vec3::Zero();
    for (std::size_t i = 0; i < run.bodies.size(); ++i) {
      r_com += run.bodies[i].mass * row.states[i].r_G / M;
    }
    L_G =
        row.quantities.angular_momentum_about_origin - r_com.cross(row.quantities.linear_momentum);
  };
  Vec3 P0, L0;
  momenta(run.rows.front(), P0, L0);
  const double E0 = run.rows.front().quantities.total_energy;
  const double largest_ke = largest_kinetic_energy(run);
  // The hinges flex: the links' rates about z differ from one another at some row.
  double flex = 0.0;
  for (const test::Row& row : run.rows) {
    flex = std::max(flex, std::abs(row.extras.coordinates.at(1).values[1]));  // h23.rate
  }
  EXPECT_GT(flex, 0.1);
  const double momentum_scale = M * test::kG * 5.0 + P0.norm();
  for (const test::Row& row : run.rows) {
    Vec3 P, L_G;
    momenta(row, P, L_G);
    EXPECT_LT((P - P0).norm(), 1e-10 * momentum_scale) << "t " << row.t;
    EXPECT_LT((L_G - L0).norm(), 1e-10 * L0.norm()) << "t " << row.t;
    EXPECT_NEAR(row.quantities.total_energy, E0, 1e-10 * std::max(std::abs(E0), largest_ke))
        << "t " << row.t;
    EXPECT_LT(row.extras.loops.gap, 1e-12);
    EXPECT_LT(row.extras.loops.turn, 1e-12);
  }
}

// A weld closing a loop holds everything a joint can: two bodies hinged to each other and welded
// at the same point swing as one, their hinge never turning, and E stays.
TEST(LoopJoints, AWeldAcrossAHingeHoldsItStill) {
  const test::ScenarioRun run = test::run_inline_scenario(R"(tumble: 1
bodies:
  a: {shape: sphere, radius: 0.1, mass: 1, position: [1, 0, 0]}
  b: {shape: sphere, radius: 0.1, mass: 2, position: [2, 0, 0]}
joints:
  p: {type: hinge, bodies: [ground, a], at: [0, 0, 0], axis: [0, 1, 0]}
  q: {type: hinge, bodies: [a, b], at: [1.5, 0, 0], axis: [0, 1, 0]}
  weld: {type: fixed, bodies: [a, b], at: [1.5, 0, 0]}
simulate: {duration: 3, integrator: dop853, rtol: 1e-10, atol: 1e-12, output_every: 0.01}
)",
                                                          "weld");
  const double E0 = run.rows.front().quantities.total_energy;
  const double largest_ke = largest_kinetic_energy(run);
  ASSERT_GT(largest_ke, 1.0);
  for (const test::Row& row : run.rows) {
    EXPECT_LT(std::abs(row.extras.coordinates.at(1).values[0]), 1e-12) << "t " << row.t;  // q.angle
    EXPECT_NEAR(row.quantities.total_energy, E0, 1e-9 * largest_ke) << "t " << row.t;
    EXPECT_LT(row.extras.loops.turn, 1e-13);
  }
}

// The four-bar closed by a ball joint at B instead of a hinge: the same motion (the plane's
// hinges hold B in it, so the ball's row out of the plane is one no force moves).
TEST(LoopJoints, AFourBarClosedByABallMovesAsByAHinge) {
  const std::string text = test::read_file(test::example("four_bar.yaml"));
  const test::ScenarioRun hinge = test::run_inline_scenario(text, "four_bar_hinge");
  const std::string ball_text =
      test::replaced(test::replaced(text, "B: {type: hinge, bodies: [coupler, rocker]",
                                    "B: {type: ball, bodies: [coupler, rocker]"),
                     "0.4999897501000391], axis: [0, 1, 0]}", "0.4999897501000391]}");
  const test::ScenarioRun ball = test::run_inline_scenario(ball_text, "four_bar_ball");
  ASSERT_EQ(hinge.rows.size(), ball.rows.size());
  for (std::size_t i = 0; i < hinge.rows.size(); ++i) {
    // Both runs are within their tolerance (rtol 1e-10) of the one motion.
    EXPECT_NEAR(ball.rows[i].extras.coordinates.at(0).values[0],
                hinge.rows[i].extras.coordinates.at(0).values[0], 1e-7)
        << "t " << hinge.rows[i].t;
    EXPECT_LT(ball.rows[i].extras.loops.gap, 1e-12);
  }
}

TEST(LoopJoints, WhatLoopsDoNotTakeYetIsRefusedAtItsKey) {
  const std::string links = R"(tumble: 1
bodies:
  a: {shape: sphere, radius: 0.1, mass: 1, position: [1, 0, 0]}
  b: {shape: sphere, radius: 0.1, mass: 1, position: [1, 0, -1]}
joints:
  p: {type: hinge, bodies: [ground, a], at: [0, 0, 0], axis: [0, 1, 0]}
  q: {type: hinge, bodies: [a, b], at: [1, 0, -0.5], axis: [0, 1, 0]}
)";
  const std::string run = "simulate: {duration: 1}\n";
  // A loop's closing joint (r: b is already joined to ground) cannot carry a speed motor (a
  // torque it can: LoopJoints.ATorqueAcrossTheClosingJointMovesTheLinkageAsAcrossATreeJoint).
  test::expect_error(links +
                         "  r: {type: hinge, bodies: [ground, b], at: [0, 0, -1], axis: [0, 1, 0], "
                         "motor: {speed: 1}}\n" +
                         run,
                     8, 74, "motor", "takes no speed motor");
  // Nor a lock.
  test::expect_error(links +
                         "  r: {type: hinge, bodies: [ground, b], at: [0, 0, -1], axis: [0, 1, 0], "
                         "lock: {at: 0.5}}\n" +
                         run,
                     8, 3, "joints.r", "cannot lock");
  // Three hinges in a triangle with ground make a structure: nothing can move.
  test::expect_error(
      links + "  r: {type: hinge, bodies: [ground, b], at: [0, 0, -1], axis: [0, 1, 0]}\n" + run, 8,
      3, "joints.r", "leave nothing free to move");
  // So do two welds.
  test::expect_error(R"(tumble: 1
bodies:
  a: {shape: sphere, radius: 0.1, mass: 1, position: [1, 0, 0]}
joints:
  p: {type: fixed, bodies: [ground, a], at: [0, 0, 0]}
  q: {type: fixed, bodies: [a, ground], at: [2, 0, 0]}
simulate: {duration: 1}
)",
                     6, 3, "joints.q", "leave nothing free to move");
  // Contacts are not yet solved with a loop's forces.
  test::expect_error(links +
                         "  r: {type: ball, bodies: [ground, b], at: [0, 0, -1]}\n"
                         "contacts:\n  - {type: plane, body: b, plane: {point: [0, 0, -2], normal: "
                         "[0, 0, 1]}, friction: 0}\n" +
                         run,
                     10, 5, "contacts[0]", "not supported yet");
}

}  // namespace
}  // namespace tumble
