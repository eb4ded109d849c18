// A sliding contact is stiff where its slip is small: Coulomb's friction -mu N s/|s| turns with
// the slip's direction, and a slip across it of speed u is pulled back at the rate
// mu N / (m |s|), which no explicit method can take steps past. A ring sliding down a ramp just
// below its critical friction (equations.md, 2: mu_crit = tan(theta) / 2 for a ring) has such a
// slip, growing from none at g sin(theta) (1 - mu / mu_crit) t: DOP853 needs two million steps
// over 1.5 s. `integrator: auto` finds it stiff and hands it to radau5, whose Jacobian now
// carries the contacts in their modes (modes/state_jacobian.hpp; contact/contact_hold.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "jacobian_checks.hpp"
#include "scenario_run.hpp"
#include "test_constants.hpp"

namespace tumble {
namespace {

using test::kG;

// A ring of radius R on a ramp of slope theta (the plane z = -x tan(theta), descending towards
// +x), started at rest with its axis across the slope, friction `below` under its critical value
// (mu = (1 - below) tan(theta) / 2), run by `auto` at `rtol`.
std::string ring_on_ramp(double below, double rtol) {
  return fmt::format(R"(tumble: 1
parameters: {{theta: 30 deg, R: 0.1, below: {:.17g}, mu: (1 - below) * tan(theta) / 2}}
gravity: [0, 0, -{:.17g}]
bodies:
  ring:
    {{shape: ring, radius: R, mass: 1, position: [R*sin(theta), 0, R*cos(theta)],
     orientation: {{axis: [1, 0, 0], angle: 90 deg}}}}
contacts:
  - {{name: ramp, type: plane, body: ring, friction: mu,
     plane: {{point: [0, 0, 0], normal: [sin(theta), 0, cos(theta)]}}}}
simulate:
  {{duration: 1.5, integrator: auto, rtol: {}, atol: 1e-12, output_every: 0.01}}
)",
                     below, kG, rtol);
}

// A ring sliding down the ramp and across it, not turning, its slip small (the friction's
// direction turns at 4e6 1/s per unit of slip speed across it), and a ball at rest beside it,
// rolling from rest, on a ramp of 30 degrees.
const char* const kSlidingAndRolling = R"(tumble: 1
parameters: {theta: 30 deg, R: 0.1, s: 1e-5}
gravity: [0, 0, -9.81]
bodies:
  ring:
    {shape: ring, radius: R, mass: 1, position: [R*sin(theta), 0, R*cos(theta)],
     orientation: {axis: [1, 0, 0], angle: 90 deg}, velocity: [s*cos(theta), 0.3*s, -s*sin(theta)]}
  ball: {shape: sphere, radius: R, mass: 2, position: [R*sin(theta), 0.5, R*cos(theta)]}
contacts:
  - {name: ramp, type: plane, body: ring, friction: 0.28,
     plane: {point: [0, 0, 0], normal: [sin(theta), 0, cos(theta)]}}
  - {name: ramp2, type: plane, body: ball, friction: 0.5,
     plane: {point: [0, 0, 0], normal: [sin(theta), 0, cos(theta)]}}
simulate: {duration: 1, integrator: auto}
)";

TEST(StiffContact, TheJacobianIsTheRunsOwnWithContactsInTheirModes) {
  // Along the speeds (jacobian_checks.hpp says why those), a sliding contact's friction turning
  // with its slip and a rolling one's three rows: central differences of the run's equations,
  // with steps of 1e-11 m/s against a slip of 1e-5 m/s (truncation ~ (1e-6)^2 of the entries),
  // agree with the exact derivative to about 1e-9 of the largest entry.
  EXPECT_LT(test::largest_jacobian_departure(kSlidingAndRolling, "sliding_and_rolling",
                                             test::JacobianColumns::Speeds, 1e-11),
            1e-7);
}

TEST(StiffContact, ARingJustBelowItsCriticalFrictionSlidesAsTheClosedFormInUnderTwoThousandSteps) {
  const double below = 1e-6, theta = M_PI / 6, R = 0.1, rtol = 1e-9;
  const double mu = (1 - below) * std::tan(theta) / 2;
  const test::ScenarioRun run = test::run_inline_scenario(ring_on_ramp(below, rtol), "ring");
  ASSERT_EQ(run.rows.size(), 151u);
  // Down the slope, d, and the plane's normal, n.
  const Vec3 d(std::cos(theta), 0, -std::sin(theta)), n(std::sin(theta), 0, std::cos(theta));
  // Sliding throughout: the COM's acceleration g (sin - mu cos) along d, the ring's turning
  // mu g cos R / (m R^2) (I = m R^2), so the slip of its point at the ramp grows at
  // g sin(theta) below.
  double worst_slip = 0.0, worst_across = 0.0, worst_speed = 0.0;
  for (const test::Row& row : run.rows) {
    const BodyState& ring = row.states[0];
    const Vec3 slip = ring.v_G + ring.omega_W.cross(-R * n);
    worst_slip = std::max(worst_slip, std::abs(slip.dot(d) - kG * std::sin(theta) * below * row.t));
    worst_across = std::max(worst_across, std::abs(slip.y()));
    const double speed = kG * (std::sin(theta) - mu * std::cos(theta)) * row.t;
    worst_speed = std::max(worst_speed, std::abs(ring.v_G.dot(d) - speed));
  }
  // The speeds are held to rtol of themselves (3.7 m/s at the end), and the slip is the
  // difference of two of them: 7.4e-9 m/s at most, against a slip of 7.4e-6 m/s at the end.
  // (Measured: 9e-10 m/s; at rtol 1e-10, 2,693 steps and 1.5e-10 m/s.)
  const double v_end = kG * (std::sin(theta) - mu * std::cos(theta)) * 1.5;
  EXPECT_LT(worst_speed, rtol * v_end);
  EXPECT_LT(worst_slip, 2 * rtol * v_end);
  EXPECT_LT(worst_across, rtol * v_end);
  // DOP853 takes 2,076,683 steps: stability, not accuracy, holds them. (Measured: 1,704.)
  EXPECT_LT(run.result.report.stats.accepted_steps, 2000);
}

}  // namespace
}  // namespace tumble
