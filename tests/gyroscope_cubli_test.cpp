// The chapter's 3D gyroscope (example 7) and its Cubli (example 6), and a long pendulum chain:
// steady precession is an exact solution, nutation conserves E, the quick brake conserves angular
// momentum about the pivot while kinetic energy is lost, the critical wheel speed divides
// falling back from passing upright, and joints hold to round-off however long the chain.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "scenario_run.hpp"
#include "test_constants.hpp"

namespace tumble {
namespace {

using test::kG;
using test::kPi;
using test::Row;
using test::run_inline_scenario;

struct Gyro {
  double mass, radius, thickness, d, spin;
  double axial_inertia() const { return mass * radius * radius / 2; }
  double precession_rate() const { return mass * kG * d / (axial_inertia() * spin); }
};

// The azimuth of the wheel's COM about z at each row, unwrapped: the precession angle turned.
std::vector<double> precession_angles(const std::vector<Row>& rows) {
  std::vector<double> angles;
  double unwrapped = 0.0, previous = 0.0;
  for (const Row& row : rows) {
    const double angle = std::atan2(row.states[0].r_G.y(), row.states[0].r_G.x());
    unwrapped += std::remainder(angle - previous, 2 * kPi);
    previous = angle;
    angles.push_back(unwrapped);
  }
  return angles;
}

// A wheel (cylinder, axis along x) pivoted by a ball joint at the origin, its COM at (d, 0, 0),
// spinning at `spin` about the axle plus `precession` about z.
std::string gyroscope_scenario(const Gyro& g, double precession, double duration) {
  return fmt::format(
      "tumble: 1\n"
      "bodies:\n"
      "  wheel: {{shape: cylinder, radius: {}, length: {}, mass: {}, position: [{}, 0, 0],\n"
      "          orientation: {{axis: [0, 1, 0], angle: 90 deg}},\n"
      "          angular_velocity: [{}, 0, {}]}}\n"
      "joints:\n"
      "  pivot: {{type: ball, body: wheel, at: [0, 0, 0]}}\n"
      "simulate: {{duration: {}, rtol: 1e-10, atol: 1e-12, output_every: {}}}\n",
      g.radius, g.thickness, g.mass, g.d, g.spin, precession, duration, duration / 1000);
}

TEST(Gyroscope, SteadyPrecessionKeepsTheAxleHorizontal) {
  // omega = w_s n + Omega k with Omega = M g d / (I_a w_s) satisfies the equations exactly: the
  // axle stays horizontal, turns at Omega, and the pivot carries the weight M g.
  for (const Gyro& g : {Gyro{1.0, 0.1, 0.02, 0.1, 100.0}, Gyro{2.5, 0.2, 0.05, 0.15, 60.0},
                        Gyro{0.4, 0.05, 0.01, 0.08, 300.0}}) {
    const double Omega = g.precession_rate();
    const double duration = 2 * (2 * kPi / Omega);
    const auto run = run_inline_scenario(gyroscope_scenario(g, Omega, duration), "gyro_steady");
    const std::vector<double> turned = precession_angles(run.rows);
    double max_height = 0.0, max_angle_error = 0.0, max_reaction_error = 0.0;
    for (std::size_t i = 0; i < run.rows.size(); ++i) {
      const Row& row = run.rows[i];
      max_height = std::max(max_height, std::abs(row.states[0].r_G.z()));
      max_angle_error = std::max(max_angle_error, std::abs(turned[i] - Omega * row.t));
      max_reaction_error =
          std::max(max_reaction_error, std::abs(row.extras.joints[0].F_W.z() - g.mass * kG));
    }
    EXPECT_LT(max_height, 1e-8 * g.d);
    EXPECT_LT(max_angle_error, 1e-7 * Omega * duration);
    EXPECT_LT(max_reaction_error, 1e-7 * g.mass * kG);
    EXPECT_LT(run.result.conservation.max_relative_energy_drift, 1e-9);
  }
}

TEST(Gyroscope, StartedWithoutPrecessionItNodsAboutTheSteadyRate) {
  // Released with the spin alone, the axle dips and rises (nutation) while precessing; for a
  // fast top the mean precession rate is Omega to first order in
  // eps = Omega / omega_nutation = M g d I_t / (I_a w_s)^2 (I_t about the pivot, transverse),
  // and the axle dips at most 2 eps (rad) below horizontal. E is conserved throughout.
  for (const Gyro& g : {Gyro{1.0, 0.1, 0.02, 0.1, 400.0}, Gyro{2.5, 0.2, 0.05, 0.15, 250.0}}) {
    const double Omega = g.precession_rate();
    const double I_t =
        g.mass * (3 * g.radius * g.radius + g.thickness * g.thickness) / 12 + g.mass * g.d * g.d;
    const double eps = g.mass * kG * g.d * I_t / std::pow(g.axial_inertia() * g.spin, 2);
    ASSERT_LT(eps, 0.01);
    const double duration = 2 * kPi / Omega;
    const auto run = run_inline_scenario(gyroscope_scenario(g, 0.0, duration), "gyro_nutation");
    double lowest = 0.0;
    for (const Row& row : run.rows)
      lowest = std::min(lowest, std::asin(row.states[0].r_G.z() / g.d));
    const double mean_rate = precession_angles(run.rows).back() / duration;
    EXPECT_NEAR(mean_rate, Omega, 2 * eps * Omega);
    EXPECT_LT(lowest, -0.5 * eps) << "it does nod";
    EXPECT_GT(lowest, -2.5 * eps);
    EXPECT_LT(run.result.conservation.max_relative_energy_drift, 1e-9);
  }
}

// ---- Cubli (equations.md, 6), in the x-z plane: frame pivoted at its corner O ---------------

struct Cubli {
  double M, m, L, R;
  double total_inertia() const { return M * L * L / 3 + (M + m) * L * L / 2 + m * R * R; }
  double critical_speed() const {
    return std::sqrt((std::sqrt(2.0) - 1) * (M + m) * kG * L * total_inertia()) / (m * R * R);
  }
};

// The frame (four rods) rests on its edge with the centre at (L/2, 0, L/2); the ring wheel at the
// centre spins at w0 about -y, and its hinge locks at t = 1e-4 s, turning the frame about -y:
// towards upright (centre above O).
std::string cubli_scenario(const Cubli& c, double w0, double duration) {
  return fmt::format(
      "tumble: 1\n"
      "parameters: {{M: {}, m: {}, L: {}, R: {}}}\n"
      "bodies:\n"
      "  frame:\n"
      "    parts:\n"
      "      - {{shape: rod, length: L, mass: M/4, position: [0, 0, -L/2]}}\n"
      "      - {{shape: rod, length: L, mass: M/4, position: [0, 0, L/2]}}\n"
      "      - {{shape: rod, length: L, mass: M/4, position: [-L/2, 0, 0], orientation: "
      "{{axis: [0, 1, 0], angle: 90 deg}}}}\n"
      "      - {{shape: rod, length: L, mass: M/4, position: [L/2, 0, 0], orientation: "
      "{{axis: [0, 1, 0], angle: 90 deg}}}}\n"
      "    position: [L/2, 0, L/2]\n"
      "  wheel: {{shape: ring, radius: R, mass: m, position: [L/2, 0, L/2],\n"
      "          orientation: {{axis: [1, 0, 0], angle: 90 deg}}, angular_velocity: [0, {}, 0]}}\n"
      "joints:\n"
      "  corner: {{type: hinge, body: frame, at: [0, 0, 0], axis: [0, 1, 0]}}\n"
      "  axle: {{type: hinge, bodies: [frame, wheel], at: [L/2, 0, L/2], axis: [0, 1, 0],\n"
      "          lock: {{at: 1e-4}}}}\n"
      "simulate: {{duration: {}, rtol: 1e-10, atol: 1e-12, output_every: 0.001}}\n",
      c.M, c.m, c.L, c.R, -w0, duration);
}

TEST(Cubli, TheBrakeKeepsAngularMomentumAboutThePivotAndLosesEnergy) {
  for (const Cubli& c : {Cubli{0.8, 0.3, 0.15, 0.06}, Cubli{1.5, 0.2, 0.25, 0.1}}) {
    const double w0 = c.critical_speed();
    const auto run = run_inline_scenario(cubli_scenario(c, w0, 0.01), "cubli_lock");
    ASSERT_EQ(run.jumps.size(), 1u);
    const JumpRecord& lock = run.jumps[0];
    EXPECT_NEAR(lock.t, 1e-4, 1e-18);
    // L about O (the origin) through the lock; the weight's moment acts for no time.
    EXPECT_LT((lock.angular_momentum_after_W - lock.angular_momentum_before_W).norm(),
              1e-12 * lock.angular_momentum_before_W.norm());
    // Just after, frame and wheel turn as one about O: Omega = |L_O| / I_total, KE = I_total
    // Omega^2 / 2 (the frame turned ~1e-8 rad before the lock: I_total is that of t = 0). Before
    // the weight acted, L_O = m R^2 w0: the chapter's Omega = m R^2 w0 / I_total.
    const double KE_after = 0.5 * lock.angular_momentum_before_W.squaredNorm() / c.total_inertia();
    EXPECT_NEAR(lock.kinetic_energy_after, KE_after, 1e-6 * KE_after);
    EXPECT_NEAR(run.rows.front().quantities.angular_momentum_about_origin.norm(),
                c.m * c.R * c.R * w0, 1e-12 * c.m * c.R * c.R * w0);
    EXPECT_LT(lock.kinetic_energy_after, lock.kinetic_energy_before);
    // The lock's work is what the kinetic energy lost.
    const std::size_t lock_entry = run.rows.back().extras.elements.size() - 1;
    EXPECT_NEAR(run.rows.back().extras.elements[lock_entry].work,
                lock.kinetic_energy_after - lock.kinetic_energy_before,
                1e-12 * lock.kinetic_energy_before);
  }
}

TEST(Cubli, TheCriticalWheelSpeedDividesFallingBackFromPassingUpright) {
  for (const Cubli& c : {Cubli{0.8, 0.3, 0.15, 0.06}, Cubli{1.5, 0.2, 0.25, 0.1}}) {
    for (const double factor : {0.98, 1.02}) {
      const auto run =
          run_inline_scenario(cubli_scenario(c, factor * c.critical_speed(), 1.5), "cubli_jump");
      // The frame's centre at angle phi = atan2(z, x) about O: 45 deg at rest on its edge, 90 deg
      // upright. Follow the first swing (until phi turns back): it passes 90 deg or falls back.
      double highest = 0.0, previous = -1.0;
      for (const Row& row : run.rows) {
        const Vec3& r = row.states[0].r_G;
        const double phi = std::atan2(r.z(), r.x());
        if (row.t > 0.0 && phi < previous) break;
        highest = std::max(highest, phi);
        previous = phi;
      }
      if (factor < 1) {
        EXPECT_GT(highest, 0.3 * kPi) << "it rises towards upright";
        EXPECT_LT(highest, 0.5 * kPi) << "falls back";
      } else {
        EXPECT_GT(highest, 0.5 * kPi) << "passes upright";
      }
      EXPECT_LT(run.result.conservation.max_work_energy_residual,
                1e-7 * run.result.conservation.max_kinetic_energy);
    }
  }
}

// ---- A long chain ---------------------------------------------------------------------------

TEST(PendulumChain, JointsHoldToRoundOffAndEnergyIsConserved) {
  // n links (thin cylinders along x, length l) hinged about y end to end from the origin, started
  // horizontal and at rest: a chaotic motion, yet every joint point of two links coincides to
  // round-off (joint coordinates hold the joints by construction) and E is conserved.
  for (const int n : {2, 8}) {
    const double l = 0.3;
    std::string yaml = "tumble: 1\nbodies:\n";
    for (int i = 0; i < n; ++i) {
      yaml += fmt::format(
          "  link{}: {{shape: cylinder, radius: 0.01, length: {}, mass: {}, "
          "position: [{}, 0, 0], orientation: {{axis: [0, 1, 0], angle: 90 deg}}}}\n",
          i, l, 0.5 + 0.1 * i, (i + 0.5) * l);
    }
    yaml += "joints:\n";
    for (int i = 0; i < n; ++i) {
      yaml += fmt::format(
          "  j{}: {{type: hinge, bodies: [{}, link{}], at: [{}, 0, 0], axis: [0, 1, "
          "0]}}\n",
          i, i == 0 ? std::string("ground") : fmt::format("link{}", i - 1), i, i * l);
    }
    yaml += "simulate: {duration: 5, rtol: 1e-9, atol: 1e-11, output_every: 0.01}\n";
    const auto run = run_inline_scenario(yaml, "chain");
    double worst_gap = 0.0;
    for (const Row& row : run.rows) {
      for (int i = 1; i < n; ++i) {
        // The end of link i-1 (+l/2 along its axis, body z) meets the start of link i.
        const BodyState& a = row.states[static_cast<std::size_t>(i - 1)];
        const BodyState& b = row.states[static_cast<std::size_t>(i)];
        const Vec3 end_a = a.r_G + a.R_WB * Vec3(0, 0, l / 2);
        const Vec3 start_b = b.r_G + b.R_WB * Vec3(0, 0, -l / 2);
        worst_gap = std::max(worst_gap, (end_a - start_b).norm());
      }
    }
    EXPECT_LT(worst_gap, 1e-13 * n * l) << n;
    EXPECT_LT(run.result.conservation.max_relative_energy_drift, 1e-6) << n;
  }
}

}  // namespace
}  // namespace tumble
