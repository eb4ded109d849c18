// A sphere against a tube (a hollow cylinder: its outer side, its bore, its annular end faces and
// their rims) and against a cone (its slant side, its apex, its base and the base's rim), each
// against its closed form:
//  - a ball rolling without slip inside a fixed pipe, in the plane across the pipe's axis, is the
//    ball in a bowl's section (tests/bowl_test.cpp): with rho = a - r from the axis, a pendulum of
//    length rho in the gravity 5g/7, whose exact period is 2 pi / AGM(1, cos(theta0 / 2))
//    sqrt(7 rho / 5g) = 4 K(sin(theta0 / 2)) sqrt(7 rho / 5g); the bore pushes N = m g (17
//    cos(theta) - 10 cos(theta0)) / 7;
//  - a ball dropped from rest at height z0 onto a fixed cone (base radius R, height H, base on the
//    floor), its centre x0 from the axis: it touches the slant side where its centre is r from the
//    side's line, z = (r - (x0 - R) n_rho) / n_z above the base with n = (H, R) / sqrt(R^2 + H^2)
//    (out, up), at t = sqrt(2 (z0 - z) / g); frictionless, its velocity after is v - (1 + e)
//    (v . n) n. On the apex (x0 = 0), it bounces straight up at e u;
//  - a ball dropped onto an upright fixed tube's annular end face bounces straight up at e u, and
//    one dropped at the bore's rim (its centre within the bore) bounces off the rim's point along
//    the line from that point to its centre.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "tumble/exact/jacobi_elliptic.hpp"

namespace tumble {
namespace {

constexpr double kGravityTubeCone = 9.81;  // m/s^2, the scenarios'

TEST(SphereTube, ABallRollingInsideAPipeSwingsAsAPendulumInFiveSeventhsOfGravity) {
  const double a = 0.5, r = 0.05, m = 0.2, rho = a - r, axis_height = 0.6;
  const double theta0 = 40 * std::numbers::pi / 180;
  // The pipe's axis along y, fixed; the ball at its middle, theta0 up its wall.
  const test::ScenarioRun run = test::run_inline_scenario(R"yaml(tumble: 1
parameters: {a: 0.5, r: 0.05, theta0: 40 deg}
gravity: [0, 0, -9.81]
bodies:
  pipe: {shape: tube, inner_radius: a, outer_radius: 0.55, length: 2, mass: 5,
         position: [0, 0, 0.6], orientation: {axis: [1, 0, 0], angle: 90 deg}}
  ball: {shape: sphere, radius: r, mass: 0.2,
         position: ["(a - r)*sin(theta0)", 0, "0.6 - (a - r)*cos(theta0)"]}
joints:
  stand: {type: fixed, bodies: [ground, pipe], at: [0, 0, 0]}
contacts:
  - {name: in_pipe, type: bodies, bodies: [pipe, ball], friction: inf, restitution: 0}
events:
  - {name: far_side, when: ball.vx, direction: up}
  - {name: back, when: ball.vx, direction: down}
simulate: {duration: 2.5, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: 0.01}
)yaml",
                                                          "pipe");
  ASSERT_EQ(run.contact_events.size(), 1u);
  EXPECT_EQ(run.contact_events[0].what, "rolls");
  // 4 K(sin(theta0 / 2)) / w0 (K by the AGM, checked against Boost.Math in torque_free_test).
  const double half = std::sin(theta0 / 2);
  const double period = 4 * JacobiElliptic(half * half, 1 - half * half).quarter_period() *
                        std::sqrt(7 * rho / (5 * kGravityTubeCone));
  const std::vector<UserEventRecord>& ends = run.result.user_events;
  ASSERT_EQ(ends.size(), 3u);
  for (std::size_t k = 0; k < ends.size(); ++k) {
    EXPECT_EQ(ends[k].name, k % 2 == 0 ? "far_side" : "back");
    EXPECT_NEAR(ends[k].t, 0.5 * period * static_cast<double>(k + 1), 1e-9);
  }
  for (const test::Row& row : run.rows) {
    const BodyState& ball = row.states[1];
    // Across the axis, at rho from it; nothing moves it along the pipe (but round-off: the pipe's
    // axes, turned 90 degrees, hold cos(90 deg) = 6e-17).
    const Vec3 from_axis(ball.r_G.x(), 0.0, ball.r_G.z() - axis_height);
    EXPECT_NEAR(from_axis.norm(), rho, 1e-12 * rho) << row.t;
    EXPECT_NEAR(ball.r_G.y(), 0.0, 1e-12 * rho) << row.t;
    const double cos_theta = -from_axis.z() / rho;
    EXPECT_EQ(row.extras.contacts[0].mode, 2) << row.t;
    EXPECT_NEAR(ball.v_G.norm(), std::abs(ball.omega_W.y()) * r, 1e-12) << row.t;
    EXPECT_NEAR(row.extras.contacts[0].normal_force,
                m * kGravityTubeCone * (17 * cos_theta - 10 * std::cos(theta0)) / 7,
                1e-10 * m * kGravityTubeCone)
        << row.t;
    EXPECT_NEAR(row.quantities.total_energy, run.rows.front().quantities.total_energy,
                1e-11 * m * kGravityTubeCone * rho)
        << row.t;
  }
}

// A ball (r 0.05, 0.2 kg) dropped from rest with its centre at (x0, 0, 1) onto `obstacle`, fixed
// to ground, frictionless, e = 0.5: the one impact's time and the impulse the ball takes.
struct Strike {
  double t = 0.0;
  Vec3 impulse_W = Vec3::Zero();
};
Strike dropped_onto(const std::string& obstacle, double x0) {
  const test::ScenarioRun run = test::run_inline_scenario(
      "tumble: 1\n"
      "gravity: [0, 0, -9.81]\n"
      "bodies:\n"
      "  obstacle: " +
          obstacle +
          "\n"
          "  ball: {shape: sphere, radius: 0.05, mass: 0.2, position: [" +
          std::to_string(x0) +
          ", 0, 1]}\n"
          "joints:\n"
          "  stand: {type: fixed, bodies: [ground, obstacle], at: [0, 0, 0]}\n"
          "contacts:\n"
          "  - {name: hit, type: bodies, bodies: [obstacle, ball], friction: 0, restitution: "
          "0.5}\n"
          "simulate: {duration: 0.45, integrator: dop853, rtol: 1e-12, atol: 1e-14}\n",
      "drop");
  EXPECT_GE(run.contact_events.size(), 1u);
  if (run.contact_events.empty() || !run.contact_events[0].impact) return {};
  return {run.contact_events[0].t, run.contact_events[0].impact->impulse_W};
}

TEST(SphereCone, ABallDroppedOnAConesSideOrApexBouncesOffItsNormal) {
  const double R = 0.3, H = 0.4, r = 0.05, m = 0.2, e = 0.5, z0 = 1.0;
  // The cone's COM is a quarter of its height above its base, which stands on the floor.
  const std::string cone =
      "{shape: cone, radius: 0.3, height: 0.4, mass: 5, position: [0, 0, 0.1]}";
  const double slant = std::hypot(R, H), n_rho = H / slant, n_z = R / slant;
  for (const double x0 : {0.15, 0.05}) {
    const double z = (r - (x0 - R) * n_rho) / n_z;
    const double t = std::sqrt(2 * (z0 - z) / kGravityTubeCone), u = kGravityTubeCone * t;
    const Strike strike = dropped_onto(cone, x0);
    EXPECT_NEAR(strike.t, t, 1e-12) << x0;
    // v = -u z; v . n = -u n_z; the impulse m (1 + e) u n_z n.
    const Vec3 impulse = m * (1 + e) * u * n_z * Vec3(n_rho, 0.0, n_z);
    EXPECT_NEAR((strike.impulse_W - impulse).norm(), 0.0, 1e-12 * m * u) << x0;
  }
  // On the apex: straight up.
  const double t_apex = std::sqrt(2 * (z0 - H - r) / kGravityTubeCone),
               u_apex = kGravityTubeCone * t_apex;
  const Strike apex = dropped_onto(cone, 0.0);
  EXPECT_NEAR(apex.t, t_apex, 1e-12);
  EXPECT_NEAR((apex.impulse_W - Vec3(0, 0, m * (1 + e) * u_apex)).norm(), 0.0, 1e-12 * m * u_apex);
}

TEST(SphereTube, ABallDroppedOnATubesEndOrItsBoresRimBouncesOffItsNormal) {
  const double r = 0.05, m = 0.2, e = 0.5, z0 = 1.0, L = 0.4, a = 0.2, R = 0.3;
  // Upright, its top face at z = L, its bore a = 0.2, its outside R = 0.3.
  const std::string tube =
      "{shape: tube, inner_radius: 0.2, outer_radius: 0.3, length: 0.4, mass: 5, "
      "position: [0, 0, 0.2]}";
  // On the face, between the radii: straight up.
  const double t_face = std::sqrt(2 * (z0 - L - r) / kGravityTubeCone),
               u_face = kGravityTubeCone * t_face;
  const Strike face = dropped_onto(tube, 0.5 * (a + R));
  EXPECT_NEAR(face.t, t_face, 1e-12);
  EXPECT_NEAR((face.impulse_W - Vec3(0, 0, m * (1 + e) * u_face)).norm(), 0.0, 1e-12 * m * u_face);
  // Its centre 0.03 inside the bore: it meets the rim's point (a, 0, L) when that point is r
  // from its centre, along n = (x0 - a, z - L) / r.
  const double x0 = a - 0.03;
  const double z = L + std::sqrt(r * r - (x0 - a) * (x0 - a));
  const double t = std::sqrt(2 * (z0 - z) / kGravityTubeCone), u = kGravityTubeCone * t;
  const Vec3 n((x0 - a) / r, 0.0, (z - L) / r);
  const Strike rim = dropped_onto(tube, x0);
  EXPECT_NEAR(rim.t, t, 1e-12);
  EXPECT_NEAR((rim.impulse_W - m * (1 + e) * u * n.z() * n).norm(), 0.0, 1e-12 * m * u);
}

}  // namespace
}  // namespace tumble
