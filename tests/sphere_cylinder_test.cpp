// A sphere against a cylinder or a disk (the other body's own solid, pair_core.hpp), each against
// its closed form:
//  - a ball dropped onto a standing cylinder's top face, off its axis, or onto its rim: the
//    relative normal velocity reverses times e along the normal from the face or the rim's
//    nearest point, v' = v - (1 + e) (v . n) n, the ball fixed in its spin (frictionless);
//  - a frictionless ball sliding off a level cylinder's side while moving along its axis
//    (tests/capsule_test.cpp, with the capsule's);
//  - a ball rolling without slip across a fixed disk's face and over its rim: it turns about the
//    rim's point, v^2 = v0^2 + (10/7) g r (1 - cos theta), and leaves where N = 0:
//    cos theta = (10 + 7 v0^2 / (g r)) / 17;
//  - a ball striking a free composite's cylinder part (a mallet's head, a point mass at its other
//    end) on its face, frictionless: the impulse J = (1 + e) u / (1/m + 1/M + b^2 / I), b the
//    face centre's height over the composite's COM across the blow and I the composite's moment
//    of inertia about its COM there, by the parallel axis theorem.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "tumble/scenario/scenario.hpp"

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

// A mallet, free and without gravity: its head a cylinder (R 0.05, L 0.2, mass M_h) lying along
// x at z = 0.3, a point mass m_p at z = -0.3; a ball (r 0.1, m) at the head's height moving
// along -x at u strikes the centre of the head's +x face.
TEST(SphereCylinder, ABallStrikingACompositesCylinderPartTakesTheClosedFormsImpulse) {
  const double R = 0.05, L = 0.2, M_h = 1.0, m_p = 0.25, z_h = 0.3, z_p = -0.3;
  const double m = 0.5, u = 2.0;
  const double M = M_h + m_p, z_G = (M_h * z_h + m_p * z_p) / M;
  // About y through the COM: the head across its axis, and both offsets along z.
  const double I = M_h * (3 * R * R + L * L) / 12 + M_h * (z_h - z_G) * (z_h - z_G) +
                   m_p * (z_p - z_G) * (z_p - z_G);
  const double b = z_h - z_G;
  for (const double e : {1.0, 0.5}) {
    const std::string text =
        "tumble: 1\n"
        "gravity: [0, 0, 0]\n"
        "bodies:\n"
        "  mallet:\n"
        "    parts:\n"
        "      - {name: head, shape: cylinder, radius: 0.05, length: 0.2, mass: 1, position: [0, "
        "0, 0.3], orientation: {axis: [0, 1, 0], angle: 90 deg}}\n"
        "      - {name: weight, shape: point, mass: 0.25, position: [0, 0, -0.3]}\n"
        "  ball: {shape: sphere, radius: 0.1, mass: 0.5, position: [0.5, 0, 0.3], velocity: [-2, "
        "0, 0]}\n"
        "contacts:\n"
        "  - {name: hit, type: bodies, bodies: [mallet, ball], friction: 0, restitution: " +
        std::to_string(e) +
        "}\n"
        "simulate: {duration: 0.2, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
        "0.01}\n";
    const test::ScenarioRun run = test::run_inline_scenario(text, "mallet");
    ASSERT_GE(run.contact_events.size(), 1u) << e;
    const ContactEventRecord& hit = run.contact_events[0];
    ASSERT_TRUE(hit.impact.has_value()) << hit.what;
    // The ball's surface 0.5 - 0.1 - 0.1 = 0.3 from the face.
    EXPECT_NEAR(hit.t, 0.3 / u, 1e-12) << e;
    EXPECT_LT((hit.normal_W - Vec3::UnitX()).norm(), 1e-12) << e;
    const double J = (1 + e) * u / (1 / m + 1 / M + b * b / I);
    const test::Row& last = run.rows.back();
    const BodyState& mallet = last.states[0];
    const BodyState& ball = last.states[1];
    EXPECT_NEAR(ball.v_G.x(), -u + J / m, 1e-12 * u) << e;
    EXPECT_NEAR(mallet.v_G.x(), -J / M, 1e-12 * u) << e;
    EXPECT_NEAR(mallet.omega_W.y(), -J * b / I, 1e-12 * u / b) << e;
    EXPECT_LT(ball.omega_W.norm(), 1e-12) << e;
    if (e == 1.0) {
      EXPECT_NEAR(hit.kinetic_energy_after, hit.kinetic_energy_before,
                  1e-12 * hit.kinetic_energy_before);
    }
  }
}

TEST(SphereCylinder, TwoOfThemOrABallInOneAreRefusedAndACompositesPartsEachTouch) {
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
  // A composite with two cylinder or disk parts and none that comes first: each touches the ball,
  // a contact of its own named by the part.
  const Scenario parts = load_scenario_text(
      bodies +
          "  d:\n"
          "    parts:\n"
          "      - {name: p, shape: cylinder, radius: 0.1, length: 0.2, mass: 1}\n"
          "      - {name: q, shape: disk, radius: 0.1, mass: 1, position: [0, 0, 0.5]}\n"
          "    position: [0, 3, 0]\n"
          "contacts:\n"
          "  - {type: bodies, bodies: [c, d], friction: 0}\n"
          "simulate: {duration: 1}\n",
      "parts.yaml", {});
  ASSERT_EQ(parts.contacts.size(), 2u);
  EXPECT_EQ(parts.contacts[0].name, "contact1_p");
  EXPECT_EQ(parts.contacts[0].other_part, 0);
  EXPECT_EQ(parts.contacts[1].name, "contact1_q");
  EXPECT_EQ(parts.contacts[1].other_part, 1);
}

}  // namespace
}  // namespace tumble
