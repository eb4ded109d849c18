// Two capsules touching each other, each case against its closed form:
//  - the nearest points of two segments, against a dense search of the two parameters, and how
//    fast they slide, against the difference quotient of the points of two moving segments;
//  - a capsule dropping crosswise onto another, frictionless, free and untouched by gravity,
//    above the other's axis at b from its centre: touchdown where the gap closes at u, and the
//    impulse J = (1 + e) u / (1/m_a + 1/m_b + b^2 / I_b) of a blow at b along the other's axis;
//  - a capsule thrown along a fixed capsule rail that it lies across, with friction: it slides,
//    friction mu m g slowing it and spinning it about its own axis, until its slip stops at
//    t = v0 / (mu g (1 + m r^2 / I_axis)); then it rolls at v0 - mu g t with no slip, the rail's
//    push m g throughout;
//  - the same capsule dropped plastically onto the rail at its middle: it comes to rest there and
//    stays, its centre still to 1e-12 m; lying off-centre, it tips off the rail, its energy less
//    friction's work conserved (the normal turning, the point sliding along both axes);
//  - a log sliding frictionless along a swinging seesaw beam keeps its energy while they touch (the
//    beam's point slides along its axis as it turns about another);
//  - rolling off the rail with friction: inf, no mode holds where the push falls to zero: the run
//    ends and says so;
//  - a group makes two capsules' pairs but none of a capsule and a box, and refusals name where.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "tumble/contact/axes_closest.hpp"
#include "tumble/math/rotation.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble {
namespace {

// The nearest points by search: a fine grid on both parameters, then a few passes of
// coordinate-wise exact minimisation (each a convex quadratic in one parameter), from the best.
double searched_distance(const AxisSegment& a, const AxisSegment& b, double& s, double& t) {
  const auto distance = [&](double si, double ti) {
    return (a.centre_W + si * a.axis_W - b.centre_W - ti * b.axis_W).norm();
  };
  double best = 1e300;
  const int n = 400;
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      const double si = a.half_length * (2.0 * i / n - 1), ti = b.half_length * (2.0 * j / n - 1);
      const double d = distance(si, ti);
      if (d < best) {
        best = d;
        s = si;
        t = ti;
      }
    }
  }
  for (int pass = 0; pass < 200; ++pass) {
    t = std::clamp(b.axis_W.dot(a.centre_W + s * a.axis_W - b.centre_W), -b.half_length,
                   b.half_length);
    s = std::clamp(a.axis_W.dot(b.centre_W + t * b.axis_W - a.centre_W), -a.half_length,
                   a.half_length);
  }
  return std::min(best, distance(s, t));
}

AxisSegment random_segment(unsigned& seed) {
  const auto uniform = [&] {
    seed = seed * 1664525u + 1013904223u;
    return (seed >> 8) / double(1u << 24) * 2.0 - 1.0;
  };
  AxisSegment segment;
  segment.centre_W = Vec3(uniform(), uniform(), uniform());
  segment.axis_W = Vec3(uniform(), uniform(), uniform()).normalized();
  segment.half_length = 0.2 + 0.8 * (uniform() + 1.0);
  return segment;
}

TEST(CapsulePairs, TheSegmentsNearestPointsAreTheLeastDistanceApart) {
  unsigned seed = 12345u;
  for (int k = 0; k < 200; ++k) {
    const AxisSegment a = random_segment(seed), b = random_segment(seed);
    const SegmentsClosest closest = segments_closest(a, b);
    ASSERT_LE(std::abs(closest.s), a.half_length);
    ASSERT_LE(std::abs(closest.t), b.half_length);
    double s = 0.0, t = 0.0;
    const double searched = searched_distance(a, b, s, t);
    // The closed form's distance is the least: no point pair of the search comes nearer.
    EXPECT_NEAR(segments_apart_W(a, b, closest).norm(), searched, 1e-12) << k;
    EXPECT_LE(segments_apart_W(a, b, closest).norm(), searched + 1e-14) << k;
  }
  // Parallel, overlapping along [0.5, 1] of the first: the middle of the overlap, 0.3 apart.
  const AxisSegment first{Vec3::Zero(), Vec3::UnitX(), 1.0};
  const AxisSegment second{Vec3(1.5, 0.3, 0.0), Vec3::UnitX(), 1.0};
  const SegmentsClosest along = segments_closest(first, second);
  EXPECT_DOUBLE_EQ(along.s, 0.75);
  EXPECT_DOUBLE_EQ(along.t, -0.75);
  EXPECT_FALSE(along.s_slides);
  EXPECT_TRUE(along.t_slides);
  EXPECT_NEAR(segments_apart_W(first, second, along).norm(), 0.3, 1e-15);
}

// A segment of a body moving at v (its centre's velocity) and turning at omega about its centre.
AxisSegment moved(const AxisSegment& segment, const Vec3& v, const Vec3& omega, double dt) {
  AxisSegment at = segment;
  at.centre_W += v * dt;
  at.axis_W = exp_so3(omega * dt) * segment.axis_W;
  return at;
}

TEST(CapsulePairs, TheNearestPointsSlideAtTheRatesTheirMotionGives) {
  unsigned seed = 777u;
  int checked[4] = {0, 0, 0, 0};
  for (int k = 0; k < 400; ++k) {
    const AxisSegment a = random_segment(seed), b = random_segment(seed);
    const AxisSegment motion_a = random_segment(seed), motion_b = random_segment(seed);
    const Vec3 v_a = motion_a.centre_W, v_b = motion_b.centre_W;
    const Vec3 omega_a = 2.0 * motion_a.axis_W, omega_b = -1.5 * motion_b.axis_W;
    const SegmentsClosest closest = segments_closest(a, b);
    const Vec3 p_a = a.centre_W + closest.s * a.axis_W, p_b = b.centre_W + closest.t * b.axis_W;
    const Vec3 w = v_a + omega_a.cross(p_a - a.centre_W) - (v_b + omega_b.cross(p_b - b.centre_W));
    const SlideRates rates = segments_slide_rates<double>(
        a, b, closest, p_a - p_b, w, omega_a.cross(a.axis_W), omega_b.cross(b.axis_W));
    const double h = 1e-6;
    const SegmentsClosest ahead =
        segments_closest(moved(a, v_a, omega_a, h), moved(b, v_b, omega_b, h));
    const SegmentsClosest behind =
        segments_closest(moved(a, v_a, omega_a, -h), moved(b, v_b, omega_b, -h));
    // Where a point changes between sliding and held within the quotient's span, skip.
    if (ahead.s_slides != behind.s_slides || ahead.t_slides != behind.t_slides ||
        ahead.s_slides != closest.s_slides || ahead.t_slides != closest.t_slides) {
      continue;
    }
    ++checked[(closest.s_slides ? 2 : 0) + (closest.t_slides ? 1 : 0)];
    // Central differences: error ~ h^2 times the third derivative, over rates of order 1-100.
    const double scale = 1.0 + std::abs(rates.s) + std::abs(rates.t);
    EXPECT_NEAR(rates.s, (ahead.s - behind.s) / (2 * h), 1e-5 * scale) << k;
    EXPECT_NEAR(rates.t, (ahead.t - behind.t) / (2 * h), 1e-5 * scale) << k;
  }
  // Every case met: both held (ends), one sliding, both sliding.
  for (const int count : checked) EXPECT_GT(count, 5);
}

// Capsule a (radius 0.05, length 0.6, mass 2) along x, b (radius 0.08, length 0.4, mass 3) along
// y at the origin; a's centre above b's axis at y = b, at z = 0.3, coming down at u; both free,
// frictionless, no gravity.
std::string capsule_onto_capsule(double b, double e) {
  return "tumble: 1\n"
         "parameters: {b: " +
         std::to_string(b) + ", u: 3, cor: " + std::to_string(e) +
         "}\n"
         "gravity: [0, 0, 0]\n"
         "bodies:\n"
         "  a: {shape: capsule, radius: 0.05, length: 0.6, mass: 2, position: [0, b, 0.3], "
         "velocity: [0, 0, -u], orientation: {axis: [0, 1, 0], angle: 90 deg}}\n"
         "  b: {shape: capsule, radius: 0.08, length: 0.4, mass: 3, orientation: {axis: [1, 0, "
         "0], angle: 90 deg}}\n"
         "contacts:\n"
         "  - {name: hit, type: bodies, bodies: [a, b], friction: 0, restitution: cor}\n"
         "simulate: {duration: 0.1, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
         "0.01}\n";
}

TEST(CapsulePairs, ACapsuleDroppingAcrossAnotherTakesTheClosedFormsImpulse) {
  for (const double b : {0.0, 0.1, 0.19}) {
    SCOPED_TRACE(b);
    const double u = 3, m_a = 2, m_b = 3, e = 0.6;
    const test::ScenarioRun run = test::run_inline_scenario(capsule_onto_capsule(b, e), "crossed");
    ASSERT_EQ(run.contact_events.size(), 1u);
    const ContactEventRecord& hit = run.contact_events[0];
    ASSERT_TRUE(hit.impact.has_value());
    // Two capsules keep the list's order: a is the contact's body.
    EXPECT_EQ(run.contacts[0].body, 0u);
    EXPECT_NEAR(hit.t, (0.3 - 0.13) / u, 1e-12);
    EXPECT_NEAR(hit.normal_W.z(), 1.0, 1e-12);
    // The point: the middle of the two surfaces' nearest points, above b's axis at y = b.
    EXPECT_NEAR(hit.point_W.y(), b, 1e-12);
    EXPECT_NEAR(hit.point_W.x(), 0.0, 1e-12);
    EXPECT_NEAR(hit.point_W.z(), 0.08, 1e-12);
    // b's axis is along y: a blow along z at y = b turns it about x, its transverse inertia.
    const double I_b = run.bodies[1].I_G_B(0, 0);
    const double J = (1 + e) * u / (1 / m_a + 1 / m_b + b * b / I_b);
    EXPECT_NEAR(hit.impact->impulse_W.z(), J, 1e-12 * m_a * u);
    EXPECT_NEAR(hit.impact->impulse_W.head<2>().norm(), 0.0, 1e-12 * m_a * u);
    const test::Row& last = run.rows.back();
    EXPECT_NEAR(last.states[0].v_G.z(), -u + J / m_a, 1e-12 * u);
    EXPECT_NEAR(last.states[1].v_G.z(), -J / m_b, 1e-12 * u);
    // Pushed down at +b along y, b turns about -x.
    EXPECT_NEAR(last.states[1].omega_W.x(), -J * b / I_b, 1e-12 * u / 0.2);
    EXPECT_NEAR(last.states[0].omega_W.norm(), 0.0, 1e-12 * u / 0.3);
    // The impulse takes (1 - e^2) of the approach's energy, mu u^2 / 2 with mu the effective mass
    // at the point.
    const double effective = J / ((1 + e) * u);
    EXPECT_NEAR(hit.kinetic_energy_before - hit.kinetic_energy_after,
                (1 - e * e) * effective * u * u / 2, 1e-12 * m_a * u * u);
  }
}

// A fixed rail, a capsule of radius 0.05 and length 3 along y; the capsule a (radius 0.04, length
// 0.4, mass 1) lies across it along x at its top, moving at v0 along the rail.
std::string capsule_on_a_rail(const std::string& start) {
  return "tumble: 1\n"
         "parameters: {v0: 1, mu: 0.3}\n"
         "gravity: [0, 0, -" +
         std::to_string(test::kG) +
         "]\n"
         "bodies:\n"
         "  rail: {shape: capsule, radius: 0.05, length: 3, mass: 10, orientation: {axis: [1, "
         "0, 0], angle: 90 deg}}\n"
         "  a: {shape: capsule, radius: 0.04, length: 0.4, mass: 1, " +
         start +
         ", orientation: {axis: [0, 1, 0], angle: 90 deg}}\n"
         "joints:\n"
         "  footing: {type: fixed, bodies: [ground, rail], at: [0, 0, 0]}\n"
         "contacts:\n"
         "  - {name: on_rail, type: bodies, bodies: [a, rail], friction: mu, restitution: 0}\n"
         "simulate: {duration: 0.5, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
         "0.005}\n";
}

TEST(CapsulePairs, ACapsuleThrownAlongARailItLiesAcrossSlidesThenRolls) {
  const double g = test::kG, v0 = 1, mu = 0.3, m = 1, r = 0.04;
  const test::ScenarioRun run = test::run_inline_scenario(
      capsule_on_a_rail("position: [0, -1, 0.09], velocity: [0, v0, 0]"), "rail");
  const double I = run.bodies[1].I_G_B(2, 2);  // about its own axis
  const double t_roll = v0 / (mu * g * (1 + m * r * r / I));
  const double v_roll = v0 - mu * g * t_roll;
  // It slides from the start; its slip stops, and it rolls, at t_roll.
  ASSERT_EQ(run.contact_events.size(), 3u);
  EXPECT_EQ(run.contact_events[0].what, "slides");
  EXPECT_NEAR(run.contact_events[0].t, 0.0, 1e-15);
  EXPECT_EQ(run.contact_events[1].what, "slip stops");
  EXPECT_EQ(run.contact_events[2].what, "rolls");
  EXPECT_NEAR(run.contact_events[1].t, t_roll, 1e-9);
  EXPECT_EQ(run.contact_events[2].t, run.contact_events[1].t);
  int rolling = 0;
  for (const test::Row& row : run.rows) {
    const BodyState& a = row.states[1];
    const double t = std::min(row.t, t_roll);
    const double v = v0 - mu * g * t;
    // Its axis is x: friction below its centre, against the slip, spins it about -x.
    const double omega = -mu * m * g * r * t / I;
    const double y = -1 + v0 * t - mu * g * t * t / 2 + v_roll * (row.t - t);
    EXPECT_NEAR(a.v_G.y(), row.t < t_roll ? v : v_roll, 1e-10) << row.t;
    EXPECT_NEAR(a.omega_W.x(), row.t < t_roll ? omega : -v_roll / r, 1e-9) << row.t;
    EXPECT_NEAR(a.r_G.y(), y, 1e-10) << row.t;
    EXPECT_NEAR(a.r_G.z(), 0.09, 1e-12) << row.t;
    EXPECT_NEAR(a.r_G.x(), 0.0, 1e-12) << row.t;
    EXPECT_NEAR(row.extras.contacts[0].normal_force, m * g, 1e-9 * m * g) << row.t;
    if (row.t > t_roll + 1e-6) {
      EXPECT_EQ(row.extras.contacts[0].mode, 2) << row.t;
      EXPECT_LT(row.extras.contacts[0].slip_speed, 1e-10) << row.t;
      ++rolling;
    } else if (row.t < t_roll - 1e-6) {
      EXPECT_EQ(row.extras.contacts[0].mode, 1) << row.t;
    }
  }
  EXPECT_GT(rolling, 50);
}

TEST(CapsulePairs, ACapsuleDroppedAcrossARailComesToRestAndStays) {
  const double g = test::kG, h = 0.01;
  const test::ScenarioRun run =
      test::run_inline_scenario(capsule_on_a_rail("position: [0, 0.2, 0.1]"), "drop");
  ASSERT_GE(run.contact_events.size(), 1u);
  const ContactEventRecord& touchdown = run.contact_events[0];
  EXPECT_NEAR(touchdown.t, std::sqrt(2 * h / g), 1e-12);
  ASSERT_TRUE(touchdown.impact.has_value());
  // Plastic: all of the fall's energy goes at once, and the capsule then lies still on the rail.
  EXPECT_NEAR(touchdown.kinetic_energy_after, 0.0, 1e-24);
  EXPECT_NEAR(touchdown.kinetic_energy_before, 1 * g * h, 1e-12);
  int after = 0;
  for (const test::Row& row : run.rows) {
    if (row.t <= touchdown.t) continue;
    ++after;
    const BodyState& a = row.states[1];
    EXPECT_NEAR((a.r_G - Vec3(0, 0.2, 0.09)).norm(), 0.0, 1e-12) << row.t;
    EXPECT_NEAR(a.v_G.norm(), 0.0, 1e-12) << row.t;
    EXPECT_NEAR(a.omega_W.norm(), 0.0, 1e-12) << row.t;
    EXPECT_NEAR(row.extras.contacts[0].normal_force, g, 1e-9 * g) << row.t;
  }
  EXPECT_GT(after, 50);
}

// A capsule (a) lying across the fixed rail with its centre 0.1 to one side of it, at rest: it
// tips about the rail, its axis turning in the x-z plane (the normal turns with it, and the point
// of contact slides along its axis), and leaves it. Frictionless, it slides from the start and
// nothing takes energy; with friction it rolls until the friction that needs leaves the cone,
// then slides: E less the contact's work (friction's, never positive) holds.
TEST(CapsulePairs, ACapsuleTippingOffARailKeepsItsEnergyLessFrictionsWork) {
  for (const char* friction : {"0", "0.5"}) {
    SCOPED_TRACE(friction);
    const bool frictionless = std::string(friction) == "0";
    const std::string yaml = test::replaced(capsule_on_a_rail("position: [0.1, 0, 0.09]"),
                                            "friction: mu", std::string("friction: ") + friction);
    const test::ScenarioRun run = test::run_inline_scenario(yaml, "tips");
    ASSERT_EQ(run.contact_events.size(), frictionless ? 2u : 3u);
    EXPECT_EQ(run.contact_events[0].what, frictionless ? "slides" : "rolls");
    const ContactEventRecord& off = run.contact_events.back();
    EXPECT_EQ(off.what, "lifts off");
    // It has turned (the normal leans towards its centre's side) before it leaves.
    EXPECT_GT(off.normal_W.x(), 0.5);
    const double E0 = run.rows.front().quantities.total_energy;
    // E and the work are integrated at rtol 1e-12: their errors are ~1e-12 of the energy's scale,
    // m g times the height it falls through (under 0.09 m).
    const double tolerance = 1e-10 * 1 * test::kG * 0.09;
    int touching = 0;
    for (const test::Row& row : run.rows) {
      const double work = row.extras.elements[0].work;
      EXPECT_NEAR(row.quantities.total_energy - work, E0, tolerance) << row.t;
      EXPECT_LE(work, tolerance) << row.t;
      if (frictionless) {
        EXPECT_NEAR(work, 0.0, tolerance) << row.t;
      }
      if (row.t >= off.t) continue;
      ++touching;
      EXPECT_GE(row.extras.contacts[0].normal_force, 0.0) << row.t;
    }
    EXPECT_GT(touching, 10);
    if (!frictionless) {
      EXPECT_LT(run.rows.back().extras.elements[0].work, -1e-3);
    }
  }
}

// A log (a) thrown along a seesaw beam (a capsule on a hinge about x at its middle, swinging),
// frictionless: it drops onto the beam, then slides along it while the beam turns under it. The
// beam's point of contact slides along its axis while the beam turns about another axis, so the
// contact's gap gains the Coriolis term omega x (the point's slide): without it the contact
// would hold the wrong acceleration and E would drift (by 0.037 J of 1.07 J). Nothing takes
// energy while they touch: E holds, from the landing to the lift-off, to 1e-10 of the scale.
TEST(CapsulePairs, ALogSlidingAlongASwingingSeesawKeepsItsEnergyWhileTheyTouch) {
  const test::ScenarioRun run = test::run_inline_scenario(
      "tumble: 1\n"
      "gravity: [0, 0, -" +
          std::to_string(test::kG) +
          "]\n"
          "bodies:\n"
          "  beam: {shape: capsule, radius: 0.05, length: 2, mass: 4, orientation: {axis: [1, 0, "
          "0], angle: 90 deg}, angular_velocity: [0.3, 0, 0]}\n"
          "  a: {shape: capsule, radius: 0.04, length: 0.4, mass: 1, position: [0, -0.3, 0.09], "
          "velocity: [0, 0.5, 0], orientation: {axis: [0, 1, 0], angle: 90 deg}}\n"
          "joints:\n"
          "  pivot: {type: hinge, bodies: [ground, beam], at: [0, 0, 0], axis: [1, 0, 0]}\n"
          "contacts:\n"
          "  - {name: on_beam, type: bodies, bodies: [a, beam], friction: 0, restitution: 0}\n"
          "simulate: {duration: 1, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
          "0.01}\n",
      "seesaw");
  ASSERT_EQ(run.contact_events.size(), 3u);
  ASSERT_TRUE(run.contact_events[0].impact.has_value());
  EXPECT_EQ(run.contact_events[1].what, "slides");
  EXPECT_EQ(run.contact_events[2].what, "lifts off");
  const double landed = run.contact_events[0].t, off = run.contact_events[2].t;
  EXPECT_GT(off - landed, 0.5);
  double E_landed = 0.0;
  int touching = 0;
  for (const test::Row& row : run.rows) {
    if (row.t <= landed || row.t >= off) continue;
    if (touching++ == 0) E_landed = row.quantities.total_energy;
    // The scale: the energy itself, about 1 J; rtol 1e-12 leaves ~1e-12 of it.
    EXPECT_NEAR(row.quantities.total_energy, E_landed, 1e-10 * std::abs(E_landed)) << row.t;
    EXPECT_EQ(row.extras.contacts[0].mode, 1) << row.t;
  }
  EXPECT_GT(touching, 50);
}

// With friction: inf it rolls on the rail from the start, doing no work, until the push falls
// to zero with the friction that rolling takes still there: rolling on would pull the two
// together, and without that friction the capsule is pressed on. No mode is consistent; the run
// says so (exit 4 from the command) after a thousand settling touchdowns that nothing holds,
// rather than going on by millions of them.
TEST(CapsulePairs, ACapsuleRollingOffARailWithoutALimitToFrictionEndsTheRunWhereNoModeHolds) {
  const std::string yaml = test::replaced(capsule_on_a_rail("position: [0.1, 0, 0.09]"),
                                          "friction: mu", "friction: inf");
  Scenario scenario = test::load_inline_scenario(yaml, "rolls_off");
  PreparedSimulation simulation = prepare_simulation(scenario);
  std::vector<test::Row> rows;
  const SimulationResult result =
      run_simulation(simulation, [&](double t, std::span<const BodyState> states,
                                     const SystemQuantities& q, const RowExtras& e) {
        rows.push_back({t, std::vector<BodyState>(states.begin(), states.end()), q, e});
      });
  EXPECT_FALSE(result.report.completed);
  EXPECT_NE(result.report.failure.find("1000 landings"), std::string::npos)
      << result.report.failure;
  EXPECT_NE(result.report.failure.find("friction: inf never lets them slip"), std::string::npos)
      << result.report.failure;
  ASSERT_GE(result.contact_events.size(), 2u);
  EXPECT_EQ(result.contact_events[0].what, "rolls");
  const ContactEventRecord& off = result.contact_events[1];
  EXPECT_EQ(off.what, "lifts off");
  ASSERT_FALSE(rows.empty());
  const double E0 = rows.front().quantities.total_energy;
  int rolling = 0;
  for (const test::Row& row : rows) {
    if (row.t >= off.t) break;
    ++rolling;
    EXPECT_EQ(row.extras.contacts[0].mode, 2) << row.t;
    EXPECT_LT(row.extras.contacts[0].slip_speed, 1e-10) << row.t;
    EXPECT_NEAR(row.quantities.total_energy, E0, 1e-10 * 1 * test::kG * 0.09) << row.t;
  }
  EXPECT_GT(rolling, 10);
}

TEST(CapsulePairs, AGroupPairsItsCapsulesButNotACapsuleWithABox) {
  const test::ScenarioRun run = test::run_inline_scenario(
      "tumble: 1\n"
      "gravity: [0, 0, 0]\n"
      "bodies:\n"
      "  a: {shape: capsule, radius: 0.1, length: 0.5, mass: 1}\n"
      "  b: {shape: capsule, radius: 0.1, length: 0.5, mass: 1, position: [1, 0, 0]}\n"
      "  c: {shape: box, size: [0.2, 0.2, 0.2], mass: 1, position: [0, 1, 0]}\n"
      "contacts:\n"
      "  - {name: hit, type: bodies, bodies: all, friction: 0}\n"
      "simulate: {duration: 0.01}\n",
      "group");
  ASSERT_EQ(run.contacts.size(), 1u);
  EXPECT_EQ(run.contacts[0].name, "hit_a_b");
}

TEST(CapsulePairs, RefusedAgainstABoxAndWhereTheyStartOverlapping) {
  const std::string bodies =
      "tumble: 1\n"
      "bodies:\n"
      "  a: {shape: capsule, radius: 0.1, length: 0.5, mass: 1}\n"
      "  b: {shape: capsule, radius: 0.1, length: 0.5, mass: 1, position: [0.1, 0, 0.15], "
      "orientation: {axis: [0, 1, 0], angle: 90 deg}}\n"
      "  c: {shape: box, size: [0.2, 0.2, 0.2], mass: 1, position: [1, 0, 0]}\n";
  test::expect_error(bodies +
                         "contacts:\n"
                         "  - {type: bodies, bodies: [a, c], friction: 0}\n",
                     7, 28, "contacts[0].bodies", "a capsule and a box do not touch");
  // b lies along x through a's axis at z = 0.15, within a's cap's centre (at 0.25): their axes
  // cross, 0 apart, and their radii add to 0.2.
  test::expect_error(bodies +
                         "contacts:\n"
                         "  - {type: bodies, bodies: [a, b], friction: 0}\n"
                         "simulate: {duration: 1}\n",
                     7, 5, "contacts[0]",
                     "start overlapping by 0.2 m (their axes between their caps' centres are 0 m "
                     "apart, their radii add to 0.2 m)");
}

}  // namespace
}  // namespace tumble
