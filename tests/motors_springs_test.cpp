// Joints, forces and reactions as a whole: hinge motors (prescribed speed, applied torque), a
// reaction wheel on a free satellite, linear and torsional springs with damping, hinges named in
// either order, the work ledger of a damped and driven pendulum, and the conservation laws of
// every example in examples/. Each against an exact solution, a conservation law or a chapter
// formula (equations.md; section 6.6 for work and energy), at several parameter values.
//
// Tolerances: the runs here ask rtol 1e-10, atol 1e-12 unless said otherwise. Where the exact
// motion is a polynomial in t of degree <= 2 (a rate held constant, a constant torque on a fixed
// axis) every Runge-Kutta method of order >= 2 integrates it exactly, so only round-off remains
// and the checks are at 1e-12. Elsewhere the global error of a few hundred adaptive steps at that
// accuracy is a few hundred times rtol: the checks are at 1e-8 of the quantity's scale.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "tumble/math/rotation.hpp"

namespace tumble {
namespace {

using test::kG;
using test::kPi;
using test::Row;
using test::run_inline_scenario;
using test::upward_zero_crossings;

// The sum of every element's work at a row (forces, springs, motors, impulses, locks).
double total_element_work(const Row& row) {
  double work = 0.0;
  for (const ElementWork& e : row.extras.elements) work += e.work;
  return work;
}

// Gravity's potential -M g . r_G summed over the bodies (PE without the springs' energy).
double gravity_potential(const Row& row) {
  return row.quantities.potential_energy - row.extras.elastic_energy;
}

// ---- 1. Speed motors ------------------------------------------------------------------------

struct Door {
  double mass, a, b, c;  // a box a x b x c
  double d;              // hinge line (vertical, world z) to the COM, along x
  double inertia_about_hinge() const { return mass * (a * a + b * b) / 12 + mass * d * d; }
};

// The box with its COM at (d, 0, 0), on a vertical hinge through the origin turning at w0, with
// a speed motor that drives it at w for t1 <= t < t2. Gravity acts along the hinge: it does no
// work and has no moment about it.
std::string door_scenario(const Door& door, double w0, const std::string& motor, double duration,
                          double output_every) {
  return fmt::format(
      "tumble: 1\n"
      "bodies:\n"
      "  door: {{shape: box, size: [{}, {}, {}], mass: {}, position: [{}, 0, 0],\n"
      "         angular_velocity: [0, 0, {}]}}\n"
      "joints:\n"
      "  hinge: {{type: hinge, body: door, at: [0, 0, 0], axis: [0, 0, 1], motor: {}}}\n"
      "simulate: {{duration: {}, rtol: 1e-10, atol: 1e-12, output_every: {}}}\n",
      door.a, door.b, door.c, door.mass, door.d, w0, motor, duration, output_every);
}

TEST(SpeedMotor, OnAVerticalHingeItHoldsTheRateExactlyAndItsStartIsItsWork) {
  // Free, the door keeps w0 (no moment about the vertical hinge). The motor starting at t1 makes
  // the rate jump to w: an impulsive torque whose work, impulse times the mean rate, is exactly
  // the kinetic energy it adds, I_O (w^2 - w0^2) / 2. While it runs (and after it stops: nothing
  // then acts about the hinge) the rate is w: prescribed, not integrated, so to round-off; and
  // holding a constant rate about a vertical axis takes no torque, so the motor's work stays.
  for (const Door& door : {Door{3.0, 0.8, 0.04, 2.0, 0.4}, Door{0.5, 0.3, 0.3, 0.1, 0.0},
                           Door{12.0, 1.2, 0.1, 2.1, 0.9}}) {
    for (const auto& [w0, w] : {std::pair{0.0, 2.0}, std::pair{1.5, -3.0}, std::pair{-0.7, 0.4}}) {
      const double t1 = 0.25, t2 = 0.75;
      const auto run = run_inline_scenario(
          door_scenario(door, w0, fmt::format("{{speed: {}, from: {}, to: {}}}", w, t1, t2), 1.0,
                        0.01),
          "door");
      const double I_O = door.inertia_about_hinge();
      const double rate_scale = std::abs(w) + std::abs(w0);
      const double dKE = 0.5 * I_O * (w * w - w0 * w0);
      const double E0 = run.rows.front().quantities.total_energy;
      for (const Row& row : run.rows) {
        const double rate = row.states[0].omega_W.z();
        // The motor acts from t1 on (from <= t): the row at t1 shows the rate after its jump.
        EXPECT_NEAR(rate, row.t < t1 ? w0 : w, 1e-12 * rate_scale) << row.t;
        const double motor_work = row.extras.elements[0].work;
        EXPECT_NEAR(motor_work, row.t < t1 ? 0.0 : dKE, 1e-12 * I_O * rate_scale * rate_scale)
            << row.t;
        EXPECT_NEAR(row.quantities.total_energy - E0, motor_work,
                    1e-12 * I_O * rate_scale * rate_scale)
            << row.t;
      }
      ASSERT_EQ(run.jumps.size(), 1u);
      EXPECT_EQ(run.jumps[0].t, t1);
      // One row at t1, after the jump (rows every 0.01 s land on it).
      const auto at_t1 = std::count_if(run.rows.begin(), run.rows.end(),
                                       [&](const Row& row) { return row.t == t1; });
      EXPECT_EQ(at_t1, 1);
    }
  }
}

struct Pendulum {
  double mass, radius, length;  // a cylinder
  double L;                     // hinge to the COM
  double inertia_about_hinge() const {
    return mass * (3 * radius * radius + length * length) / 12 + mass * L * L;
  }
};

// A cylinder hanging at rest from a hinge about y at the origin (COM at (0, 0, -L)); its angle
// theta turns it about +y: COM at (-L sin theta, 0, -L cos theta).
std::string hanging_scenario(const Pendulum& p, const std::string& joint_extra,
                             const std::string& forces, double duration, double output_every,
                             const std::string& body_extra = "") {
  return fmt::format(
      "tumble: 1\n"
      "bodies:\n"
      "  bob: {{shape: cylinder, radius: {}, length: {}, mass: {}, position: [0, 0, {}]{}}}\n"
      "joints:\n"
      "  pivot: {{type: hinge, body: bob, at: [0, 0, 0], axis: [0, 1, 0]{}}}\n"
      "{}"
      "simulate: {{duration: {}, rtol: 1e-10, atol: 1e-12, output_every: {}}}\n",
      p.radius, p.length, p.mass, -p.L, body_extra, joint_extra, forces, duration, output_every);
}

TEST(SpeedMotor, OnAHorizontalHingeItTurnsThePendulumUniformlyAgainstGravity) {
  // From rest, hanging; the motor turns it at w for t1 <= t < t2, round and round whatever
  // gravity does: theta = w (t - t1) exactly (a constant rate integrates exactly), the COM at
  // (-L sin theta, 0, -L cos theta). The hinge carries the motor's torque, which balances
  // gravity's moment about O (6.7.7 with alpha = 0): M_y = -(r_G x M g)_y = -M g x_G. Its work is
  // the jump I_O w^2 / 2 at t1 plus the rise of the COM, M g (z_G - z_G0): Delta(KE + PE). After
  // t2 the pendulum swings freely and E holds. Also with the motor running from t = 0 (the bob
  // then starts turning at w: no jump).
  for (const Pendulum& p : {Pendulum{1.0, 0.02, 0.6, 0.3}, Pendulum{2.5, 0.05, 1.0, 0.8},
                            Pendulum{0.4, 0.01, 0.3, 0.15}}) {
    for (const auto& [w, from_start] : {std::pair{2.0, false}, std::pair{-7.0, false},
                                        std::pair{0.6, false}, std::pair{-3.0, true}}) {
      const double t1 = from_start ? 0.0 : 0.2, t2 = 2.2;
      const auto run = run_inline_scenario(
          from_start
              ? hanging_scenario(p, fmt::format(", motor: {{speed: {}, to: {}}}", w, t2), "", 3.0,
                                 0.005, fmt::format(", angular_velocity: [0, {}, 0]", w))
              : hanging_scenario(p,
                                 fmt::format(", motor: {{speed: {}, from: {}, to: {}}}", w, t1, t2),
                                 "", 3.0, 0.005),
          "driven_pendulum");
      const double I_O = p.inertia_about_hinge();
      const double jump = from_start ? 0.0 : 0.5 * I_O * w * w;
      const double energy_scale = p.mass * kG * p.L + 0.5 * I_O * w * w;
      const double E0 = run.rows.front().quantities.total_energy;
      double worst_position = 0.0, worst_moment = 0.0, worst_work = 0.0;
      for (const Row& row : run.rows) {
        const BodyState& s = row.states[0];
        const double motor_work = row.extras.elements[0].work;
        worst_work = std::max(worst_work, std::abs(row.quantities.total_energy - E0 - motor_work));
        if (row.t < t1) {  // from t1 on, the row at t1 included, it turns at w
          EXPECT_EQ(motor_work, 0.0);
          continue;
        }
        if (row.t >= t2) continue;  // to t2, not at it: the row at t2 has the motor off
        EXPECT_NEAR(s.omega_W.y(), w, 1e-12 * std::abs(w)) << row.t;
        const double theta = w * (row.t - t1);
        worst_position =
            std::max(worst_position,
                     (s.r_G - Vec3(-p.L * std::sin(theta), 0, -p.L * std::cos(theta))).norm() /
                         (1 + std::abs(theta)));
        worst_moment = std::max(worst_moment,
                                std::abs(row.extras.joints[0].M_J_W.y() + p.mass * kG * s.r_G.x()));
        EXPECT_NEAR(motor_work, jump + p.mass * kG * (s.r_G.z() + p.L), 1e-8 * energy_scale)
            << row.t;
      }
      EXPECT_LT(worst_position, 1e-12 * p.L) << w;
      EXPECT_LT(worst_moment, 1e-8 * p.mass * kG * p.L) << w;
      EXPECT_LT(worst_work, 1e-8 * energy_scale) << w;
      // Free after t2: the motor's work no longer changes and E holds.
      const Row& at_t2 = *std::find_if(run.rows.begin(), run.rows.end(),
                                       [&](const Row& r) { return r.t >= t2 - 1e-12; });
      EXPECT_NEAR(run.rows.back().extras.elements[0].work, at_t2.extras.elements[0].work,
                  1e-8 * energy_scale);
      EXPECT_NEAR(run.rows.back().quantities.total_energy, at_t2.quantities.total_energy,
                  1e-8 * energy_scale);
    }
  }
}

// ---- 2. Torque motor ------------------------------------------------------------------------

TEST(TorqueMotor, OnAVerticalHingeTheDoorSpinsUpAtTauOverI) {
  // About the fixed vertical hinge (6.7.7), I_O theta'' = tau while the motor acts: omega =
  // tau (t - t1) / I_O and theta = tau (t - t1)^2 / (2 I_O), polynomials that the integrator
  // follows exactly, so to round-off; after t2 the door coasts at tau (t2 - t1) / I_O. The motor's
  // work tau theta is all kinetic energy (gravity acts along the hinge): KE = I_O omega^2 / 2.
  for (const Door& door : {Door{3.0, 0.8, 0.04, 2.0, 0.4}, Door{0.5, 0.3, 0.3, 0.1, 0.0},
                           Door{12.0, 1.2, 0.1, 2.1, 0.9}}) {
    for (const auto& [tau, t1, t2] :
         {std::tuple{1.5, -1.0, 10.0}, std::tuple{-0.2, 0.3, 1.4}, std::tuple{40.0, 0.0, 0.5}}) {
      const std::string schedule =
          t1 < 0 ? "" : fmt::format(", from: {}, to: {}", t1, t2);  // t1 < 0: always on
      const auto run = run_inline_scenario(
          door_scenario(door, 0.0, fmt::format("{{torque: {}{}}}", tau, schedule), 2.0, 0.01),
          "door_torque");
      const double I_O = door.inertia_about_hinge();
      const double t_on = std::max(t1, 0.0);
      const double omega_end = tau * (std::min(2.0, t2) - t_on) / I_O;
      const double theta_end =
          0.5 * omega_end * (std::min(2.0, t2) - t_on) + omega_end * std::max(0.0, 2.0 - t2);
      const double work_end = 0.5 * I_O * omega_end * omega_end;
      double worst_omega = 0.0, worst_R = 0.0, worst_work = 0.0, worst_KE = 0.0;
      for (const Row& row : run.rows) {
        const double running = std::clamp(row.t, t_on, t2) - t_on;  // time the motor acted
        const double omega = tau * running / I_O;
        const double theta = 0.5 * omega * running + omega * std::max(0.0, row.t - t2);
        const BodyState& s = row.states[0];
        worst_omega = std::max(worst_omega, (s.omega_W - Vec3(0, 0, omega)).norm());
        worst_R = std::max(
            worst_R,
            (s.R_WB - rotation_from_axis_angle(Vec3::UnitZ(), theta)).cwiseAbs().maxCoeff());
        const double work = row.extras.elements[0].work;
        worst_work = std::max(worst_work, std::abs(work - 0.5 * I_O * omega * omega));
        worst_KE = std::max(worst_KE, std::abs(row.quantities.kinetic_energy - work));
      }
      EXPECT_LT(worst_omega, 1e-12 * std::abs(omega_end)) << tau;
      EXPECT_LT(worst_R, 1e-12 * (1 + std::abs(theta_end))) << tau;
      EXPECT_LT(worst_work, 1e-12 * work_end) << tau;
      EXPECT_LT(worst_KE, 1e-12 * work_end) << tau;
    }
  }
}

// ---- 3. Reaction wheel ----------------------------------------------------------------------

struct Satellite {
  double M, a, b, c;  // the box
  double m, R, h;     // the wheel, a cylinder (axis along its body z)
  Vec3 wheel_at;      // the wheel's centre, world (the satellite's COM at the origin)
  Vec3 axis;          // the wheel's axle, world
  double tau;         // N m, the motor
};

std::string satellite_scenario(const Satellite& s, double duration, double output_every) {
  // The wheel's body z onto the axle: turn z about z x axis.
  const Vec3 n = s.axis.normalized();
  const Vec3 turn = Vec3::UnitZ().cross(n);
  const double angle = std::atan2(turn.norm(), n.z());
  const Vec3 about = turn.norm() > 0 ? Vec3(turn.normalized()) : Vec3::UnitX();
  return fmt::format(
      "tumble: 1\n"
      "gravity: [0, 0, 0]\n"
      "bodies:\n"
      "  satellite: {{shape: box, size: [{}, {}, {}], mass: {}}}\n"
      "  wheel: {{shape: cylinder, radius: {}, length: {}, mass: {}, position: [{}, {}, {}],\n"
      "          orientation: {{axis: [{}, {}, {}], angle: {:.17g}}}}}\n"
      "joints:\n"
      "  axle: {{type: hinge, bodies: [satellite, wheel], at: [{}, {}, {}], axis: [{}, {}, {}],\n"
      "          motor: {{torque: {}}}}}\n"
      "simulate: {{duration: {}, rtol: 1e-10, atol: 1e-12, output_every: {}}}\n",
      s.a, s.b, s.c, s.M, s.R, s.h, s.m, s.wheel_at.x(), s.wheel_at.y(), s.wheel_at.z(), about.x(),
      about.y(), about.z(), angle, s.wheel_at.x(), s.wheel_at.y(), s.wheel_at.z(), n.x(), n.y(),
      n.z(), s.tau, duration, output_every);
}

TEST(ReactionWheel, AlignedWithAPrincipalAxisTheSatelliteCounterRotates) {
  // The motor's torque is internal: L of the whole stays 0 (it starts at rest, no external load).
  // With the axle along the satellite's principal axis z and the wheel's centre in the satellite's
  // x-y plane through its COM, both turn about z only and the system COM C stays put:
  //   I_sat,total omega_sat + I_w (omega_sat + omega_rel) = 0,
  // with I_sat,total = I_zz + M |r_sat - C|^2 + m |r_wheel - C|^2 (the wheel's mass rides on the
  // satellite) and I_w = m R^2 / 2 its axial moment. The wheel gets tau, the satellite -tau:
  // omega_sat = -tau t / I_sat,total and omega_wheel = tau t / I_w (polynomials: exact to
  // round-off). KE = tau^2 t^2 (1 / I_sat,total + 1 / I_w) / 2 is the motor's work.
  for (const Satellite& s :
       {Satellite{50.0, 1.0, 0.8, 0.6, 2.0, 0.15, 0.03, Vec3::Zero(), Vec3::UnitZ(), 0.05},
        Satellite{20.0, 0.5, 0.5, 0.7, 1.0, 0.1, 0.04, Vec3(0.15, 0.1, 0), Vec3::UnitZ(), -0.3},
        Satellite{5.0, 0.3, 0.6, 0.4, 0.8, 0.08, 0.02, Vec3(0, -0.2, 0), -Vec3::UnitZ(), 0.02}}) {
    const double duration = 4.0;
    const auto run = run_inline_scenario(satellite_scenario(s, duration, 0.02), "reaction_wheel");
    const Vec3 C = s.m * s.wheel_at / (s.M + s.m);
    const double I_sat = s.M * (s.a * s.a + s.b * s.b) / 12 + s.M * C.squaredNorm() +
                         s.m * (s.wheel_at - C).squaredNorm();
    const double I_w = s.m * s.R * s.R / 2;
    const double tau_z = s.tau * s.axis.z();            // on the wheel, world z
    const double L_scale = std::abs(tau_z) * duration;  // the wheel's |L| at the end
    const double KE_end = 0.5 * L_scale * L_scale * (1 / I_sat + 1 / I_w);
    double worst_L = 0.0, worst_balance = 0.0, worst_rates = 0.0, worst_energy = 0.0,
           worst_com = 0.0;
    for (const Row& row : run.rows) {
      const double w_sat = row.states[0].omega_W.z(), w_wheel = row.states[1].omega_W.z();
      const double w_rel = w_wheel - w_sat;
      worst_L = std::max(worst_L, row.quantities.angular_momentum_about_origin.norm());
      worst_balance = std::max(worst_balance, std::abs(I_sat * w_sat + I_w * (w_sat + w_rel)));
      worst_rates = std::max({worst_rates, std::abs(w_sat + tau_z * row.t / I_sat) * I_sat,
                              std::abs(w_wheel - tau_z * row.t / I_w) * I_w,
                              row.states[0].omega_W.head<2>().norm() * I_sat,
                              row.states[1].omega_W.head<2>().norm() * I_w});
      worst_energy = std::max(worst_energy,
                              std::abs(row.quantities.total_energy - row.extras.elements[0].work));
      const Vec3 com = (s.M * row.states[0].r_G + s.m * row.states[1].r_G) / (s.M + s.m);
      worst_com = std::max(worst_com, (com - C).norm());
    }
    EXPECT_LT(worst_L, 1e-12 * L_scale);
    EXPECT_LT(worst_balance, 1e-12 * L_scale);
    EXPECT_LT(worst_rates, 1e-12 * L_scale);
    EXPECT_LT(worst_energy, 1e-12 * KE_end);
    // Positions are integrated (the satellite's COM circles C): to rtol of the size.
    EXPECT_LT(worst_com, 1e-10 * (s.a + s.b + s.c));
    EXPECT_NEAR(run.rows.back().extras.elements[0].work, KE_end, 1e-12 * KE_end);
  }
}

TEST(ReactionWheel, ASpeedMotorsStartSetsTheSatelliteTurningAtOnce) {
  // The same satellites with a speed motor from t1: at t1 the wheel's rate relative to the
  // satellite jumps to w, an impulsive start inside the system, so L stays 0 through it:
  //   I_sat,total omega_sat + I_w (omega_sat + w) = 0,  omega_sat = -I_w w / (I_sat,total + I_w),
  // constant after (nothing acts; no torque holds a constant rate here). The start's work,
  // impulse times the mean rate, I_w (omega_sat + w) w / 2, is the KE it gives. All algebraic:
  // to round-off.
  for (const Satellite& s :
       {Satellite{50.0, 1.0, 0.8, 0.6, 2.0, 0.15, 0.03, Vec3::Zero(), Vec3::UnitZ(), 0.0},
        Satellite{20.0, 0.5, 0.5, 0.7, 1.0, 0.1, 0.04, Vec3(0.15, 0.1, 0), Vec3::UnitZ(), 0.0},
        Satellite{5.0, 0.3, 0.6, 0.4, 0.8, 0.08, 0.02, Vec3(0, -0.2, 0), -Vec3::UnitZ(), 0.0}}) {
    for (const double w : {300.0, -40.0}) {
      std::string yaml = satellite_scenario(s, 1.0, 0.01);
      const std::string torque = "motor: {torque: 0}";
      yaml.replace(yaml.find(torque), torque.size(),
                   fmt::format("motor: {{speed: {}, from: 0.3}}", w));
      const auto run = run_inline_scenario(yaml, "wheel_speed");
      const Vec3 C = s.m * s.wheel_at / (s.M + s.m);
      const double I_sat = s.M * (s.a * s.a + s.b * s.b) / 12 + s.M * C.squaredNorm() +
                           s.m * (s.wheel_at - C).squaredNorm();
      const double I_w = s.m * s.R * s.R / 2;
      const double w_z = w * s.axis.z();  // the relative rate about world z
      const double w_sat = -I_w * w_z / (I_sat + I_w);
      const double KE = 0.5 * I_w * (w_sat + w_z) * w_z;
      ASSERT_EQ(run.jumps.size(), 1u);
      EXPECT_LT(run.jumps[0].angular_momentum_after_W.norm(), 1e-12 * I_w * std::abs(w));
      EXPECT_NEAR(run.jumps[0].kinetic_energy_after, KE, 1e-12 * KE);
      for (const Row& row : run.rows) {
        if (row.t <= 0.3) continue;
        EXPECT_NEAR(row.states[0].omega_W.z(), w_sat, 1e-12 * std::abs(w)) << row.t;
        EXPECT_NEAR(row.states[1].omega_W.z() - row.states[0].omega_W.z(), w_z,
                    1e-12 * std::abs(w));
        EXPECT_LT(row.quantities.angular_momentum_about_origin.norm(), 1e-12 * I_w * std::abs(w));
        EXPECT_NEAR(row.extras.elements[0].work, KE, 1e-12 * KE);
        EXPECT_NEAR(row.quantities.kinetic_energy, KE, 1e-12 * KE);
      }
    }
  }
}

TEST(ReactionWheel, OnAnyAxleAndOffsetLStaysZeroAndKEIsTheMotorsWork) {
  // A wheel off the COM on a tilted axle: the satellite tumbles (no closed form), but the motor
  // is still internal: L = 0 and p = 0 throughout, and the motor's work is all the KE. Checked to
  // 1e-8 of the wheel's final |L| and of the final KE (integrated, not polynomial, motion).
  for (const Satellite& s :
       {Satellite{50.0, 1.0, 0.8, 0.6, 2.0, 0.15, 0.03, Vec3(0.3, 0.1, 0.2), Vec3(1, 1, 1), 0.5},
        Satellite{5.0, 0.3, 0.6, 0.4, 0.8, 0.08, 0.02, Vec3(-0.1, 0.2, 0.05), Vec3(0, 1, 3),
                  -0.05}}) {
    const double duration = 4.0;
    const auto run = run_inline_scenario(satellite_scenario(s, duration, 0.02), "tilted_wheel");
    const double I_w = s.m * s.R * s.R / 2;
    const double L_scale = std::abs(s.tau) * duration;
    const double KE_scale = 0.5 * L_scale * L_scale / I_w;  // the wheel's own share, about
    double worst_L = 0.0, worst_p = 0.0, worst_energy = 0.0;
    for (const Row& row : run.rows) {
      worst_L = std::max(worst_L, row.quantities.angular_momentum_about_origin.norm());
      worst_p = std::max(worst_p, row.quantities.linear_momentum.norm());
      worst_energy = std::max(worst_energy,
                              std::abs(row.quantities.total_energy - row.extras.elements[0].work));
    }
    EXPECT_LT(worst_L, 1e-8 * L_scale);
    EXPECT_LT(worst_p, 1e-8 * L_scale / s.R);
    EXPECT_LT(worst_energy, 1e-8 * KE_scale);
    // The satellite did turn: the test is not of bodies at rest.
    EXPECT_GT(run.rows.back().states[0].omega_W.norm(), 1e-3 * L_scale / (s.M * s.a * s.a));
  }
}

TEST(ReactionWheel, TheExampleSlewsTheSatelliteANinetyDegreeTurnAndStops) {
  // examples/reaction_wheel.yaml: the wheel spun up for t_on, coasting, then the axle locked at
  // t_stop. With L = 0 the lock leaves everything at rest, the satellite turned by -slew about
  // z; the lock's work takes all of the KE. The satellite's orientation is integrated (a free
  // body's quaternion) at the example's rtol 1e-9: checked to 1e-8 (ten times rtol, on a turn of
  // 1.6 rad).
  const auto run = test::run_scenario(
      load_scenario(std::string(TUMBLE_SOURCE_DIR) + "/examples/reaction_wheel.yaml", {}));
  ASSERT_TRUE(run.result.report.completed);
  const std::vector<Row>& rows = run.rows;
  const double slew = run.scenario.parameters.at("slew");
  const Row& last = rows.back();
  EXPECT_LT(
      (last.states[0].R_WB - rotation_from_axis_angle(Vec3::UnitZ(), -slew)).cwiseAbs().maxCoeff(),
      1e-8);
  const double KE_peak = std::max_element(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
                           return a.quantities.kinetic_energy < b.quantities.kinetic_energy;
                         })->quantities.kinetic_energy;
  EXPECT_LT(last.quantities.kinetic_energy, 1e-12 * KE_peak);
  EXPECT_NEAR(total_element_work(last), 0.0, 1e-8 * KE_peak);  // motor's work + lock's = 0
}

// ---- 4. A linear spring from ground ---------------------------------------------------------

struct SpringMassDamper {
  double m, k, c;
  bool gravity;
};

// A ball hanging from a spring (rest length 1 m) fixed to ground at the origin, along z; y is its
// displacement below the equilibrium l_eq = 1 + m g / k (1 without gravity), started at y0
// moving down at ydot0. The spring's points are the origin and the ball's COM.
std::string oscillator_scenario(const SpringMassDamper& o, double y0, double ydot0, double duration,
                                double output_every) {
  const double l_eq = 1.0 + (o.gravity ? o.m * kG / o.k : 0.0);
  return fmt::format(
      "tumble: 1\n"
      "gravity: [0, 0, {}]\n"
      "bodies:\n"
      "  ball: {{shape: sphere, radius: 0.05, mass: {}, position: [0, 0, {:.17g}],\n"
      "         velocity: [0, 0, {}]}}\n"
      "forces:\n"
      "  - {{type: spring, bodies: [ground, ball], at: [[0, 0, 0], [0, 0, {:.17g}]],\n"
      "     stiffness: {}, damping: {}, rest_length: 1}}\n"
      "simulate: {{duration: {}, rtol: 1e-10, atol: 1e-12, output_every: {}}}\n",
      o.gravity ? -kG : 0.0, o.m, -(l_eq + y0), -ydot0, -(l_eq + y0), o.k, o.c, duration,
      output_every);
}

TEST(LinearSpring, PeriodEnvelopeAndTheWorkOfItsDamper) {
  // m y'' + c y' + k y = 0 about the equilibrium (gravity only shifts it by m g / k):
  //   y = e^(-gamma t) (y0 cos(w_d t) + (ydot0 + gamma y0) / w_d sin(w_d t)),
  // gamma = c / (2 m), w_d = sqrt(k / m - gamma^2): period 2 pi / w_d (2 pi sqrt(m / k) undamped),
  // read from the upward zero crossings of y; the amplitude
  //   A = sqrt(y^2 + ((y' + gamma y) / w_d)^2) = A0 e^(-gamma t)
  // is the decay envelope. The spring's reported work is its whole force's (elastic and damper:
  // the summary's KE - KE0 = W_gravity + sum W), so its damper's work is W + Delta(k (l - l0)^2
  // / 2) and E0 - E is minus that, which the exact motion gives as
  // k (y0^2 - y^2) / 2 + m (ydot0^2 - ydot^2) / 2.
  for (const SpringMassDamper& o :
       {SpringMassDamper{1.0, 100.0, 0.0, false}, SpringMassDamper{2.5, 40.0, 0.0, true},
        SpringMassDamper{0.5, 200.0, 1.0, true}, SpringMassDamper{3.0, 30.0, 2.0, false},
        SpringMassDamper{1.0, 10.0, 0.5, true}}) {
    const double gamma = o.c / (2 * o.m);
    const double w_d = std::sqrt(o.k / o.m - gamma * gamma);
    const double T = 2 * kPi / w_d;
    const double y0 = 0.1, ydot0 = 0.3;
    const auto run =
        run_inline_scenario(oscillator_scenario(o, y0, ydot0, 3.2 * T, T / 2000), "oscillator");
    const double l_eq = 1.0 + (o.gravity ? o.m * kG / o.k : 0.0);
    const double A0 = std::hypot(y0, (ydot0 + gamma * y0) / w_d);
    const double E_scale = 0.5 * o.k * A0 * A0;
    const double E0 = run.rows.front().quantities.total_energy;
    const double KE0 = run.rows.front().quantities.kinetic_energy;
    const double gravity0 = gravity_potential(run.rows.front());
    const double elastic0 = run.rows.front().extras.elastic_energy;
    std::vector<double> t, y, ydot;
    double worst_y = 0.0, worst_envelope = 0.0, worst_lost = 0.0, worst_balance = 0.0,
           worst_elastic = 0.0;
    for (const Row& row : run.rows) {
      const BodyState& s = row.states[0];
      t.push_back(row.t);
      y.push_back(-s.r_G.z() - l_eq);
      ydot.push_back(-s.v_G.z());
      const double decay = std::exp(-gamma * row.t);
      const double b = (ydot0 + gamma * y0) / w_d;
      const double c = std::cos(w_d * row.t), sn = std::sin(w_d * row.t);
      const double y_exact = decay * (y0 * c + b * sn);
      const double ydot_exact = decay * (w_d * (b * c - y0 * sn)) - gamma * y_exact;
      worst_y = std::max(worst_y, std::abs(y.back() - y_exact));
      worst_envelope = std::max(
          worst_envelope,
          std::abs(std::hypot(y.back(), (ydot.back() + gamma * y.back()) / w_d) - A0 * decay));
      const double W = row.extras.elements[0].work;
      const double damper_work = W + row.extras.elastic_energy - elastic0;
      const double lost_exact = 0.5 * o.k * (y0 * y0 - y_exact * y_exact) +
                                0.5 * o.m * (ydot0 * ydot0 - ydot_exact * ydot_exact);
      worst_lost =
          std::max(worst_lost, std::abs((E0 - row.quantities.total_energy) - (-damper_work)) +
                                   std::abs(-damper_work - lost_exact));
      worst_balance = std::max(worst_balance, std::abs(row.quantities.kinetic_energy - KE0 +
                                                       gravity_potential(row) - gravity0 - W));
      const double stretch = -s.r_G.z() - 1.0;
      worst_elastic = std::max(worst_elastic,
                               std::abs(row.extras.elastic_energy - 0.5 * o.k * stretch * stretch));
      if (o.c == 0.0) {
        EXPECT_NEAR(damper_work, 0.0, 1e-8 * E_scale) << row.t;
      }
    }
    const std::vector<double> up = upward_zero_crossings(t, y, ydot);
    ASSERT_GE(up.size(), 3u);
    EXPECT_NEAR(up[1] - up[0], T, 1e-8 * T) << o.m << " " << o.k << " " << o.c;
    EXPECT_NEAR(up[2] - up[1], T, 1e-8 * T) << o.m << " " << o.k << " " << o.c;
    if (o.c == 0.0) {
      EXPECT_NEAR(T, 2 * kPi * std::sqrt(o.m / o.k), 1e-15 * T);
    } else {
      // It does decay: over the run the amplitude falls by e^(-gamma 3.2 T), at least 20% here.
      EXPECT_LT(std::exp(-gamma * 3.2 * T), 0.8);
    }
    EXPECT_LT(worst_y, 1e-8 * A0);
    EXPECT_LT(worst_envelope, 1e-8 * A0);
    EXPECT_LT(worst_lost, 1e-8 * E_scale);
    EXPECT_LT(worst_balance, 1e-8 * E_scale);
    EXPECT_LT(worst_elastic, 1e-12 * (E_scale + 0.5 * o.k * l_eq * l_eq));
  }
}

TEST(LinearSpring, BetweenTwoFreeBodiesTheyOscillateAtTheReducedMass) {
  // Two balls on the x axis joined at their COMs, no gravity: the separation obeys
  // mu s'' = -k (s - l0), mu = m1 m2 / (m1 + m2), so its period is 2 pi sqrt(mu / k); the spring
  // pulls both ways alike, so p and L are conserved, and E (KE + the spring's energy) too.
  for (const auto& [m1, m2, k] :
       {std::tuple{1.0, 1.0, 50.0}, std::tuple{0.3, 4.0, 12.0}, std::tuple{5.0, 2.0, 400.0}}) {
    const double mu = m1 * m2 / (m1 + m2), T = 2 * kPi * std::sqrt(mu / k);
    const auto run = run_inline_scenario(
        fmt::format("tumble: 1\n"
                    "gravity: [0, 0, 0]\n"
                    "bodies:\n"
                    "  one: {{shape: sphere, radius: 0.05, mass: {}, velocity: [0.2, 0.1, 0]}}\n"
                    "  two: {{shape: sphere, radius: 0.05, mass: {}, position: [1.1, 0, 0],\n"
                    "        velocity: [-0.3, 0.1, 0]}}\n"
                    "forces:\n"
                    "  - {{type: spring, bodies: [one, two], at: [[0, 0, 0], [1.1, 0, 0]], "
                    "stiffness: {}, rest_length: 1}}\n"
                    "simulate: {{duration: {}, rtol: 1e-10, atol: 1e-12, output_every: {}}}\n",
                    m1, m2, k, 3.2 * T, T / 2000),
        "two_balls");
    std::vector<double> t, stretch, rate;
    const Row& first = run.rows.front();
    double worst_p = 0.0, worst_L = 0.0, worst_E = 0.0;
    for (const Row& row : run.rows) {
      const Vec3 d = row.states[1].r_G - row.states[0].r_G;
      t.push_back(row.t);
      stretch.push_back(d.norm() - 1.0);
      rate.push_back(d.normalized().dot(row.states[1].v_G - row.states[0].v_G));
      worst_p = std::max(
          worst_p, (row.quantities.linear_momentum - first.quantities.linear_momentum).norm());
      worst_L = std::max(worst_L, (row.quantities.angular_momentum_about_origin -
                                   first.quantities.angular_momentum_about_origin)
                                      .norm());
      worst_E =
          std::max(worst_E, std::abs(row.quantities.total_energy - first.quantities.total_energy));
    }
    // Their relative velocity lies along the line between them (both drift alike along y, which
    // makes L about the origin nonzero), so the separation stays on the x axis: the period is
    // exactly 2 pi sqrt(mu / k), read as in the tests above.
    const std::vector<double> up = upward_zero_crossings(t, stretch, rate);
    ASSERT_GE(up.size(), 3u);
    EXPECT_NEAR(up[1] - up[0], T, 1e-8 * T) << m1 << " " << m2 << " " << k;
    EXPECT_NEAR(up[2] - up[1], T, 1e-8 * T) << m1 << " " << m2 << " " << k;
    const double E0 = first.quantities.total_energy;
    EXPECT_LT(worst_E, 1e-8 * E0);
    EXPECT_LT(worst_p, 1e-8 * first.quantities.linear_momentum.norm());
    EXPECT_LT(worst_L, 1e-8 * first.quantities.angular_momentum_about_origin.norm());
  }
}

// ---- 5. A torsional spring between two free bodies ------------------------------------------

std::string two_bodies_scenario(double k, double c) {
  return fmt::format(
      "tumble: 1\n"
      "gravity: [0, 0, 0]\n"
      "bodies:\n"
      "  a: {{shape: box, size: [0.4, 0.3, 0.2], mass: 2, orientation: {{axis: [1, 2, 3], angle: "
      "0.4}},\n"
      "      velocity: [0.1, 0, 0], angular_velocity: [0.3, -0.2, 0.5]}}\n"
      "  b: {{shape: cylinder, radius: 0.1, length: 0.5, mass: 1.5, position: [0.8, 0.3, -0.2],\n"
      "      orientation: {{axis: [0, 1, 1], angle: 1.0}}, velocity: [0, -0.2, 0.1],\n"
      "      angular_velocity: [-0.6, 0.9, 0.2]}}\n"
      "forces:\n"
      "  - {{type: torsional_spring, bodies: [a, b], stiffness: {}, damping: {}}}\n"
      "simulate: {{duration: 10, rtol: 1e-10, atol: 1e-12, output_every: 0.005}}\n",
      k, c);
}

TEST(TorsionalSpring, BetweenTwoFreeBodiesLIsConservedAndTheDamperOnlyTakesEnergy) {
  // The spring's moments on a and b are equal and opposite and no force acts: p and L (about
  // the origin) are conserved whatever the spring does (6.6). Without damping E = KE + k
  // theta^2 / 2 is conserved; with it dE/dt = -c |omega_b - omega_a|^2 <= 0, so E falls row by
  // row, and E0 - E is minus the damper's work (the spring's work plus the change of its stored
  // energy). theta stays below pi here, where the spring's moment is smooth.
  for (const auto& [k, c] :
       {std::pair{0.2, 0.0}, std::pair{1.0, 0.0}, std::pair{0.2, 0.01}, std::pair{1.0, 0.05}}) {
    const auto run = run_inline_scenario(two_bodies_scenario(k, c), "two_bodies");
    const Row& first = run.rows.front();
    const Vec3 L0 = first.quantities.angular_momentum_about_origin;
    const Vec3 p0 = first.quantities.linear_momentum;
    const double E0 = first.quantities.total_energy;
    ASSERT_NEAR(first.extras.elastic_energy, 0.0, 1e-15 * E0);  // at rest at t = 0
    const Mat3 R_BA0 = first.states[1].R_WB.transpose() * first.states[0].R_WB;
    double worst_L = 0.0, worst_p = 0.0, worst_E = 0.0, worst_rise = 0.0, worst_lost = 0.0,
           largest_theta = 0.0;
    double previous_E = E0;
    for (const Row& row : run.rows) {
      worst_L = std::max(worst_L, (row.quantities.angular_momentum_about_origin - L0).norm());
      worst_p = std::max(worst_p, (row.quantities.linear_momentum - p0).norm());
      const double E = row.quantities.total_energy;
      worst_E = std::max(worst_E, std::abs(E - E0));
      worst_rise = std::max(worst_rise, E - previous_E);
      previous_E = E;
      const double damper_work = row.extras.elements[0].work + row.extras.elastic_energy;
      worst_lost = std::max(worst_lost, std::abs((E0 - E) + damper_work));
      // The turn of b relative to a from rest: R_WB R_rest^T R_WA^T.
      const Mat3 turn = row.states[1].R_WB * R_BA0 * row.states[0].R_WB.transpose();
      largest_theta = std::max(largest_theta, log_so3(turn).norm());
    }
    ASSERT_LT(largest_theta, 0.9 * kPi);
    EXPECT_GT(largest_theta, 0.1) << "the spring is wound";
    EXPECT_LT(worst_L, 1e-8 * L0.norm()) << k << " " << c;
    // p is integrated too (each COM velocity through its body's turning axes).
    EXPECT_LT(worst_p, 1e-8 * p0.norm()) << k << " " << c;
    EXPECT_LT(worst_lost, 1e-8 * E0) << k << " " << c;
    if (c == 0.0) {
      EXPECT_LT(worst_E, 1e-8 * E0) << k;
    } else {
      // Each row's E at most the previous one's, up to the integration error between them.
      EXPECT_LT(worst_rise, 1e-10 * E0) << k << " " << c;
      EXPECT_LT(run.rows.back().quantities.total_energy, 0.9 * E0) << "the damper takes energy";
    }
  }
}

// ---- 6. A hinge named in either order -------------------------------------------------------

// A bob hanging from a hinge about y at the origin, the joint listing its bodies as `joint_bodies`
// ("ground, bob" or "bob, ground"), swinging at w0 at t = 0; `extra` adds to the joint.
std::string ordered_pendulum(const std::string& joint_bodies, const std::string& extra,
                             const std::string& forces) {
  return fmt::format(
      "tumble: 1\n"
      "bodies:\n"
      "  bob: {{shape: cylinder, radius: 0.03, length: 0.8, mass: 1.2, position: [0, 0, -0.5],\n"
      "        angular_velocity: [0, 4, 0]}}\n"
      "joints:\n"
      "  pivot: {{type: hinge, bodies: [{}], at: [0, 0, 0], axis: [0, 1, 0]{}}}\n"
      "{}"
      "simulate: {{duration: 3, rtol: 1e-10, atol: 1e-12, output_every: 0.01}}\n",
      joint_bodies, extra, forces);
}

// Two links: link1 hinged about y to ground at the origin, link2 about x to link1's end, swinging
// in 3D; `order1` and `order2` list each joint's bodies.
std::string ordered_double_pendulum(const std::string& order1, const std::string& order2) {
  return fmt::format(
      "tumble: 1\n"
      "bodies:\n"
      "  link1: {{shape: cylinder, radius: 0.02, length: 0.5, mass: 1, position: [0, 0, -0.25],\n"
      "          angular_velocity: [0, 2, 0]}}\n"
      "  link2: {{shape: box, size: [0.1, 0.05, 0.5], mass: 0.7, position: [0, 0, -0.75],\n"
      "          angular_velocity: [1.5, 2, 0]}}\n"
      "joints:\n"
      "  j1: {{type: hinge, bodies: [{}], at: [0, 0, 0], axis: [0, 1, 0]}}\n"
      "  j2: {{type: hinge, bodies: [{}], at: [0, 0, -0.5], axis: [1, 0, 0]}}\n"
      "simulate: {{duration: 2, rtol: 1e-10, atol: 1e-12, output_every: 0.01}}\n",
      order1, order2);
}

// The two runs move alike to `tolerance` (relative to the largest state), and each joint's
// reaction in `reversed_joints` is the other's negated (what the first body exerts on the
// second): both to `tolerance` of the largest reaction. Element works agree.
void expect_mirrored_runs(const test::ScenarioRun& normal, const test::ScenarioRun& reversed,
                          const std::vector<bool>& joint_reversed, double tolerance) {
  ASSERT_EQ(normal.rows.size(), reversed.rows.size());
  double state_scale = 0.0, reaction_scale = 0.0, work_scale = 0.0;
  for (const Row& row : normal.rows) {
    for (const BodyState& s : row.states) {
      state_scale = std::max({state_scale, s.r_G.norm(), s.v_G.norm(), s.omega_W.norm()});
    }
    for (const JointReaction& r : row.extras.joints) {
      reaction_scale = std::max({reaction_scale, r.F_W.norm(), r.M_J_W.norm()});
    }
    work_scale = std::max(work_scale, row.quantities.kinetic_energy);
  }
  double worst_state = 0.0, worst_reaction = 0.0, worst_work = 0.0;
  for (std::size_t i = 0; i < normal.rows.size(); ++i) {
    const Row& a = normal.rows[i];
    const Row& b = reversed.rows[i];
    ASSERT_EQ(a.t, b.t);
    for (std::size_t k = 0; k < a.states.size(); ++k) {
      const BodyState& sa = a.states[k];
      const BodyState& sb = b.states[k];
      worst_state = std::max({worst_state, (sa.r_G - sb.r_G).norm(), (sa.v_G - sb.v_G).norm(),
                              (sa.omega_W - sb.omega_W).norm(),
                              state_scale * (sa.R_WB - sb.R_WB).cwiseAbs().maxCoeff()});
    }
    for (std::size_t j = 0; j < a.extras.joints.size(); ++j) {
      const double sign = joint_reversed[j] ? -1.0 : 1.0;
      worst_reaction =
          std::max({worst_reaction, (b.extras.joints[j].F_W - sign * a.extras.joints[j].F_W).norm(),
                    (b.extras.joints[j].M_J_W - sign * a.extras.joints[j].M_J_W).norm()});
    }
    for (std::size_t e = 0; e < a.extras.elements.size(); ++e) {
      worst_work =
          std::max(worst_work, std::abs(a.extras.elements[e].work - b.extras.elements[e].work));
    }
  }
  EXPECT_LT(worst_state, tolerance * state_scale);
  EXPECT_LT(worst_reaction, tolerance * reaction_scale);
  EXPECT_LT(worst_work, tolerance * std::max(work_scale, 1.0));
}

TEST(HingeOrder, ReversedBodiesGiveTheSameMotionAndTheOppositeReaction) {
  // [bob, ground] is the same hinge as [ground, bob]: the same motion; its columns are what the
  // first body exerts on the second, so the bob's push on ground: the reaction negated (Newton's
  // third law). Its angle turns ground relative to the bob: a motor's torque or speed on it acts
  // on the bob as the opposite one on [ground, bob] does. The two runs integrate the same
  // equations with the hinge coordinate's sign flipped, which changes nothing but round-off
  // (the adaptive steps see the same magnitudes): checked to 1e-12.
  const std::string spring =
      "forces:\n  - {type: torsional_spring, bodies: [ground, bob], stiffness: 3, damping: 0.2}\n";
  const std::string spring_reversed =
      "forces:\n  - {type: torsional_spring, bodies: [bob, ground], stiffness: 3, damping: 0.2}\n";
  struct Case {
    std::string extra, extra_reversed, forces, forces_reversed;
  };
  for (const Case& c :
       {Case{"", "", "", ""}, Case{"", "", spring, spring}, Case{"", "", spring, spring_reversed},
        Case{", motor: {torque: -2.5, from: 0.5, to: 2}",
             ", motor: {torque: 2.5, from: 0.5, to: 2}", spring, spring},
        Case{", motor: {speed: -3, from: 1}", ", motor: {speed: 3, from: 1}", "", ""}}) {
    const auto normal =
        run_inline_scenario(ordered_pendulum("ground, bob", c.extra, c.forces), "normal");
    const auto reversed = run_inline_scenario(
        ordered_pendulum("bob, ground", c.extra_reversed, c.forces_reversed), "reversed");
    SCOPED_TRACE(c.extra_reversed + " " + c.forces_reversed);
    expect_mirrored_runs(normal, reversed, {true}, 1e-12);
  }
  // A speed motor on [bob, ground]: the bob turns at minus its speed about the axis.
  const auto driven = run_inline_scenario(
      ordered_pendulum("bob, ground", ", motor: {speed: 3, from: 1}", ""), "reversed_speed");
  for (const Row& row : driven.rows) {
    if (row.t > 1) {
      EXPECT_NEAR(row.states[0].omega_W.y(), -3.0, 1e-12 * 3) << row.t;
    }
  }
}

TEST(HingeOrder, ATorsionalSpringsRestIsTheSameHingeAngleInEitherOrder) {
  // A spring across the hinge whose rest is the hinge at 0.3 rad, stated as an angle or as the
  // orientation of its second body relative to its first, in either body order, for bodies that
  // start turned (R0) about the hinge's normal: at t = 0 (hinge angle 0) it stores k 0.3^2 / 2.
  const double k = 2.0, rest = 0.3;
  for (const double turn_deg : {0.0, 30.0, 90.0}) {
    const Mat3 R0 = rotation_from_axis_angle(Vec3::UnitZ(), turn_deg * kPi / 180);
    const Mat3 R_rest = rotation_from_axis_angle(Vec3::UnitY(), rest) * R0;  // bob at 0.3, world
    for (const bool bob_first : {false, true}) {
      const Mat3 relative = bob_first ? Mat3(R_rest.transpose()) : R_rest;
      const auto matrix = [](const Mat3& R) {
        return fmt::format(
            "[[{:.17g}, {:.17g}, {:.17g}], [{:.17g}, {:.17g}, {:.17g}], "
            "[{:.17g}, {:.17g}, {:.17g}]]",
            R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2));
      };
      const std::string pair = bob_first ? "[bob, ground]" : "[ground, bob]";
      for (const std::string& rest_text :
           {fmt::format("{{matrix: {}}}", matrix(relative)), fmt::format("{}", rest)}) {
        const std::string yaml = fmt::format(
            "tumble: 1\n"
            "gravity: [0, 0, 0]\n"
            "bodies:\n"
            "  bob: {{shape: box, size: [0.2, 0.3, 0.8], mass: 1, position: [0, 0, -0.5],\n"
            "        orientation: {{matrix: {}}}}}\n"
            "joints:\n"
            "  pivot: {{type: hinge, bodies: [ground, bob], at: [0, 0, 0], axis: [0, 1, 0]}}\n"
            "forces:\n"
            "  - {{type: torsional_spring, bodies: {}, stiffness: {}, rest: {}}}\n"
            "simulate: {{duration: 0.1, rtol: 1e-10, atol: 1e-12}}\n",
            matrix(R0), pair, k, rest_text);
        const auto run = run_inline_scenario(yaml, "spring_rest_order");
        EXPECT_NEAR(run.rows.front().extras.elastic_energy, k * rest * rest / 2, 1e-12)
            << turn_deg << " deg, " << pair << ", rest " << rest_text;
      }
    }
  }
}

TEST(HingeOrder, ADoublePendulumMovesAlikeWithEitherJointReversed) {
  const auto normal =
      run_inline_scenario(ordered_double_pendulum("ground, link1", "link1, link2"), "normal");
  for (const auto& [order1, order2, flips] :
       {std::tuple{"link1, ground", "link1, link2", std::vector<bool>{true, false}},
        std::tuple{"ground, link1", "link2, link1", std::vector<bool>{false, true}},
        std::tuple{"link1, ground", "link2, link1", std::vector<bool>{true, true}}}) {
    SCOPED_TRACE(std::string(order1) + " / " + order2);
    const auto reversed = run_inline_scenario(ordered_double_pendulum(order1, order2), "reversed");
    expect_mirrored_runs(normal, reversed, flips, 1e-12);
  }
}

// ---- 7. A damped, driven pendulum: the work of each load --------------------------------------

struct Driven {
  double k, c;  // torsional spring-damper across the hinge, N m/rad and N m s/rad
  Vec3 F;       // N, world, at the bob's lower end for t1 <= t < t2
  double t1, t2;
  double tau;  // N m, torque motor on the hinge for t3 <= t < t4
  double t3, t4;
};

TEST(WorkLedger, EachLoadsWorkAndTheirSumMatchTheEnergy) {
  // A cylinder (length 0.6 m, 1.5 kg) hanging from a hinge about y, with a torsional
  // spring-damper across the hinge, a constant world force at its lower end P for t1 <= t < t2
  // and a torque motor for t3 <= t < t4. Each load's work has a closed form over the motion:
  //  - the constant force: F . (r_P(t) - r_P(t1)) (the work of a constant force is path
  //    independent), frozen after t2;
  //  - the motor: tau (theta(t) - theta(t3)), theta the hinge angle, frozen after t4 (the ledger
  //    integrates tau theta' with the same Runge-Kutta weights as theta: equal to round-off);
  //  - the spring: its stored energy k theta^2 / 2 drops by its elastic work, and what remains
  //    is the damper's, which only ever decreases (power -c theta'^2).
  // And the work-energy theorem (6.6): with PE gravity's and the spring's, E - E0 = the work of
  // the force, the motor and the damper (the summary's KE - KE0 = W_gravity + sum W, the spring's
  // elastic work moved to the left). The ledger integrates each power at rtol 1e-10: checked to
  // 1e-8 of the energy scale.
  const double M = 1.5, length = 0.6, L = 0.4;
  const Pendulum p{M, 0.03, length, L};
  for (const Driven& d : {Driven{4.0, 0.3, Vec3(5, 0, 2), 0.5, 1.5, 1.2, 1.0, 3.0},
                          Driven{20.0, 0.05, Vec3(-3, 0, -4), 0.2, 2.7, -0.8, 1.5, 2.5},
                          Driven{0.0, 1.0, Vec3(2, 1, 0), 1.0, 3.0, 0.5, 0.0, 4.0}}) {
    const std::string joint =
        fmt::format(", motor: {{torque: {}, from: {}, to: {}}}", d.tau, d.t3, d.t4);
    const std::string forces = fmt::format(
        "forces:\n"
        "  - {{type: torsional_spring, name: spring, bodies: [ground, bob], stiffness: {}, "
        "damping: {}}}\n"
        "  - {{type: force, name: push, body: bob, at: [0, 0, {}], value: [{}, {}, {}], from: {}, "
        "to: {}}}\n",
        d.k, d.c, -L - length / 2, d.F.x(), d.F.y(), d.F.z(), d.t1, d.t2);
    const auto run =
        run_inline_scenario(hanging_scenario(p, joint, forces, 4.0, 0.005), "damped_driven");
    // Ledger order: loads, springs, torsional springs, motors.
    const std::vector<std::string> names =
        prepare_simulation(run.scenario).formulation->element_names();
    ASSERT_EQ(names, (std::vector<std::string>{"push", "spring", "pivot.motor"}));
    const std::size_t push = 0, spring = 1, motor = 2;

    // The hinge angle, unwrapped, from the COM: (-L sin theta, 0, -L cos theta).
    std::vector<double> theta;
    for (const Row& row : run.rows) {
      const double angle = std::atan2(-row.states[0].r_G.x(), -row.states[0].r_G.z());
      theta.push_back(theta.empty() ? angle
                                    : theta.back() + std::remainder(angle - theta.back(), 2 * kPi));
    }
    const auto row_at = [&](double t) {
      const auto it = std::find_if(run.rows.begin(), run.rows.end(),
                                   [&](const Row& r) { return std::abs(r.t - t) < 1e-9; });
      EXPECT_NE(it, run.rows.end()) << t;
      return static_cast<std::size_t>(it - run.rows.begin());
    };
    const auto point_P = [&](const Row& row) -> Vec3 {
      return row.states[0].r_G + row.states[0].R_WB * Vec3(0, 0, -length / 2);
    };
    const std::size_t i1 = row_at(d.t1), i2 = row_at(d.t2), i3 = row_at(std::max(d.t3, 0.0)),
                      i4 = row_at(d.t4);
    const Row& first = run.rows.front();
    const double KE0 = first.quantities.kinetic_energy, gravity0 = gravity_potential(first),
                 E0 = first.quantities.total_energy;
    double energy_scale = M * kG * L;
    for (const Row& row : run.rows) {
      energy_scale = std::max(energy_scale, row.quantities.kinetic_energy);
    }
    double worst_push = 0.0, worst_motor = 0.0, worst_elastic = 0.0, worst_balance = 0.0,
           worst_theorem = 0.0, damper_rise = 0.0, previous_damper = 0.0;
    for (std::size_t i = 0; i < run.rows.size(); ++i) {
      const Row& row = run.rows[i];
      const auto& work = row.extras.elements;
      const double push_work =
          row.t <= d.t1 ? 0.0 : d.F.dot(point_P(run.rows[std::min(i, i2)]) - point_P(run.rows[i1]));
      worst_push = std::max(worst_push, std::abs(work[push].work - push_work));
      const double motor_work =
          row.t <= std::max(d.t3, 0.0) ? 0.0 : d.tau * (theta[std::min(i, i4)] - theta[i3]);
      worst_motor = std::max(worst_motor, std::abs(work[motor].work - motor_work));
      worst_elastic = std::max(
          worst_elastic, std::abs(row.extras.elastic_energy - 0.5 * d.k * theta[i] * theta[i]));
      const double damper = work[spring].work + row.extras.elastic_energy;
      damper_rise = std::max(damper_rise, damper - previous_damper);
      previous_damper = damper;
      const double elastic_work = -(row.extras.elastic_energy - first.extras.elastic_energy);
      worst_balance =
          std::max(worst_balance, std::abs(row.quantities.total_energy - E0 -
                                           (work[push].work + work[motor].work + damper)));
      worst_theorem = std::max(
          worst_theorem, std::abs(row.quantities.kinetic_energy - KE0 + gravity_potential(row) -
                                  gravity0 - total_element_work(row)));
      EXPECT_NEAR(work[spring].work, damper + elastic_work, 1e-12 * energy_scale);
    }
    SCOPED_TRACE(fmt::format("k {} c {} tau {}", d.k, d.c, d.tau));
    EXPECT_LT(worst_push, 1e-8 * energy_scale);
    EXPECT_LT(worst_motor, 1e-12 * energy_scale);
    EXPECT_LT(worst_elastic, 1e-12 * energy_scale * (1 + d.k));
    EXPECT_LT(damper_rise, 1e-10 * energy_scale);
    EXPECT_LT(previous_damper, -1e-3 * energy_scale) << "the damper did take energy";
    EXPECT_LT(worst_balance, 1e-8 * energy_scale);
    EXPECT_LT(worst_theorem, 1e-8 * energy_scale);
    // The loads did work: the checks above are not of zeros.
    EXPECT_GT(std::abs(run.rows.back().extras.elements[push].work), 1e-3 * energy_scale);
    EXPECT_GT(std::abs(run.rows.back().extras.elements[motor].work), 1e-3 * energy_scale);
  }
}

// ---- 8. The examples ------------------------------------------------------------------------

// Nothing in the scenario does work but gravity and ideal joints: E = KE + PE is conserved.
bool is_conservative(const Scenario& s) {
  // Contacts may slide (friction) or strike (restitution < 1): left to their own tests.
  if (!s.loads.empty() || !s.impulses.empty() || !s.contacts.empty()) return false;
  for (const SpringSpec& spring : s.springs) {
    if (spring.damping != 0.0) return false;
  }
  for (const TorsionalSpringSpec& spring : s.torsional_springs) {
    if (spring.damping != 0.0) return false;
  }
  for (const JointSpec& joint : s.joints) {
    if (joint.motor.kind != MotorSpec::Kind::None || std::isfinite(joint.lock_at)) return false;
  }
  return true;
}

// The point O about which no external moment acts but gravity's (r_G - O) x M g, if there is
// one: no loads, impulses, contacts or springs to ground, and the system either free (O the origin)
// or held to ground by ball joints at one point only. Motors, locks and springs between bodies are
// internal.
std::optional<Vec3> moment_free_point(const Scenario& s) {
  if (!s.loads.empty() || !s.impulses.empty() || !s.contacts.empty()) return std::nullopt;
  for (const SpringSpec& spring : s.springs) {
    if (spring.body_a == kGroundName || spring.body_b == kGroundName) return std::nullopt;
  }
  for (const TorsionalSpringSpec& spring : s.torsional_springs) {
    if (spring.body_a == kGroundName || spring.body_b == kGroundName) return std::nullopt;
  }
  std::optional<Vec3> O;
  for (const JointSpec& joint : s.joints) {
    if (joint.body_a != kGroundName && joint.body_b != kGroundName) continue;
    if (joint.type != JointType::Ball || (O && (*O - joint.at_W).norm() > 0.0)) {
      return std::nullopt;
    }
    O = joint.at_W;
  }
  return O.value_or(Vec3::Zero());
}

TEST(Examples, ConservativeOnesKeepEnergyAndMomentFreeOnesKeepL) {
  // Over each example's own run (at most 30 s of it, to keep the test quick), at its own rtol:
  //  - the work-energy theorem KE - KE0 = W_gravity + sum W holds for every example;
  //  - E is conserved where nothing but gravity and ideal joints acts;
  //  - about a point O with no external moment but gravity's (a free system: the origin; one
  //    ball joint to ground: its centre), L_O is conserved along g, all of it without gravity
  //    (the gyroscope's Lz about its pivot, a free prism's L).
  // The drift of an invariant under an adaptive method grows with the run; over these runs of a
  // few thousand steps it stays below 100 rtol of the quantity's scale (measured: at most 4 rtol,
  // the gyroscope's Lz; E at most 0.6 rtol, the pendulum chain).
  const std::filesystem::path dir = std::filesystem::path(TUMBLE_SOURCE_DIR) / "examples";
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".yaml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  int conservative = 0, moment_free = 0;
  for (const std::filesystem::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    Scenario loaded = load_scenario(file.string(), {});
    loaded.simulate.duration = std::min(loaded.simulate.duration, 30.0);  // all of them now
    const auto run = test::run_scenario(std::move(loaded));
    ASSERT_TRUE(run.result.report.completed);
    const Scenario& scenario = run.scenario;
    const SimulationResult& result = run.result;
    const std::vector<Row>& rows = run.rows;
    const double rtol = scenario.simulate.rtol;
    double energy_scale = std::abs(rows.front().quantities.total_energy);
    for (const Row& row : rows) {
      energy_scale = std::max(energy_scale, row.quantities.kinetic_energy);
    }
    EXPECT_LT(result.conservation.max_work_energy_residual, 100 * rtol * energy_scale);
    if (is_conservative(scenario)) {
      ++conservative;
      const double E0 = rows.front().quantities.total_energy;
      double worst = 0.0;
      for (const Row& row : rows)
        worst = std::max(worst, std::abs(row.quantities.total_energy - E0));
      EXPECT_LT(worst, 100 * rtol * energy_scale);
    }
    if (const std::optional<Vec3> O = moment_free_point(scenario)) {
      ++moment_free;
      const Vec3 g = scenario.gravity_W;
      const auto L_O = [&](const Row& row) -> Vec3 {
        return row.quantities.angular_momentum_about_origin -
               O->cross(row.quantities.linear_momentum);
      };
      // The conserved part: along g with gravity, all of it without.
      const auto conserved = [&](const Vec3& L) -> Vec3 {
        return g.norm() > 0 ? Vec3(g.normalized() * g.normalized().dot(L)) : L;
      };
      // Scale: the bodies' own angular momenta about O (the total may be 0: the reaction wheel).
      const std::vector<RigidBody>& bodies = run.bodies;
      double L_scale = 0.0, worst = 0.0;
      for (const Row& row : rows) {
        double sum = 0.0;
        for (std::size_t i = 0; i < bodies.size(); ++i) {
          sum += calc_angular_momentum_about_point_W(bodies[i], row.states[i], *O).norm();
        }
        L_scale = std::max(L_scale, sum);
      }
      const Vec3 L0 = conserved(L_O(rows.front()));
      for (const Row& row : rows) worst = std::max(worst, (conserved(L_O(row)) - L0).norm());
      EXPECT_LT(worst, 100 * rtol * L_scale);
    }
  }
  // The examples this covers (so the test cannot pass on an empty or changed directory):
  // compound pendulum, gyroscope, inverted mast, pendulum chain, three prisms, projectile; and
  // for L the gyroscope, the prisms, the projectile and the reaction wheel.
  EXPECT_GE(conservative, 8);
  EXPECT_GE(moment_free, 6);
}

}  // namespace
}  // namespace tumble
