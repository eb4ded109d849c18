// examples/rimless_wheel.yaml: McGeer's rimless wheel, one composite body whose six ball feet are
// each a contact of their own with the ramp (`part:` listing them), walking down the ramp. The
// wheel hands over from foot to foot as it turns, and each handover is a plastic impact without
// slip at the landing foot, with the foot it rolled on sent away at that instant. Against the
// closed forms, derived here (2D: the wheel turns about its axle, across the ramp):
//  - at a landing the feet touch at P1 (behind) and P2 (ahead); the impulse acts at P2 alone, so
//    angular momentum about P2 is kept: I_G w- + m (G - P2) x v_G- = I_P w+, with v_G- = w- x
//    (G - P1) (rolling about P1) and I_P = I_G + m |G - P2|^2. So w+ / w- = (I_G + m (G - P1).(G -
//    P2)) / I_P, and with |G - P1| = |G - P2| the kinetic energy (1/2 I_P w^2) falls by that
//    ratio squared, r2;
//  - feet of radius rho with centres C at l from G, alpha either side of the ramp's normal n:
//    G - P = (G - C) + rho n, so (G - P1).(G - P2) = l^2 cos(2 alpha) + 2 rho l cos(alpha) + rho^2
//    and |G - P|^2 = l^2 + 2 rho l cos(alpha) + rho^2;
//  - between landings it rolls over a foot (no work), turning 2 alpha, the contact point moving
//    2 alpha rho along the ramp, and G, from alpha behind the foot to alpha ahead of it, moves
//    2 l sin(alpha) + 2 alpha rho along the ramp: it drops by that times sin(gamma). The energy
//    before a landing follows KE-(k+1) = r2 KE-(k) + m g drop, whose fixed point KE* = m g drop /
//    (1 - r2) is the gait the example starts on.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "scenario_run.hpp"
#include "test_files.hpp"
#include "tumble/scenario/scenario.hpp"

namespace tumble {
namespace {

// The example's parameters.
constexpr double kSlope = 0.12, kSpoke = 0.3, kFootRadius = 0.02, kHubMass = 2.0, kHubRadius = 0.05,
                 kFootMass = 0.1, kHalfAngle = std::numbers::pi / 6, kGravity = 9.81;
constexpr int kFeet = 6;

struct Gait {
  double energy_ratio = 0.0;    // r2: KE after a landing over KE before it
  double drop = 0.0;            // m: G's fall between landings
  double landing_energy = 0.0;  // J: KE* before each landing
  double rate_after = 0.0;      // rad/s: w+ just after each, about P2: r2 KE* = I_P w+^2 / 2
};

Gait rimless_gait() {
  const double m = kHubMass + kFeet * kFootMass;
  // About the axle through G: a ball's 2/5 m r^2, and each foot's own plus m l^2.
  const double I_G = 0.4 * kHubMass * kHubRadius * kHubRadius +
                     kFeet * kFootMass * (0.4 * kFootRadius * kFootRadius + kSpoke * kSpoke);
  const double rolled =
      2.0 * kFootRadius * kSpoke * std::cos(kHalfAngle) + kFootRadius * kFootRadius;
  const double I_P = I_G + m * (kSpoke * kSpoke + rolled);
  const double kept = I_G + m * (kSpoke * kSpoke * std::cos(2.0 * kHalfAngle) + rolled);
  Gait gait;
  gait.energy_ratio = (kept / I_P) * (kept / I_P);
  gait.drop =
      (2.0 * kSpoke * std::sin(kHalfAngle) + 2.0 * kHalfAngle * kFootRadius) * std::sin(kSlope);
  gait.landing_energy = m * kGravity * gait.drop / (1.0 - gait.energy_ratio);
  gait.rate_after = std::sqrt(2.0 * gait.energy_ratio * gait.landing_energy / I_P);
  return gait;
}

test::ScenarioRun walked() {
  return test::run_scenario(
      load_scenario(std::string(TUMBLE_SOURCE_DIR) + "/examples/rimless_wheel.yaml", {}));
}

TEST(RimlessWheel, EachFootHandsOverToTheNextAtALocatedLandingThatSendsTheOldOneAway) {
  const test::ScenarioRun run = walked();
  const Gait gait = rimless_gait();
  const double leaving_speed = gait.rate_after * 2.0 * kSpoke * std::sin(kHalfAngle);
  ASSERT_EQ(run.contacts.size(), static_cast<std::size_t>(kFeet));
  for (int k = 0; k < kFeet; ++k) {
    EXPECT_EQ(run.contacts[static_cast<std::size_t>(k)].name, "ramp_foot" + std::to_string(k));
  }
  // It starts rolling on foot0; then each landing is three events at one instant: the next foot
  // lands, the one behind lifts off, the new one rolls.
  ASSERT_EQ(run.contact_events.size(), 1u + 3u * kFeet);
  EXPECT_EQ(run.contact_events[0].contact, 0u);
  EXPECT_EQ(run.contact_events[0].what, "rolls");
  for (std::size_t k = 0; k < kFeet; ++k) {
    const std::size_t landing = (k + 1) % kFeet;
    const ContactEventRecord& lands = run.contact_events[1 + 3 * k];
    const ContactEventRecord& leaves = run.contact_events[2 + 3 * k];
    const ContactEventRecord& rolls = run.contact_events[3 + 3 * k];
    EXPECT_EQ(lands.contact, landing);
    EXPECT_NE(lands.what.find("touchdown at normal speed"), std::string::npos) << lands.what;
    EXPECT_EQ(leaves.contact, k);
    EXPECT_EQ(leaves.what,
              "lifts off: the impact at ramp_foot" + std::to_string(landing) + " sends it away");
    EXPECT_EQ(rolls.contact, landing);
    EXPECT_EQ(rolls.what, "rolls");
    EXPECT_EQ(leaves.t, lands.t);
    EXPECT_EQ(rolls.t, lands.t);
    // The foot sent away leaves the ramp at w+ times P1's distance behind P2, 2 l sin(alpha); the
    // landed one rolls (no slip, no bounce: round-off of the ~1 m/s speeds).
    EXPECT_NEAR(leaves.normal_speed, leaving_speed, 1e-10 * leaving_speed);
    EXPECT_LT(rolls.slip_speed, 1e-12);
    EXPECT_LT(std::abs(rolls.normal_speed), 1e-12);
  }
}

TEST(RimlessWheel, EachLandingKeepsAngularMomentumAboutTheNewFootAndTheGaitIsTheClosedForms) {
  const test::ScenarioRun run = walked();
  const Gait gait = rimless_gait();
  std::vector<double> landing_times;
  for (const ContactEventRecord& event : run.contact_events) {
    if (!event.impact) continue;
    const double before = event.impact->kinetic_energy_before;
    const double after = event.impact->kinetic_energy_after;
    // The impulse is a linear solve at the located landing: round-off.
    EXPECT_NEAR(after / before, gait.energy_ratio, 1e-12) << event.t;
    // Rolling between landings, integrated at rtol 1e-12: the energy reaches the gait's again.
    EXPECT_NEAR(before / gait.landing_energy, 1.0, 1e-10) << event.t;
    landing_times.push_back(event.t);
  }
  ASSERT_EQ(landing_times.size(), static_cast<std::size_t>(kFeet));
  // One step period apart: the gait repeats.
  const double period = landing_times[0];
  for (std::size_t k = 1; k < landing_times.size(); ++k) {
    EXPECT_NEAR(landing_times[k] - landing_times[k - 1], period, 1e-10 * period);
  }
  // Rolling does no work: E is constant between landings and drops by (1 - r2) KE* at each.
  double E_step = run.rows.front().quantities.total_energy;
  std::size_t next = 0;
  for (const test::Row& row : run.rows) {
    while (next < landing_times.size() && row.t >= landing_times[next]) {
      E_step -= (1.0 - gait.energy_ratio) * gait.landing_energy;
      ++next;
    }
    EXPECT_NEAR(row.quantities.total_energy, E_step, 1e-10 * gait.landing_energy) << row.t;
  }
}

}  // namespace
}  // namespace tumble
