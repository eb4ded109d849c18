// Contact on bodies in joints, against closed forms:
//  - a pendulum's bob (a sphere on a hinge, or a disk in the hinge's plane striking with its rim)
//    swings down and strikes a frictionless wall where the pendulum hangs vertically: it rebounds
//    with e times the angular speed it struck with, so the energy left is the bottom's potential
//    energy plus e^2 of the kinetic energy at the strike. The contact's three velocity rows are
//    one freedom of the hinge: the solve takes them as redundant, and the impact slides (no
//    impulse both bounces it and stops its slip);
//  - a cylinder rolling on the ground with a rod hung on its axle: the linearised equations in x
//    (the axle's travel) and phi (the rod's angle) are
//        (M + I/R^2 + m) x'' + m l phi'' = 0,   (I_p + m l^2) phi'' + m l x'' + m g l phi = 0,
//    (the rolling adds I/R^2 to the cylinder's mass), so the rod swings at
//        omega^2 = m g l / (I_p + m l^2 - (m l)^2 / (M + I/R^2 + m));
//  - the chapter's Cubli (equations.md, 6) started on the ground: its frame (a box with the four
//    rods' inertia) lies on its face, hinged at the edge through O, with the wheel spinning at
//    w0 below w0_crit. The brake hands the frame Omega = m R^2 w0 / I_total about O, it rises to
//    where (M + m) g (L/sqrt(2)) (sin phi_max - sin 45 deg) = I_total Omega^2 / 2, falls back and
//    lands on its face at t_lock + 2 T, T = the integral of dphi / phi' from 45 deg to phi_max,
//    at Omega again (energy); it rebounds at e Omega, and with e = 0 lies still on its face with
//    the plane pushing (M + m) g / 2 at the far edge (moments about O);
//  - a ball joint's bob (a sphere, its centre p from the pivot) resting on a floor of normal n in
//    the plane of p and z: the floor's contact rows are redundant with the joint (the joint
//    carries any force along the line from the pivot to the contact point), and of the forces that
//    hold it the one without friction does, the floor pushing N = m g / (n_z - n_x p_z / p_x)
//    (moments about the pivot: p x (N n - m g z) = 0) and the joint carrying m g z - N n: on a
//    level floor N = m g and the joint nothing. It rests there from the start, sticking, with no
//    event after the first (before, the least-norm force needed friction outside the cone, and
//    the bob landed and went apart every 2e-10 s).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "tumble/math/types.hpp"

namespace tumble {
namespace {

using test::Row;
using test::run_inline_scenario;

using test::kG;

TEST(ContactOnAJointedBody, APendulumStrikingAWallReboundsWithEOfItsAngularSpeed) {
  const double r = 0.05, l = 0.5, m = 1.0, a = 60 * M_PI / 180;
  struct Bob {
    const char* shape;   // the bob's shape and orientation, as the scenario writes them
    const char* impact;  // how its impact begins in the events
  };
  // A disk turned into the hinge's plane (x-z) strikes with the point of its rim level with its
  // centre: a round body on a held body.
  const Bob bobs[] = {
      {"sphere", "impact"},
      {"disk\n    orientation: {axis: [1, 0, 0], angle: 90 deg}", "impact on its rim"}};
  for (const Bob& kind : bobs) {
    for (const double e : {0.3, 0.6, 1.0}) {
      const auto run = run_inline_scenario(fmt::format(R"(tumble: 1
parameters: {{r: {}, l: {}, m: {}, rest: {}, a: {}}}
gravity: [0, 0, -{}]
bodies:
  bob:
    shape: {}
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
                                                       r, l, m, e, a, kG, kind.shape),
                                           "pendulum_wall");
      ASSERT_GE(run.contact_events.size(), 1u);
      EXPECT_EQ(run.contact_events[0].what.rfind(kind.impact, 0), 0u) << run.contact_events[0].what;
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
          EXPECT_NEAR(row.quantities.total_energy, E_after, 1e-9 * E_scale)
              << kind.shape << ", e " << e;
          EXPECT_LT(bob.v_G.x(), 0.0);
        }
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

// The Cubli's frame on the ground: a box on a hinge, on a plane (a held polyhedron).
std::string cubli_on_the_ground(double w0_fraction, double e) {
  return fmt::format(R"(tumble: 1
parameters:
  M: 0.8
  m: 0.3
  L: 0.15
  w: 0.02
  R: 0.06
  g: {}
  I_total: M*L^2/3 + (M + m)*L^2/2 + m*R^2
  w0_crit: sqrt((sqrt(2) - 1)*(M + m)*g*L*I_total)/(m*R^2)
  w0: {}*w0_crit
gravity: [0, 0, -g]
bodies:
  frame:
    shape: box
    size: [L, w, L]
    mass: M
    inertia: [M*L^2/6, M*L^2/3, M*L^2/6]
    position: [L/2, 0, L/2]
  wheel:
    shape: ring
    radius: R
    mass: m
    position: [L/2, 0, L/2]
    orientation: {{axis: [1, 0, 0], angle: 90 deg}}
    angular_velocity: [0, -w0, 0]
joints:
  corner: {{type: hinge, body: frame, at: [0, 0, 0], axis: [0, 1, 0]}}
  axle: {{type: hinge, bodies: [frame, wheel], at: [L/2, 0, L/2], axis: [0, 1, 0],
          lock: {{at: 0.001}}}}
contacts:
  - {{name: floor, type: plane, body: frame, plane: {{point: [0, 0, 0], normal: [0, 0, 1]}},
     friction: 0.5, restitution: {}}}
simulate: {{duration: 1.2, integrator: dop853, rtol: 1e-11, atol: 1e-14, output_every: 0.001}}
)",
                     kG, w0_fraction, e);
}

TEST(ContactOnAJointedBody, TheCubliStartedOnTheGroundFallsBackAndLandsOnItsFace) {
  const double M = 0.8, m = 0.3, L = 0.15, R = 0.06, t_lock = 0.001;
  const double I_total = M * L * L / 3 + (M + m) * L * L / 2 + m * R * R;
  const double w0_crit = std::sqrt((std::sqrt(2.0) - 1) * (M + m) * kG * L * I_total) / (m * R * R);
  const double w0 = 0.9 * w0_crit;
  const double Omega = m * R * R * w0 / I_total;
  // The centre's angle phi about O (45 deg on the ground): phi'^2 = Omega^2 - (2 (M + m) g d /
  // I_total) (sin phi - sin 45 deg), d = L/sqrt(2) from O to the centre.
  const double d = L / std::sqrt(2.0), phi0 = M_PI / 4;
  const double k = 2 * (M + m) * kG * d / I_total;
  const double phi_max = std::asin(std::sin(phi0) + Omega * Omega / k);
  // The time to rise, with phi = phi_max - s^2 (the integrand 2 s / phi' stays finite), by
  // Simpson's rule: its error at 4000 intervals is far below the 1e-9 asked.
  const auto rate = [&](double phi) {
    return std::sqrt(std::max(0.0, Omega * Omega - k * (std::sin(phi) - std::sin(phi0))));
  };
  const double s_end = std::sqrt(phi_max - phi0);
  const int n = 4000;
  const auto integrand = [&](double s) {
    if (s == 0.0) return 2.0 / std::sqrt(k * std::cos(phi_max));  // the limit of 2 s / phi'
    return 2.0 * s / rate(phi_max - s * s);
  };
  double rise = integrand(0.0) + integrand(s_end);
  for (int i = 1; i < n; ++i) rise += (i % 2 == 1 ? 4.0 : 2.0) * integrand(s_end * i / n);
  rise *= s_end / (3.0 * n);
  const double t_land = t_lock + 2 * rise;

  for (const double e : {0.0, 0.5}) {
    const auto run = run_inline_scenario(cubli_on_the_ground(0.9, e), "cubli_ground");
    const auto& events = run.contact_events;
    ASSERT_GE(events.size(), 3u) << "e " << e;
    EXPECT_EQ(events[0].what, "sticks on a face");
    EXPECT_EQ(events[1].t, t_lock);
    EXPECT_EQ(events[1].what, "apart");  // thrown up by the brake: only the hinge's edge stays
    EXPECT_NEAR(events[2].t, t_land, 1e-9 * t_land) << events[2].what;
    EXPECT_NE(events[2].what.find("on a face"), std::string::npos) << events[2].what;
    const double E_flight = run.rows.front().quantities.potential_energy +
                            0.5 * I_total * Omega * Omega;  // after the lock
    const double E_scale = (M + m) * kG * L;
    double highest = 0.0;
    for (const Row& row : run.rows) {
      const BodyState& frame = row.states[0];
      const double phi = std::atan2(frame.r_G.z(), frame.r_G.x());
      // No corner of the frame below the floor: the lowest is the one off the hinge, at
      // phi - 45 deg below the x axis when phi < 45 deg.
      EXPECT_GE(phi, phi0 - 1e-9) << "the frame is through the floor at t " << row.t;
      highest = std::max(highest, phi);
      const double N = row.extras.contacts[0].normal_force;
      if (row.t < t_lock) {
        // On its face, the plane at the far edge carries half the weight (moments about O).
        EXPECT_NEAR(phi, phi0, 1e-12);
        EXPECT_NEAR(N, (M + m) * kG / 2, 1e-9 * (M + m) * kG);
      } else if (row.t > t_lock && row.t < t_land) {
        EXPECT_NEAR(row.quantities.total_energy, E_flight, 1e-9 * E_scale) << row.t;
        EXPECT_EQ(N, 0.0);
      } else if (row.t > t_land && e == 0.0) {
        // It lands plastically and lies still on its face.
        EXPECT_NEAR(phi, phi0, 1e-12) << row.t;
        EXPECT_NEAR(frame.omega_W.norm(), 0.0, 1e-9 * Omega);
        EXPECT_NEAR(N, (M + m) * kG / 2, 1e-9 * (M + m) * kG) << row.t;
        EXPECT_EQ(row.extras.contacts[0].mode, 2);
      } else if (row.t > t_land && row.t < t_land + 0.05) {
        // It rebounds at e Omega: e^2 of the kinetic energy it landed with.
        const double E_rebound =
            run.rows.front().quantities.potential_energy + 0.5 * I_total * e * e * Omega * Omega;
        EXPECT_NEAR(row.quantities.total_energy, E_rebound, 1e-9 * E_scale) << row.t;
        EXPECT_LT(frame.omega_W.y(), 0.0);  // rising again (about -y)
      }
    }
    EXPECT_NEAR(highest, phi_max, 1e-4) << "the rows are 1 ms apart: the peak within their step";
  }
}

TEST(ContactOnAJointedBody, ABobAJointHoldsOnAFloorRestsOnTheFloorsPushWithoutFriction) {
  const Vec3 p(0.6, 0.0, -0.8);  // the bob's centre from the pivot, m
  const double m = 1.0, r = 0.05;
  for (const Vec3& floor_normal : {Vec3(0.0, 0.0, 1.0), Vec3(0.2, 0.0, 1.0).normalized()}) {
    SCOPED_TRACE(
        fmt::format("floor normal ({:.6f}, 0, {:.6f})", floor_normal.x(), floor_normal.z()));
    const Vec3 c = p - r * floor_normal;  // the contact point
    const std::string yaml = fmt::format(
        "tumble: 1\n"
        "gravity: [0, 0, -{}]\n"
        "bodies:\n"
        "  bob: {{shape: sphere, radius: {}, mass: {}, position: [{}, {}, {}]}}\n"
        "joints:\n"
        "  pivot: {{type: ball, body: bob, at: [0, 0, 0]}}\n"
        "contacts:\n"
        "  - {{name: floor, type: plane, body: bob, plane: {{point: [{:.17g}, 0, {:.17g}], "
        "normal: [{:.17g}, 0, {:.17g}]}}, friction: 0.5}}\n"
        "simulate: {{duration: 1, integrator: dop853, rtol: 1e-10, atol: 1e-12, "
        "output_every: 0.01}}\n",
        kG, r, m, p.x(), p.y(), p.z(), c.x(), c.z(), floor_normal.x(), floor_normal.z());
    const auto run = run_inline_scenario(yaml, "bob_on_floor");
    const double N = m * kG / (floor_normal.z() - floor_normal.x() * p.z() / p.x());
    const Vec3 joint_force_W = m * kG * Vec3::UnitZ() - N * floor_normal;  // on the bob
    EXPECT_LE(run.contact_events.size(), 1u) << run.contact_events.back().what;
    ASSERT_EQ(run.rows.size(), 101u);
    for (const Row& row : run.rows) {
      EXPECT_NEAR((row.states[0].r_G - p).norm(), 0.0, 1e-12) << "t = " << row.t;
      EXPECT_EQ(row.extras.contacts[0].mode, 2);
      // The solve takes the least friction to ~1e-6 of the push (a normal row's force counts
      // 1e-6 of a friction row's: kNormalRowScale = 1e3), and N and the joint's force with it.
      EXPECT_NEAR(row.extras.contacts[0].normal_force, N, 1e-5 * m * kG) << "t = " << row.t;
      // Without the choice, the least-norm force took 4.6 N of friction on the level floor.
      EXPECT_LT(row.extras.contacts[0].friction_W.norm(), 1e-5 * m * kG) << "t = " << row.t;
      // The joint's force on the bob (the first body, ground, exerts it on the second).
      EXPECT_NEAR((row.extras.joints[0].F_W - joint_force_W).norm(), 0.0, 1e-5 * m * kG);
    }
  }
}

}  // namespace
}  // namespace tumble
