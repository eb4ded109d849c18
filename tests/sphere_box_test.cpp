// A sphere against a box (a box body's core, pair_core.hpp), each against its closed form. A ball
// (radius R, mass m, I = 2 m R^2 / 5) rolls without slip on the floor at v0 into a step of height
// h < R, a box welded to ground; it meets the step's edge where its centre is
// sqrt(R^2 - (R - h)^2) short of it. The edge's impact is plastic and without slip (`friction:
// inf`, e = 0), its impulse at the edge (the floor's none: the ball leaves the floor), so the
// angular momentum about the edge is kept:
//     m v0 (R - h) + I v0 / R = (I + m R^2) omega'   =>   omega' = (v0 / R) (1 - 5 h / (7 R)),
// and the ball turns about the edge at omega'. It climbs if its kinetic energy then, (7/10) m R^2
// omega'^2, lifts its centre by h: the least speed that climbs is
//     v* = sqrt(10 g h / 7) / (1 - 5 h / (7 R)).
// (It stays on the edge as it turns if omega'^2 R <= g (R - h) / R: at v*, for h <= 7 R / 17.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "tumble/sweep/find.hpp"
#include "tumble/sweep/outcome.hpp"

namespace tumble {
namespace {

constexpr double kStepBallRadius = 0.1, kStepBallMass = 0.5, kStepHeight = 0.03;

std::string ball_into_step(double v0) {
  return "tumble: 1\n"
         "parameters: {R: 0.1, m: 0.5, h: 0.03, v0: " +
         std::to_string(v0) + ", g: " + std::to_string(test::kG) +
         "}\n"
         "gravity: [0, 0, -g]\n"
         "bodies:\n"
         "  ball: {shape: sphere, radius: R, mass: m, position: [-0.3, 0, R], velocity: [v0, 0, "
         "0], angular_velocity: [0, v0/R, 0]}\n"
         "  step: {shape: box, size: [1, 1, h], mass: 10, position: [0.5, 0, h/2]}\n"
         "joints:\n"
         "  footing: {type: fixed, bodies: [ground, step], at: [0, 0, 0]}\n"
         "contacts:\n"
         "  - {name: floor, type: plane, body: ball, plane: {point: [0, 0, 0], normal: [0, 0, "
         "1]}, friction: 0.5}\n"
         "  - {name: edge, type: bodies, bodies: [step, ball], friction: inf, restitution: 0}\n"
         "simulate: {duration: 3, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
         "0.01}\n";
}

TEST(SphereBox, ABallRollingIntoAStepTurnsAboutItsEdgeAtTheClosedFormsSpin) {
  const double R = kStepBallRadius, m = kStepBallMass, h = kStepHeight, g = test::kG, v0 = 0.9;
  const test::ScenarioRun run = test::run_inline_scenario(ball_into_step(v0), "climbs");
  ASSERT_GE(run.contact_events.size(), 4u);
  // The box named first goes second: the contact's body is the ball.
  EXPECT_EQ(run.contacts[1].body, 0u);
  const ContactEventRecord& impact = run.contact_events[1];
  EXPECT_EQ(impact.contact, 1u);
  const double reach = std::sqrt(R * R - (R - h) * (R - h));
  EXPECT_NEAR(impact.t, (0.3 - reach) / v0, 1e-12);
  EXPECT_NEAR(impact.normal_W.z(), (R - h) / R, 1e-12);
  ASSERT_TRUE(impact.impact.has_value());
  // The spin and velocity just after, from the impulse on the ball at the edge.
  const Vec3 edge(0, 0, h), centre(-reach, 0, R);
  const Vec3 P = impact.impact->impulse_W;
  const double I = 0.4 * m * R * R;
  const Vec3 omega_after = Vec3(0, v0 / R, 0) + (edge - centre).cross(P) / I;
  const Vec3 v_after = Vec3(v0, 0, 0) + P / m;
  const double omega_turn = (v0 / R) * (1 - 5 * h / (7 * R));
  EXPECT_NEAR(omega_after.y(), omega_turn, 1e-12 * v0 / R);
  EXPECT_NEAR(omega_after.x(), 0.0, 1e-12 * v0 / R);
  EXPECT_NEAR(omega_after.z(), 0.0, 1e-12 * v0 / R);
  // Turning about the edge: the centre moves at omega' x (centre - edge).
  EXPECT_LT((v_after - Vec3(0, omega_turn, 0).cross(centre - edge)).norm(), 1e-12 * v0);
  // The floor lets go; the edge holds the ball, rolling, from the impact on.
  EXPECT_EQ(run.contact_events[2].what, "lifts off: an impact between bodies sends it away");
  EXPECT_EQ(run.contact_events[3].what, "rolls");
  EXPECT_EQ(run.contact_events[3].t, impact.t);
  // It climbs: at the end it rolls on the step's top, its centre h + R up, E kept since the edge.
  const test::Row& last = run.rows.back();
  EXPECT_GT(last.states[0].r_G.x(), 0.0);
  EXPECT_NEAR(last.states[0].r_G.z(), h + R, 1e-12);
  EXPECT_EQ(last.extras.contacts[1].mode, 2);
  EXPECT_NEAR(last.extras.contacts[1].normal_force, m * g, 1e-10 * m * g);
  double E_after = std::nan("");
  for (const test::Row& row : run.rows) {
    if (row.t <= impact.t) continue;
    if (std::isnan(E_after)) E_after = row.quantities.total_energy;
    EXPECT_NEAR(row.quantities.total_energy, E_after, 1e-10 * m * g * R) << row.t;
  }
}

// `tumble find` on whether it climbs (its centre past the edge at the end): v* to 1e-7.
TEST(SphereBox, FindTheLeastSpeedThatClimbsTheStep) {
  const double R = kStepBallRadius, h = kStepHeight, g = test::kG;
  SweepSpec spec;
  spec.path = "step.yaml";
  spec.text = ball_into_step(0.8);
  spec.varied = {"v0"};
  spec.outcomes = {parse_outcome("condition", "final(ball.x) > 0")};
  const FindResult found = find_change(spec, 0.7, 1.0, 1e-8);
  EXPECT_FALSE(found.at_lo);
  EXPECT_TRUE(found.at_hi);
  const double v_star = std::sqrt(10 * g * h / 7) / (1 - 5 * h / (7 * R));
  EXPECT_NEAR(found.lo + 0.5 * (found.hi - found.lo), v_star, 1e-7);
}

// A ball (radius r = 0.05) rolling without slip from rest down a fixed box's top face, which
// slopes down at beta, reaches the face's lower edge after s = 0.5 + x0 along it, at
// t_e = sqrt(2 s / a), a = (5/7) g sin(beta), moving at v = a t_e. Beyond the face the nearest
// point is the edge, and the normal turns about it with the centre's motion at once: held on,
// its centre would accelerate at v^2 / r towards the edge, more than gravity's g cos(beta) pulls
// it there (v^2 > g r cos(beta) for every case here). So it leaves the box at the edge, at t_e,
// rolling, and flies off as a projectile: r(t) = r_e + v (t - t_e) + g (t - t_e)^2 / 2, its spin
// v / r held. The push and the friction rolling needs jump at the edge together; the push's
// jump is the event it takes (before, the friction's was taken where it came first, and the
// ball slid on the edge pulling on it, gaining energy without bound).
TEST(SphereBox, ABallRollingDownAFaceLeavesItAtTheEdge) {
  const double r = 0.05, g = test::kG;
  for (const double beta_deg : {10.0, 20.0, 30.0}) {
    for (const double x0 : {0.0, -0.3}) {
      SCOPED_TRACE(::testing::Message() << "beta " << beta_deg << ", x0 " << x0);
      const double beta = beta_deg * M_PI / 180.0;
      const double s = 0.5 - x0, a = 5.0 / 7.0 * g * std::sin(beta);
      const double t_e = std::sqrt(2 * s / a), v = a * t_e;
      ASSERT_GT(v * v, g * r * std::cos(beta));
      const std::string yaml =
          "tumble: 1\n"
          "parameters: {beta: " +
          std::to_string(beta_deg) + " deg, x0: " + std::to_string(x0) +
          ", g: " + std::to_string(g) +
          "}\n"
          "gravity: [0, 0, -g]\n"
          "bodies:\n"
          "  block: {shape: box, size: [1, 0.4, 0.1], mass: 5, orientation: {axis: [0, 1, 0], "
          "angle: beta}}\n"
          "  ball: {shape: sphere, radius: 0.05, mass: 0.2, position: [x0*cos(beta) + "
          "0.1*sin(beta), 0, -x0*sin(beta) + 0.1*cos(beta)]}\n"
          "joints:\n"
          "  stand: {type: fixed, bodies: [ground, block], at: [0, 0, 0]}\n"
          "contacts:\n"
          "  - {name: face, type: bodies, bodies: [ball, block], friction: 0.5}\n"
          "simulate: {duration: 1.2, integrator: dop853, rtol: 1e-12, atol: 1e-14, "
          "output_every: 0.01}\n";
      const test::ScenarioRun run = test::run_inline_scenario(yaml, "down_a_face");
      // It rolls from the start, and leaves at the edge; nothing else happens.
      ASSERT_EQ(run.contact_events.size(), 2u);
      EXPECT_EQ(run.contact_events[0].what, "rolls");
      EXPECT_EQ(run.contact_events[1].what, "lifts off");
      EXPECT_NEAR(run.contact_events[1].t, t_e, 1e-10);
      const Vec3 down(std::cos(beta), 0, -std::sin(beta));  // along the face, downhill
      const Vec3 start(x0 * std::cos(beta) + 0.1 * std::sin(beta), 0,
                       -x0 * std::sin(beta) + 0.1 * std::cos(beta));
      const Vec3 r_e = start + s * down, gravity(0, 0, -g);
      for (const test::Row& row : run.rows) {
        const BodyState& ball = row.states[1];
        const double t = row.t;
        const Vec3 expected =
            t <= t_e ? Vec3(start + 0.5 * a * t * t * down)
                     : Vec3(r_e + v * (t - t_e) * down + 0.5 * (t - t_e) * (t - t_e) * gravity);
        EXPECT_NEAR((ball.r_G - expected).norm(), 0.0, 1e-9) << t;
        // Rolling about y (down the slope along +x), at its speed over r, before and after.
        EXPECT_NEAR((ball.omega_W - Vec3(0, std::min(t, t_e) * a / r, 0)).norm(), 0.0, 1e-8) << t;
      }
    }
  }
}

// A ball rolling without slip (`friction: inf`) at v0 along a table's top (a box welded to
// ground, or a round table: a standing cylinder, which it leaves over its rim, rolling out along
// a radius) off its edge: it turns about the edge as about a dome of radius 0, its centre on a
// circle of radius r, and with rolling's kinetic energy (7/10) m r^2 theta'^2 the push falls to
// zero where cos(theta) = (10 + 7 v0^2 / (g r)) / 17 (v0^2 < g r: it does not leave at once),
// theta from the vertical. The lift-off is located there, its normal (from the edge to the
// centre) at that angle, with the kinetic energy the fall of r (1 - cos(theta)) gave it.
TEST(SphereBox, ABallRollingOffATablesEdgeLeavesWhereTheClosedFormSays) {
  const double r = 0.05, g = test::kG, m = 0.2;
  for (const char* table :
       {"shape: box, size: [1, 1, 0.1]", "shape: cylinder, radius: 0.5, length: 0.1"}) {
    for (const double v0 : {0.1, 0.3, 0.6}) {
      SCOPED_TRACE(::testing::Message() << table << ", v0 " << v0);
      const std::string yaml =
          "tumble: 1\n"
          "parameters: {v0: " +
          std::to_string(v0) + ", g: " + std::to_string(g) +
          "}\n"
          "gravity: [0, 0, -g]\n"
          "bodies:\n"
          "  table: {" +
          table +
          ", mass: 5}\n"
          "  ball: {shape: sphere, radius: 0.05, mass: 0.2, position: [0.45, 0, 0.1], "
          "velocity: [v0, 0, 0], angular_velocity: [0, v0 / 0.05, 0]}\n"
          "joints:\n"
          "  stand: {type: fixed, bodies: [ground, table], at: [0, 0, 0]}\n"
          "contacts:\n"
          "  - {name: top, type: bodies, bodies: [ball, table], friction: inf}\n"
          "simulate: {duration: 1, integrator: dop853, rtol: 1e-12, atol: 1e-14, "
          "output_every: 0.01}\n";
      const test::ScenarioRun run = test::run_inline_scenario(yaml, "off_the_edge");
      ASSERT_EQ(run.contact_events.size(), 2u);
      EXPECT_EQ(run.contact_events[0].what, "rolls");
      const ContactEventRecord& leaves = run.contact_events[1];
      EXPECT_EQ(leaves.what, "lifts off");
      const double cos_theta = (10 + 7 * v0 * v0 / (g * r)) / 17;
      EXPECT_NEAR(leaves.normal_W.z(), cos_theta, 1e-9);
      EXPECT_NEAR(leaves.normal_W.y(), 0.0, 1e-12);
      EXPECT_NEAR((leaves.point_W - Vec3(0.5, 0, 0.05)).norm(), 0.0, 1e-9);
      const double ke0 = 0.7 * m * v0 * v0;
      EXPECT_NEAR(leaves.kinetic_energy_after, ke0 + m * g * r * (1 - cos_theta), 1e-10);
    }
  }
}

}  // namespace
}  // namespace tumble
