// A capsule (a cylinder of length L and radius r capped by two hemispheres) and a sphere touching
// it, each against its closed form:
//  - its inertia, against the slices' sums: the capsule is the disks of radius rho(z) stacked
//    along its axis, each dm = density pi rho^2 dz adding dm rho^2 / 2 about the axis and
//    dm (rho^2 / 4 + z^2) about a diameter;
//  - a sphere striking its side at right angles, frictionless, at the axial distance b from its
//    COM: the impulse J = (1 + e) u / (1/m + 1/M + b^2 / I_t), both free and untouched by gravity;
//  - a frictionless ball sliding off a fixed capsule or cylinder lying level, started at its top
//    and moving along its axis at w as well: the axis takes no force, so the ball keeps w along it,
//    and across it slides as a particle off a circle of radius rho = r + R, leaving where cos theta
//    = 2/3 + v0^2 / (3 g rho);
//  - examples/billiard_cue.yaml: a cue whose tip does not slip strikes a ball on the table; the
//    ball rolls at once where the blow's line passes 2R/5 above its centre (below).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "test_files.hpp"
#include "tumble/inertia/shapes.hpp"

namespace tumble {
namespace {

TEST(Capsule, InertiaIsTheSumOfItsSlices) {
  // (Plain names, not a structured binding: clang's lambdas do not capture those before C++20's
  // last revision.)
  for (const std::pair<double, double>& sizes :
       {std::pair{0.1, 0.5}, std::pair{0.3, 0.05}, std::pair{0.02, 1.4}}) {
    const double r = sizes.first, L = sizes.second;
    Shape shape;
    shape.kind = ShapeKind::Capsule;
    shape.radius = r;
    shape.length = L;
    const double mass = 2.5;
    const MassProperties mp = shape_mass_properties(shape, mass);
    // Three-point Gauss-Legendre over each cap and the cylinder: exact for the integrands, of
    // degree 4 in z at most.
    const auto slices = [&](double& volume, double& axial, double& transverse) {
      volume = axial = transverse = 0.0;
      const auto add = [&](double z0, double z1, auto rho2) {
        const double half = (z1 - z0) / 2, mid = (z0 + z1) / 2, x = std::sqrt(0.6);
        for (const auto& [t, weight] :
             {std::pair{-x, 5.0 / 9.0}, {0.0, 8.0 / 9.0}, {x, 5.0 / 9.0}}) {
          const double z = mid + half * t, w = half * weight;
          const double a = std::numbers::pi * rho2(z);
          volume += w * a;
          axial += w * a * rho2(z) / 2.0;
          transverse += w * a * (rho2(z) / 4.0 + z * z);
        }
      };
      const double h = L / 2;
      add(-h - r, -h, [&](double z) { return r * r - (z + h) * (z + h); });
      add(-h, h, [&](double) { return r * r; });
      add(h, h + r, [&](double z) { return r * r - (z - h) * (z - h); });
    };
    double volume = 0.0, axial = 0.0, transverse = 0.0;
    slices(volume, axial, transverse);
    const double density = mass / volume;
    EXPECT_NEAR(shape_measure(shape), volume, 1e-13 * volume);
    EXPECT_NEAR(mp.inertia_about_com(2, 2), density * axial, 1e-12 * density * axial);
    EXPECT_NEAR(mp.inertia_about_com(0, 0), density * transverse, 1e-12 * density * transverse);
    EXPECT_NEAR(mp.inertia_about_com(1, 1), density * transverse, 1e-12 * density * transverse);
    EXPECT_EQ(mp.inertia_about_com(0, 1), 0.0);
  }
  // Length zero is a sphere's; the reader refuses it, but the limit holds.
  Shape ball;
  ball.kind = ShapeKind::Capsule;
  ball.radius = 0.2;
  ball.length = 1e-300;
  EXPECT_NEAR(shape_mass_properties(ball, 1.0).inertia_about_com(0, 0), 0.4 * 0.04, 1e-15);
}

// A capsule (r 0.05, L 0.6, mass M 2) lying along x at the origin, free; a ball (R 0.1, m 0.5)
// above its axis's point b along it, coming down at u; no gravity.
std::string ball_onto_capsule_side(double b, double e) {
  return "tumble: 1\n"
         "parameters: {b: " +
         std::to_string(b) +
         ", u: 3}\n"
         "gravity: [0, 0, 0]\n"
         "bodies:\n"
         "  log: {shape: capsule, radius: 0.05, length: 0.6, mass: 2, orientation: {axis: [0, 1, "
         "0], angle: 90 deg}}\n"
         "  ball: {shape: sphere, radius: 0.1, mass: 0.5, position: [b, 0, 0.3], velocity: [0, 0, "
         "-u]}\n"
         "contacts:\n"
         "  - {name: hit, type: bodies, bodies: [log, ball], friction: 0, restitution: " +
         std::to_string(e) +
         "}\n"
         "simulate: {duration: 0.1, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
         "0.01}\n";
}

TEST(Capsule, ABallStrikingItsSideAtRightAnglesTakesTheClosedFormsImpulse) {
  for (const double b : {0.0, 0.2, 0.3}) {
    const double u = 3, m = 0.5, M = 2, e = 0.6;
    const test::ScenarioRun run = test::run_inline_scenario(ball_onto_capsule_side(b, e), "side");
    ASSERT_GE(run.contact_events.size(), 1u);
    const ContactEventRecord& hit = run.contact_events[0];
    ASSERT_TRUE(hit.impact.has_value());
    // The capsule named first goes second: the ball is the contact's body.
    EXPECT_EQ(run.contacts[0].body, 1u);
    EXPECT_NEAR(hit.t, (0.3 - 0.15) / u, 1e-12);
    EXPECT_NEAR(hit.normal_W.z(), 1.0, 1e-12);
    EXPECT_NEAR(hit.point_W.x(), b, 1e-12);
    const double I_t = run.bodies[0].I_G_B(0, 0);
    const double J = (1 + e) * u / (1 / m + 1 / M + b * b / I_t);
    EXPECT_NEAR(hit.impact->impulse_W.z(), J, 1e-12 * m * u);
    const test::Row& last = run.rows.back();
    EXPECT_NEAR(last.states[1].v_G.z(), -u + J / m, 1e-12 * u);
    EXPECT_NEAR(last.states[0].v_G.z(), -J / M, 1e-12 * u);
    // The blow at b along x, downwards, turns the capsule about +y at J b / I_t.
    EXPECT_NEAR(last.states[0].omega_W.y(), J * b / I_t, 1e-12 * u / 0.3);
    EXPECT_NEAR(last.states[0].omega_W.x(), 0.0, 1e-12 * u / 0.3);
  }
}

// A fixed log of radius 0.2 and length 3, a capsule or a cylinder, lying along x; a ball (R 0.1)
// on its top, moving at w along it and v0 across it. (On a cylinder's side the nearest point moves
// round the axis as well as along it.)
std::string ball_on_a_log(const std::string& shape) {
  return "tumble: 1\n"
         "parameters: {w: 0.4, v0: 0.02}\n"
         "gravity: [0, 0, -" +
         std::to_string(test::kG) +
         "]\n"
         "bodies:\n"
         "  log: {shape: " +
         shape +
         ", radius: 0.2, length: 3, mass: 50, orientation: {axis: [0, 1, 0], angle: 90 deg}}\n"
         "  ball: {shape: sphere, radius: 0.1, mass: 0.5, position: [-1, 0, 0.3], velocity: [w, "
         "v0, 0]}\n"
         "joints:\n"
         "  footing: {type: fixed, bodies: [ground, log], at: [0, 0, 0]}\n"
         "contacts:\n"
         "  - {name: on_log, type: bodies, bodies: [ball, log], friction: 0, restitution: 0}\n"
         "simulate: {duration: 1.2, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
         "0.01}\n";
}

// The ball slides off the log, as a particle off a circle, keeping its motion along the axis.
void slides_off_a_log(const test::ScenarioRun& run) {
  const double g = test::kG, rho = 0.3, m = 0.5, w = 0.4, v0 = 0.02;
  ASSERT_EQ(run.contact_events.size(), 2u);
  EXPECT_EQ(run.contact_events[0].what, "slides");
  EXPECT_EQ(run.contact_events[1].what, "lifts off");
  const ContactEventRecord& off = run.contact_events[1];
  // The normal at lift-off is the ball's direction from the axis: its z is cos theta; it has no
  // part along the axis.
  EXPECT_NEAR(off.normal_W.z(), 2.0 / 3.0 + v0 * v0 / (3 * g * rho), 1e-9);
  EXPECT_NEAR(off.normal_W.x(), 0.0, 1e-12);
  EXPECT_NEAR(off.point_W.x(), -1 + w * off.t, 1e-12);
  for (const test::Row& row : run.rows) {
    if (row.t >= off.t) break;
    const BodyState& ball = row.states[1];
    const double cos_theta = ball.r_G.z() / rho;
    EXPECT_NEAR(ball.r_G.x(), -1 + w * row.t, 1e-12) << row.t;
    EXPECT_NEAR(ball.v_G.x(), w, 1e-12) << row.t;
    EXPECT_NEAR(std::hypot(ball.r_G.y(), ball.r_G.z()), rho, 1e-12 * rho) << row.t;
    EXPECT_EQ(row.extras.contacts[0].mode, 1) << row.t;
    const double across2 = ball.v_G.y() * ball.v_G.y() + ball.v_G.z() * ball.v_G.z();
    EXPECT_NEAR(across2, v0 * v0 + 2 * g * rho * (1 - cos_theta), 1e-11 * g * rho) << row.t;
    EXPECT_NEAR(row.extras.contacts[0].normal_force,
                m * g * (3 * cos_theta - 2) - m * v0 * v0 / rho, 1e-10 * m * g)
        << row.t;
  }
}

TEST(Capsule, AFrictionlessBallSlidesOffALogAlongItsAxisWhereCosThetaIsTwoThirds) {
  for (const char* shape : {"capsule", "cylinder"}) {
    SCOPED_TRACE(shape);
    slides_off_a_log(test::run_inline_scenario(ball_on_a_log(shape), "log"));
  }
}
// examples/billiard_cue.yaml. A cue (mass M, a capsule of radius r and length L, its weight
// carried by the player's hands) moving level at V along x strikes a ball (radius R, mass m,
// I = 2 m R^2 / 5) at rest on the table, its tip's centre (R + r) s above the ball's centre. They
// touch at Q = R (-c, 0, s) from the ball's centre (c = sqrt(1 - s^2)), along the normal
// n = (c, 0, -s) into the ball. The tip does not slip (`friction: inf`) and the normal speed
// rebounds at e; the blow presses the ball into the table, which holds it (its friction takes
// none in the instant). With the blow P = (Px, 0, Pz) on the ball:
//   ball:  v = Px / m, omega_y = R (s Px + c Pz) / I; its point Q moves at (v + omega R s, omega R
//   c) cue:   its tip's centre d = (L/2, 0, 0) from its COM, Q = d + r n from it; it takes -P:
//          omega_c = (r s Px + (L/2 + r c) Pz) / I_c, Q moves at
//          (V - Px / M - omega_c r s, -Pz / M - omega_c (L/2 + r c))
// and the relative velocity at Q after is -e times its normal part before, (-V c) n: two linear
// equations in Px and Pz. The ball then rolls at once (v = omega R) where s makes the blow's
// moment about the table's contact point the rolling ball's, (7/5) m R^2 omega = Px (7R/5): where
// the blow's line passes 2R/5 above the ball's centre, the chapter's level blow at h = 2R/5.
struct CueStroke {
  double Px = 0.0, Pz = 0.0, v = 0.0, omega = 0.0;
};
CueStroke cue_stroke(double s) {
  const double R = 0.028575, m = 0.17, M = 0.54, r = 0.0065, L = 1.4, V = 2, e = 0.75;
  const double c = std::sqrt(1 - s * s), I = 0.4 * m * R * R;
  // The cue's inertia about a diameter: its cylinder's and its two caps' (shapes.cpp's closed
  // form, checked above).
  const double cylinder = L / (L + 4 * r / 3), m_c = M * cylinder, m_s = M - m_c;
  const double I_c =
      m_c * (3 * r * r + L * L) / 12 + m_s * (0.4 * r * r + L * L / 4 + 3 * L * r / 8);
  const double arm = L / 2 + r * c;
  // The relative velocity's change at Q (ball less cue) per unit Px and per unit Pz.
  const auto change = [&](double Px, double Pz) {
    const double omega = R * (s * Px + c * Pz) / I;
    const double omega_c = (r * s * Px + arm * Pz) / I_c;
    return Vec3(Px / m + omega * R * s + Px / M + omega_c * r * s, 0.0,
                omega * R * c + Pz / M + omega_c * arm);
  };
  const Vec3 per_x = change(1, 0), per_z = change(0, 1);
  const Vec3 n(c, 0, -s);
  const Vec3 wanted = -e * (-V * c) * n - Vec3(-V, 0, 0);
  const double det = per_x.x() * per_z.z() - per_z.x() * per_x.z();
  CueStroke stroke;
  stroke.Px = (wanted.x() * per_z.z() - per_z.x() * wanted.z()) / det;
  stroke.Pz = (per_x.x() * wanted.z() - wanted.x() * per_x.z()) / det;
  stroke.v = stroke.Px / m;
  stroke.omega = R * (s * stroke.Px + c * stroke.Pz) / I;
  return stroke;
}

TEST(Capsule, ACueWhoseTipDoesNotSlipRollsTheBallAtOnceWhereItsBlowsLinePassesTwoFifthsR) {
  const double R = 0.028575, V = 2;
  // The tip's height at which the ball rolls at once: the root of v - omega R (more top spin as
  // the tip touches higher), by bisection to round-off.
  double lo = 0.5, hi = 0.99;
  for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) {
    const double mid = 0.5 * (lo + hi);
    const CueStroke stroke = cue_stroke(mid);
    (stroke.v - stroke.omega * R > 0 ? lo : hi) = mid;
  }
  const double s_rolls = 0.5 * (lo + hi);
  const CueStroke stroke = cue_stroke(s_rolls);

  Scenario scenario = load_scenario(test::example("billiard_cue.yaml"), {});
  ASSERT_NEAR(scenario.parameters.at("tip"), s_rolls, 1e-14);
  const test::ScenarioRun run = test::run_scenario(std::move(scenario));
  // The table touches from the start and rolls; the stroke is the one event after that: the ball
  // never slides.
  ASSERT_EQ(run.contact_events.size(), 2u);
  EXPECT_EQ(run.contact_events[0].what, "rolls");
  const ContactEventRecord& blow = run.contact_events[1];
  EXPECT_EQ(blow.contact, 1u);
  EXPECT_NEAR(blow.t, 0.01 / V, 1e-12);
  ASSERT_TRUE(blow.impact.has_value());
  const Vec3 P = blow.impact->impulse_W;
  EXPECT_NEAR(P.x(), stroke.Px, 1e-12 * stroke.Px);
  EXPECT_NEAR(P.z(), stroke.Pz, 1e-12 * stroke.Px);
  EXPECT_NEAR(P.y(), 0.0, 1e-14);
  // The blow's line, through the point of contact, meets the vertical through the ball's centre
  // (at x = 0) 2R/5 above the centre.
  const Vec3 centre(0, 0, R);
  const double along = (centre.x() - blow.point_W.x()) / P.x();
  EXPECT_NEAR(blow.point_W.z() + along * P.z() - centre.z(), 0.4 * R, 1e-10 * R);
  // Every row after: the ball rolls at the stroke's speed, the table's slip nought, mode rolling.
  int after = 0;
  for (const test::Row& row : run.rows) {
    EXPECT_EQ(row.extras.contacts[0].mode, 2) << row.t;
    EXPECT_LT(row.extras.contacts[0].slip_speed, 1e-10 * stroke.v) << row.t;
    if (row.t <= blow.t) continue;
    ++after;
    const BodyState& ball = row.states[0];
    EXPECT_NEAR(ball.v_G.x(), stroke.v, 1e-9 * stroke.v) << row.t;
    EXPECT_NEAR(ball.omega_W.y() * R, stroke.v, 1e-9 * stroke.v) << row.t;
  }
  EXPECT_GT(after, 10);
}

TEST(Capsule, RefusedWhereABallStartsInsideIt) {
  const std::string bodies =
      "tumble: 1\n"
      "bodies:\n"
      "  a: {shape: capsule, radius: 0.1, length: 0.5, mass: 1}\n"
      "  b: {shape: capsule, radius: 0.1, length: 0.5, mass: 1, position: [1, 0, 0]}\n"
      "  c: {shape: sphere, radius: 0.1, mass: 1, position: [0, 0, 0.25]}\n";
  // The ball's centre 0.25 above a's: 0.05 into it (its cap's centre is at 0.25 along z, the
  // radii add to 0.2): located at the start, with the depth.
  const std::string overlap = bodies +
                              "contacts:\n"
                              "  - {type: bodies, bodies: [a, c], friction: 0}\n"
                              "simulate: {duration: 1}\n";
  test::expect_error(
      overlap, 7, 5, "contacts[0]",
      "start overlapping by 0.2 m (the sphere's centre is 0 m from the capsule's axis");
}

}  // namespace
}  // namespace tumble
