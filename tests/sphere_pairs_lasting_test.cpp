// Two bodies' spheres in contact that lasts (pressing, rolling, sliding on each other), each
// against its closed form. A ball of radius r (mass m, I = 2 m r^2 / 5) on a fixed dome of radius
// R, its centre on the circle of radius rho = R + r at the angle theta from the top, started
// there at the speed v0:
//  - rolling without slip (`friction: inf`): its centre's speed is omega r (the contact point at
//    rest), so the energy gives v^2 = v0^2 + (10/7) g rho (1 - cos theta), the tangential
//    equation a_t = (5/7) g sin theta with the friction (2/7) m g sin theta, and the radial one
//    N = m g cos theta - m v^2 / rho = m g (17 cos theta - 10) / 7 - m v0^2 / rho. It leaves
//    where N = 0: cos theta = 10/17 + 7 v0^2 / (17 g rho);
//  - frictionless: it slides as a particle would (its spin is kept), v^2 = v0^2 + 2 g rho (1 -
//    cos theta), and it leaves where cos theta = 2/3 + v0^2 / (3 g rho).
//  - A ball resting on top of another that rests on the floor: the pair's push is m_top g, the
//    floor's (m_top + m_bottom) g, and neither moves.
//  - A ball dropped onto a ball resting on the floor rebounds at e of its speed: the floor holds
//    the lower ball in the same instant.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scenario_run.hpp"
#include "test_constants.hpp"

namespace tumble {
namespace {

constexpr double kLastingDomeRadius = 1.0, kLastingBallRadius = 0.1, kLastingBallMass = 0.5,
                 kLastingStartSpeed = 0.01;

// The ball at the dome's top, moving along x at v0 (and turning at v0 / r about y: rolling).
std::string ball_on_dome(const std::string& friction) {
  return "tumble: 1\n"
         "parameters: {R: 1, r: 0.1, m: 0.5, v0: 0.01}\n"
         "gravity: [0, 0, -" +
         std::to_string(test::kG) +
         "]\n"
         "bodies:\n"
         "  dome: {shape: sphere, radius: R, mass: 100, position: [0, 0, 0]}\n"
         "  ball: {shape: sphere, radius: r, mass: m, position: [0, 0, R + r], velocity: [v0, "
         "0, 0], angular_velocity: [0, v0 / r, 0]}\n"
         "joints:\n"
         "  footing: {type: fixed, bodies: [ground, dome], at: [0, 0, 0]}\n"
         "contacts:\n"
         "  - {name: on_dome, type: bodies, bodies: [ball, dome], friction: " +
         friction +
         ", restitution: 0}\n"
         "simulate: {duration: 3.5, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
         "0.01}\n";
}

struct DomeRun {
  double leaves_t = 0.0;
  Vec3 leaves_normal_W = Vec3::Zero();
};

// The run's events: it touches from the start in `mode`, then lifts off, once.
DomeRun leaves_the_dome(const test::ScenarioRun& run, const std::string& mode) {
  EXPECT_EQ(run.contact_events.size(), 2u);
  if (run.contact_events.size() != 2u) return {};
  EXPECT_EQ(run.contact_events[0].t, 0.0);
  EXPECT_EQ(run.contact_events[0].what, mode);
  EXPECT_EQ(run.contact_events[1].what, "lifts off");
  return {run.contact_events[1].t, run.contact_events[1].normal_W};
}

TEST(SpherePairsLasting, ABallRollingOffADomeLeavesWhereCosThetaIsTenSeventeenths) {
  const double g = test::kG, rho = kLastingDomeRadius + kLastingBallRadius, m = kLastingBallMass;
  const double v0 = kLastingStartSpeed;
  const test::ScenarioRun run = test::run_inline_scenario(ball_on_dome("inf"), "rolls");
  const DomeRun off = leaves_the_dome(run, "rolls");
  // The normal at lift-off is the ball's direction from the dome's centre: its z is cos theta.
  const double cos_off = 10.0 / 17.0 + 7 * v0 * v0 / (17 * g * rho);
  EXPECT_NEAR(off.leaves_normal_W.z(), cos_off, 1e-9);
  EXPECT_NEAR(off.leaves_normal_W.y(), 0.0, 1e-12);
  for (const test::Row& row : run.rows) {
    if (row.t >= off.leaves_t) break;
    const BodyState& ball = row.states[1];
    const double cos_theta = ball.r_G.z() / rho, sin_theta = ball.r_G.x() / rho;
    EXPECT_NEAR(ball.r_G.norm(), rho, 1e-12 * rho) << row.t;
    EXPECT_EQ(row.extras.contacts[0].mode, 2) << row.t;
    EXPECT_LT(row.extras.contacts[0].slip_speed, 1e-12) << row.t;
    // Rolling: the centre's speed is omega r, about the axis across the motion.
    EXPECT_NEAR(ball.v_G.norm(), std::abs(ball.omega_W.y()) * kLastingBallRadius, 1e-12) << row.t;
    const double v2 = v0 * v0 + 10.0 / 7.0 * g * rho * (1 - cos_theta);
    EXPECT_NEAR(ball.v_G.squaredNorm(), v2, 1e-11 * g * rho) << row.t;
    EXPECT_NEAR(row.extras.contacts[0].normal_force,
                m * g * (17 * cos_theta - 10) / 7 - m * v0 * v0 / rho, 1e-10 * m * g)
        << row.t;
    EXPECT_NEAR(row.extras.contacts[0].friction_W.norm(), 2.0 / 7.0 * m * g * sin_theta,
                1e-10 * m * g)
        << row.t;
  }
  // E kept throughout, rolling and then flying: rolling does no work. (The run takes ~300 steps
  // at rtol 1e-12, each of which may add its error: E to 3e-10 of its scale.)
  for (const test::Row& row : run.rows) {
    EXPECT_NEAR(row.quantities.total_energy, run.rows.front().quantities.total_energy,
                3e-10 * m * g * rho)
        << row.t;
  }
}

TEST(SpherePairsLasting, AFrictionlessBallSlidesOffADomeWhereCosThetaIsTwoThirds) {
  const double g = test::kG, rho = kLastingDomeRadius + kLastingBallRadius, m = kLastingBallMass;
  const double v0 = kLastingStartSpeed;
  const test::ScenarioRun run = test::run_inline_scenario(ball_on_dome("0"), "slides");
  const DomeRun off = leaves_the_dome(run, "slides");
  EXPECT_NEAR(off.leaves_normal_W.z(), 2.0 / 3.0 + v0 * v0 / (3 * g * rho), 1e-9);
  for (const test::Row& row : run.rows) {
    if (row.t >= off.leaves_t) break;
    const BodyState& ball = row.states[1];
    const double cos_theta = ball.r_G.z() / rho;
    EXPECT_NEAR(ball.r_G.norm(), rho, 1e-12 * rho) << row.t;
    EXPECT_EQ(row.extras.contacts[0].mode, 1) << row.t;
    // No friction: the spin is the start's, and the centre moves as a particle on the circle.
    EXPECT_NEAR(ball.omega_W.y(), v0 / kLastingBallRadius, 1e-12) << row.t;
    EXPECT_NEAR(ball.v_G.squaredNorm(), v0 * v0 + 2 * g * rho * (1 - cos_theta), 1e-11 * g * rho)
        << row.t;
    EXPECT_NEAR(row.extras.contacts[0].normal_force,
                m * g * (3 * cos_theta - 2) - m * v0 * v0 / rho, 1e-10 * m * g)
        << row.t;
  }
}

// A ball of radius 0.2 m (0.7 kg) on the floor and one of 0.1 m (0.3 kg) above it, its centre
// `top_z` up, straight above the lower one's; restitution e between them.
std::string two_balls_on_the_floor(double top_z, double e, double duration) {
  return "tumble: 1\n"
         "gravity: [0, 0, -" +
         std::to_string(test::kG) +
         "]\n"
         "bodies:\n"
         "  bottom: {shape: sphere, radius: 0.2, mass: 0.7, position: [0, 0, 0.2]}\n"
         "  top: {shape: sphere, radius: 0.1, mass: 0.3, position: [0, 0, " +
         std::to_string(top_z) +
         "]}\n"
         "contacts:\n"
         "  - {name: floor, type: plane, body: bottom, plane: {point: [0, 0, 0], normal: [0, 0, "
         "1]}, friction: 0.5}\n"
         "  - {name: stack, type: bodies, bodies: [top, bottom], friction: 0.5, restitution: " +
         std::to_string(e) +
         "}\n"
         "simulate: {duration: " +
         std::to_string(duration) +
         ", integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: 0.01}\n";
}

// Two balls stacked on the floor, the top one's centre straight above the bottom one's: the
// pair presses with the top ball's weight and the floor with both, and nothing moves (an
// unstable rest, held exactly: nothing breaks its symmetry).
TEST(SpherePairsLasting, ABallRestingOnABallOnTheFloorPressesWithItsWeight) {
  const double g = test::kG, m_top = 0.3, m_bottom = 0.7;
  const std::string yaml = two_balls_on_the_floor(0.5, 0.0, 1.0);
  const test::ScenarioRun run = test::run_inline_scenario(yaml, "stack");
  ASSERT_EQ(run.contact_events.size(), 2u);
  for (const test::Row& row : run.rows) {
    EXPECT_NEAR(row.extras.contacts[0].normal_force, (m_top + m_bottom) * g, 1e-12 * g) << row.t;
    EXPECT_NEAR(row.extras.contacts[1].normal_force, m_top * g, 1e-12 * g) << row.t;
    EXPECT_NEAR(row.states[0].r_G.z(), 0.2, 1e-12) << row.t;
    EXPECT_NEAR(row.states[1].r_G.z(), 0.5, 1e-12) << row.t;
    EXPECT_LT(row.states[0].v_G.norm() + row.states[1].v_G.norm(), 1e-12) << row.t;
  }
}

// A ball dropped onto a ball resting on the floor, straight down through its centre: the floor
// takes its part of the blow in the same instant (it holds the lower ball), so the top ball
// rebounds at e of its speed as off the floor itself, the lower ball stays at rest, and the
// impact takes (1 - e^2) m v^2 / 2. (Struck first as two free balls and held by the floor after,
// the lower ball would be driven into the floor and stopped there, and the top ball would leave
// at (m_top - e m_bottom) v / (m_top + m_bottom).)
TEST(SpherePairsLasting, ABallDroppedOnABallOnTheFloorReboundsAsOffTheFloorItself) {
  const double g = test::kG, m_top = 0.3, e = 0.6, drop = 0.2;
  const std::string yaml = two_balls_on_the_floor(0.7, e, 0.25);
  const test::ScenarioRun run = test::run_inline_scenario(yaml, "dropped");
  const double t_hit = std::sqrt(2 * drop / g), v = g * t_hit;
  ASSERT_GE(run.contact_events.size(), 2u);
  const ContactEventRecord& hit = run.contact_events[1];
  EXPECT_EQ(hit.contact, 1u);
  EXPECT_NEAR(hit.t, t_hit, 1e-12);
  ASSERT_TRUE(hit.impact.has_value());
  EXPECT_NEAR(hit.impact->rebound_speed, e * v, 1e-12 * v);
  EXPECT_NEAR(hit.impact->impulse_W.z(), (1 + e) * m_top * v, 1e-12 * m_top * v);
  EXPECT_NEAR(hit.impact->kinetic_energy_before - hit.impact->kinetic_energy_after,
              (1 - e * e) * m_top * v * v / 2, 1e-12 * m_top * v * v);
  for (const test::Row& row : run.rows) {
    // The lower ball never moves; the top one, after the blow, flies up at e v less g t.
    EXPECT_LT(row.states[0].v_G.norm(), 1e-12) << row.t;
    EXPECT_NEAR(row.states[0].r_G.z(), 0.2, 1e-12) << row.t;
    EXPECT_EQ(row.extras.contacts[0].mode, 2) << row.t;
    if (row.t > t_hit) {
      EXPECT_NEAR(row.states[1].v_G.z(), e * v - g * (row.t - t_hit), 1e-11 * v) << row.t;
    }
  }
}

}  // namespace
}  // namespace tumble
