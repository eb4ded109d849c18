#pragma once
// Checks shared by the tests of bodies standing or sliding on a face on a ramp of slope theta
// that descends towards +x (normal (sin theta, 0, cos theta)), gravity 9.81 m/s^2 down -z.
#include <gtest/gtest.h>

#include <cmath>

#include "scenario_run.hpp"

namespace tumble::test {

// Every row at rest where it started (within 1e-12 m, speeds 1e-12), N = M g cos(theta) to 1e-12
// of M g: sticking is a constraint, and the anchor keeps round-off from walking it away.
inline void expect_at_rest_on_ramp(const ScenarioRun& run, double mass, double theta) {
  const double weight = mass * 9.81;
  const Vec3 r0 = run.rows.front().states[0].r_G;
  for (const Row& row : run.rows) {
    EXPECT_LT((row.states[0].r_G - r0).norm(), 1e-12) << "t " << row.t;
    EXPECT_LT(row.states[0].v_G.norm() + row.states[0].omega_W.norm(), 1e-12) << "t " << row.t;
    EXPECT_NEAR(row.extras.contacts[0].normal_force, weight * std::cos(theta), 1e-12 * weight);
  }
}

// Sliding straight down from rest at a = g (sin - mu cos): s = a t^2 / 2 to 1e-10 (1 + s), not
// turning (1e-10 rad/s), N = M g cos(theta) to 1e-10 of M g.
inline void expect_sliding_down_ramp(const ScenarioRun& run, double mass, double theta, double a) {
  const double weight = mass * 9.81;
  const Vec3 r0 = run.rows.front().states[0].r_G;
  const Vec3 down(std::cos(theta), 0, -std::sin(theta));
  for (const Row& row : run.rows) {
    const double s = 0.5 * a * row.t * row.t;
    EXPECT_NEAR((row.states[0].r_G - r0).dot(down), s, 1e-10 * (1 + s)) << "t " << row.t;
    EXPECT_LT(row.states[0].omega_W.norm(), 1e-10) << "t " << row.t;
    EXPECT_NEAR(row.extras.contacts[0].normal_force, weight * std::cos(theta), 1e-10 * weight);
  }
}

}  // namespace tumble::test
