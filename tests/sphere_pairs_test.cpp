// Two bodies' spheres meeting in impacts (`type: bodies` contacts), each against its closed form:
//  - Head on (masses m1, m2, restitution e): Newton's law and the momentum give
//      v1' = (m1 v1 + m2 v2 - m2 e (v1 - v2)) / (m1 + m2),
//      v2' = (m1 v1 + m2 v2 + m1 e (v1 - v2)) / (m1 + m2),
//    at the instant the gap closes, d / (v1 - v2).
//  - Oblique, frictionless, equal masses, e = 1: the struck ball leaves along the line of centres
//    and the striker across it, at 90 degrees to each other.
//  - Oblique with friction: for solid spheres on free bodies the relative velocity at the contact
//    point jumps by W p per impulse p, with W = k_n I + (k_t - k_n) (I - n n), k_n = 1/m1 + 1/m2
//    and k_t = k_n + r1^2 / I1 + r2^2 / I2 (I = 2 m r^2 / 5): the normal impulse is
//    -(1 + e) v_n / k_n, and the tangential one stops the slip (-slip / k_t) if that lies in the
//    cone, else is mu of the normal one against the slip, which keeps its direction. The spins
//    after are the impulse's moments about each centre over I.
//  - Newton's cradle (five balls on hinges, touching in a row, e = 1): the impacts go one pair at
//    a time down the row (docs/scenario.md), each an exchange of equal effective masses, and the
//    last ball leaves with the first's speed while the other four stay at rest; E through the
//    impacts to round-off.
//  - A ball striking a pendulum's bob (a sphere on a hinge, or a composite's sphere part):
//    Newton's law with the bob's effective mass I_O / L^2, and the angular momentum about the
//    pivot kept; struck plastically (a ballistic pendulum), one speed after, then the ball
//    pressing on the bob, the angular momentum kept throughout.
//  - A ball bounces off a dome (a sphere welded to ground), frictionless and with friction.
//  - A rolling cue ball strikes an object ball on a table: both slide, then roll at 2/7 and 5/7
//    of its speed.
//  - A small ball rolling into a big one at rest on the table lifts it off, the small one held by
//    the table in the impulse: the big one's flight against the impulse's closed form.
//  - A millimetre ball at 100 m/s is not stepped through.
//  - A group makes every pair of its bodies a contact (but those a joint joins).
//  - A ball settling onto the first of two touching balls settles the row at once: one plastic
//    impulse, the three at v0 / 3.
//  - `tumble find` brackets the restitution at which a striker stops, to 1e-12.
//  - `tumble modes` takes the cradle hanging with its balls apart (five pendulums), and refuses
//    it touching.
//  - What the reader and the start refuse, located.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "modes_checks.hpp"
#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "tumble/modes/not_steady.hpp"
#include "tumble/sweep/find.hpp"
#include "tumble/sweep/outcome.hpp"

namespace tumble {
namespace {

// Two free solid balls, a and b, in space with no gravity; `a` and `b` their keys after shape.
std::string two_balls(const std::string& a, const std::string& b, double mu, double e,
                      double duration) {
  return "tumble: 1\n"
         "gravity: [0, 0, 0]\n"
         "bodies:\n"
         "  a: {shape: sphere, " +
         a + "}\n  b: {shape: sphere, " + b +
         "}\n"
         "contacts:\n"
         "  - {name: touch, type: bodies, bodies: [a, b], friction: " +
         std::to_string(mu) + ", restitution: " + std::to_string(e) +
         "}\n"
         "simulate: {duration: " +
         std::to_string(duration) +
         ", integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: 0.05}\n";
}

TEST(SpherePairs, HeadOnTheVelocitiesAfterAreNewtonsAndTheMomentums) {
  const double m1 = 2.0, m2 = 0.5, v1 = 3.0, v2 = -1.0, e = 0.7;
  const test::ScenarioRun run = test::run_inline_scenario(
      two_balls("radius: 0.1, mass: 2, position: [0, 0, 0], velocity: [3, 0, 0]",
                "radius: 0.05, mass: 0.5, position: [1, 0, 0], velocity: [-1, 0, 0]", 0.3, e, 0.5),
      "head_on");
  ASSERT_EQ(run.contact_events.size(), 1u);
  const ContactEventRecord& impact = run.contact_events[0];
  EXPECT_NEAR(impact.t, 0.85 / (v1 - v2), 1e-13);
  ASSERT_TRUE(impact.impact.has_value());
  EXPECT_NEAR(impact.impact->approach_speed, v1 - v2, 1e-12);
  EXPECT_NEAR(impact.impact->rebound_speed, e * (v1 - v2), 1e-12);
  // Where (events.csv's point and normal): a's surface, 0.1 beyond its centre at v1 t; the normal
  // from b towards a.
  EXPECT_LT((impact.point_W - Vec3(v1 * impact.t + 0.1, 0, 0)).norm(), 1e-12);
  EXPECT_LT((impact.normal_W - Vec3(-1, 0, 0)).norm(), 1e-15);
  const double p = m1 * v1 + m2 * v2;
  const double v1_after = (p - m2 * e * (v1 - v2)) / (m1 + m2);
  const double v2_after = (p + m1 * e * (v1 - v2)) / (m1 + m2);
  // The energy Newton's law takes: (1 - e^2) of the relative motion's, m1 m2 / (m1 + m2) (v1 -
  // v2)^2 / 2.
  const double lost = (1 - e * e) * m1 * m2 / (m1 + m2) * (v1 - v2) * (v1 - v2) / 2;
  EXPECT_NEAR(impact.kinetic_energy_before - impact.kinetic_energy_after, lost, 1e-12 * lost);
  const test::Row& last = run.rows.back();
  EXPECT_NEAR(last.states[0].v_G.x(), v1_after, 1e-12 * v1);
  EXPECT_NEAR(last.states[1].v_G.x(), v2_after, 1e-12 * v1);
  for (const BodyState& s : last.states) {
    EXPECT_NEAR(s.v_G.y(), 0.0, 1e-15);
    EXPECT_NEAR(s.omega_W.norm(), 0.0, 1e-15);
  }
  // Momentum through the impact; the impulses' work in the contact's ledger entry.
  EXPECT_NEAR(last.quantities.linear_momentum.x(), p, 1e-12 * p);
  ASSERT_FALSE(last.extras.elements.empty());
  EXPECT_NEAR(last.extras.elements.back().work, -lost, 1e-12 * lost);
  EXPECT_NEAR(last.quantities.total_energy + lost, run.rows.front().quantities.total_energy,
              1e-12 * lost);
}

// Free flight is exact for any step, so an error-controlled method would cross 10 m in one step
// and a millimetre ball would pass through another unseen: the step limit keeps each step short
// of closing the gap by more than a millionth of the radius, and the impact is found.
TEST(SpherePairs, ASmallFastBallDoesNotPassThroughAnotherInOneLongStep) {
  const double v = 100.0;
  const test::ScenarioRun run = test::run_inline_scenario(
      two_balls("radius: 0.001, mass: 0.01, position: [-10, 0, 0], velocity: [100, 0, 0]",
                "radius: 0.001, mass: 0.01, position: [0, 0, 0]", 0.0, 1.0, 1.0),
      "fast");
  ASSERT_EQ(run.contact_events.size(), 1u);
  EXPECT_NEAR(run.contact_events[0].t, (10 - 0.002) / v, 1e-13);
  EXPECT_NEAR(run.rows.back().states[1].v_G.x(), v, 1e-12 * v);
  EXPECT_NEAR(run.rows.back().states[0].v_G.x(), 0.0, 1e-12 * v);
}

TEST(SpherePairs, ObliqueFrictionlessEqualMassesElasticLeaveAtRightAngles) {
  // b at rest, a along x with its line of centres at the impact offset by 0.12 in y: sin(angle)
  // = 0.12 / (2 R) from the x axis.
  const double R = 0.1, v = 2.0, offset = 0.12;
  const test::ScenarioRun run = test::run_inline_scenario(
      two_balls("radius: 0.1, mass: 1, position: [-0.5, 0.12, 0], velocity: [2, 0, 0]",
                "radius: 0.1, mass: 1, position: [0, 0, 0]", 0.0, 1.0, 0.6),
      "oblique");
  ASSERT_EQ(run.contact_events.size(), 1u);
  const Vec3 va = run.rows.back().states[0].v_G, vb = run.rows.back().states[1].v_G;
  EXPECT_NEAR(va.dot(vb), 0.0, 1e-12 * v * v);
  EXPECT_NEAR(va.squaredNorm() + vb.squaredNorm(), v * v, 1e-12 * v * v);
  // The struck ball along the line of centres at the impact, from a's centre to b's.
  const double angle = std::asin(offset / (2 * R));
  const Vec3 n(std::cos(angle), -std::sin(angle), 0.0);
  EXPECT_NEAR(vb.normalized().dot(n), 1.0, 1e-12);
  EXPECT_NEAR(vb.norm(), v * std::cos(angle), 1e-12 * v);
  const double t_impact = (0.5 - 2 * R * std::cos(angle)) / v;
  EXPECT_NEAR(run.contact_events[0].t, t_impact, 1e-13);
}

// `tumble find` on what an impact leaves: a light ball (0.5 kg at 3 m/s) strikes a heavy one at
// rest (2 kg) head on, and comes to a stop where Newton's law gives it no speed after: e* =
// (m1 v1 + m2 v2) / (m2 (v1 - v2)) = 1/4. Above it the light ball bounces back: final(a.vx) < 0.
TEST(SpherePairs, FindTheRestitutionAtWhichTheStrikerStops) {
  SweepSpec spec;
  spec.path = "stops.yaml";
  spec.text =
      "tumble: 1\n"
      "parameters: {rest: 0.5}\n"
      "gravity: [0, 0, 0]\n"
      "bodies:\n"
      "  a: {shape: sphere, radius: 0.05, mass: 0.5, position: [0, 0, 0], velocity: [3, 0, 0]}\n"
      "  b: {shape: sphere, radius: 0.1, mass: 2, position: [1, 0, 0]}\n"
      "contacts:\n"
      "  - {name: touch, type: bodies, bodies: [a, b], friction: 0, restitution: rest}\n"
      "simulate: {duration: 0.5, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
      "0.1}\n";
  spec.varied = {"rest"};
  spec.outcomes = {parse_outcome("condition", "final(a.vx) < 0")};
  const FindResult found = find_change(spec, 0.0, 1.0, 1e-12);
  EXPECT_FALSE(found.at_lo);
  EXPECT_TRUE(found.at_hi);
  const double e_star = (0.5 * 3.0) / (2.0 * 3.0);
  EXPECT_NEAR(found.lo + 0.5 * (found.hi - found.lo), e_star, 1e-12);
}

// The spins and velocities after an oblique impact of two solid balls with friction, by the
// closed form of the header, against the run's.
void expect_friction_impact(double mu) {
  const double r1 = 0.1, m1 = 1.0, r2 = 0.15, m2 = 3.0, v = 2.0, offset = 0.1, e = 0.6;
  const test::ScenarioRun run = test::run_inline_scenario(
      two_balls("radius: 0.1, mass: 1, position: [-0.6, 0.1, 0], velocity: [2, 0, 0]",
                "radius: 0.15, mass: 3, position: [0, 0, 0]", mu, e, 0.5),
      "friction");
  ASSERT_EQ(run.contact_events.size(), 1u) << "mu " << mu;
  // At the impact: the centres r1 + r2 apart, a's offset in y unchanged.
  const double x_a = -std::sqrt((r1 + r2) * (r1 + r2) - offset * offset);
  const Vec3 n = Vec3(x_a, offset, 0.0).normalized();  // from b's centre to a's
  const Vec3 v_rel(v, 0.0, 0.0);
  const double vn = n.dot(v_rel);
  const Vec3 slip = v_rel - vn * n;
  const double I1 = 0.4 * m1 * r1 * r1, I2 = 0.4 * m2 * r2 * r2;
  const double k_n = 1 / m1 + 1 / m2, k_t = k_n + r1 * r1 / I1 + r2 * r2 / I2;
  const double p_n = -(1 + e) * vn / k_n;
  const Vec3 stop_slip = -slip / k_t;
  const bool sticks = stop_slip.norm() <= mu * p_n;
  const Vec3 p = p_n * n + (sticks ? stop_slip : Vec3(-mu * p_n * slip.normalized()));
  const test::Row& last = run.rows.back();
  const double scale = v;
  EXPECT_LT((last.states[0].v_G - (Vec3(v, 0, 0) + p / m1)).norm(), 1e-12 * scale) << mu;
  EXPECT_LT((last.states[1].v_G - (-p / m2)).norm(), 1e-12 * scale) << mu;
  const Vec3 w1 = (-r1 * n).cross(p) / I1, w2 = (r2 * n).cross(-p) / I2;
  EXPECT_LT((last.states[0].omega_W - w1).norm(), 1e-12 * scale / r1) << mu;
  EXPECT_LT((last.states[1].omega_W - w2).norm(), 1e-12 * scale / r1) << mu;
  EXPECT_GT(w1.norm(), 1.0) << "the friction spins them";
  // The event's impulse is what b gave a.
  EXPECT_LT((run.contact_events[0].impact->impulse_W - p).norm(), 1e-12 * m1 * v) << mu;
  if (sticks) {
    // No slip at the contact point after.
    const Vec3 va = last.states[0].v_G + last.states[0].omega_W.cross(-r1 * n);
    const Vec3 vb = last.states[1].v_G + last.states[1].omega_W.cross(r2 * n);
    const Vec3 rel = va - vb;
    EXPECT_LT((rel - n * n.dot(rel)).norm(), 1e-12 * v);
  }
  EXPECT_EQ(sticks, mu > 0.5) << "the two cases this test means to cover";
}

TEST(SpherePairs, ObliqueWithFrictionTheSpinsAfterAreTheImpulsesClosedForm) {
  expect_friction_impact(0.05);  // slides through the impact
  expect_friction_impact(0.9);   // the slip stops
}

// Five balls of radius R on hinges at L below pivots s = 2R apart, touching in a row; the first
// pulled back by theta0 and let go.
std::string cradle(double theta0_deg) {
  std::string yaml =
      "tumble: 1\n"
      "parameters: {R: 0.02, s: 2*R, m: 0.1, L: 0.3, theta0: " +
      std::to_string(theta0_deg) + " deg, g: " + std::to_string(test::kG) +
      "}\n"
      "gravity: [0, 0, -g]\n"
      "bodies:\n"
      "  ball1: {shape: sphere, radius: R, mass: m, position: [-L*sin(theta0), 0, "
      "-L*cos(theta0)]}\n";
  for (int i = 2; i <= 5; ++i) {
    yaml += "  ball" + std::to_string(i) + ": {shape: sphere, radius: R, mass: m, position: [" +
            std::to_string(i - 1) + "*s, 0, -L]}\n";
  }
  yaml += "joints:\n";
  for (int i = 1; i <= 5; ++i) {
    yaml += "  string" + std::to_string(i) + ": {type: hinge, body: ball" + std::to_string(i) +
            ", at: [" + std::to_string(i - 1) + "*s, 0, 0], axis: [0, 1, 0]}\n";
  }
  yaml += "contacts:\n";
  for (int i = 1; i <= 4; ++i) {
    yaml += "  - {name: touch" + std::to_string(i) + ", type: bodies, bodies: [ball" +
            std::to_string(i) + ", ball" + std::to_string(i + 1) +
            "], friction: 0, restitution: 1}\n";
  }
  yaml +=
      "simulate: {duration: 0.6, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
      "0.01}\n";
  return yaml;
}

TEST(SpherePairs, NewtonsCradleHandsTheStrikeDownTheRowOnePairAtATime) {
  const double R = 0.02, m = 0.1, L = 0.3, theta0 = 20.0 * std::numbers::pi / 180.0;
  const test::ScenarioRun run = test::run_inline_scenario(cradle(20.0), "cradle");
  // The first ball's speed at the bottom: its energy m g L (1 - cos theta0) in the pendulum's
  // rotation about its pivot, I_O = m L^2 + 2 m R^2 / 5.
  const double I_O = m * L * L + 0.4 * m * R * R;
  const double omega = std::sqrt(2 * m * test::kG * L * (1 - std::cos(theta0)) / I_O);
  ASSERT_GE(run.contact_events.size(), 4u);
  const double t_strike = run.contact_events[0].t;
  for (int i = 0; i < 4; ++i) {
    const ContactEventRecord& e = run.contact_events[static_cast<std::size_t>(i)];
    EXPECT_EQ(e.contact, static_cast<std::size_t>(i)) << "down the row, in order";
    EXPECT_EQ(e.t, t_strike);
    ASSERT_TRUE(e.impact.has_value());
    // Each pair exchanges: the approach is the first ball's speed, and so is the rebound.
    EXPECT_NEAR(e.impact->approach_speed, omega * L, 1e-9 * omega * L) << i;
    EXPECT_NEAR(e.impact->rebound_speed, omega * L, 1e-9 * omega * L) << i;
    EXPECT_NEAR(e.kinetic_energy_after, e.kinetic_energy_before, 1e-14 * e.kinetic_energy_before);
  }
  // Through the four impacts the speed passes on exactly (the 1e-9 above is the integration's
  // error in the first ball's speed at the bottom; the exchange itself is to round-off).
  for (int i = 1; i < 4; ++i) {
    const auto k = static_cast<std::size_t>(i);
    EXPECT_NEAR(run.contact_events[k].impact->approach_speed,
                run.contact_events[0].impact->approach_speed, 1e-12 * omega * L);
  }
  // Then the last ball swings out alone, up to the first's height, and comes back: until then the
  // other four hang at rest.
  const double E0 = run.rows.front().quantities.total_energy;
  bool seen_after = false;
  for (const test::Row& row : run.rows) {
    EXPECT_NEAR(row.quantities.total_energy, E0, 1e-10 * m * test::kG * L) << row.t;
    if (row.t <= t_strike || (run.contact_events.size() > 4 && row.t >= run.contact_events[4].t)) {
      continue;
    }
    seen_after = true;
    for (int i = 0; i < 4; ++i) {
      EXPECT_LT(row.states[static_cast<std::size_t>(i)].omega_W.norm(), 1e-12 * omega)
          << "ball " << i + 1 << " t " << row.t;
    }
  }
  EXPECT_TRUE(seen_after);
}

// A group, `bodies: [ball1, ball2, ball3]`: every pair of it a contact (touch_ball1_ball2,
// touch_ball1_ball3, touch_ball2_ball3), and a strike down the row as the cradle's: the third ball
// leaves with the first's speed, the other two at rest. A pair that a joint joins to each other
// is left out, unless `joined: true`.
// A ball meets the first of two balls that touch, slower than a settling touchdown: the
// settling impulse holds the touching pair it drives together too, so the three settle at once,
// one plastic impulse on the row, and move on together at the momentum's speed v0 / 3, with a
// third of the kinetic energy. (One pair at a time, the rounds handed the push back and forth,
// each a fraction of the last: tens of events at one instant, converging to v0 / 3 only as far
// as the pairs' round-off.)
TEST(SpherePairs, ASettlingTouchdownSettlesATouchingRowAtOnce) {
  const double r = 0.05, v0 = 5e-4;  // the settling speed: sqrt(2 g 1e-6 r) = 9.9e-4 m/s
  const std::string yaml =
      "tumble: 1\n"
      "gravity: [0, 0, -" +
      std::to_string(test::kG) +
      "]\n"
      "bodies:\n"
      "  a: {shape: sphere, radius: 0.05, mass: 0.1, position: [-0.1001, 0, 0], velocity: [" +
      std::to_string(v0) +
      ", 0, 0]}\n"
      "  b: {shape: sphere, radius: 0.05, mass: 0.1, position: [0, 0, 0]}\n"
      "  c: {shape: sphere, radius: 0.05, mass: 0.1, position: [0.1, 0, 0]}\n"
      "contacts:\n"
      "  - {name: touch, type: bodies, bodies: [a, b, c], friction: 0, restitution: 0.5}\n"
      "simulate: {duration: 0.3, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
      "0.01}\n";
  const test::ScenarioRun run = test::run_inline_scenario(yaml, "settling_row");
  std::vector<std::string> seen;
  for (const ContactEventRecord& event : run.contact_events) {
    seen.push_back(run.contacts[event.contact].name + ": " + event.what);
  }
  ASSERT_EQ(run.contact_events.size(), 1u) << ::testing::PrintToString(seen);
  const ContactEventRecord& settles = run.contact_events[0];
  EXPECT_EQ(run.contacts[settles.contact].name, "touch_a_b");
  EXPECT_NE(settles.what.find("settles"), std::string::npos) << settles.what;
  EXPECT_NEAR(settles.t, 1e-4 / v0, 1e-12);
  // The three fall together, their vertical speeds untouched: the impulse takes two thirds of
  // the x motion's m v0^2 / 2 (to the round-off of KE, ~0.58 J by then).
  EXPECT_NEAR(settles.kinetic_energy_before - settles.kinetic_energy_after, 0.1 * v0 * v0 / 3.0,
              1e-14);
  const test::Row& last = run.rows.back();
  for (const BodyState& ball : last.states) {
    EXPECT_NEAR(ball.v_G.x(), v0 / 3.0, 1e-12 * v0);
  }
  // Together from the instant they settled: each gap where it was then.
  const double t = last.t - settles.t;
  EXPECT_NEAR(last.states[1].r_G.x() - last.states[0].r_G.x(), 2 * r, 1e-12);
  EXPECT_NEAR(last.states[2].r_G.x() - last.states[1].r_G.x(), 2 * r, 1e-12);
  EXPECT_NEAR(last.states[2].r_G.x(), 0.1 + v0 / 3.0 * t, 1e-12);
}

TEST(SpherePairs, AGroupMakesEveryPairOfItAContact) {
  const std::string yaml =
      "tumble: 1\n"
      "gravity: [0, 0, 0]\n"
      "bodies:\n"
      "  ball1: {shape: sphere, radius: 0.1, mass: 1, position: [-1, 0, 0], velocity: [2, 0, 0]}\n"
      "  ball2: {shape: sphere, radius: 0.1, mass: 1, position: [0, 0, 0]}\n"
      "  ball3: {shape: sphere, radius: 0.1, mass: 1, position: [0.2, 0, 0]}\n"
      "contacts:\n"
      "  - {name: touch, type: bodies, bodies: [ball1, ball2, ball3], friction: 0, restitution: "
      "1}\n"
      "simulate: {duration: 1, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: 0.1}\n";
  const test::ScenarioRun run = test::run_inline_scenario(yaml, "group");
  ASSERT_EQ(run.contacts.size(), 3u);
  EXPECT_EQ(run.contacts[0].name, "touch_ball1_ball2");
  EXPECT_EQ(run.contacts[1].name, "touch_ball1_ball3");
  EXPECT_EQ(run.contacts[2].name, "touch_ball2_ball3");
  ASSERT_EQ(run.contact_events.size(), 2u);
  EXPECT_EQ(run.contact_events[0].contact, 0u);
  EXPECT_EQ(run.contact_events[1].contact, 2u);
  const test::Row& last = run.rows.back();
  EXPECT_NEAR(last.states[0].v_G.norm() + last.states[1].v_G.norm(), 0.0, 1e-14);
  EXPECT_NEAR(last.states[2].v_G.x(), 2.0, 1e-14);

  const std::string dumbbell = test::replaced(
      yaml, "contacts:",
      "joints:\n  bar: {type: ball, bodies: [ball2, ball3], at: [0.1, 0, 0]}\ncontacts:");
  EXPECT_EQ(test::load_inline_scenario(dumbbell, "joined").contacts.size(), 2u);
  EXPECT_EQ(test::load_inline_scenario(
                test::replaced(dumbbell, "restitution: 1}", "restitution: 1, joined: true}"),
                "joined_too")
                .contacts.size(),
            3u);
}

// `tumble modes` takes a pair of bodies while they are apart: the cradle hanging at rest with its
// balls a millimetre apart is five pendulums, each at omega^2 = m g L / I_O. Touching, they hang
// side by side without pressing on each other: the least swing parts them or presses them, which
// has no linearisation, and modes refuses it, saying so (modes_pair_test.cpp: pairs that press).
TEST(SpherePairs, ModesTakeTheCradleApartAndRefuseItTouching) {
  const double R = 0.02, m = 0.1, L = 0.3;
  const double omega = std::sqrt(m * test::kG * L / (m * L * L + 0.4 * m * R * R));
  const ScenarioModes apart = modes_of_scenario(
      test::load_inline_scenario(test::replaced(cradle(0.0), "s: 2*R", "s: 2*R + 0.001"), "apart"));
  test::expect_oscillating_at(apart.analysis, std::vector<double>(5, omega), 1e-9);
  try {
    modes_of_scenario(test::load_inline_scenario(cradle(0.0), "touching"));
    ADD_FAILURE() << "touching balls taken";
  } catch (const NotSteady& refused) {
    EXPECT_NE(std::string(refused.what())
                  .find("contact touch1: the two bodies touch without pressing (N = "),
              std::string::npos)
        << refused.what();
  }
}

// A ball fired along the line through a hanging pendulum's bob (a sphere on a hinge L below its
// pivot; no gravity, so that the ball flies straight and the bob waits at the bottom), with
// restitution e. The hinge holds the bob, so it meets the ball with the effective mass I_O / L^2
// (I_O = M L^2 + 2 M R^2 / 5 about the pivot), and Newton's law gives
//     u' = (m - e m_eff) u / (m + m_eff),   V' = (1 + e) m u / (m + m_eff),   omega' = V' / L;
// the hinge's impulse passes through the pivot, so the angular momentum about it is kept (with
// friction too: sticking, the bob's contact point, which its turn about its own centre moves
// along the rod, drags the ball along with it).
std::string ballistic_pendulum(double e, double mu) {
  return "tumble: 1\n"
         "parameters: {L: 0.5, M: 1, Rb: 0.05, m: 0.2, r: 0.02, u: 3}\n"
         "gravity: [0, 0, 0]\n"
         "bodies:\n"
         "  bob: {shape: sphere, radius: Rb, mass: M, position: [0, 0, -L]}\n"
         "  ball: {shape: sphere, radius: r, mass: m, position: [-0.5, 0, -L], velocity: [u, 0, "
         "0]}\n"
         "joints:\n"
         "  pivot: {type: hinge, body: bob, at: [0, 0, 0], axis: [0, 1, 0]}\n"
         "contacts:\n"
         "  - {name: strike, type: bodies, bodies: [ball, bob], friction: " +
         std::to_string(mu) + ", restitution: " + std::to_string(e) +
         "}\n"
         "simulate: {duration: 0.4, integrator: dop853, rtol: 1e-12, atol: 1e-14, "
         "output_every: 0.01}\n";
}

TEST(SpherePairs, ABallStrikingAPendulumKeepsTheAngularMomentumAboutThePivot) {
  const double L = 0.5, M = 1.0, Rb = 0.05, m = 0.2, r = 0.02, u = 3.0, e = 0.5;
  const double I_O = M * L * L + 0.4 * M * Rb * Rb, m_eff = I_O / (L * L);
  const double u_after = (m - e * m_eff) * u / (m + m_eff);
  const double V_after = (1 + e) * m * u / (m + m_eff);
  for (const double mu : {0.0, 0.4}) {
    const test::ScenarioRun run = test::run_inline_scenario(ballistic_pendulum(e, mu), "strike");
    ASSERT_EQ(run.contact_events.size(), 1u);
    EXPECT_NEAR(run.contact_events[0].t, (0.5 - Rb - r) / u, 1e-13);
    const double L0 = run.rows.front().quantities.angular_momentum_about_origin.y();
    EXPECT_NEAR(L0, -L * m * u, 1e-15);
    for (const test::Row& row : run.rows) {
      EXPECT_NEAR(row.quantities.angular_momentum_about_origin.y(), L0, 1e-12 * std::abs(L0))
          << row.t << " mu " << mu;
      if (row.t <= run.contact_events[0].t) continue;
      if (mu == 0.0) {
        // The bob turns about y at -V'/L (moving +x below the pivot); the ball flies back.
        EXPECT_NEAR(row.states[0].omega_W.y(), -V_after / L, 1e-12 * u / L) << row.t;
        EXPECT_NEAR(row.states[1].v_G.x(), u_after, 1e-12 * u) << row.t;
      } else {
        EXPECT_GT(std::abs(row.states[1].v_G.z()), 1e-3 * u) << "friction drags the ball along";
      }
    }
  }
  EXPECT_LT(u_after, 0.0) << "the case this test means: they part";
}

// The same strike on a pendulum whose bob is a sphere part of one body with its rod (a uniform
// rod of mass m_rod from the pivot to the bob's centre): the contact is the part's sphere, placed
// in the body, and the effective mass takes the rod's m_rod L^2 / 3 into I_O.
TEST(SpherePairs, ABallStrikesACompositesSpherePart) {
  const double L = 0.5, M = 1.0, Rb = 0.05, m = 0.2, u = 3.0, e = 0.5, m_rod = 0.3;
  const std::string composite =
      "  bob:\n"
      "    parts:\n"
      "      - {name: rod, shape: rod, length: L, mass: 0.3, position: [0, 0, -L/2]}\n"
      "      - {name: head, shape: sphere, radius: Rb, mass: M, position: [0, 0, -L]}\n"
      "    position: [0, 0, 0]\n";
  const test::ScenarioRun run = test::run_inline_scenario(
      test::replaced(ballistic_pendulum(e, 0.0),
                     "  bob: {shape: sphere, radius: Rb, mass: M, position: [0, 0, -L]}\n",
                     composite),
      "composite");
  ASSERT_EQ(run.contact_events.size(), 1u);
  EXPECT_NEAR(run.contact_events[0].t, (0.5 - Rb - 0.02) / u, 1e-13);
  const double I_O = m_rod * L * L / 3 + M * L * L + 0.4 * M * Rb * Rb, m_eff = I_O / (L * L);
  const double u_after = (m - e * m_eff) * u / (m + m_eff);
  const double V_after = (1 + e) * m * u / (m + m_eff);
  const double L0 = run.rows.front().quantities.angular_momentum_about_origin.y();
  for (const test::Row& row : run.rows) {
    EXPECT_NEAR(row.quantities.angular_momentum_about_origin.y(), L0, 1e-12 * std::abs(L0));
    if (row.t <= run.contact_events[0].t) continue;
    EXPECT_NEAR(row.states[0].omega_W.y(), -V_after / L, 1e-12 * u / L) << row.t;
    EXPECT_NEAR(row.states[1].v_G.x(), u_after, 1e-12 * u) << row.t;
  }
}

// With e = 0 (a ballistic pendulum: the ball stays in the bob) and no friction, the two leave
// the strike at one speed along the line of centres, V = m u / (m + m_eff): the ball's impulse
// is m (V - u), the bob turns at -V / L, and the angular momentum about the pivot, -L m u, is kept
// through the strike. Then the bob turns away along its circle while the ball would fly on
// straight: the ball presses on it, and the contact holds them (sliding) until it lets go.
// Through all of it the only moment about the pivot is the hinge's, none: the angular momentum
// is kept at every row, and the energy too from the strike on.
TEST(SpherePairs, APlasticStrikeOnAPendulumLeavesThemAtOneSpeedThenPressing) {
  const double L = 0.5, M = 1.0, Rb = 0.05, m = 0.2, u = 3.0;
  const double I_O = M * L * L + 0.4 * M * Rb * Rb, m_eff = I_O / (L * L);
  const double V = m * u / (m + m_eff);
  const test::ScenarioRun run = test::run_inline_scenario(ballistic_pendulum(0.0, 0.0), "plastic");
  ASSERT_GE(run.contact_events.size(), 3u);
  const ContactEventRecord& strike = run.contact_events[0];
  EXPECT_NEAR(strike.t, (0.5 - Rb - 0.02) / u, 1e-13);
  ASSERT_TRUE(strike.impact.has_value());
  EXPECT_NEAR(strike.impact->rebound_speed, 0.0, 1e-12 * u);
  // The impulse on the ball (the contact's first body): m (V - u) along x, to 1e-12.
  EXPECT_NEAR(strike.impact->impulse_W.x(), m * (V - u), 1e-12 * m * u);
  EXPECT_NEAR(strike.impact->impulse_W.z(), 0.0, 1e-12 * m * u);
  // The energy it took: the plastic strike's m m_eff u^2 / (2 (m + m_eff)).
  EXPECT_NEAR(strike.impact->kinetic_energy_before - strike.impact->kinetic_energy_after,
              m * m_eff * u * u / (2 * (m + m_eff)), 1e-12 * m * u * u);
  // They press: the contact holds them after the strike (a settling touch may come first, the
  // bob's circle leaving the straight line by the cube of the time), and then lets go.
  double pressed_t = std::nan(""), let_go_t = std::nan("");
  for (const ContactEventRecord& e : run.contact_events) {
    if (e.what == "slides" && std::isnan(pressed_t)) pressed_t = e.t;
    if (e.what == "lifts off" && !std::isnan(pressed_t)) let_go_t = e.t;
  }
  EXPECT_LT(pressed_t - strike.t, 1e-3) << "pressed within a millisecond of the strike";
  EXPECT_GT(let_go_t, pressed_t);
  const double L0 = run.rows.front().quantities.angular_momentum_about_origin.y();
  EXPECT_NEAR(L0, -L * m * u, 1e-15);
  double E_after = std::nan("");
  for (const test::Row& row : run.rows) {
    EXPECT_NEAR(row.quantities.angular_momentum_about_origin.y(), L0, 1e-12 * std::abs(L0))
        << row.t;
    if (row.t <= strike.t) continue;
    if (std::isnan(E_after)) E_after = row.quantities.total_energy;
    EXPECT_NEAR(row.quantities.total_energy, E_after, 1e-12 * m * u * u) << row.t;
    EXPECT_GE(row.extras.contacts[0].normal_force, 0.0) << row.t << ": it only pushes";
    if (row.t > pressed_t && row.t < let_go_t) {
      EXPECT_EQ(row.extras.contacts[0].mode, 1) << row.t;
      EXPECT_GT(row.extras.contacts[0].normal_force, 0.0) << row.t;
    }
  }
}

// A ball dropped from rest onto a dome: a fixed obstacle stated as a sphere welded to ground
// (its response to any impulse is none). The ball, its centre b off the dome's axis, falls until
// its centre is R + r from the dome's, at z = sqrt((R + r)^2 - b^2) after t = sqrt(2 (h - z) /
// g); frictionless, it leaves at v - (1 + e) (v . n) n; with friction, as two balls (the dome's
// side of W is none: k_n = 1/m, k_t = 1/m + r^2 / I), spinning at (-r n) x p / I. Then it flies
// under gravity alone.
void expect_bounce_off_a_dome(double mu) {
  const double R = 0.5, r = 0.05, m = 0.1, b = 0.2, h = 1.0, e = 0.8, g = test::kG;
  const std::string yaml =
      "tumble: 1\n"
      "gravity: [0, 0, -" +
      std::to_string(g) +
      "]\n"
      "bodies:\n"
      "  dome: {shape: sphere, radius: 0.5, mass: 10, position: [0, 0, 0]}\n"
      "  ball: {shape: sphere, radius: 0.05, mass: 0.1, position: [0.2, 0, 1]}\n"
      "joints:\n"
      "  footing: {type: fixed, bodies: [ground, dome], at: [0, 0, 0]}\n"
      "contacts:\n"
      "  - {name: bounce, type: bodies, bodies: [ball, dome], friction: " +
      std::to_string(mu) +
      ", restitution: 0.8}\n"
      "simulate: {duration: 0.4, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
      "0.01}\n";
  const test::ScenarioRun run = test::run_inline_scenario(yaml, "dome");
  ASSERT_EQ(run.contact_events.size(), 1u) << mu;
  const double z = std::sqrt((R + r) * (R + r) - b * b);
  const double t_impact = std::sqrt(2 * (h - z) / g);
  EXPECT_NEAR(run.contact_events[0].t, t_impact, 1e-12) << mu;
  const Vec3 n = Vec3(b, 0, z) / (R + r);
  const Vec3 v(0, 0, -g * t_impact);
  const double vn = v.dot(n);
  const Vec3 slip = v - vn * n;
  const double I = 0.4 * m * r * r, k_n = 1 / m, k_t = 1 / m + r * r / I;
  const double p_n = -(1 + e) * vn / k_n;
  const Vec3 stop_slip = -slip / k_t;
  const Vec3 p =
      p_n * n + (stop_slip.norm() <= mu * p_n ? stop_slip : Vec3(-mu * p_n * slip.normalized()));
  const Vec3 v_after = v + p / m, w_after = (-r * n).cross(p) / I;
  if (mu > 0.0) {
    EXPECT_GT(w_after.norm(), 10.0) << "friction spins it (here it sticks)";
  }
  for (const test::Row& row : run.rows) {
    if (row.t <= t_impact) continue;
    const BodyState& ball = row.states[1];
    EXPECT_LT((ball.v_G - (v_after + Vec3(0, 0, -g * (row.t - t_impact)))).norm(), 1e-11 * g)
        << row.t << " mu " << mu;
    EXPECT_LT((ball.omega_W - w_after).norm(), 1e-11 * g / r) << row.t << " mu " << mu;
    EXPECT_LT(row.states[0].v_G.norm() + row.states[0].omega_W.norm(), 1e-15) << "the dome";
  }
}

TEST(SpherePairs, ABallBouncesOffADomeWeldedToGround) {
  expect_bounce_off_a_dome(0.0);
  expect_bounce_off_a_dome(0.3);
}

// A cue ball rolling at v0 on a table (friction mu) strikes an object ball at rest head on (the
// balls frictionless and elastic between them). The impulse passes through both centres, level
// with the table, so the table takes no part in it: the cue ball stops, still spinning at
// v0 / R, and the object ball leaves at v0 without spin. Both slide, friction mu m g on each,
// until they roll: the object ball at 5 v0 / 7 and the cue ball at 2 v0 / 7 (the "follow" of a
// rolling cue ball), both at 2 v0 / (7 mu g) after the impact (I = 2 m R^2 / 5).
TEST(SpherePairs, ARollingCueBallStrikingAnObjectBallFollowsAtTwoSevenths) {
  const double R = 0.028575, v0 = 1.0, mu = 0.2;
  const std::string yaml =
      "tumble: 1\n"
      "parameters: {R: 0.028575, m: 0.17, v0: 1}\n"
      "gravity: [0, 0, -" +
      std::to_string(test::kG) +
      "]\n"
      "bodies:\n"
      "  cue: {shape: sphere, radius: R, mass: m, position: [-0.5, 0, R], velocity: [v0, 0, 0], "
      "angular_velocity: [0, v0/R, 0]}\n"
      "  object: {shape: sphere, radius: R, mass: m, position: [0, 0, R]}\n"
      "contacts:\n"
      "  - {name: cue_on_table, type: plane, body: cue, plane: {point: [0, 0, 0], normal: [0, 0, "
      "1]}, friction: 0.2}\n"
      "  - {name: object_on_table, type: plane, body: object, plane: {point: [0, 0, 0], normal: "
      "[0, 0, 1]}, friction: 0.2}\n"
      "  - {name: balls, type: bodies, bodies: [cue, object], friction: 0, restitution: 1}\n"
      "simulate: {duration: 1.2, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
      "0.01}\n";
  const test::ScenarioRun run = test::run_inline_scenario(yaml, "billiards");
  const double t_impact = (0.5 - 2 * R) / v0;
  const double t_rolls = t_impact + 2 * v0 / (7 * mu * test::kG);
  std::vector<std::string> seen;
  for (const ContactEventRecord& e : run.contact_events) {
    seen.push_back(run.contacts[e.contact].name + ": " + e.what);
  }
  // At the start both roll; then the one impact.
  int impacts = 0;
  for (const ContactEventRecord& e : run.contact_events) {
    if (e.contact != 2) continue;
    ++impacts;
    EXPECT_NEAR(e.t, t_impact, 1e-12);
  }
  EXPECT_EQ(impacts, 1) << ::testing::PrintToString(seen);
  // Then both table contacts slide, and each slip stops (rolls) at t_rolls.
  int stops = 0;
  for (const ContactEventRecord& e : run.contact_events) {
    if (e.what.rfind("slip stops", 0) != 0) continue;
    ++stops;
    EXPECT_NEAR(e.t, t_rolls, 1e-9) << ::testing::PrintToString(seen);
  }
  EXPECT_EQ(stops, 2) << ::testing::PrintToString(seen);
  ASSERT_GT(run.rows.back().t, t_rolls);
  const test::Row& last = run.rows.back();
  EXPECT_NEAR(last.states[0].v_G.x(), 2 * v0 / 7, 1e-10 * v0);
  EXPECT_NEAR(last.states[1].v_G.x(), 5 * v0 / 7, 1e-10 * v0);
  EXPECT_NEAR(last.states[0].omega_W.y(), 2 * v0 / 7 / R, 1e-10 * v0 / R);
  EXPECT_NEAR(last.states[1].omega_W.y(), 5 * v0 / 7 / R, 1e-10 * v0 / R);
  for (const ContactOutput& contact : last.extras.contacts) EXPECT_NE(contact.mode, 1);
}

// A small ball rolling on the table into a big ball at rest on it meets it below the big one's
// centre: the line of centres n rises (n_z = (R_A - R_B) / (R_A + R_B)), and the frictionless
// impulse P n lifts the big ball off the table, while the small one, driven into the table, is
// held by it (its normal motion stopped, no friction in the instant). With the small ball's
// vertical speed held at zero, Newton's law on the pair's normal speed gives
//     P = (1 + e) v0 n_x / (1 / m_A + n_x^2 / m_B),
// and the big ball flies: v_A = P n / m_A, its centre at R_A + v_z s - g s^2 / 2, s after the
// impact. A third ball at rest elsewhere, its table contact listed first, is classified (rolls)
// first after the jump: its projection must not take away the big ball's bounce, which it did
// while the big ball's table contact was still marked rolling (the contacts a jump sends away are
// let go first).
TEST(SpherePairs, ASmallBallStrikingABigOneBelowItsCentreLiftsItOffTheTable) {
  const double RA = 0.1, RB = 0.05, mA = 1.0, mB = 0.2, v0 = 3.0, e = 0.5;
  const std::string yaml =
      "tumble: 1\n"
      "parameters: {RA: 0.1, RB: 0.05, v0: 3}\n"
      "gravity: [0, 0, -" +
      std::to_string(test::kG) +
      "]\n"
      "bodies:\n"
      "  rest: {shape: sphere, radius: RB, mass: 0.2, position: [1, 1, RB]}\n"
      "  big: {shape: sphere, radius: RA, mass: 1, position: [0, 0, RA]}\n"
      "  small: {shape: sphere, radius: RB, mass: 0.2, position: [-0.5, 0, RB], "
      "velocity: [v0, 0, 0], angular_velocity: [0, v0/RB, 0]}\n"
      "contacts:\n"
      "  - {name: rest_on_table, type: plane, body: rest, plane: {point: [0, 0, 0], normal: [0, 0, "
      "1]}, friction: 0.5}\n"
      "  - {name: big_on_table, type: plane, body: big, plane: {point: [0, 0, 0], normal: [0, 0, "
      "1]}, friction: 0.5}\n"
      "  - {name: small_on_table, type: plane, body: small, plane: {point: [0, 0, 0], normal: [0, "
      "0, 1]}, friction: 0.5}\n"
      "  - {name: hit, type: bodies, bodies: [small, big], friction: 0, restitution: 0.5}\n"
      "simulate: {duration: 0.16, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
      "0.002}\n";
  const test::ScenarioRun run = test::run_inline_scenario(yaml, "lifted");
  const double reach = std::sqrt((RA + RB) * (RA + RB) - (RA - RB) * (RA - RB));
  const double t_impact = (0.5 - reach) / v0;
  const Vec3 n(reach / (RA + RB), 0.0, (RA - RB) / (RA + RB));
  const double P = (1.0 + e) * v0 * n.x() / (1.0 / mA + n.x() * n.x() / mB);
  const Vec3 v_A = P * n / mA;
  std::vector<std::string> seen;
  for (const ContactEventRecord& event : run.contact_events) {
    seen.push_back(run.contacts[event.contact].name + ": " + event.what);
  }
  int impacts = 0, lifts = 0;
  for (const ContactEventRecord& event : run.contact_events) {
    if (event.contact == 3) {
      ++impacts;
      EXPECT_NEAR(event.t, t_impact, 1e-12);
    }
    if (event.contact == 1 && event.what.rfind("lifts off", 0) == 0) {
      ++lifts;
      EXPECT_NEAR(event.t, t_impact, 1e-12);
    }
  }
  EXPECT_EQ(impacts, 1) << ::testing::PrintToString(seen);
  EXPECT_EQ(lifts, 1) << ::testing::PrintToString(seen);
  // In flight until it lands again, 2 v_z / g after the impact.
  int in_flight = 0;
  for (const test::Row& row : run.rows) {
    const double s = row.t - t_impact;
    if (s <= 0.0 || s >= 2.0 * v_A.z() / test::kG) continue;
    ++in_flight;
    const BodyState& big = row.states[1];
    EXPECT_NEAR(big.v_G.x(), v_A.x(), 1e-11 * v0);
    EXPECT_NEAR(big.v_G.z(), v_A.z() - test::kG * s, 1e-11 * v0);
    EXPECT_NEAR(big.r_G.z(), RA + v_A.z() * s - 0.5 * test::kG * s * s, 1e-11 * RA);
    EXPECT_NEAR(big.omega_W.norm(), 0.0, 1e-11 * v0 / RA);  // frictionless: no spin
  }
  EXPECT_GT(in_flight, 10);
}

TEST(SpherePairs, TheReaderAndTheStartRefuseWhatTheyCannotTake) {
  const std::string base = two_balls("radius: 0.1, mass: 1, position: [0, 0, 0]",
                                     "radius: 0.1, mass: 1, position: [1, 0, 0]", 0.2, 0.5, 1.0);
  // Each: what is changed in `base`, to what, and where the error is (line 7 is the contact's).
  struct Refused {
    const char *from, *to;
    int column;
    const char *key, *why;
  };
  const Refused refused[] = {
      {"bodies: [a, b]", "bodies: [a, c]", 45, "contacts[0].bodies[1]", "'c'"},
      {"bodies: [a, b]", "bodies: [a, a]", 45, "contacts[0].bodies[1]", "named twice"},
      {"bodies: [a, b]", "bodies: [a]", 41, "contacts[0].bodies", "names two"},
      {"b: {shape: sphere, radius: 0.1,", "b: {shape: rod, length: 0.2,", 45,
       "contacts[0].bodies[1]", "is a rod"},
      {"type: bodies,", "type: bodies, plane: {point: [0, 0, 0]},", 33, "contacts[0].plane",
       "no plane"},
      {"type: bodies,", "type: plane,", 32, "contacts[0].bodies", "`type: bodies`"},
      {"restitution: 0.500000}", "restitution: 0.500000, joined: true}", 92, "contacts[0].joined",
       "for a group of more than two"},
      // At the start: overlapping by 0.05 m; touching and closing.
      {"position: [1, 0, 0]", "position: [0.15, 0, 0]", 5, "contacts[0]", "overlapping by 0.05 m"},
      {"position: [1, 0, 0]", "position: [0.2, 0, 0], velocity: [-1, 0, 0]", 5, "contacts[0]",
       "moving into each other at 1 m/s"},
  };
  for (const Refused& r : refused) {
    test::expect_error(test::replaced(base, r.from, r.to), 7, r.column, r.key, r.why);
  }
  // Two boxes; a sphere inside a box at the start; `friction: inf` on a plane's contact.
  const std::string boxes = test::replaced(
      test::replaced(base, "a: {shape: sphere, radius: 0.1,", "a: {shape: box, size: [1, 1, 1],"),
      "b: {shape: sphere, radius: 0.1,", "b: {shape: box, size: [1, 1, 1],");
  test::expect_error(boxes, 7, 41, "contacts[0].bodies", "two boxes do not touch");
  test::expect_error(
      test::replaced(base, "a: {shape: sphere, radius: 0.1,", "a: {shape: box, size: [1.9, 1, 1],"),
      7, 5, "contacts[0]", "overlapping by 0.05 m (the sphere's centre is 0.05 m from the box");
  test::expect_error(
      "tumble: 1\n"
      "bodies:\n"
      "  a: {shape: sphere, radius: 0.1, mass: 1, position: [0, 0, 0.1]}\n"
      "contacts:\n"
      "  - {type: plane, body: a, plane: {point: [0, 0, 0], normal: [0, 0, 1]}, friction: inf}\n"
      "simulate: {duration: 1}\n",
      5, 84, "contacts[0].friction", "for contacts between two bodies");
}

}  // namespace
}  // namespace tumble
