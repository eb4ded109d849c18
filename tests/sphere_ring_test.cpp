// A sphere against a ring or a torus (the other body's centre circle, radius a, swept by the
// torus's tube radius b, 0 for a ring: pair_core.hpp), each against its closed form, with no
// gravity and a ball (radius r) falling at u onto the circle's top from beside it, off by delta
// (its centre at a + delta from the axis):
//  - it touches when its centre is r + b from the circle's nearest point, at the height
//    z = sqrt((r + b)^2 - delta^2) above the circle's plane, at t = (z0 - z) / u, along
//    n = (delta, 0, z) / (r + b);
//  - the other body fixed, frictionless: v' = v - (1 + e) (v . n) n, the ball not turned;
//  - the other body free (mass M; a torus's moments M (a^2/2 + 5 b^2/8) across its axis and
//    M (a^2 + 3 b^2/4) about it, a ring's with b = 0), frictionless: the impulse
//    J = (1 + e) u n_z / (1/m + 1/M + k^2 / I_x), k = (c x n)_y the moment arm of the blow at the
//    contact point c = (a, 0, 0) + b n about the centre; after it the ball moves at v + J n / m,
//    the other at -J n / M, turning at -k J / I_x about y; at e = 1 no energy is lost.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "scenario_run.hpp"

namespace tumble {
namespace {

constexpr double kHoopA = 0.3, kDelta = 0.04, kBallR = 0.1, kBallM = 0.5, kHoopM = 2.0,
                 kFallU = 2.0, kBallZ0 = 1.0;

// A ring (b = 0) or a torus lying flat at the origin, fixed (welded to ground) or free, and the
// ball falling onto it, with restitution e.
std::string ball_onto(double b, bool fixed, double e) {
  const std::string shape = b > 0.0 ? "shape: torus, radius: 0.3, tube_radius: " + std::to_string(b)
                                    : std::string("shape: ring, radius: 0.3");
  return "tumble: 1\n"
         "gravity: [0, 0, 0]\n"
         "bodies:\n"
         "  hoop: {" +
         shape +
         ", mass: 2}\n"
         "  ball: {shape: sphere, radius: 0.1, mass: 0.5, position: [0.34, 0, 1], velocity: [0, 0, "
         "-2]}\n" +
         (fixed ? "joints:\n  footing: {type: fixed, bodies: [ground, hoop], at: [0, 0, 0]}\n"
                : "") +
         "contacts:\n"
         "  - {name: hit, type: bodies, bodies: [ball, hoop], friction: 0, restitution: " +
         std::to_string(e) +
         "}\n"
         "simulate: {duration: 0.6, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
         "0.01}\n";
}

struct Touch {
  double t = 0.0;
  Vec3 n = Vec3::UnitZ();
};
Touch touch(double b) {
  const double z = std::sqrt((kBallR + b) * (kBallR + b) - kDelta * kDelta);
  return {(kBallZ0 - z) / kFallU, Vec3(kDelta, 0, z) / (kBallR + b)};
}

TEST(SphereRing, ABallDroppedBesideAFixedRingOrTorusReboundsAlongTheNormalFromItsCircle) {
  const double e = 0.5;
  for (const double b : {0.0, 0.05}) {
    const test::ScenarioRun run = test::run_inline_scenario(ball_onto(b, true, e), "fixed");
    ASSERT_GE(run.contact_events.size(), 1u) << b;
    const ContactEventRecord& hit = run.contact_events[0];
    ASSERT_TRUE(hit.impact.has_value()) << hit.what;
    const Touch expected = touch(b);
    EXPECT_NEAR(hit.t, expected.t, 1e-12) << b;
    EXPECT_LT((hit.normal_W - expected.n).norm(), 1e-12) << b;
    const Vec3 v(0, 0, -kFallU);
    const Vec3 v_after = v - (1 + e) * v.dot(expected.n) * expected.n;
    const BodyState& ball = run.rows.back().states[1];
    EXPECT_LT((ball.v_G - v_after).norm(), 1e-12 * kFallU) << b;
    EXPECT_LT(ball.omega_W.norm(), 1e-12) << b;
  }
}

TEST(SphereRing, AFreeRingOrTorusStruckOnItsCircleTakesTheClosedFormsImpulse) {
  for (const double b : {0.0, 0.05}) {
    for (const double e : {1.0, 0.5}) {
      SCOPED_TRACE(::testing::Message() << "b " << b << ", e " << e);
      const test::ScenarioRun run = test::run_inline_scenario(ball_onto(b, false, e), "free");
      ASSERT_GE(run.contact_events.size(), 1u);
      const ContactEventRecord& hit = run.contact_events[0];
      ASSERT_TRUE(hit.impact.has_value()) << hit.what;
      const Touch expected = touch(b);
      EXPECT_NEAR(hit.t, expected.t, 1e-12);
      const Vec3& n = expected.n;
      const Vec3 c = Vec3(kHoopA, 0, 0) + b * n;
      const double k = c.cross(n).y();
      const double I_x = kHoopM * (kHoopA * kHoopA / 2 + 5 * b * b / 8);
      const double J = (1 + e) * kFallU * n.z() / (1 / kBallM + 1 / kHoopM + k * k / I_x);
      const test::Row& last = run.rows.back();
      const BodyState& hoop = last.states[0];
      const BodyState& ball = last.states[1];
      EXPECT_LT((ball.v_G - (Vec3(0, 0, -kFallU) + J / kBallM * n)).norm(), 1e-12 * kFallU);
      EXPECT_LT((hoop.v_G + J / kHoopM * n).norm(), 1e-12 * kFallU);
      EXPECT_LT((hoop.omega_W - Vec3(0, -k * J / I_x, 0)).norm(), 1e-12 * kFallU / kHoopA);
      EXPECT_LT(ball.omega_W.norm(), 1e-12);
      if (e == 1.0) {
        EXPECT_NEAR(hit.impact->kinetic_energy_after, hit.impact->kinetic_energy_before,
                    1e-12 * hit.impact->kinetic_energy_before);
      }
    }
  }
}

// Dropped from rest with its centre on the axis of the circle it lands on (a ring's, a torus's
// centre circle, a standing pipe's mouth: its bore's rim, radius a), a ball (radius r = 0.05)
// touches the whole circle at once: the pushes round it add up along the axis, so it lands at
// t = sqrt(2 (z0 - z) / g), z = sqrt((r + b)^2 - a^2) above the circle's plane, and bounces
// straight back up at e of its speed (the normal speed at each point of the circle, v cos(alpha),
// reverses times e, which a vertical velocity meets only at -e v; friction round the circle adds
// up to a push along the axis too). It never moves off the axis (x = y = 0 at every row, exactly)
// nor turns. Plastic (e = 0) it sits on the circle, N = m g.
TEST(SphereRing, ABallDroppedCentredOntoACircleBouncesStraightUpOrSitsOnIt) {
  struct Seat {
    const char* name;
    std::string shape;
    double touch_z;  // the centre's height at touchdown
  };
  const double r = 0.05, z0 = 0.3, g = 9.81, m = 0.2;
  const std::vector<Seat> seats = {
      {"a ring", "shape: ring, radius: 0.03", std::sqrt(r * r - 0.03 * 0.03)},
      {"a torus's hole", "shape: torus, radius: 0.06, tube_radius: 0.02",
       std::sqrt((r + 0.02) * (r + 0.02) - 0.06 * 0.06)},
      {"a pipe's mouth", "shape: tube, inner_radius: 0.03, outer_radius: 0.04, length: 0.2",
       0.1 + std::sqrt(r * r - 0.03 * 0.03)},
  };
  for (const Seat& seat : seats) {
    for (const double e : {0.5, 0.0}) {
      SCOPED_TRACE(testing::Message() << seat.name << ", e " << e);
      const std::string yaml =
          "tumble: 1\n"
          "gravity: [0, 0, -9.81]\n"
          "bodies:\n"
          "  seat: {" +
          seat.shape +
          ", mass: 1}\n"
          "  ball: {shape: sphere, radius: 0.05, mass: 0.2, position: [0, 0, 0.3]}\n"
          "joints:\n"
          "  stand: {type: fixed, bodies: [ground, seat], at: [0, 0, 0]}\n"
          "contacts:\n"
          "  - {name: on_seat, type: bodies, bodies: [ball, seat], friction: 0.5, restitution: " +
          std::to_string(e) +
          "}\n"
          "simulate: {duration: 0.5, integrator: dop853, rtol: 1e-12, atol: 1e-14, "
          "output_every: 0.01}\n";
      const test::ScenarioRun run = test::run_inline_scenario(yaml, "centred");
      ASSERT_GE(run.contact_events.size(), 1u);
      const ContactEventRecord& touchdown = run.contact_events[0];
      const double t_touch = std::sqrt(2 * (z0 - seat.touch_z) / g);
      EXPECT_NEAR(touchdown.t, t_touch, 1e-12);
      ASSERT_TRUE(touchdown.impact.has_value());
      // The kinetic energy after is e^2 of the fall's.
      EXPECT_NEAR(touchdown.kinetic_energy_before, m * g * (z0 - seat.touch_z), 1e-12);
      EXPECT_NEAR(touchdown.kinetic_energy_after, e * e * m * g * (z0 - seat.touch_z), 1e-12);
      for (const test::Row& row : run.rows) {
        const BodyState& ball = row.states[1];
        EXPECT_EQ(ball.r_G.x(), 0.0) << row.t;
        EXPECT_EQ(ball.r_G.y(), 0.0) << row.t;
        EXPECT_EQ(ball.omega_W.norm(), 0.0) << row.t;
        if (e == 0.0 && row.t > t_touch) {
          EXPECT_NEAR(ball.r_G.z(), seat.touch_z, 1e-12) << row.t;
          EXPECT_NEAR(ball.v_G.norm(), 0.0, 1e-12) << row.t;
          EXPECT_NEAR(row.extras.contacts[0].normal_force, m * g, 1e-9 * m * g) << row.t;
        }
      }
      if (e > 0.0) {
        // Straight back up at e of the landing speed: the next landing 2 e g t_touch / g later.
        ASSERT_GE(run.contact_events.size(), 2u);
        EXPECT_NEAR(run.contact_events[1].t - touchdown.t, 2 * e * t_touch, 1e-11);
      }
    }
  }
}

}  // namespace
}  // namespace tumble
