// Contact on bodies in joints, against closed forms:
//  - a pendulum's bob (a sphere on a hinge) swings down and strikes a frictionless wall where the
//    pendulum hangs vertically: it rebounds with e times the angular speed it struck with, so the
//    energy left is the bottom's potential energy plus e^2 of the kinetic energy at the strike.
//    The contact's three velocity rows are one freedom of the hinge: the solve takes them as
//    redundant, and the impact slides (no impulse both bounces it and stops its slip);
//  - a cylinder rolling on the ground with a rod hung on its axle: the linearised equations in x
//    (the axle's travel) and phi (the rod's angle) are
//        (M + I/R^2 + m) x'' + m l phi'' = 0,   (I_p + m l^2) phi'' + m l x'' + m g l phi = 0,
//    (the rolling adds I/R^2 to the cylinder's mass), so the rod swings at
//        omega^2 = m g l / (I_p + m l^2 - (m l)^2 / (M + I/R^2 + m)).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "scenario_run.hpp"

namespace tumble {
namespace {

using test::Row;
using test::run_inline_scenario;

constexpr double kG = 9.81;

TEST(ContactOnAJointedBody, APendulumStrikingAWallReboundsWithEOfItsAngularSpeed) {
  const double r = 0.05, l = 0.5, m = 1.0, a = 60 * M_PI / 180;
  for (const double e : {0.3, 0.6, 1.0}) {
    const auto run = run_inline_scenario(fmt::format(R"(tumble: 1
parameters: {{r: {}, l: {}, m: {}, rest: {}, a: {}}}
gravity: [0, 0, -{}]
bodies:
  bob:
    shape: sphere
    radius: r
    mass: m
    position: [-l*sin(a), 0, l - l*cos(a)]
joints:
  pivot: {{type: hinge, body: bob, at: [0, 0, l], axis: [0, 1, 0]}}
contacts:
  - {{name: wall, type: plane, body: bob, plane: {{point: [r, 0, 0], normal: [-1, 0, 0]}},
     friction: 0, restitution: rest}}
simulate: {{duration: 0.7, integrator: dop853, rtol: 1e-11, atol: 1e-13, output_every: 0.002}}
)",
                                                     r, l, m, e, a, kG),
                                         "pendulum_wall");
    ASSERT_GE(run.contact_events.size(), 1u);
    EXPECT_NE(run.contact_events[0].what.find("impact"), std::string::npos)
        << run.contact_events[0].what;
    const double t_strike = run.contact_events[0].t;
    // The energy at the strike is all kinetic above the bottom's potential energy.
    const double E0 = run.rows.front().quantities.total_energy;
    const double PE_bottom = 0.0;  // the bob's COM at z = 0 when it hangs vertically
    const double E_after = PE_bottom + e * e * (E0 - PE_bottom);
    const double E_scale = m * kG * l;
    for (const Row& row : run.rows) {
      const BodyState& bob = row.states[0];
      EXPECT_LE(bob.r_G.x(), 1e-12) << "the bob is through the wall at t " << row.t;
      if (row.t < t_strike) {
        EXPECT_NEAR(row.quantities.total_energy, E0, 1e-9 * E_scale);
      } else if (row.t > t_strike && row.t < t_strike + 0.2) {
        // Swinging back (not yet at the wall again): e of the angular speed, e^2 of the KE.
        EXPECT_NEAR(row.quantities.total_energy, E_after, 1e-9 * E_scale) << "e " << e;
        EXPECT_LT(bob.v_G.x(), 0.0);
      }
    }
  }
}

TEST(ContactOnAJointedBody, ARodHungOnARollingCylindersAxleSwingsAtTheLinearisedFrequency) {
  const double R = 0.1, M = 2.0, m = 0.5, L = 0.4, rod_r = 0.005, a = 1e-3;
  const auto run = run_inline_scenario(fmt::format(R"(tumble: 1
parameters: {{R: {}, M: {}, m: {}, L: {}, a: {}}}
gravity: [0, 0, -{}]
bodies:
  drum:
    shape: cylinder
    radius: R
    length: 0.2
    mass: M
    position: [0, 0, R]
    orientation: {{axis: [1, 0, 0], angle: 90 deg}}
  rod:
    shape: cylinder
    radius: {}
    length: L
    mass: m
    position: [L/2*sin(a), 0, R - L/2*cos(a)]
    orientation: {{axis: [0, 1, 0], angle: -a}}
joints:
  axle: {{type: hinge, bodies: [drum, rod], at: [0, 0, R], axis: [0, 1, 0]}}
contacts:
  - {{name: floor, type: plane, body: drum, plane: {{point: [0, 0, 0], normal: [0, 0, 1]}},
     friction: 1}}
simulate: {{duration: 6, integrator: dop853, rtol: 1e-11, atol: 1e-14, output_every: 0.002}}
)",
                                                   R, M, m, L, a, kG, rod_r),
                                       "drum_pendulum");
  const double l = L / 2, I_p = m * (3 * rod_r * rod_r + L * L) / 12, I = M * R * R / 2;
  const double M_rolling = M + I / (R * R) + m;
  const double omega = std::sqrt(m * kG * l / (I_p + m * l * l - m * m * l * l / M_rolling));
  std::vector<double> t, phi, rate;
  for (const Row& row : run.rows) {
    const BodyState& drum = row.states[0];
    const BodyState& rod = row.states[1];
    t.push_back(row.t);
    // The rod's angle from hanging straight down, positive swinging towards +x: -(turn about y).
    phi.push_back(std::atan2(rod.r_G.x() - drum.r_G.x(), drum.r_G.z() - rod.r_G.z()));
    rate.push_back(-rod.omega_W.y());
    // Rolling without slip, on its side, the whole time.
    EXPECT_EQ(row.extras.contacts[0].mode, 2);
    EXPECT_LT(row.extras.contacts[0].slip_speed, 1e-12);
    EXPECT_NEAR(drum.r_G.z(), R, 1e-13);
    EXPECT_NEAR(drum.v_G.x(), drum.omega_W.y() * R, 1e-13);  // the contact point at rest
  }
  const std::vector<double> up = test::upward_zero_crossings(t, phi, rate);
  ASSERT_GE(up.size(), 5u);
  const double period = (up.back() - up.front()) / static_cast<double>(up.size() - 1);
  // The amplitude's own correction to the period is a^2 / 16 = 6e-8 of it.
  EXPECT_NEAR(period, 2 * M_PI / omega, 1e-6 * period);
}

}  // namespace
}  // namespace tumble
