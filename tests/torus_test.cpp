// The torus (a toroidal tyre): a ring's centre circle of radius R with a tube of radius r about it.
//  - Its mass properties against an integration of its own: the tube's cross-section, a disk of
//    radius r at distance R + s from the axis (s across it), swept round the axis, by
//    Gauss-Legendre in the section's polar coordinates (exact for the polynomials these are):
//    V = 2 pi^2 R r^2, I_axis = M (R^2 + 3 r^2 / 4), I_diameter = M (R^2 / 2 + 5 r^2 / 8).
//  - Upright on a ramp of angle alpha, it rolls on the radius R + r (its lowest point is the
//    centre circle's lowest point, r further down): a = g sin(alpha) / (1 + I_axis / (M (R +
//    r)^2)), the ramp's push M g cos(alpha), E conserved.
//  - Lying flat and spinning, it bears on its centre circle as a ring does: the floor's torsional
//    friction mu M g R slows it uniformly to rest at t = w0 I_axis / (mu M g R), a located event.
//  - Standing upright at rest it falls (tumble modes): held at its point of contact, which rolls
//    sideways over its tube as it leans, its COM at height R cos(phi) + r, it turns about that
//    point at first: lambda^2 = M g R / (I_d + M (R + r)^2); on ice its COM only drops, and
//    lambda^2 = M g R / I_d (I_d about a diameter).
//  - The reader refuses a tube that reaches the axis, at the key.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cmath>
#include <numbers>
#include <string>

#include "modes_checks.hpp"
#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "tumble/inertia/shapes.hpp"

namespace tumble {
namespace {

constexpr double kR = 0.3, kTube = 0.05, kMass = 1.5;

// A torus of those dimensions and mass, `tyre`, placed by `placement` (its other keys), touching
// one plane with friction mu (`plane`: its point and normal), for `simulate`.
std::string torus_scenario(const std::string& placement, double mu, const std::string& plane,
                           const std::string& simulate, const std::string& parameters = "") {
  return "tumble: 1\n"
         "parameters: {R: 0.3, r: 0.05, m: 1.5" +
         parameters + "}\ngravity: [0, 0, -" + std::to_string(test::kG) +
         "]\n"
         "bodies:\n"
         "  tyre: {shape: torus, radius: R, tube_radius: r, mass: m, " +
         placement + "}\ncontacts:\n  - {name: floor, type: plane, body: tyre, friction: " +
         std::to_string(mu) + ", plane: " + plane + "}\nsimulate: " + simulate + "\n";
}

const std::string kRows =
    "{duration: 1, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: 0.01}";

TEST(Torus, ItsMassPropertiesAreTheSweptSectionsIntegrals) {
  Shape torus;
  torus.kind = ShapeKind::Torus;
  torus.radius = kR;
  torus.tube_radius = kTube;
  // Gauss-Legendre on [-1, 1], 5 points: exact to degree 9.
  const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                       0.9061798459386640};
  const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                       0.4786286704993665, 0.2369268850561891};
  // Over the section: rho in [0, r], phi in [0, 2 pi]; s = rho cos(phi) outwards, z = rho
  // sin(phi); the ring at distance R + s from the axis has length 2 pi (R + s). In phi the
  // integrands are trigonometric polynomials of degree 3 at most: 8 equal steps are exact.
  double volume = 0.0, axis = 0.0, z_squared = 0.0;
  for (int i = 0; i < 5; ++i) {
    const double rho = 0.5 * kTube * (x[i] + 1.0), w_rho = 0.5 * kTube * w[i];
    for (int j = 0; j < 8; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / 8.0, w_phi = 2.0 * std::numbers::pi / 8.0;
      const double s = rho * std::cos(phi), z = rho * std::sin(phi), d = kR + s;
      const double dV = w_rho * w_phi * rho * 2.0 * std::numbers::pi * d;
      volume += dV;
      axis += dV * d * d;  // x^2 + y^2 over the ring
      z_squared += dV * z * z;
    }
  }
  EXPECT_NEAR(shape_measure(torus), volume, 1e-15);
  EXPECT_NEAR(volume, 2.0 * std::numbers::pi * std::numbers::pi * kR * kTube * kTube, 1e-15);
  const double density = kMass / volume;
  const Mat3 I = shape_mass_properties(torus, kMass).inertia_about_com;
  // About the axis: (x^2 + y^2) dm; about a diameter: (x^2 + y^2) / 2 + z^2 (the ring's mass
  // spread evenly round it).
  EXPECT_NEAR(I(2, 2), density * axis, 1e-14);
  EXPECT_NEAR(I(0, 0), density * (axis / 2.0 + z_squared), 1e-14);
  EXPECT_NEAR(I(1, 1), I(0, 0), 0.0);
  EXPECT_NEAR(I(2, 2), kMass * (kR * kR + 0.75 * kTube * kTube), 1e-15);
  EXPECT_NEAR(I(0, 0), kMass * (kR * kR / 2 + 5.0 * kTube * kTube / 8), 1e-15);
  EXPECT_TRUE((I - Mat3(I.diagonal().asDiagonal())).isZero(0.0));
}

TEST(Torus, UprightOnARampItRollsOnItsCentreCirclePlusItsTube) {
  const double alpha = 20.0 * std::numbers::pi / 180.0;
  const test::ScenarioRun run = test::run_inline_scenario(
      torus_scenario("position: [(R + r)*sin(alpha), 0, (R + r)*cos(alpha)], "
                     "orientation: {axis: [1, 0, 0], angle: 90 deg}",
                     0.8, "{point: [0, 0, 0], normal: [sin(alpha), 0, cos(alpha)]}", kRows,
                     ", alpha: 20 deg"),
      "torus_ramp");
  const double rolling = kR + kTube, I_axis = kMass * (kR * kR + 0.75 * kTube * kTube);
  const double a = test::kG * std::sin(alpha) / (1.0 + I_axis / (kMass * rolling * rolling));
  ASSERT_EQ(run.rows.size(), 101u);
  test::expect_rolls_down_from_rest(run, a, Vec3(std::cos(alpha), 0.0, -std::sin(alpha)),
                                    Vec3::UnitY(), rolling, kMass);
  for (const test::Row& row : run.rows) {
    EXPECT_NEAR(row.extras.contacts[0].normal_force, kMass * test::kG * std::cos(alpha),
                1e-10 * kMass * test::kG)
        << "t " << row.t;
  }
}

TEST(Torus, LyingFlatItSpinsDownAsARingOfItsCentreCircle) {
  const double mu = 0.2, w0 = 10.0;
  const test::ScenarioRun run = test::run_inline_scenario(
      torus_scenario("position: [0, 0, r], angular_velocity: [0, 0, 10]", mu,
                     "{point: [0, 0, 0], normal: [0, 0, 1]}",
                     "{duration: 3, integrator: dop853, rtol: 1e-12, atol: 1e-14, "
                     "output_every: 0.01}"),
      "torus_flat");
  const double I_axis = kMass * (kR * kR + 0.75 * kTube * kTube);
  const double slowing = mu * kMass * test::kG * kR / I_axis, t_stop = w0 / slowing;
  for (const test::Row& row : run.rows) {
    const BodyState& s = row.states[0];
    EXPECT_NEAR(s.omega_W.z(), std::max(w0 - slowing * row.t, 0.0), 1e-12 * w0) << row.t;
    EXPECT_NEAR(s.r_G.z(), kTube, 1e-12 * kTube) << row.t;  // on its tube, not on a point
    EXPECT_NEAR(row.extras.contacts[0].normal_force, kMass * test::kG, 1e-12 * kMass * test::kG)
        << row.t;
  }
  ASSERT_EQ(run.contact_events.size(), 3u);
  EXPECT_EQ(run.contact_events[0].what, "slides on its face");
  EXPECT_EQ(run.contact_events[1].what, "slip stops");
  EXPECT_NEAR(run.contact_events[1].t, t_stop, 1e-9 * t_stop);
  EXPECT_EQ(run.contact_events[2].what, "sticks on its face");
}

TEST(Torus, UprightAtRestItFallsAboutItsPointOfContactOrOnIceAboutItsCentre) {
  const double I_d = kMass * (kR * kR / 2 + 5.0 * kTube * kTube / 8);
  for (const double mu : {0.8, 0.0}) {
    const ScenarioModes modes = modes_of_scenario(test::load_inline_scenario(
        torus_scenario("position: [0, 0, R + r], orientation: {axis: [1, 0, 0], angle: 90 deg}", mu,
                       "{point: [0, 0, 0], normal: [0, 0, 1]}", "{duration: 1}"),
        "torus_upright"));
    const double turning = mu > 0.0 ? I_d + kMass * (kR + kTube) * (kR + kTube) : I_d;
    ASSERT_FALSE(modes.analysis.modes.empty()) << mu;
    EXPECT_EQ(modes.analysis.modes[0].kind, Mode::Kind::Growing) << mu;
    test::expect_relative(modes.analysis.modes[0].growth_rate,
                          std::sqrt(kMass * test::kG * kR / turning));
  }
}

TEST(Torus, TheReaderRefusesATubeThatReachesItsAxis) {
  test::expect_error(
      "tumble: 1\n"
      "bodies:\n"
      "  tyre: {shape: torus, radius: 0.1, tube_radius: 0.1, mass: 1}\n"
      "simulate: {duration: 1}\n",
      3, 50, "bodies.tyre.tube_radius", "tube_radius 0.1 must be less than radius 0.1");
}

}  // namespace
}  // namespace tumble
