// Slip that starts from rolling, where the friction rolling needs reaches the edge of the cone
// (docs/design.md, "Slip onset"): a coin wobbling on its rim with too little friction to roll
// throughout, which alternates rolling and sliding with Coulomb's law holding at every row and no
// chatter; and a cone rolling over its rim on a steep ramp with high friction, which slides if the
// slip can grow (slender) and lifts off where friction would have to press it on to slide
// (squat: Painleve's case), after which it flies free; and a slender top falling onto its side,
// which a consistent mode holds at every landing.
// Every run asks rtol 1e-10.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "rolling_coin_scenario.hpp"
#include "scenario_run.hpp"
#include "test_constants.hpp"

namespace tumble {
namespace {

using test::kDeg;
using test::kG;
using test::Row;
using test::run_inline_scenario;

TEST(SlipOnset, AWobblingCoinAlternatesRollingAndSlidingUnderCoulombsLaw) {
  // The coin of examples/rolling_coin.yaml with its precession started `lean` times the steady
  // rate: it wobbles, and with mu 0.15 the friction rolling needs leaves the cone once a wobble.
  const test::RollingCoin coin{15 * kDeg, 0.1};
  const double r = coin.r, mu = 0.15, m = 0.0075;
  for (const double lean : {1.3, 1.6}) {
    const auto run = run_inline_scenario(test::rolling_coin_scenario(coin, mu, lean, 1.5, 0.002),
                                         "wobbling_coin");
    // Each slide that starts from rolling grows, and only stops a while later: no chatter.
    int onsets = 0;
    for (std::size_t i = 0; i < run.contact_events.size(); ++i) {
      if (run.contact_events[i].what != "slides: the friction sticking needs leaves the cone") {
        continue;
      }
      ++onsets;
      if (i + 1 == run.contact_events.size()) continue;  // it slides on to the end
      EXPECT_EQ(run.contact_events[i + 1].what, "slip stops");
      EXPECT_GT(run.contact_events[i + 1].t - run.contact_events[i].t, 1e-3) << "lean " << lean;
    }
    EXPECT_GE(onsets, 4) << "lean " << lean;
    test::expect_energy_never_rises(run, 1e-9);
    for (const Row& row : run.rows) {
      const ContactOutput& c = row.extras.contacts[0];
      const BodyState& s = row.states[0];
      // The rim's lowest point: from the COM, r along the coin's plane away from the normal.
      const Vec3 n = Vec3::UnitZ();
      const Vec3 axis = s.R_WB.col(2);
      const Vec3 down = -(n - n.dot(axis) * axis).normalized();
      const Vec3 v_P = s.v_G + s.omega_W.cross(r * down);
      const Vec3 slip = v_P - n * n.dot(v_P);
      const double limit = mu * c.normal_force;
      ASSERT_GT(c.normal_force, 0.0) << "t " << row.t;
      EXPECT_NEAR(slip.norm(), c.slip_speed, 1e-9 * (1 + slip.norm())) << "t " << row.t;
      if (c.mode == 1) {
        // Sliding: mu N, against the slip (once it is more than round-off of its start).
        EXPECT_NEAR(c.friction_W.norm(), limit, 1e-9 * m * kG) << "t " << row.t;
        if (slip.norm() > 1e-6) {
          EXPECT_NEAR(c.friction_W.dot(slip.normalized()), -limit, 1e-9 * m * kG) << "t " << row.t;
        }
      } else {
        // Rolling: no slip, and the friction within the cone.
        EXPECT_EQ(c.mode, 2) << "t " << row.t;
        EXPECT_LT(slip.norm(), 1e-9) << "t " << row.t;
        EXPECT_LE(c.friction_W.norm(), limit * (1 + 1e-9)) << "t " << row.t;
      }
    }
  }
}

// A cone standing on its base on a ramp 2% steeper than atan(4r/h), where the base's CoP reaches
// its rim: with mu 3 it rolls over its rim point until the friction that needs runs out.
std::string cone_over_its_rim(double r, double h) {
  const double theta = 1.02 * std::atan(4 * r / h);
  return fmt::format(
      "tumble: 1\n"
      "parameters: {{theta: {}, d: {}}}\n"
      "bodies:\n"
      "  cone: {{shape: cone, radius: {}, height: {}, mass: 0.5,\n"
      "          position: [d * sin(theta), 0, d * cos(theta)],\n"
      "          orientation: {{axis: [0, 1, 0], angle: theta}}}}\n"
      "contacts:\n"
      "  - {{name: ramp, type: plane, body: cone, plane: {{point: [0, 0, 0],\n"
      "      normal: [sin(theta), 0, cos(theta)]}}, friction: 3}}\n"
      "simulate: {{duration: 1, integrator: dop853, rtol: 1e-10, atol: 1e-13, "
      "output_every: 0.005}}\n",
      theta, 0.25 * h, r, h);
}

TEST(SlipOnset, ASlenderConeRollingOverItsRimSlidesWhenTheFrictionRunsOut) {
  const auto run = run_inline_scenario(cone_over_its_rim(0.05, 0.2), "slender_cone");
  ASSERT_EQ(run.contact_events.size(), 4u);
  EXPECT_EQ(run.contact_events[0].what, "rolls on its rim");
  EXPECT_EQ(run.contact_events[1].what, "slides: the friction sticking needs leaves the cone");
  EXPECT_NE(run.contact_events[2].what.find("touchdown on its side"), std::string::npos);
  EXPECT_EQ(run.contact_events[3].what, "rolls on its side");
  test::expect_energy_never_rises(run, 1e-9);
  // Sliding, the slip only grows until the side lands (it never stops and restarts).
  double slip_before = 0.0;
  for (const Row& row : run.rows) {
    const ContactOutput& c = row.extras.contacts[0];
    if (row.t <= run.contact_events[1].t || row.t >= run.contact_events[2].t) continue;
    EXPECT_EQ(c.mode, 1) << "t " << row.t;
    EXPECT_GT(c.slip_speed, slip_before) << "t " << row.t;
    EXPECT_NEAR(c.friction_W.norm(), 3 * c.normal_force, 1e-9 * 0.5 * kG) << "t " << row.t;
    slip_before = c.slip_speed;
  }
}

TEST(SlipOnset, ASquatConeWhereFrictionWouldPressItOnLiftsOffAndFliesFree) {
  // Painleve's case: sliding, the friction mu N would press the rim onto the ramp (the slip's
  // jerk is against it, so it cannot grow), while with no force the rim point leaves the ramp.
  // Lifting off is the consistent mode: from then on it flies, its COM on a parabola under g and
  // its angular momentum about the COM constant, until it lands.
  // examples/cone_lifted_by_friction.yaml: cone_over_its_rim(0.1, 0.15).
  const double h = 0.15;
  const auto run = test::run_scenario(
      load_scenario(std::string(TUMBLE_SOURCE_DIR) + "/examples/cone_lifted_by_friction.yaml", {}));
  ASSERT_GE(run.contact_events.size(), 3u);
  EXPECT_EQ(run.contact_events[0].what, "rolls on its rim");
  EXPECT_EQ(run.contact_events[1].what, "lifts off: sliding would need friction pressing it on");
  EXPECT_NE(run.contact_events[2].what.find("touchdown"), std::string::npos);
  const double t_off = run.contact_events[1].t, t_land = run.contact_events[2].t;
  ASSERT_GT(t_land - t_off, 0.1);
  const Row* first = nullptr;
  const Vec3 g(0, 0, -kG);
  for (const Row& row : run.rows) {
    if (row.t <= t_off || row.t >= t_land) continue;
    const BodyState& s = row.states[0];
    EXPECT_EQ(row.extras.contacts[0].mode, 0) << "t " << row.t;
    if (first == nullptr) {
      first = &row;
      continue;
    }
    const BodyState& s0 = first->states[0];
    const double dt = row.t - first->t;
    EXPECT_LT((s.r_G - (s0.r_G + s0.v_G * dt + 0.5 * g * dt * dt)).norm(), 1e-9 * h)
        << "t " << row.t;
    const auto L_G = [&](const BodyState& b) {
      return Vec3(calc_inertia_about_com_W(run.bodies[0], b.R_WB) * b.omega_W);
    };
    EXPECT_LT((L_G(s) - L_G(s0)).norm(), 1e-9 * L_G(s0).norm()) << "t " << row.t;
  }
  ASSERT_NE(first, nullptr);
}

TEST(SlipOnset, ASlenderTopFallingOntoItsSideFindsAModeThatHoldsItAtEveryLanding) {
  // A slender top too slow to stand (200 rad/s) falls onto its side, spinning. With friction at
  // the side's middle (one slip, and a moment against the spin) no mode held it at mu 2 where
  // the side's centre of pressure reached the rim: on the rim the apex went into the plane, apart
  // it landed again at once, a thousand times. With friction at each end against that end's own
  // slip (the rim's end slips at ~10 m/s, the apex's hardly at all) it lands, slides and rolls
  // on its rim, lifts off and lands again, with a consistent mode at every landing: at mu 2 and
  // at mu 0.8, a few dozen events in the second, Coulomb's law at every row, and no energy
  // gained.
  const auto top = [](double mu) {
    return fmt::format(
        "tumble: 1\n"
        "parameters: {{d: 0.15, s: -200}}\n"
        "bodies:\n"
        "  top: {{shape: cone, radius: 0.05, height: 0.2, mass: 0.5,\n"
        "         position: [d * sin(20 deg), 0, d * cos(20 deg)],\n"
        "         orientation: {{axis: [0, 1, 0], angle: 200 deg}},\n"
        "         angular_velocity: [s * sin(20 deg), 0, s * cos(20 deg)]}}\n"
        "contacts:\n"
        "  - {{name: floor, type: plane, body: top, plane: {{point: [0, 0, 0], normal: [0, 0, "
        "1]}}, "
        "friction: {}}}\n"
        "simulate: {{duration: 1, integrator: dop853, rtol: 1e-10, atol: 1e-13, "
        "output_every: 0.01}}\n",
        mu);
  };
  for (const double mu : {2.0, 0.8}) {
    SCOPED_TRACE(mu);
    const auto run = run_inline_scenario(top(mu), fmt::format("top_{}", mu));
    ASSERT_TRUE(run.result.report.completed) << run.result.report.failure;
    EXPECT_LT(run.contact_events.size(), 100u);
    bool landed_on_its_side = false;
    for (const ContactEventRecord& e : run.contact_events) {
      landed_on_its_side |= e.what.find("touchdown on its side") != std::string::npos;
    }
    EXPECT_TRUE(landed_on_its_side);
    test::expect_energy_never_rises(run, 1e-9);
    for (const test::Row& row : run.rows) {
      const ContactOutput& c = row.extras.contacts[0];
      EXPECT_LE(c.friction_W.norm(), mu * c.normal_force * (1.0 + 1e-9)) << "t " << row.t;
    }
    // The work-energy theorem, friction's and the landings' work included: 1e-9 of the energy
    // scale (8.2 J), from rtol 1e-10 over the run's steps.
    EXPECT_LT(run.result.conservation.max_work_energy_residual, 1e-9 * 8.2);
  }
}

}  // namespace
}  // namespace tumble
