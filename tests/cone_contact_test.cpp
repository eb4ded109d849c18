// A cone on a plane, on each of its parts: rolling on its side in a circle about its apex (the
// steady motion of rolling kinematics), resting and sliding on its base on a ramp, spinning down
// on its base under torsional friction, tipping off its base onto its rim past atan(4r/h),
// spinning on its apex like a top on a pivot (against the same top on a ball joint), and dropped:
// impacts that never add energy. Every run asks rtol 1e-10 (contact_test.cpp says what that
// buys).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "ramp_checks.hpp"
#include "scenario_run.hpp"
#include "test_constants.hpp"

namespace tumble {
namespace {

using test::kDeg;
using test::kG;
using test::kPi;
using test::Row;
using test::run_inline_scenario;
constexpr double kConeMass = 0.5;

struct Cone {
  double r, h;  // base radius and height, m
};
constexpr Cone kCones[] = {{0.05, 0.2}, {0.1, 0.15}};

std::string cone_keys(const Cone& cone) {
  return fmt::format("shape: cone, radius: {}, height: {}, mass: {}", cone.r, cone.h, kConeMass);
}

// The apex from the COM, world axes.
Vec3 apex_W(const Row& row, const Cone& cone) {
  return row.states[0].r_G + row.states[0].R_WB * Vec3(0, 0, 0.75 * cone.h);
}

TEST(ConeOnItsSide, ItRollsInACircleAboutItsApex) {
  // Lying on its side with the apex at the origin, turning at w about the line it touches along:
  // every point of that line is at rest, so it rolls, and the line turns about the vertical
  // through the apex at Omega = w tan(alpha) (alpha the half-angle: the COM, (3h/4)(cos, sin)
  // from the apex, moves at w (3h/4) sin = Omega (3h/4) cos). That steady motion is exact: the
  // apex stays put, the COM goes round at Omega at a constant height, N = M g, no slip, E fixed.
  for (const Cone& cone : kCones) {
    for (const double Omega : {1.0, 3.0}) {
      const double alpha = std::atan(cone.r / cone.h);
      const double w = Omega / std::tan(alpha);
      const double turn = 2 * kPi / Omega;
      const std::string yaml = fmt::format(
          "tumble: 1\n"
          "parameters: {{alpha: {}, d: {}, w: {}}}\n"
          "bodies:\n"
          "  cone: {{{}, position: [d * cos(alpha), 0, d * sin(alpha)],\n"
          "          orientation: {{axis: [0, 1, 0], angle: -(90 deg + alpha)}},\n"
          "          velocity: [0, w * d * sin(alpha), 0], angular_velocity: [-w, 0, 0]}}\n"
          "contacts:\n"
          "  - {{name: floor, type: plane, body: cone, plane: {{point: [0, 0, 0], normal: [0, 0, "
          "1]}}, friction: 1}}\n"
          "simulate: {{duration: {}, integrator: dop853, rtol: 1e-10, atol: 1e-13, "
          "output_every: {}}}\n",
          alpha, 0.75 * cone.h, w, cone_keys(cone), turn, turn / 100);
      const auto run = run_inline_scenario(yaml, "cone_rolls_on_its_side");
      ASSERT_EQ(run.contact_events.size(), 1u);
      EXPECT_EQ(run.contact_events[0].what, "rolls on its side");
      const double rho = 0.75 * cone.h * std::cos(alpha);  // the COM's circle
      const double height = 0.75 * cone.h * std::sin(alpha);
      const double E0 = run.rows.front().quantities.total_energy;
      for (const Row& row : run.rows) {
        const Vec3& r_G = row.states[0].r_G;
        const Vec3 expected(rho * std::cos(Omega * row.t), rho * std::sin(Omega * row.t), height);
        EXPECT_LT((r_G - expected).norm(), 1e-9 * rho) << "t " << row.t;
        EXPECT_LT(apex_W(row, cone).norm(), 1e-12) << "t " << row.t;
        const ContactOutput& c = row.extras.contacts[0];
        EXPECT_EQ(c.mode, 2);
        EXPECT_LT(c.slip_speed, 1e-12);
        EXPECT_NEAR(c.normal_force, kConeMass * kG, 1e-9 * kConeMass * kG);
        EXPECT_NEAR(row.quantities.total_energy, E0, 1e-10 * E0);
      }
    }
  }
}

// A cone standing on its base on a ramp of slope theta descending towards +x, spinning at w0
// about its axis (the ramp's normal).
std::string cone_on_ramp(const Cone& cone, double theta, double mu, double w0, double duration) {
  return fmt::format(
      "tumble: 1\n"
      "parameters: {{theta: {}, d: {}, w0: {}}}\n"
      "bodies:\n"
      "  cone: {{{}, position: [d * sin(theta), 0, d * cos(theta)],\n"
      "          orientation: {{axis: [0, 1, 0], angle: theta}},\n"
      "          angular_velocity: [w0 * sin(theta), 0, w0 * cos(theta)]}}\n"
      "contacts:\n"
      "  - {{name: ramp, type: plane, body: cone, plane: {{point: [0, 0, 0],\n"
      "      normal: [sin(theta), 0, cos(theta)]}}, friction: {}}}\n"
      "simulate: {{duration: {}, integrator: dop853, rtol: 1e-10, atol: 1e-13, "
      "output_every: {}}}\n",
      theta, 0.25 * cone.h, w0, cone_keys(cone), mu, duration, duration / 100);
}

TEST(ConeOnItsBase, BelowTheFrictionAngleItStaysAtRestFor100Seconds) {
  for (const Cone& cone : kCones) {
    for (const double theta : {10 * kDeg, 30 * kDeg}) {
      const auto run = run_inline_scenario(
          cone_on_ramp(cone, theta, 1.05 * std::tan(theta), 0, 100), "cone_at_rest");
      ASSERT_EQ(run.contact_events.size(), 1u);
      EXPECT_EQ(run.contact_events[0].what, "sticks on its base");
      test::expect_at_rest_on_ramp(run, kConeMass, theta);
    }
  }
}

TEST(ConeOnItsBase, AboveTheFrictionAngleItSlidesWithTheExactAcceleration) {
  // a = g (sin - mu cos); the friction at the base, h/4 below the COM, moves the CoP downhill by
  // mu h / 4, inside the base for these cones (mu h / 4 < r).
  for (const Cone& cone : kCones) {
    for (const double theta : {20 * kDeg, 40 * kDeg}) {
      const double mu = 0.9 * std::tan(theta);
      ASSERT_LT(mu * cone.h / 4, cone.r);
      const double a = kG * (std::sin(theta) - mu * std::cos(theta));
      const auto run = run_inline_scenario(cone_on_ramp(cone, theta, mu, 0, 2), "cone_slides");
      ASSERT_EQ(run.contact_events.size(), 1u);
      EXPECT_EQ(run.contact_events[0].what, "slides on its base");
      test::expect_sliding_down_ramp(run, kConeMass, theta, a);
    }
  }
}

TEST(ConeOnItsBase, ItSpinsDownUnderTorsionalFrictionAtTheExactTime) {
  // Even pressure over the base: the friction moment is mu M g times the mean distance 2r/3, so
  // the spin I w0 (I = 3 M r^2 / 10) stops at t = I w0 / (mu M g 2r/3), falling linearly.
  for (const Cone& cone : kCones) {
    for (const double mu : {0.3, 0.6}) {
      const double w0 = 20;
      const double I = 0.3 * kConeMass * cone.r * cone.r;
      const double t_stop = I * w0 / (mu * kConeMass * kG * 2 * cone.r / 3);
      const auto run =
          run_inline_scenario(cone_on_ramp(cone, 0, mu, w0, 1.5 * t_stop), "cone_spins_down");
      ASSERT_EQ(run.contact_events.size(), 3u);
      EXPECT_EQ(run.contact_events[0].what, "slides on its base");
      EXPECT_EQ(run.contact_events[1].what, "slip stops");
      EXPECT_NEAR(run.contact_events[1].t, t_stop, 1e-9 * t_stop);
      EXPECT_EQ(run.contact_events[2].what, "sticks on its base");
      const Vec3 r0 = run.rows.front().states[0].r_G;
      for (const Row& row : run.rows) {
        EXPECT_LT((row.states[0].r_G - r0).norm(), 1e-12);
        const double w = w0 * std::max(0.0, 1 - row.t / t_stop);
        EXPECT_NEAR(row.states[0].omega_W.z(), w, 1e-9 * w0) << "t " << row.t;
      }
    }
  }
}

TEST(ConeOnItsBase, PastAtan4rOverHItTipsOntoItsRim) {
  // With friction enough to hold it, the CoP reaches the base's rim when tan(theta) = r / (h/4):
  // below, it stays on its base; above, it rolls over its rim point (a pivot: no slip, no work
  // but gravity's) until it lands on its side.
  for (const Cone& cone : kCones) {
    const double theta_tip = std::atan(4 * cone.r / cone.h);
    {
      const auto run =
          run_inline_scenario(cone_on_ramp(cone, 0.98 * theta_tip, 3, 0, 1), "cone_does_not_tip");
      ASSERT_EQ(run.contact_events.size(), 1u);
      EXPECT_EQ(run.contact_events[0].what, "sticks on its base");
      const Vec3 r0 = run.rows.front().states[0].r_G;
      for (const Row& row : run.rows) EXPECT_LT((row.states[0].r_G - r0).norm(), 1e-12);
    }
    // Over its rim until just before the friction runs out (the slender cone slides at 0.475 s,
    // the squat one lifts off at 0.488 s: tests/slip_onset_test.cpp).
    const auto run =
        run_inline_scenario(cone_on_ramp(cone, 1.02 * theta_tip, 3, 0, 0.45), "cone_tips");
    ASSERT_EQ(run.contact_events.size(), 1u);
    EXPECT_EQ(run.contact_events[0].what, "rolls on its rim");
    EXPECT_EQ(run.contact_events[0].t, 0.0);
    const double E0 = run.rows.front().quantities.total_energy;
    const auto tilt_of = [](const Row& row) {
      return std::acos(std::clamp(row.states[0].R_WB(2, 2), -1.0, 1.0));
    };
    double tilt_before = tilt_of(run.rows.front());
    for (const Row& row : run.rows) {
      EXPECT_NEAR(row.quantities.total_energy, E0, 1e-9 * std::abs(E0)) << "t " << row.t;
      EXPECT_LT(row.extras.contacts[0].slip_speed, 1e-10);
      EXPECT_EQ(row.extras.contacts[0].mode, 2);
      // It turns one way, downhill, ever faster.
      const double tilt = tilt_of(row);
      EXPECT_GE(tilt, tilt_before - 1e-12) << "t " << row.t;
      tilt_before = tilt;
    }
    EXPECT_GT(tilt_before - tilt_of(run.rows.front()), 0.1);
  }
}

TEST(ConeOnItsApex, ItSpinsLikeATopOnAPivot) {
  // Standing on its apex, tilted and spinning fast, with friction enough to hold the apex: the
  // apex is a pivot, and the top must move as the same cone on a ball joint there does (it
  // nutates and precesses; the plane only ever pushes). The squat cone spins at 300 rad/s, well
  // above the 86 rad/s a sleeping top needs (I_a^2 s^2 > 4 M g l I_apex).
  const Cone cone = kCones[1];
  for (const double tilt : {10.0, 30.0}) {
    const std::string body = fmt::format(
        "  top: {{{}, position: [d * sin({} deg), 0, d * cos({} deg)],\n"
        "         orientation: {{axis: [0, 1, 0], angle: 180 deg + {} deg}},\n"
        "         angular_velocity: [s * sin({} deg), 0, s * cos({} deg)]}}\n",
        cone_keys(cone), tilt, tilt, tilt, tilt, tilt);
    const std::string head =
        fmt::format("tumble: 1\nparameters: {{d: {}, s: -300}}\nbodies:\n{}", 0.75 * cone.h, body);
    const std::string simulate =
        "simulate: {duration: 1, integrator: dop853, rtol: 1e-10, atol: 1e-13, output_every: "
        "0.01}\n";
    const auto on_plane = run_inline_scenario(
        head +
            "contacts:\n  - {name: floor, type: plane, body: top, plane: {point: [0, 0, 0], "
            "normal: [0, 0, 1]}, friction: 2}\n" +
            simulate,
        "top_on_plane");
    const auto on_pivot = run_inline_scenario(
        head + "joints:\n  pivot: {type: ball, body: top, at: [0, 0, 0]}\n" + simulate,
        "top_on_pivot");
    ASSERT_EQ(on_plane.contact_events.size(), 1u);
    EXPECT_EQ(on_plane.contact_events[0].what, "sticks on its apex");
    ASSERT_EQ(on_plane.rows.size(), on_pivot.rows.size());
    for (std::size_t i = 0; i < on_plane.rows.size(); ++i) {
      const Row& a = on_plane.rows[i];
      const Row& b = on_pivot.rows[i];
      EXPECT_LT((a.states[0].r_G - b.states[0].r_G).norm(), 1e-8 * cone.h) << "t " << a.t;
      EXPECT_LT((a.states[0].omega_W - b.states[0].omega_W).norm(), 1e-8 * 300) << "t " << a.t;
      EXPECT_GT(a.extras.contacts[0].normal_force, 0.0);
      EXPECT_LT(apex_W(a, cone).norm(), 1e-12);
    }
  }
}

// A cone dropped from 0.3 m, tilted by `tilt` degrees about (1, 0.3, 0), onto a floor with
// friction 0.4 and restitution e.
std::string dropped(const Cone& cone, double tilt, double e, double duration) {
  return fmt::format(
      "tumble: 1\n"
      "bodies:\n"
      "  cone: {{{}, position: [0, 0, 0.3], orientation: {{axis: [1, 0.3, 0], angle: {} deg}}}}\n"
      "contacts:\n"
      "  - {{name: floor, type: plane, body: cone, plane: {{point: [0, 0, 0], normal: [0, 0, 1]}}, "
      "friction: 0.4, restitution: {}}}\n"
      "simulate: {{duration: {}, integrator: dop853, rtol: 1e-10, atol: 1e-13, "
      "output_every: 0.01}}\n",
      cone_keys(cone), tilt, e, duration);
}

TEST(ConeDropped, ImpactsNeverAddEnergyAndItComesToLieOnItsSide) {
  // The slender cone (the squat one rocks onto its base: the next test).
  const Cone& cone = kCones[0];
  for (const double e : {0.0, 0.5}) {
    for (const double tilt : {60.0, 100.0, 150.0}) {
      const auto run = run_inline_scenario(dropped(cone, tilt, e, 3), "cone_dropped");
      test::expect_energy_never_rises(run, 1e-8);
      // Rolling on its side (in a circle, or at rest) it carries its weight with its COM at
      // (3h/4) sin(alpha).
      const Row& end = run.rows.back();
      EXPECT_NE(run.contact_events.back().what.find("on its side"), std::string::npos);
      EXPECT_EQ(end.extras.contacts[0].mode, 2);
      EXPECT_NEAR(end.extras.contacts[0].normal_force, kConeMass * kG, 1e-9 * kConeMass * kG);
      const double alpha = std::atan(cone.r / cone.h);
      EXPECT_NEAR(end.states[0].r_G.z(), 0.75 * cone.h * std::sin(alpha), 1e-12);
    }
  }
}

TEST(ConeDropped, ASquatConeRockingOntoItsBaseComesToRestThere) {
  // Landing on its rim, the squat cone rocks over onto its base; the base lands (plastically,
  // with its far side up to the landing height still above the plane) and holds it: at rest on
  // its base, COM h/4 above the floor, N = M g.
  const Cone& cone = kCones[1];
  for (const double e : {0.0, 0.5}) {
    const auto run = run_inline_scenario(dropped(cone, 60, e, 1.5), "squat_cone_dropped");
    test::expect_energy_never_rises(run, 1e-8);
    EXPECT_EQ(run.contact_events.back().what, "sticks on its base");
    const Row& end = run.rows.back();
    EXPECT_EQ(end.extras.contacts[0].mode, 2);
    EXPECT_NEAR(end.extras.contacts[0].normal_force, kConeMass * kG, 1e-9 * kConeMass * kG);
    EXPECT_NEAR(end.states[0].r_G.z(), 0.25 * cone.h, 1e-12);
    EXPECT_LT(end.states[0].v_G.norm() + end.states[0].omega_W.norm() * cone.h, 1e-12);
  }
}

TEST(ConeTumbling, ItsApexLandsWhereItFirstReachesThePlaneThoughADipLastsLessThanAStep) {
  // No gravity: the cone turns steadily at w about a transverse principal axis, its COM at rest a
  // depth less than the apex's reach ha = 3h/4 above the floor. The apex's height is
  // d - ha sin(w t): it reaches the floor at t = asin(d / ha) / w at the speed w sqrt(ha^2 - d^2),
  // and without the floor would dip through it for 2 acos(d / ha) / w (0.02 to 0.0006 s here). A
  // steady turn is smooth, so the method's steps span more than that (a whole dip can lie inside
  // one); the landing is found all the same, to the event location's round-off.
  const Cone& cone = kCones[0];
  const double ha = 0.75 * cone.h;
  for (const double w : {10.0, 40.0}) {
    for (const double depth : {1e-3, 1e-5}) {
      const double d = ha - depth;
      const std::string yaml = fmt::format(
          "tumble: 1\n"
          "gravity: [0, 0, 0]\n"
          "bodies:\n"
          "  cone: {{{}, position: [0, 0, {}],\n"
          "          orientation: {{axis: [1, 0, 0], angle: 90 deg}}, angular_velocity: [{}, 0, "
          "0]}}\n"
          "contacts:\n"
          "  - {{name: floor, type: plane, body: cone, plane: {{point: [0, 0, 0], normal: [0, 0, "
          "1]}},\n"
          "      friction: 0.5, restitution: 0.5}}\n"
          "simulate: {{duration: {}, integrator: dop853, rtol: 1e-10, atol: 1e-13, "
          "output_every: {}}}\n",
          cone_keys(cone), d, w, 4 / w, 0.04 / w);
      const auto run = run_inline_scenario(yaml, "tumbling");
      SCOPED_TRACE(fmt::format("w {} rad/s, depth {} m", w, depth));
      ASSERT_FALSE(run.contact_events.empty());
      const double t_land = std::asin(d / ha) / w;
      EXPECT_NEAR(run.contact_events[0].t, t_land, 1e-9 * t_land);
      const std::string& what = run.contact_events[0].what;
      EXPECT_EQ(what.rfind("impact on its apex: normal speed ", 0), 0u) << what;
      EXPECT_NEAR(
          std::stod(what.substr(what.find("speed ") + 6)) / (w * std::sqrt(ha * ha - d * d)), 1.0,
          5e-4);  // the message's 4 digits
      // Never through the floor: every row's apex at or above it.
      for (const Row& row : run.rows) EXPECT_GE(apex_W(row, cone).z(), -1e-9) << "t = " << row.t;
      test::expect_energy_never_rises(run, 1e-8);
    }
  }
}

}  // namespace
}  // namespace tumble
