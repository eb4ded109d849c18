// A box (and a plate, and a cube given as a mesh) on a plane: at rest below the friction angle,
// sliding above it with the exact acceleration, sliding to rest, spinning down under torsional
// friction, tipping over an edge past the tipping angle, and dropped onto a corner: impacts that
// never add energy, ending at rest on a face. Every run asks rtol 1e-10 (see contact_test.cpp
// for what that buys); motion that is a polynomial of degree 2 in t is checked at 1e-10
// relative, held positions at 1e-12 m (the integrated round-off of a zero acceleration).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "scenario_run.hpp"
#include "test_constants.hpp"

namespace tumble {
namespace {

using test::kDeg;
using test::kG;
using test::Row;
using test::run_inline_scenario;
constexpr double kBoxMass = 2.0;

// A body of the given shape keys on a ramp of slope theta descending towards +x, resting on its
// face whose COM height is `half_height`, at rest or sliding down at v0.
std::string crate_on_ramp(const std::string& shape, double half_height, double theta, double mu,
                          double duration, double v0 = 0.0) {
  return fmt::format(
      "tumble: 1\n"
      "parameters: {{theta: {}, h: {}}}\n"
      "bodies:\n"
      "  crate: {{{}, mass: {}, position: [h * sin(theta), 0, h * cos(theta)],\n"
      "           orientation: {{axis: [0, 1, 0], angle: theta}},\n"
      "           velocity: [{} * cos(theta), 0, -{} * sin(theta)]}}\n"
      "contacts:\n"
      "  - {{name: ramp, type: plane, body: crate, plane: {{point: [0, 0, 0],\n"
      "      normal: [sin(theta), 0, cos(theta)]}}, friction: {}}}\n"
      "simulate: {{duration: {}, integrator: dop853, rtol: 1e-10, atol: 1e-13, "
      "output_every: {}}}\n",
      theta, half_height, shape, kBoxMass, v0, v0, mu, duration, duration / 50);
}

struct Solid {
  const char* name;
  const char* shape;
  double half_height;  // of the COM over the face it rests on
};
const Solid kSolids[] = {
    {"box", "shape: box, size: [0.4, 0.3, 0.2]", 0.1},
    {"tall box", "shape: box, size: [0.4, 0.3, 0.5]", 0.25},
    {"plate", "shape: plate, size: [0.4, 0.3]", 0.0},
    {"mesh cube", "shape: mesh, file: " TUMBLE_TEST_DATA_DIR "/meshes/unit_cube.obj", 0.5},
};

TEST(BoxOnRamp, BelowTheFrictionAngleItStaysAtRestFor100Seconds) {
  for (const Solid& solid : kSolids) {
    for (const double theta : {10 * kDeg, 30 * kDeg}) {
      const double mu = 1.05 * std::tan(theta);
      const auto run = run_inline_scenario(
          crate_on_ramp(solid.shape, solid.half_height, theta, mu, 100), "box_at_rest");
      const Vec3 r0 = run.rows.front().states[0].r_G;
      for (const Row& row : run.rows) {
        EXPECT_LT((row.states[0].r_G - r0).norm(), 1e-12) << solid.name << " t " << row.t;
        EXPECT_LT(row.states[0].v_G.norm() + row.states[0].omega_W.norm(), 1e-12) << solid.name;
        const ContactOutput& c = row.extras.contacts[0];
        EXPECT_EQ(c.mode, 2) << solid.name;
        EXPECT_NEAR(c.normal_force, kBoxMass * kG * std::cos(theta), 1e-12 * kBoxMass * kG);
        EXPECT_NEAR(c.friction_W.norm(), kBoxMass * kG * std::sin(theta), 1e-12 * kBoxMass * kG);
      }
      ASSERT_EQ(run.contact_events.size(), 1u) << solid.name;
      EXPECT_EQ(run.contact_events[0].what, "sticks on a face");
    }
  }
}

TEST(BoxOnRamp, AboveTheFrictionAngleItSlidesWithTheExactAcceleration) {
  // a = g (sin - mu cos) down the slope, N = M g cos, no turning; from rest, and already sliding.
  for (const Solid& solid : kSolids) {
    for (const double theta : {20 * kDeg, 40 * kDeg}) {
      for (const double v0 : {0.0, 1.5}) {
        const double mu = 0.9 * std::tan(theta);
        const double a = kG * (std::sin(theta) - mu * std::cos(theta));
        const auto run = run_inline_scenario(
            crate_on_ramp(solid.shape, solid.half_height, theta, mu, 2, v0), "box_slides");
        const Vec3 r0 = run.rows.front().states[0].r_G;
        const Vec3 down(std::cos(theta), 0, -std::sin(theta));
        for (const Row& row : run.rows) {
          const double s = v0 * row.t + 0.5 * a * row.t * row.t;
          EXPECT_NEAR((row.states[0].r_G - r0).dot(down), s, 1e-10 * (1 + s)) << solid.name;
          EXPECT_NEAR(row.states[0].v_G.dot(down), v0 + a * row.t, 1e-10 * (1 + v0 + a * row.t));
          EXPECT_LT(row.states[0].omega_W.norm(), 1e-10) << solid.name;
          EXPECT_EQ(row.extras.contacts[0].mode, 1) << solid.name;
          EXPECT_NEAR(row.extras.contacts[0].normal_force, kBoxMass * kG * std::cos(theta),
                      1e-10 * kBoxMass * kG);
        }
      }
    }
  }
}

// A box sliding on level ground at (vx, vy).
std::string floor_scenario(const std::string& shape, double half_height, double mu, Vec3 v0,
                           Vec3 omega0, double duration) {
  return fmt::format(
      "tumble: 1\n"
      "bodies:\n"
      "  crate: {{{}, mass: {}, position: [0, 0, {}], velocity: [{}, {}, 0],\n"
      "           angular_velocity: [{}, {}, {}]}}\n"
      "contacts:\n"
      "  - {{name: floor, type: plane, body: crate, plane: {{point: [0, 0, 0], normal: [0, 0, 1]}},"
      " friction: {}}}\n"
      "simulate: {{duration: {}, integrator: dop853, rtol: 1e-10, atol: 1e-13, "
      "output_every: {}}}\n",
      shape, kBoxMass, half_height, v0.x(), v0.y(), omega0.x(), omega0.y(), omega0.z(), mu,
      duration, duration / 100);
}

TEST(BoxOnFloor, ItSlidesToRestAtTheLocatedTimeAndDistance) {
  // Friction mu M g against the motion: it stops at t = v0 / (mu g) after v0^2 / (2 mu g), the
  // friction's work is -M v0^2 / 2, and it stays there; no step is rejected (below).
  for (const Solid& solid : kSolids) {
    for (const Vec3& v0 : {Vec3(3, 0, 0), Vec3(1, -2, 0)}) {
      const double mu = 0.3;
      const double speed = v0.norm();
      const double t_stop = speed / (mu * kG);
      const auto run = run_inline_scenario(
          floor_scenario(solid.shape, solid.half_height, mu, v0, Vec3::Zero(), 1.5 * t_stop),
          "box_slides_to_rest");
      ASSERT_EQ(run.contact_events.size(), 3u) << solid.name;
      // Its motion is a quadratic in t to the stop, and runs on as one through it (a stage past
      // the stop keeps the friction's direction, the slip-stop event finds the stop): dop853 is
      // exact on it, and rejects no step. (When a stage past the stop took the reversed slip's
      // direction, the steps that reached it were rejected, twenty times, down to 2e-8 s.)
      EXPECT_EQ(run.result.report.stats.rejected_steps, 0) << solid.name;
      EXPECT_EQ(run.contact_events[1].what, "slip stops");
      EXPECT_NEAR(run.contact_events[1].t, t_stop, 1e-9 * t_stop) << solid.name;
      EXPECT_EQ(run.contact_events[2].what, "sticks on a face");
      const Vec3 r0 = run.rows.front().states[0].r_G;
      for (const Row& row : run.rows) {
        const double t = std::min(row.t, t_stop);
        const double s = speed * t - 0.5 * mu * kG * t * t;
        EXPECT_LT((row.states[0].r_G - r0 - s * v0 / speed).norm(), 1e-10) << solid.name;
      }
      const Row& end = run.rows.back();
      EXPECT_LT(end.states[0].v_G.norm(), 1e-12) << solid.name;
      EXPECT_NEAR(end.extras.elements.back().work, -0.5 * kBoxMass * speed * speed,
                  1e-10 * kBoxMass * speed * speed);
    }
  }
}

TEST(BoxOnFloor, ASpinningSquareFaceStopsUnderTorsionalFriction) {
  // A cube spinning about the vertical on its face: the friction moment mu M g rho, rho the mean
  // distance from the face's centre (uniform pressure; (sqrt 2 + asinh 1) / 3 times the
  // half-side), turns it down uniformly: it stops at I w0 / (mu M g rho) with I = M a^2 / 6.
  for (const double side : {0.2, 0.5}) {
    for (const double w0 : {4.0, 10.0}) {
      const double mu = 0.4;
      const double rho = 0.5 * side * (std::sqrt(2.0) + std::asinh(1.0)) / 3;
      const double I = kBoxMass * side * side / 6;
      const double t_stop = I * w0 / (mu * kBoxMass * kG * rho);
      const auto run = run_inline_scenario(
          floor_scenario(fmt::format("shape: box, size: [{0}, {0}, {0}]", side), side / 2, mu,
                         Vec3::Zero(), Vec3(0, 0, w0), 1.5 * t_stop),
          "box_spins_down");
      ASSERT_EQ(run.contact_events.size(), 3u);
      EXPECT_NEAR(run.contact_events[1].t, t_stop, 1e-9 * t_stop);
      for (const Row& row : run.rows) {
        const double w = std::max(0.0, w0 - w0 * row.t / t_stop);
        EXPECT_NEAR(row.states[0].omega_W.z(), w, 1e-9 * w0) << "t " << row.t;
        EXPECT_LT(row.states[0].r_G.head<2>().norm(), 1e-12);
      }
    }
  }
}

TEST(BoxOnRamp, PastTheTippingAngleItPivotsOnItsLowerEdge) {
  // With friction enough to hold it, a box of base a (along the slope) and height c tips iff
  // tan(theta) > a / c: its weight's line leaves the base. Below: it stays. Above: it turns about
  // the lower edge, which stays put, so E is conserved until the box lands on its next face.
  const double a = 0.2, c = 0.6;
  const double theta_tip = std::atan(a / c);
  for (const double factor : {0.98, 1.02}) {
    const double theta = factor * theta_tip;
    const auto run = run_inline_scenario(
        crate_on_ramp(fmt::format("shape: box, size: [{}, 0.3, {}]", a, c), c / 2, theta, 1.5, 0.5),
        "box_tips");
    ASSERT_GE(run.contact_events.size(), 1u);
    if (factor < 1) {
      ASSERT_EQ(run.contact_events.size(), 1u);
      EXPECT_EQ(run.contact_events[0].what, "sticks on a face");
      EXPECT_LT(run.rows.back().states[0].omega_W.norm(), 1e-12);
      continue;
    }
    EXPECT_EQ(run.contact_events[0].what, "sticks on an edge");
    const double E0 = run.rows.front().quantities.total_energy;
    const double t_next = run.contact_events.size() > 1 ? run.contact_events[1].t : 1e300;
    for (const Row& row : run.rows) {
      if (row.t >= t_next) break;
      EXPECT_NEAR(row.quantities.total_energy, E0, 1e-9 * std::abs(E0)) << "t " << row.t;
      EXPECT_NEAR(row.extras.contacts[0].slip_speed, 0.0, 1e-12);
    }
    EXPECT_GT(run.rows.back().states[0].omega_W.norm(), 0.1);
  }
}

TEST(BoxDropped, ImpactsNeverAddEnergyAndItComesToRestOnAFace) {
  for (const double e : {0.0, 0.5}) {
    for (const double mu : {0.2, 0.8}) {
      for (const double tilt : {5.0, 40.0}) {
        const std::string yaml = fmt::format(
            "tumble: 1\n"
            "bodies:\n"
            "  crate: {{shape: box, size: [0.4, 0.3, 0.2], mass: {}, position: [0, 0, 0.6],\n"
            "           orientation: {{axis: [1, 1, 0.3], angle: {} deg}},\n"
            "           velocity: [0.5, 0, 0], angular_velocity: [0, 1, 2]}}\n"
            "contacts:\n"
            "  - {{name: floor, type: plane, body: crate, plane: {{point: [0, 0, 0], normal: [0, "
            "0, "
            "1]}}, friction: {}, restitution: {}}}\n"
            "simulate: {{duration: 4, integrator: dop853, rtol: 1e-10, atol: 1e-13, "
            "output_every: 0.01}}\n",
            kBoxMass, tilt, mu, e);
        const auto run = run_inline_scenario(yaml, "box_dropped");
        test::expect_energy_never_rises(run, 1e-8);
        const Row& end = run.rows.back();
        EXPECT_LT(end.states[0].v_G.norm() + end.states[0].omega_W.norm(), 1e-9);
        EXPECT_EQ(end.extras.contacts[0].mode, 2);
        EXPECT_NEAR(end.extras.contacts[0].normal_force, kBoxMass * kG, 1e-9 * kBoxMass * kG);
        const double z = end.states[0].r_G.z();
        const double nearest = std::min({std::abs(z - 0.2), std::abs(z - 0.15), std::abs(z - 0.1)});
        EXPECT_LT(nearest, 1e-12) << "z " << z;
        // Its last event lands it on a face (settling) or sticks it there.
        EXPECT_NE(run.contact_events.back().what.find("on a face"), std::string::npos);
      }
    }
  }
}

TEST(BoxDropped, SpinningAndBouncingOnARampItComesToRestOnItsLargestFace) {
  // Spinning at 15 rad/s, bouncing (e 0.6) on a 5.7 degree ramp with mu 1 (above tan 5.7): its
  // stages once blew up while it slid on a vertex, which must shorten the step, not end the run.
  // It ends at rest on its largest face, COM half its thickness above the ramp, energy never
  // gained.
  const std::string yaml =
      "tumble: 1\n"
      "bodies:\n"
      "  b: {shape: box, size: [0.1, 0.06, 0.03], mass: 0.3, position: [0, 0, 0.2],\n"
      "      orientation: {axis: [1, 0.4, 0], angle: 25 deg}, velocity: [0.3, 0, 0],\n"
      "      angular_velocity: [0, 4.5, 15]}\n"
      "contacts:\n"
      "  - {name: floor, type: plane, body: b, plane: {point: [0, 0, 0], normal: [0.1, 0, 1]},\n"
      "     friction: 1, restitution: 0.6}\n"
      "simulate: {duration: 2, integrator: dop853, rtol: 1e-8, atol: 1e-11, output_every: 0.02}\n";
  const auto run = run_inline_scenario(yaml, "spinning_box");
  test::expect_energy_never_rises(run, 1e-8);
  const Row& end = run.rows.back();
  const Vec3 n = Vec3(0.1, 0, 1).normalized();
  EXPECT_EQ(end.extras.contacts[0].mode, 2);
  EXPECT_NEAR(end.states[0].r_G.dot(n), 0.015, 1e-10);
  EXPECT_LT(end.states[0].v_G.norm() + 0.1 * end.states[0].omega_W.norm(), 1e-10);
  EXPECT_NEAR(end.extras.contacts[0].normal_force, 0.3 * kG * n.z(), 1e-8 * 0.3 * kG);
}

}  // namespace
}  // namespace tumble
