// Disks, rings, cylinders and tubes on a plane, on the parts a rolling rim does not cover: an end
// face (a can standing on a ramp, at rest and sliding; a coin, a ring, a can and a tube spinning
// down flat under torsional friction, each at the exact time its face's mean pressure radius
// gives), the side (a can tipped past its balance falls onto it and lies there; a can rocking on
// one rim lands its other and bounces off it), and a coin dropped nearly flat that comes to rest
// on its face. Every run asks rtol 1e-10
// (contact_test.cpp says what that buys).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ramp_checks.hpp"
#include "scenario_run.hpp"
#include "test_constants.hpp"

namespace tumble {
namespace {

using test::kDeg;
using test::kG;
using test::Row;
using test::run_inline_scenario;

// A drinks can: radius 0.033 m, length 0.115 m, 0.35 kg.
constexpr double kCanRadius = 0.033, kCanHalfLength = 0.0575, kCanMass = 0.35;
const std::string kCanKeys = "shape: cylinder, radius: 0.033, length: 0.115, mass: 0.35";

// The can standing on its -z face on a ramp of slope theta descending towards +x.
std::string can_on_ramp(double theta, double mu, double duration) {
  return fmt::format(
      "tumble: 1\n"
      "parameters: {{theta: {}, h: {}}}\n"
      "bodies:\n"
      "  can: {{{}, position: [h * sin(theta), 0, h * cos(theta)],\n"
      "         orientation: {{axis: [0, 1, 0], angle: theta}}}}\n"
      "contacts:\n"
      "  - {{name: ramp, type: plane, body: can, plane: {{point: [0, 0, 0],\n"
      "      normal: [sin(theta), 0, cos(theta)]}}, friction: {}}}\n"
      "simulate: {{duration: {}, integrator: dop853, rtol: 1e-10, atol: 1e-13, "
      "output_every: {}}}\n",
      theta, kCanHalfLength, kCanKeys, mu, duration, duration / 100);
}

TEST(CanOnItsEnd, BelowTheFrictionAngleItStandsAtRestFor100Seconds) {
  // Sticking holds the CoP tan(theta) h downhill of the face's centre, inside the face (< r).
  for (const double theta : {10 * kDeg, 25 * kDeg}) {
    ASSERT_LT(std::tan(theta) * kCanHalfLength, kCanRadius);
    const auto run =
        run_inline_scenario(can_on_ramp(theta, 1.05 * std::tan(theta), 100), "can_at_rest");
    ASSERT_EQ(run.contact_events.size(), 1u);
    EXPECT_EQ(run.contact_events[0].what, "sticks on its -z face");
    test::expect_at_rest_on_ramp(run, kCanMass, theta);
  }
}

TEST(CanOnItsEnd, AboveTheFrictionAngleItSlidesWithTheExactAcceleration) {
  // a = g (sin - mu cos); friction at the face, h below the COM, moves the CoP uphill by mu h,
  // inside the face (< r) for these.
  for (const double theta : {20 * kDeg, 35 * kDeg}) {
    const double mu = 0.3;
    ASSERT_LT(mu * kCanHalfLength, kCanRadius);
    const double a = kG * (std::sin(theta) - mu * std::cos(theta));
    const auto run = run_inline_scenario(can_on_ramp(theta, mu, 2), "can_slides");
    ASSERT_EQ(run.contact_events.size(), 1u);
    EXPECT_EQ(run.contact_events[0].what, "slides on its -z face");
    test::expect_sliding_down_ramp(run, kCanMass, theta, a);
  }
}

struct SpinningFlat {
  const char* name;
  std::string keys;    // the body's shape and mass
  double half_height;  // the COM above the face it lies on, m
  double I_axis;       // about its axis, kg m^2
  double mass;         // kg
  double spin_radius;  // mean distance from the centre under even pressure on the face, m
  const char* face;    // the face's name in the events
};

TEST(SpinningFlat, ItSpinsDownUnderTorsionalFrictionAtTheExactTime) {
  // Even pressure over the face: the friction moment is mu M g rho, rho the pressure's mean
  // distance from the centre (2r/3 on a disk; r on a ring, which bears on its rim; on a tube's
  // annulus (2/3)(a^3 - b^3)/(a^2 - b^2)); the spin I w0 falls linearly to zero at
  // t = I w0 / (mu M g rho), and then it sticks.
  const double r = 0.05, a = 0.04, b = 0.03;
  const SpinningFlat cases[] = {
      {"coin", fmt::format("shape: disk, radius: {}, mass: 0.2", r), 0.0, 0.5 * 0.2 * r * r, 0.2,
       2 * r / 3, "its face"},
      {"ring", fmt::format("shape: ring, radius: {}, mass: 0.2", r), 0.0, 0.2 * r * r, 0.2, r,
       "its face"},
      {"can", kCanKeys, kCanHalfLength, 0.5 * kCanMass * kCanRadius * kCanRadius, kCanMass,
       2 * kCanRadius / 3, "its -z face"},
      {"tube",
       fmt::format("shape: tube, inner_radius: {}, outer_radius: {}, length: 0.1, mass: 0.3", b, a),
       0.05, 0.5 * 0.3 * (a * a + b * b), 0.3, 2 * (a * a * a - b * b * b) / (3 * (a * a - b * b)),
       "its -z face"},
  };
  for (const SpinningFlat& body : cases) {
    for (const double mu : {0.2, 0.5}) {
      const double w0 = 20;
      const double t_stop = body.I_axis * w0 / (mu * body.mass * kG * body.spin_radius);
      const std::string yaml = fmt::format(
          "tumble: 1\n"
          "bodies:\n"
          "  b: {{{}, position: [0, 0, {}], angular_velocity: [0, 0, {}]}}\n"
          "contacts:\n"
          "  - {{name: floor, type: plane, body: b, plane: {{point: [0, 0, 0], normal: [0, 0, "
          "1]}}, friction: {}}}\n"
          "simulate: {{duration: {}, integrator: dop853, rtol: 1e-10, atol: 1e-13, "
          "output_every: {}}}\n",
          body.keys, body.half_height, w0, mu, 1.5 * t_stop, 1.5 * t_stop / 100);
      const auto run = run_inline_scenario(yaml, "spins_down_flat");
      SCOPED_TRACE(fmt::format("{} mu {}", body.name, mu));
      ASSERT_EQ(run.contact_events.size(), 3u);
      EXPECT_EQ(run.contact_events[0].what, fmt::format("slides on {}", body.face));
      EXPECT_EQ(run.contact_events[1].what, "slip stops");
      EXPECT_NEAR(run.contact_events[1].t, t_stop, 1e-9 * t_stop);
      EXPECT_EQ(run.contact_events[2].what, fmt::format("sticks on {}", body.face));
      const Vec3 r0 = run.rows.front().states[0].r_G;
      for (const Row& row : run.rows) {
        EXPECT_LT((row.states[0].r_G - r0).norm(), 1e-12);
        const double w = row.t < t_stop ? w0 * (1 - row.t / t_stop) : 0.0;
        EXPECT_NEAR(row.states[0].omega_W.z(), w, 1e-9 * w0) << "t " << row.t;
        EXPECT_NEAR(row.extras.contacts[0].normal_force, body.mass * kG, 1e-10 * body.mass * kG);
      }
    }
  }
}

TEST(CanTipped, PastItsBalanceItFallsOntoItsSideAndLiesThere) {
  // Standing on a rim point with its axis 60 degrees from the vertical (its balance is at
  // atan(r / h) = 30 degrees), it falls onto its side: the side lands, and it ends lying on it,
  // its axis level and its COM r above the floor, never having gained energy.
  for (const double e : {0.0, 0.3}) {
    const std::string yaml = fmt::format(
        "tumble: 1\n"
        "parameters: {{tilt: 60 deg, r: {}, h: {}}}\n"
        "bodies:\n"
        "  can: {{{}, position: [h * sin(tilt) - r * cos(tilt), 0, h * cos(tilt) + r * "
        "sin(tilt)],\n"
        "         orientation: {{axis: [0, 1, 0], angle: tilt}}}}\n"
        "contacts:\n"
        "  - {{name: floor, type: plane, body: can, plane: {{point: [0, 0, 0], normal: [0, 0, "
        "1]}}, friction: 0.5, restitution: {}}}\n"
        "simulate: {{duration: 2, integrator: dop853, rtol: 1e-10, atol: 1e-13, output_every: "
        "0.01}}\n",
        kCanRadius, kCanHalfLength, kCanKeys, e);
    const auto run = run_inline_scenario(yaml, "can_tipped");
    SCOPED_TRACE(fmt::format("e {}", e));
    test::expect_energy_never_rises(run, 1e-8);
    ASSERT_FALSE(run.contact_events.empty());
    EXPECT_EQ(run.contact_events.front().what, "rolls on its -z rim");
    const std::string& last = run.contact_events.back().what;
    EXPECT_TRUE(last == "rolls on its side" || last == "sticks on its side") << last;
    const Row& end = run.rows.back();
    EXPECT_NEAR(end.states[0].r_G.z(), kCanRadius, 1e-10);
    EXPECT_NEAR((end.states[0].R_WB * Vec3::UnitZ()).z(), 0.0, 1e-9);
    EXPECT_NEAR(end.extras.contacts[0].normal_force, kCanMass * kG, 1e-8 * kCanMass * kG);
  }
}

TEST(CanRockingOnOneRim, ItsOtherRimBouncesAtERestitutionAndRocksBackAtTheSameSpeed) {
  // Frictionless, released at rest on its -z rim with its axis phi0 = 10 degrees from level: no
  // force along the floor, so its COM only falls, and the rim A it rocks on stays at the floor,
  // at rest along the normal. At level (its COM at r) energy gives its rate, phi'^2 = 2 m g (z0 -
  // r) / (m (L/2)^2 + I_t), z0 = (L/2) sin(phi0) + r cos(phi0), I_t = m (3 r^2 + L^2) / 12, and
  // its +z rim B lands at u = L phi'. Newton's law at B with A on the floor leaves A at rest and B
  // rising at e u: it rocks back up on A alone, conservatively, and comes down to level at the
  // same rate, so the landings come at u, e u, e^2 u, each a factor e^2 of the energy it has.
  // (It once lay on its side after the first: A at the floor and B there too, B taken as
  // touching by its height alone although it was leaving, and the side's rows stopped it.)
  constexpr double r = 0.1, L = 0.4, m = 1.0, e = 0.5;
  const double phi0 = 10.0 * kDeg;
  const std::string yaml = fmt::format(
      "tumble: 1\n"
      "parameters: {{r: {}, L: {}, tilt: 10 deg}}\n"
      "gravity: [0, 0, -{}]\n"
      "bodies:\n"
      "  can: {{shape: cylinder, radius: r, length: L, mass: {},\n"
      "         position: [0, 0, L/2*sin(tilt) + r*cos(tilt)],\n"
      "         orientation: {{axis: [0, 1, 0], angle: 90 deg - tilt}}}}\n"
      "contacts:\n"
      "  - {{name: floor, type: plane, body: can, plane: {{point: [0, 0, 0], normal: [0, 0, "
      "1]}}, friction: 0, restitution: {}}}\n"
      "simulate: {{duration: 1, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
      "0.01}}\n",
      r, L, kG, m, e);
  const auto run = run_inline_scenario(yaml, "can_rocking");
  const double I_t = m * (3 * r * r + L * L) / 12;
  const double drop = L / 2 * std::sin(phi0) + r * std::cos(phi0) - r;
  const double u = L * std::sqrt(2 * m * kG * drop / (m * L * L / 4 + I_t));
  std::vector<const ContactEventRecord*> impacts;
  for (const ContactEventRecord& event : run.contact_events) {
    if (event.impact.has_value() && impacts.size() < 3) {
      impacts.push_back(&event);
    } else if (impacts.size() < 3) {
      EXPECT_EQ(event.what.find("side"), std::string::npos) << event.t << ": " << event.what;
    }
  }
  ASSERT_EQ(impacts.size(), 3u);
  double approach = u;
  for (const ContactEventRecord* impact : impacts) {
    SCOPED_TRACE(fmt::format("t {}: {}", impact->t, impact->what));
    const ContactImpactNumbers& numbers = *impact->impact;
    EXPECT_NEAR(numbers.approach_speed, approach, 1e-9 * u);
    EXPECT_NEAR(numbers.rebound_speed, e * approach, 1e-9 * u);
    const double energy = m * kG * drop * (approach / u) * (approach / u);
    EXPECT_NEAR(numbers.kinetic_energy_before, energy, 1e-9 * m * kG * drop);
    EXPECT_NEAR(numbers.kinetic_energy_after, e * e * energy, 1e-9 * m * kG * drop);
    approach *= e;
  }
  test::expect_energy_never_rises(run, 1e-9);
  // The bounces come ever sooner (each flight e times the last): it ends lying on its side.
  const Row& end = run.rows.back();
  EXPECT_NEAR(end.states[0].r_G.z(), r, 1e-10);
  EXPECT_NEAR((end.states[0].R_WB * Vec3::UnitZ()).z(), 0.0, 1e-9);
}

TEST(CoinDropped, NearlyFlatItComesToRestOnItsFace) {
  // Dropped 10 degrees from flat, the coin lands on its rim, and its face comes down: it ends at
  // rest on its face (its COM on the floor: a disk is thin), N = m g.
  for (const double e : {0.0, 0.5}) {
    const std::string yaml = fmt::format(
        "tumble: 1\n"
        "bodies:\n"
        "  coin: {{shape: disk, radius: 0.0125, mass: 0.0075, position: [0, 0, 0.1],\n"
        "          orientation: {{axis: [1, 0, 0], angle: 10 deg}}}}\n"
        "contacts:\n"
        "  - {{name: table, type: plane, body: coin, plane: {{point: [0, 0, 0], normal: [0, 0, "
        "1]}}, friction: 0.5, restitution: {}}}\n"
        "simulate: {{duration: 1, integrator: dop853, rtol: 1e-10, atol: 1e-13, output_every: "
        "0.01}}\n",
        e);
    const auto run = run_inline_scenario(yaml, "coin_dropped_flat");
    SCOPED_TRACE(fmt::format("e {}", e));
    test::expect_energy_never_rises(run, 1e-8);
    ASSERT_FALSE(run.contact_events.empty());
    EXPECT_EQ(run.contact_events.back().what, "sticks on its face");
    const Row& end = run.rows.back();
    EXPECT_EQ(end.extras.contacts[0].mode, 2);
    EXPECT_NEAR(std::abs((end.states[0].R_WB * Vec3::UnitZ()).z()), 1.0, 1e-12);
    EXPECT_NEAR(end.states[0].r_G.z(), 0.0, 1e-12);
    EXPECT_LT(end.states[0].v_G.norm() + end.states[0].omega_W.norm() * 0.0125, 1e-12);
    EXPECT_NEAR(end.extras.contacts[0].normal_force, 0.0075 * kG, 1e-9 * 0.0075 * kG);
  }
}

}  // namespace
}  // namespace tumble
