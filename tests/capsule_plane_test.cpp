// A capsule (radius r, a straight part of length L between its caps' centres, mass m) on a plane:
// a round body whose two ends are its caps' centres swept by r (round_contact.hpp). Against
// closed forms, with I_a = m_c r^2 / 2 + 2 m_s r^2 / 5 about its axis and I_t = m_c (3 r^2 +
// L^2) / 12 + m_s (2 r^2 / 5 + L^2 / 4 + 3 L r / 8) across it (m_c and m_s the cylinder's and the
// caps' shares of m by volume):
//  - lying across a ramp of angle alpha, it rolls down on its side as a cylinder of radius r:
//    a = g sin(alpha) / (1 + I_a / (m r^2)), the ramp's push m g cos(alpha);
//  - dropped tilted by theta, frictionless, it lands on its lower cap at the time free fall gives,
//    and takes the impulse J = (1 + e) u / (1/m + k^2 / I_t), k = (L/2) sin(theta) the moment
//    arm of the cap's lowest point about the COM: after it the COM falls at -u + J/m and the
//    capsule turns at J k / I_t; with e = 1 the kinetic energy is the same after;
//  - dropped lying level with e = 0, it lands on its side (both caps at once) and stays: its
//    centre moves by less than 1e-12 of its length over the second after;
//  - standing upright at rest on a cap it falls (tumble modes): the cap's lowest point rolls over
//    the cap as it leans, its COM at height r + (L/2) cos(phi): lambda^2 = m g (L/2) / (I_t + m (r
//    + L/2)^2), or on ice, where its COM only drops, m g (L/2) / I_t.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "modes_checks.hpp"
#include "scenario_run.hpp"
#include "test_constants.hpp"

namespace tumble {
namespace {

constexpr double kCapR = 0.1, kCapL = 0.6, kCapMass = 2.0;

struct CapsuleInertia {
  double axial = 0.0, transverse = 0.0;
};

// The closed forms above, the mass shared by volume between the cylinder and the two caps.
CapsuleInertia capsule_inertia() {
  const double r = kCapR, L = kCapL;
  const double cylinder = std::numbers::pi * r * r * L,
               caps = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const double m_c = kCapMass * cylinder / (cylinder + caps), m_s = kCapMass - m_c;
  return {m_c * r * r / 2 + 2 * m_s * r * r / 5,
          m_c * (3 * r * r + L * L) / 12 + m_s * (2 * r * r / 5 + L * L / 4 + 3 * L * r / 8)};
}

// A capsule `pill` of those dimensions placed by `placement` (its other keys), touching one plane
// with friction mu and restitution e, for `simulate`.
std::string capsule_on_plane(const std::string& placement, double mu, double e,
                             const std::string& plane, const std::string& simulate,
                             const std::string& parameters = "") {
  return "tumble: 1\n"
         "parameters: {r: 0.1, L: 0.6, m: 2" +
         parameters + "}\ngravity: [0, 0, -" + std::to_string(test::kG) +
         "]\n"
         "bodies:\n"
         "  pill: {shape: capsule, radius: r, length: L, mass: m, " +
         placement + "}\ncontacts:\n  - {name: floor, type: plane, body: pill, friction: " +
         std::to_string(mu) + ", restitution: " + std::to_string(e) + ", plane: " + plane +
         "}\nsimulate: " + simulate + "\n";
}

const std::string kLevelFloor = "{point: [0, 0, 0], normal: [0, 0, 1]}";

TEST(CapsuleOnAPlane, LyingAcrossARampItRollsDownOnItsSideAsACylinder) {
  const double alpha = 20.0 * std::numbers::pi / 180.0;
  const test::ScenarioRun run = test::run_inline_scenario(
      capsule_on_plane("position: [r*sin(alpha), 0, r*cos(alpha)], "
                       "orientation: {axis: [1, 0, 0], angle: 90 deg}",
                       0.8, 0.0, "{point: [0, 0, 0], normal: [sin(alpha), 0, cos(alpha)]}",
                       "{duration: 1, integrator: dop853, rtol: 1e-12, atol: 1e-14, "
                       "output_every: 0.01}",
                       ", alpha: 20 deg"),
      "capsule_ramp");
  const double I_a = capsule_inertia().axial;
  const double a = test::kG * std::sin(alpha) / (1.0 + I_a / (kCapMass * kCapR * kCapR));
  ASSERT_EQ(run.rows.size(), 101u);
  test::expect_rolls_down_from_rest(run, a, Vec3(std::cos(alpha), 0.0, -std::sin(alpha)),
                                    Vec3::UnitY(), kCapR, kCapMass);
  for (const test::Row& row : run.rows) {
    EXPECT_NEAR(row.extras.contacts[0].normal_force, kCapMass * test::kG * std::cos(alpha),
                1e-10 * kCapMass * test::kG)
        << "t " << row.t;
  }
  ASSERT_FALSE(run.contact_events.empty());
  EXPECT_NE(run.contact_events[0].what.find("rolls on its side"), std::string::npos)
      << run.contact_events[0].what;
}

TEST(CapsuleOnAPlane, DroppedTiltedItLandsOnItsLowerCapWithTheClosedFormsImpulse) {
  // Its lowest point h0 above the floor, falling at u0, tilted by theta about y: the -z cap is
  // the lower, at -(L/2)(sin theta, 0, cos theta) from the COM.
  const double theta = 30.0 * std::numbers::pi / 180.0, h0 = 0.05, u0 = 1.0;
  const double g = test::kG, I_t = capsule_inertia().transverse;
  const double t_land = (-u0 + std::sqrt(u0 * u0 + 2 * g * h0)) / g;
  const double u = u0 + g * t_land;  // the landing speed
  const double k = kCapL / 2 * std::sin(theta);
  for (const double e : {0.5, 1.0}) {
    const test::ScenarioRun run = test::run_inline_scenario(
        capsule_on_plane("position: [0, 0, h0 + r + L/2*cos(theta)], velocity: [0, 0, -u0], "
                         "orientation: {axis: [0, 1, 0], angle: theta}",
                         0.0, e, kLevelFloor,
                         "{duration: 0.1, integrator: dop853, rtol: 1e-12, atol: 1e-14, "
                         "output_every: 0.001}",
                         ", h0: 0.05, u0: 1, theta: 30 deg"),
        "capsule_drop");
    ASSERT_FALSE(run.contact_events.empty()) << e;
    const ContactEventRecord& landing = run.contact_events[0];
    EXPECT_NEAR(landing.t, t_land, 1e-12) << e;
    const double J = (1 + e) * u / (1 / kCapMass + k * k / I_t);
    const double v_after = -u + J / kCapMass, w_after = J * k / I_t;
    ASSERT_TRUE(landing.impact.has_value()) << landing.what;
    if (e == 1.0) {
      EXPECT_NEAR(landing.kinetic_energy_after, landing.kinetic_energy_before,
                  1e-12 * landing.kinetic_energy_before);
    }
    // Free flight after it, until the cap comes down again (well after these rows): the COM
    // falls from v_after, the turn about y stays (a principal axis, no moment).
    int after = 0;
    for (const test::Row& row : run.rows) {
      if (row.t <= t_land || row.t > t_land + 0.02) continue;
      ++after;
      const BodyState& s = row.states[0];
      EXPECT_NEAR(s.v_G.z(), v_after - g * (row.t - t_land), 1e-10 * u) << e << " t " << row.t;
      EXPECT_NEAR(s.v_G.x(), 0.0, 1e-12 * u) << e << " t " << row.t;
      EXPECT_NEAR(s.omega_W.y(), w_after, 1e-10 * w_after) << e << " t " << row.t;
      EXPECT_NEAR(s.omega_W.x(), 0.0, 1e-12 * w_after) << e << " t " << row.t;
      EXPECT_EQ(row.extras.contacts[0].mode, 0) << e << " t " << row.t;
    }
    EXPECT_GT(after, 10) << e;
  }
}

TEST(CapsuleOnAPlane, DroppedLevelWithoutBounceItLandsOnItsSideAndStays) {
  const test::ScenarioRun run = test::run_inline_scenario(
      capsule_on_plane("position: [0, 0, r + 0.05], orientation: {axis: [0, 1, 0], angle: 90 deg}",
                       0.5, 0.0, kLevelFloor,
                       "{duration: 1.2, integrator: dop853, rtol: 1e-12, atol: 1e-14, "
                       "output_every: 0.01}"),
      "capsule_level_drop");
  const double t_land = std::sqrt(2 * 0.05 / test::kG);
  ASSERT_FALSE(run.contact_events.empty());
  EXPECT_NEAR(run.contact_events[0].t, t_land, 1e-12);
  EXPECT_NE(run.contact_events[0].what.find("its side"), std::string::npos)
      << run.contact_events[0].what;
  Vec3 rest = Vec3::Zero();
  int resting = 0;
  for (const test::Row& row : run.rows) {
    if (row.t < t_land + 0.1) continue;
    const BodyState& s = row.states[0];
    if (resting++ == 0) rest = s.r_G;
    EXPECT_NEAR((s.r_G - rest).norm(), 0.0, 1e-12 * kCapL) << "t " << row.t;
    EXPECT_NEAR(s.r_G.z(), kCapR, 1e-12 * kCapR) << "t " << row.t;
    EXPECT_NEAR(s.v_G.norm(), 0.0, 1e-12) << "t " << row.t;
    EXPECT_NEAR(row.extras.contacts[0].normal_force, kCapMass * test::kG,
                1e-10 * kCapMass * test::kG)
        << "t " << row.t;
    EXPECT_EQ(row.extras.contacts[0].mode, 2) << "t " << row.t;
  }
  EXPECT_GT(resting, 90);
}

TEST(CapsuleOnAPlane, UprightAtRestItFallsAboutItsCapsLowestPointOrOnIceAboutItsCentre) {
  const double I_t = capsule_inertia().transverse, d = kCapL / 2;
  for (const double mu : {0.8, 0.0}) {
    const ScenarioModes modes = modes_of_scenario(test::load_inline_scenario(
        capsule_on_plane("position: [0, 0, r + L/2]", mu, 0.0, kLevelFloor, "{duration: 1}"),
        "capsule_upright"));
    const double turning = mu > 0.0 ? I_t + kCapMass * (kCapR + d) * (kCapR + d) : I_t;
    ASSERT_FALSE(modes.analysis.modes.empty()) << mu;
    EXPECT_EQ(modes.analysis.modes[0].kind, Mode::Kind::Growing) << mu;
    test::expect_relative(modes.analysis.modes[0].growth_rate,
                          std::sqrt(kCapMass * test::kG * d / turning));
  }
}

}  // namespace
}  // namespace tumble
