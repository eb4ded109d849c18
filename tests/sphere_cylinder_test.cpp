// A sphere against a cylinder or a disk (the other body's own solid, pair_core.hpp), each against
// its closed form:
//  - a ball dropped onto a standing cylinder's top face, off its axis, or onto its rim: the
//    relative normal velocity reverses times e along the normal from the face or the rim's
//    nearest point, v' = v - (1 + e) (v . n) n, the ball fixed in its spin (frictionless);
//  - a frictionless ball sliding off a level cylinder's side while moving along its axis
//    (tests/capsule_test.cpp, with the capsule's);
//  - a ball rolling without slip across a fixed disk's face and over its rim: it turns about the
//    rim's point, v^2 = v0^2 + (10/7) g r (1 - cos theta), and leaves where N = 0:
//    cos theta = (10 + 7 v0^2 / (g r)) / 17.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scenario_run.hpp"
#include "test_constants.hpp"

namespace tumble {
namespace {

// A fixed cylinder (R 0.3, length 0.4, its top at z = 0.2) standing on its axis at the origin;
// a ball (r 0.1) at (x, 0, 1) falling at u, no gravity.
std::string ball_onto_cylinder(double x) {
  return "tumble: 1\n"
         "parameters: {x: " +
         std::to_string(x) +
         ", u: 2}\n"
         "gravity: [0, 0, 0]\n"
         "bodies:\n"
         "  post: {shape: cylinder, radius: 0.3, length: 0.4, mass: 5}\n"
         "  ball: {shape: sphere, radius: 0.1, mass: 0.5, position: [x, 0, 1], velocity: [0, 0, "
         "-u]}\n"
         "joints:\n"
         "  footing: {type: fixed, bodies: [ground, post], at: [0, 0, 0]}\n"
         "contacts:\n"
         "  - {name: hit, type: bodies, bodies: [post, ball], friction: 0, restitution: 0.5}\n"
         "simulate: {duration: 0.6, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
         "0.01}\n";
}

TEST(SphereCylinder, ABallDroppedOnAFaceOrARimReboundsAlongTheNormal) {
  const double u = 2, e = 0.5, r = 0.1;
  // On the face (x 0.2, within the radius), and on the rim (x 0.36: 0.06 beyond it).
  for (const double x : {0.2, 0.36}) {
    const test::ScenarioRun run = test::run_inline_scenario(ball_onto_cylinder(x), "drop");
    ASSERT_GE(run.contact_events.size(), 1u) << x;
    const ContactEventRecord& hit = run.contact_events[0];
    ASSERT_TRUE(hit.impact.has_value());
    EXPECT_EQ(run.contacts[0].body, 1u);
    const double beyond = std::max(0.0, x - 0.3);
    const double up = std::sqrt(r * r - beyond * beyond);  // the centre above the top at touch
    const Vec3 n = Vec3(beyond, 0, up) / r;
    EXPECT_NEAR(hit.t, (1 - 0.2 - up) / u, 1e-12) << x;
    EXPECT_LT((hit.normal_W - n).norm(), 1e-12) << x;
    const Vec3 v(0, 0, -u);
    const Vec3 v_after = v - (1 + e) * v.dot(n) * n;
    const BodyState& ball = run.rows.back().states[1];
    EXPECT_LT((ball.v_G - v_after).norm(), 1e-12 * u) << x;
    EXPECT_LT(ball.omega_W.norm(), 1e-12) << x;
  }
}

// A fixed disk (R 1) lying flat at z = 0; a ball (r 0.1, m 0.5) rolling on it at v0 along x
// from 0.5 m short of the rim.
TEST(SphereCylinder, ABallRollingOverADisksRimLeavesWhereCosThetaIsTheSharpEdgesClosedForm) {
  const double g = test::kG, r = 0.1, m = 0.5, v0 = 0.3;
  const std::string yaml =
      "tumble: 1\n"
      "gravity: [0, 0, -" +
      std::to_string(g) +
      "]\n"
      "bodies:\n"
      "  table: {shape: disk, radius: 1, mass: 5}\n"
      "  ball: {shape: sphere, radius: 0.1, mass: 0.5, position: [0.5, 0, 0.1], velocity: [0.3, "
      "0, 0], angular_velocity: [0, 3, 0]}\n"
      "joints:\n"
      "  footing: {type: fixed, bodies: [ground, table], at: [0, 0, 0]}\n"
      "contacts:\n"
      "  - {name: on_table, type: bodies, bodies: [table, ball], friction: inf, restitution: 0}\n"
      "simulate: {duration: 2.5, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
      "0.01}\n";
  const test::ScenarioRun run = test::run_inline_scenario(yaml, "rim");
  ASSERT_EQ(run.contact_events.size(), 2u);
  EXPECT_EQ(run.contact_events[0].what, "rolls");
  EXPECT_EQ(run.contact_events[1].what, "lifts off");
  const ContactEventRecord& off = run.contact_events[1];
  const double cos_off = (10 + 7 * v0 * v0 / (g * r)) / 17;
  EXPECT_NEAR(off.normal_W.z(), cos_off, 1e-9);
  // It touches, to the last, at the rim's point it turned about.
  EXPECT_LT((off.point_W - Vec3(1, 0, 0)).norm(), 1e-12);
  for (const test::Row& row : run.rows) {
    if (row.t >= off.t) break;
    const BodyState& ball = row.states[1];
    EXPECT_EQ(row.extras.contacts[0].mode, 2) << row.t;
    if (ball.r_G.x() <= 1) {
      // On the face: rolling at v0, pressing with its weight.
      EXPECT_NEAR(ball.v_G.x(), v0, 1e-12) << row.t;
      EXPECT_NEAR(row.extras.contacts[0].normal_force, m * g, 1e-10 * m * g) << row.t;
      continue;
    }
    // Over the rim: turning about it.
    const Vec3 from_rim = ball.r_G - Vec3(1, 0, 0);
    EXPECT_NEAR(from_rim.norm(), r, 1e-12) << row.t;
    const double cos_theta = from_rim.z() / r;
    EXPECT_NEAR(ball.v_G.squaredNorm(), v0 * v0 + 10.0 / 7.0 * g * r * (1 - cos_theta),
                1e-11 * g * r)
        << row.t;
    EXPECT_NEAR(row.extras.contacts[0].normal_force,
                m * g * (17 * cos_theta - 10) / 7 - m * v0 * v0 / r, 1e-10 * m * g)
        << row.t;
  }
}

TEST(SphereCylinder, TwoOfThemOrABallInOneAreRefused) {
  const std::string bodies =
      "tumble: 1\n"
      "bodies:\n"
      "  a: {shape: cylinder, radius: 0.1, length: 0.5, mass: 1}\n"
      "  b: {shape: disk, radius: 0.1, mass: 1, position: [1, 0, 0]}\n"
      "  c: {shape: sphere, radius: 0.1, mass: 1, position: [0, 0, 0.3]}\n";
  test::expect_error(bodies +
                         "contacts:\n"
                         "  - {type: bodies, bodies: [a, b], friction: 0}\n",
                     7, 28, "contacts[0].bodies", "a cylinder and a disk do not touch");
  // The ball's centre 0.05 above the cylinder's top face, its radius 0.1: 0.05 into it.
  test::expect_error(bodies +
                         "contacts:\n"
                         "  - {type: bodies, bodies: [c, a], friction: 0}\n"
                         "simulate: {duration: 1}\n",
                     7, 5, "contacts[0]",
                     "overlapping by 0.05 m (the sphere's centre is 0.05 m from the cylinder");
}

}  // namespace
}  // namespace tumble
