// Contact with a plane against the chapter's worked examples (equations.md, 6.8: 1, 2 and 4) and
// exact solutions: rolling down a ramp, the critical friction and sliding, the disk thrown with
// backspin, a coin rolling on its rim in a circle; impacts that never add energy and a bouncing
// ball that settles. Every run asks rtol 1e-10: in a mode the motion is smooth and each step's
// error is below ~1e-10 of the state, so over the ~100 steps of a run the checks hold at 1e-8
// relative, and event times (located to a few ulps of t on the dense output) at 1e-9.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "rolling_coin_scenario.hpp"
#include "run_tumble.hpp"
#include "scenario_run.hpp"
#include "test_constants.hpp"

namespace tumble {
namespace {

using test::kDeg;
using test::kG;
using test::Row;
using test::run_inline_scenario;

// A round body's I_G / (M R^2) about its rolling axis, and the scenario text of its shape.
struct Roller {
  const char* name;
  double inertia_ratio;
  const char* shape;  // the shape's keys, with {R} for the radius
};
const Roller kRollers[] = {
    {"sphere", 2.0 / 5.0, "shape: sphere, radius: {R}"},
    {"shell", 2.0 / 3.0, "shape: shell, radius: {R}"},
    {"cylinder", 1.0 / 2.0, "shape: cylinder, radius: {R}, length: 0.05"},
    {"disk", 1.0 / 2.0, "shape: disk, radius: {R}"},
    {"ring", 1.0, "shape: ring, radius: {R}"},
};

// The roller on a ramp of slope theta descending towards +x, its axis (body z) across the slope
// along y, starting at rest touching the ramp at the origin.
std::string roller_on_ramp(const Roller& roller, double radius, double theta, double mu,
                           double duration) {
  const std::string shape = fmt::format(fmt::runtime(roller.shape), fmt::arg("R", radius));
  return fmt::format(
      "tumble: 1\n"
      "parameters: {{theta: {}}}\n"
      "bodies:\n"
      "  body: {{{}, mass: 1.5, position: [{} * sin(theta), 0, {} * cos(theta)],\n"
      "          orientation: {{axis: [1, 0, 0], angle: 90 deg}}}}\n"
      "contacts:\n"
      "  - {{name: ramp, type: plane, body: body, plane: {{point: [0, 0, 0],\n"
      "      normal: [sin(theta), 0, cos(theta)]}}, friction: {}}}\n"
      "simulate: {{duration: {}, integrator: dop853, rtol: 1e-10, atol: 1e-13, "
      "output_every: {}}}\n",
      theta, shape, radius, radius, mu, duration, duration / 50);
}

double speed(const Row& row) {
  return row.states[0].v_G.norm();
}

TEST(Ramp, ASphereAtExactlyTheCriticalFrictionRollsFromTheStartAsCheaplyAsAnyOther) {
  // mu_crit = (2/7) tan(theta) (equations.md, rolling on a ramp): at it, and within 1e-12 of it,
  // the sphere placed on the ramp rolls from t = 0 with v = (5/7) g sin(theta) t. Before, it
  // started apart and landed 8e-10 s later, at mu_crit it then "lifted off" (a Painleve case a
  // sphere cannot have), and it took 47,000 steps where any other mu takes 300.
  const double theta = 32 * kDeg;
  const auto run_at = [&](const std::string& mu) {
    return run_inline_scenario(
        fmt::format("tumble: 1\n"
                    "parameters: {{theta: {}, R: 0.1, mu: {}}}\n"
                    "bodies:\n"
                    "  ball: {{shape: sphere, radius: R, mass: 1, position: [R*sin(theta), 0, "
                    "R*cos(theta)]}}\n"
                    "contacts:\n"
                    "  - {{name: ramp, type: plane, body: ball, plane: {{point: [0, 0, 0], "
                    "normal: [sin(theta), 0, cos(theta)]}}, friction: mu}}\n"
                    "simulate: {{duration: 2, integrator: dop853, rtol: 1e-10, atol: 1e-12, "
                    "output_every: 0.01}}\n",
                    theta, mu),
        "critical_friction");
  };
  const long ordinary = run_at("0.3").result.report.stats.accepted_steps;
  for (const char* mu :
       {"2/7*tan(theta)", "2/7*tan(theta)*(1 + 1e-12)", "2/7*tan(theta)*(1 - 1e-12)"}) {
    const auto run = run_at(mu);
    ASSERT_EQ(run.contact_events.size(), 1u) << mu << ": " << run.contact_events.back().what;
    EXPECT_EQ(run.contact_events[0].t, 0.0);
    EXPECT_EQ(run.contact_events[0].what, "rolls") << mu;
    for (const Row& row : run.rows) {
      const double v = 5.0 / 7.0 * kG * std::sin(theta) * row.t;
      EXPECT_NEAR(speed(row), v, 1e-9 * (1 + v)) << mu << " t " << row.t;
      EXPECT_EQ(row.extras.contacts[0].mode, 2) << mu << " t " << row.t;
    }
    EXPECT_LE(run.result.report.stats.accepted_steps, 2 * ordinary) << mu;
  }
}

TEST(Ramp, RollingSpeedAfterADropIsTheChaptersFormula) {
  // v = sqrt(2 g h / (1 + I_G / (M R^2))) at every row, h the COM's drop; rolling throughout with
  // no slip (projected to round-off at every step), and N = M g cos(theta).
  for (const Roller& roller : kRollers) {
    for (const double theta : {10 * kDeg, 30 * kDeg}) {
      for (const double radius : {0.05, 0.3}) {
        const auto run = run_inline_scenario(roller_on_ramp(roller, radius, theta, 0.9, 1.5),
                                             fmt::format("ramp_{}", roller.name));
        const double z0 = run.rows.front().states[0].r_G.z();
        for (const Row& row : run.rows) {
          const double drop = z0 - row.states[0].r_G.z();
          const double v = std::sqrt(2 * kG * drop / (1 + roller.inertia_ratio));
          EXPECT_NEAR(speed(row), v, 1e-8 * (1 + v)) << roller.name << " t " << row.t;
          EXPECT_EQ(row.extras.contacts[0].mode, 2) << roller.name << " t " << row.t;
          EXPECT_LT(row.extras.contacts[0].slip_speed, 1e-9 * (1 + v)) << roller.name;
          EXPECT_NEAR(row.extras.contacts[0].normal_force, 1.5 * kG * std::cos(theta),
                      1e-9 * 1.5 * kG);
        }
        EXPECT_LT(run.result.conservation.max_relative_energy_drift, 1e-9) << roller.name;
      }
    }
  }
}

TEST(Ramp, ItSlidesIffFrictionIsBelowTheCriticalValue) {
  // mu_crit = tan(theta) I_G / (I_G + M R^2): just below it the body slides with
  // a = g (sin - mu cos); just above it rolls with a = g sin / (1 + I_G / (M R^2)).
  for (const Roller& roller : kRollers) {
    for (const double theta : {20 * kDeg, 40 * kDeg}) {
      const double k = roller.inertia_ratio;
      const double mu_crit = std::tan(theta) * k / (1 + k);
      for (const double factor : {0.98, 1.02}) {
        const double mu = factor * mu_crit;
        const auto run = run_inline_scenario(roller_on_ramp(roller, 0.1, theta, mu, 1.0),
                                             fmt::format("slide_{}", roller.name));
        const bool slides = factor < 1;
        const double a =
            slides ? kG * (std::sin(theta) - mu * std::cos(theta)) : kG * std::sin(theta) / (1 + k);
        for (const Row& row : run.rows) {
          EXPECT_NEAR(speed(row), a * row.t, 1e-8 * (1 + a * row.t)) << roller.name;
          if (row.t > 0) {
            EXPECT_EQ(row.extras.contacts[0].mode, slides ? 1 : 2) << roller.name;
          }
        }
      }
    }
  }
}

TEST(Ramp, TheEnergyLostIsTheWorkOfFriction) {
  // Sliding: E0 - E = -W_friction at every row (the ledger integrates F . v_slip).
  for (const Roller& roller : kRollers) {
    const double theta = 35 * kDeg;
    const double mu = 0.5 * std::tan(theta) * roller.inertia_ratio / (1 + roller.inertia_ratio);
    const auto run =
        run_inline_scenario(roller_on_ramp(roller, 0.1, theta, mu, 1.0), "friction_work");
    const double E0 = run.rows.front().quantities.total_energy;
    double lost = 0.0;
    for (const Row& row : run.rows) {
      const double work = row.extras.elements.back().work;
      lost = E0 - row.quantities.total_energy;
      EXPECT_NEAR(lost, -work, 1e-9 * (1 + row.quantities.kinetic_energy)) << roller.name;
      EXPECT_LE(row.extras.elements.back().power, 0.0) << roller.name;
    }
    EXPECT_GT(lost, 0.1) << roller.name;  // it did slide and lose energy
  }
}

// The chapter's thin disk (radius R, axis along y) rolling on its rim in the x-z plane, thrown
// along +x at v0 with backspin w0 (omega = -w0 about y).
struct Backspin {
  double v0, w0, radius, mu;
  double reversal_time() const { return v0 / (mu * kG); }
  double rolling_time() const { return (v0 + w0 * radius) / (3 * mu * kG); }
  double final_speed() const { return (2 * v0 - w0 * radius) / 3; }
};

std::string backspin_scenario(const Backspin& b, double duration) {
  return fmt::format(
      "tumble: 1\n"
      "bodies:\n"
      "  disk: {{shape: disk, radius: {R}, mass: 0.2, position: [0, 0, {R}],\n"
      "          orientation: {{axis: [1, 0, 0], angle: 90 deg}},\n"
      "          velocity: [{v0}, 0, 0], angular_velocity: [0, {w}, 0]}}\n"
      "contacts:\n"
      "  - {{name: floor, type: plane, body: disk, plane: {{point: [0, 0, 0], normal: [0, 0, "
      "1]}},\n"
      "      friction: {mu}}}\n"
      "simulate: {{duration: {T}, integrator: dop853, rtol: 1e-10, atol: 1e-13, "
      "output_every: {dt}}}\n",
      fmt::arg("R", b.radius), fmt::arg("v0", b.v0), fmt::arg("w", -b.w0), fmt::arg("mu", b.mu),
      fmt::arg("T", duration), fmt::arg("dt", duration / 200));
}

TEST(BackspinDisk, ReversesAndRollsBackAtTheChaptersTimesAndSpeed) {
  for (const Backspin& b : {Backspin{2.0, 60.0, 0.1, 0.2}, Backspin{1.0, 50.0, 0.05, 0.35},
                            Backspin{3.0, 200.0, 0.04, 0.1}}) {
    ASSERT_GT(b.w0 * b.radius, 2 * b.v0);  // it comes back
    const double duration = 1.5 * b.rolling_time();
    const auto run = run_inline_scenario(backspin_scenario(b, duration), "backspin");
    // Rolling starts at the located slip-stop event.
    double t_roll = -1;
    for (const auto& event : run.contact_events) {
      if (event.what == "slip stops") t_roll = event.t;
    }
    EXPECT_NEAR(t_roll, b.rolling_time(), 1e-9 * b.rolling_time());
    // While sliding v = v0 - mu g t exactly, so the rows' sign change of v, interpolated, is the
    // reversal.
    double t_reverse = -1;
    for (std::size_t i = 1; i < run.rows.size(); ++i) {
      const double v_a = run.rows[i - 1].states[0].v_G.x(), v_b = run.rows[i].states[0].v_G.x();
      if (v_a > 0 && v_b <= 0) {
        const double t_a = run.rows[i - 1].t, t_b = run.rows[i].t;
        t_reverse = t_a + v_a * (t_b - t_a) / (v_a - v_b);
      }
    }
    EXPECT_NEAR(t_reverse, b.reversal_time(), 1e-9 * b.reversal_time());
    for (const Row& row : run.rows) {
      const double v = row.states[0].v_G.x();
      if (row.t < b.rolling_time()) {
        EXPECT_NEAR(v, b.v0 - b.mu * kG * row.t, 1e-9 * b.v0);
        EXPECT_NEAR(row.states[0].omega_W.y(), -b.w0 + 2 * b.mu * kG * row.t / b.radius,
                    1e-9 * b.w0);
      } else {
        EXPECT_NEAR(v, b.final_speed(), 1e-9 * b.v0);
        EXPECT_EQ(row.extras.contacts[0].mode, 2);
        // No creep: the slip stays zero to round-off of the contact point's speed scale.
        EXPECT_LT(row.extras.contacts[0].slip_speed, 1e-12 * (b.v0 + b.w0 * b.radius));
      }
    }
  }
}

TEST(BackspinDisk, WithLittleBackspinItNeverComesBack) {
  // w0 R < 2 v0: the final rolling speed (2 v0 - w0 R) / 3 is forward and v never reverses.
  for (const Backspin& b : {Backspin{2.0, 30.0, 0.1, 0.2}, Backspin{1.0, 10.0, 0.05, 0.5}}) {
    ASSERT_LT(b.w0 * b.radius, 2 * b.v0);
    const auto run = run_inline_scenario(backspin_scenario(b, 2 * b.rolling_time()), "forward");
    for (const Row& row : run.rows) EXPECT_GT(row.states[0].v_G.x(), 0.0);
    EXPECT_NEAR(run.rows.back().states[0].v_G.x(), b.final_speed(), 1e-9 * b.v0);
  }
}

// A thin coin rolling on its rim in steady motion (rolling_coin_scenario.hpp has the formulas).
TEST(Coin, RollsOnItsRimInASteadyCircle) {
  for (const double theta : {10 * kDeg, 25 * kDeg}) {
    for (const double rho : {0.08, 0.2}) {
      const test::RollingCoin coin{theta, rho};
      const double r = coin.r, Omega = coin.precession(), period = coin.period();
      const std::string yaml = test::rolling_coin_scenario(coin, 0.6, 1, 2 * period, period / 50);
      const auto run = run_inline_scenario(yaml, "coin");
      for (const Row& row : run.rows) {
        const Vec3& r_G = row.states[0].r_G;
        EXPECT_NEAR(std::hypot(r_G.x(), r_G.y()), rho, 1e-9 * rho);
        EXPECT_NEAR(r_G.z(), r * std::cos(theta), 1e-9 * r);
        const double azimuth = std::atan2(r_G.y(), r_G.x());
        EXPECT_NEAR(std::remainder(azimuth - Omega * row.t, 2 * std::numbers::pi), 0.0, 1e-8);
        EXPECT_EQ(row.extras.contacts[0].mode, 2);
      }
      // Rolling without slip does no work: E is conserved.
      EXPECT_LT(run.result.conservation.max_relative_energy_drift, 1e-10);
    }
  }
}

// A ball dropped from height h onto the floor with restitution e, thrown sideways with backspin
// so that friction acts at every impact.
std::string bounce_scenario(double e, double mu, double h, double spin) {
  return fmt::format(
      "tumble: 1\n"
      "bodies:\n"
      "  ball: {{shape: sphere, radius: 0.05, mass: 0.06, position: [0, 0, {}],\n"
      "          velocity: [1, 0, 0], angular_velocity: [0, {}, 0]}}\n"
      "contacts:\n"
      "  - {{name: floor, type: plane, body: ball, plane: {{point: [0, 0, 0], normal: [0, 0, "
      "1]}},\n"
      "      friction: {}, restitution: {}}}\n"
      "simulate: {{duration: 8, integrator: dop853, rtol: 1e-10, atol: 1e-13, output_every: "
      "0.01}}\n",
      h + 0.05, spin, mu, e);
}

TEST(Bounce, ImpactsNeverAddEnergyAndTheBallSettles) {
  for (const double e : {0.5, 0.8}) {
    for (const double mu : {0.1, 0.4}) {
      for (const double spin : {-40.0, 0.0, 60.0}) {
        const auto run = run_inline_scenario(bounce_scenario(e, mu, 1.0, spin), "bounce");
        // The ledger's contact entry jumps by each impact's work, P . (v- + v+) / 2: never > 0,
        // so E never rises. Between impacts (flight, and rolling after the ball settles) the
        // contact does no work and E is conserved, to the run's accuracy (1e-8 of E0).
        const double E0 = run.rows.front().quantities.total_energy;
        double previous_work = 0.0, previous_E = E0;
        for (const Row& row : run.rows) {
          const double work = row.extras.elements.back().work;
          EXPECT_LE(work, previous_work + 1e-8 * E0);
          EXPECT_LE(row.quantities.total_energy, previous_E + 1e-8 * E0);
          previous_work = work;
          previous_E = row.quantities.total_energy;
        }
        // Each impact sends the ball up at e times its landing speed: the first one exactly.
        ASSERT_FALSE(run.contact_events.empty());
        const std::string& first = run.contact_events.front().what;
        const double v1 = std::sqrt(2 * kG * 1.0);
        EXPECT_NE(first.find(fmt::format("normal speed {:.4g} -> {:.4g} m/s", v1, e * v1)),
                  std::string::npos)
            << first;
        // The bounces end at the Zeno time t1 + (2 e v1 / g) / (1 - e) and the ball rests on
        // the floor, touching it, from then on.
        const double t1 = std::sqrt(2 * 1.0 / kG);
        const double t_zeno = t1 + 2 * e * v1 / (kG * (1 - e));
        const auto& last = run.contact_events.back();
        EXPECT_NEAR(last.t, t_zeno, 1e-3 * t_zeno) << last.what;
        const Row& end = run.rows.back();
        EXPECT_NE(end.extras.contacts[0].mode, 0);
        EXPECT_NEAR(end.states[0].r_G.z(), 0.05, 1e-9);
        EXPECT_NEAR(end.extras.contacts[0].normal_force, 0.06 * kG, 1e-9);
      }
    }
  }
}

TEST(ContactScenario, BadContactsAreRefusedWithWhereAndWhy) {
  const std::string head =
      "tumble: 1\n"                                                             // 1
      "bodies:\n"                                                               // 2
      "  ball: {shape: sphere, radius: 0.1, mass: 1, position: [0, 0, 0.1]}\n"  // 3
      "  pair: {position: [3, 0, 0.5], parts: [{shape: point, mass: 1, "        // 4
      "position: [-0.2, 0, 0]}, {shape: rod, length: 0.3, mass: 1, position: [0, 0.1, 0]}]}\n";
  const std::string simulate = "simulate: {duration: 1}\n";
  using test::expect_error;
  expect_error(head +
                   "contacts:\n  - {type: plane, body: pair, plane: {point: [0, 0, 0], normal: "
                   "[0, 0, 1]}, friction: 0.3}\n" +
                   simulate,
               6, 25, "contacts[0].body", "is a composite; none of its parts can touch a plane");
  expect_error(head +
                   "contacts:\n  - {type: plane, body: ball, plane: {point: [0, 0, 0], normal: "
                   "[0, 0, 0]}, friction: 0.3}\n" +
                   simulate,
               6, 65, "contacts[0].plane.normal", "the normal must not be zero");
  expect_error(head +
                   "contacts:\n  - {type: plane, body: ball, plane: {point: [0, 0, 0], normal: "
                   "[0, 0, 1]}}\n" +
                   simulate,
               6, 5, "contacts[0].friction", "missing required key 'friction'");
  expect_error(head +
                   "contacts:\n  - {type: plane, body: ball, plane: {point: [0, 0, 0], normal: "
                   "[0, 0, 1]}, friction: 0.3, restitution: 1.5}\n" +
                   simulate,
               6, 105, "contacts[0].restitution", "restitution must be in [0, 1]");
  expect_error(head +
                   "contacts:\n  - {type: plane, body: ball, plane: {point: [0, 0, 0.15], normal: "
                   "[0, 0, 1]}, friction: 0.3}\n" +
                   simulate,
               6, 5, "contacts[0]", "body 'ball' starts 0.15 m inside the plane");
}

TEST(ContactScenario, StartingOnThePlaneAndMovingIntoItIsRefused) {
  test::expect_error(
      "tumble: 1\n"
      "bodies:\n"
      "  ball: {shape: sphere, radius: 0.1, mass: 1, position: [0, 0, 0.1], velocity: [0, 0, -1]}\n"
      "contacts:\n"
      "  - {type: plane, body: ball, plane: {point: [0, 0, 0], normal: [0, 0, 1]}, friction: 0.3}\n"
      "simulate: {duration: 1}\n",
      5, 5, "contacts[0]", "starts touching the plane and moving into it at 1 m/s");
}

TEST(ContactScenario, TheBackspinExampleWritesContactColumnsAndEvents) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "tumble_contact_cli_columns";
  std::filesystem::create_directories(dir);
  const auto result = test::run_tumble(
      "run " +
      test::quote_for_shell(std::string(TUMBLE_SOURCE_DIR) + "/examples/backspin_disk.yaml") +
      " --out " + test::quote_for_shell(dir.string()));
  ASSERT_EQ(result.status, 0) << result.out;
  EXPECT_NE(result.out.find("t = 1.35915732248  floor: slip stops"), std::string::npos)
      << result.out;
  // The events CSV: each contact event at full precision; the slip stops at (v0 + w0 R) / (3 mu
  // g) (equations.md, the disk thrown with backspin), located to the integrator's precision.
  std::ifstream events(dir / "backspin_disk_events.csv");
  std::string events_header, event_line;
  std::getline(events, events_header);
  EXPECT_EQ(events_header,
            "t,source,what,KE_before,KE_after,approach_speed,rebound_speed,Px,Py,Pz,normal_speed,"
            "slip_speed,point_x,point_y,point_z,normal_x,normal_y,normal_z");
  std::vector<std::string> lines;
  while (std::getline(events, event_line)) lines.push_back(event_line);
  ASSERT_EQ(lines.size(), 3u);
  const auto cell = [](const std::string& line, std::size_t index) {
    std::size_t begin = 0;
    for (std::size_t i = 0; i < index; ++i) begin = line.find(',', begin) + 1;
    return line.substr(begin, line.find(',', begin) - begin);
  };
  const auto number = [&](const std::string& line, std::size_t index) {
    return std::stod(cell(line, index));
  };
  // Changes of modes: no landing (approach and rebound empty), no impulse, the energy the same
  // on both sides. At the throw: KE = M v0^2 / 2 + (M R^2 / 2) w0^2 / 2 = 2.2 J, and the rim
  // point slips at v0 + R w0 = 8 m/s along the floor, not across it.
  const double M = 0.2, R = 0.1, v0 = 2, w0 = 60;
  EXPECT_EQ(lines[0].substr(0, 30), "0,\"floor\",\"slides on its rim\",") << lines[0];
  const double KE0 = M * v0 * v0 / 2 + M * R * R * w0 * w0 / 4;
  EXPECT_NEAR(number(lines[0], 3), KE0, 1e-15 * KE0);
  EXPECT_EQ(cell(lines[0], 4), cell(lines[0], 3));
  EXPECT_EQ(cell(lines[0], 5) + cell(lines[0], 6), "");
  EXPECT_EQ(cell(lines[0], 7) + cell(lines[0], 8) + cell(lines[0], 9), "000");
  EXPECT_NEAR(number(lines[0], 10), 0.0, 1e-15 * (v0 + R * w0));
  EXPECT_NEAR(number(lines[0], 11), v0 + R * w0, 1e-15 * (v0 + R * w0));
  EXPECT_NE(lines[1].find(",\"floor\",\"slip stops\","), std::string::npos) << lines[1];
  const double t_roll = (v0 + w0 * R) / (3 * 0.2 * 9.81);
  EXPECT_NEAR(std::stod(lines[1]), t_roll, 1e-9 * t_roll) << lines[1];
  // Where the slip stops it rolls at v = (2 v0 - R w0) / 3 with KE = (3/4) M v^2 (rtol 1e-10 on
  // the speeds: 1e-9 on the energy), and nothing of the slip is left in the state it leaves.
  const double v_roll = (2 * v0 - R * w0) / 3, KE_roll = 0.75 * M * v_roll * v_roll;
  for (const std::string& line : {lines[1], lines[2]}) {
    EXPECT_NEAR(number(line, 3), KE_roll, 1e-9 * KE_roll) << line;
    EXPECT_EQ(cell(line, 4), cell(line, 3)) << line;
    EXPECT_NEAR(number(line, 10), 0.0, 1e-12 * std::abs(v_roll)) << line;
    EXPECT_NEAR(number(line, 11), 0.0, 1e-12 * std::abs(v_roll)) << line;
  }
  std::ifstream csv(dir / "backspin_disk.csv");
  std::string header, row, last;
  std::getline(csv, header);
  EXPECT_NE(header.find(",Lz,floor.N,floor.Fx,floor.Fy,floor.Fz,floor.slip,floor.mode,floor.P,"
                        "floor.W"),
            std::string::npos)
      << header;
  while (std::getline(csv, row)) last = row;
  // The last row's floor.mode: 2, rolling.
  const auto field = [](const std::string& line, std::size_t index) {
    std::size_t begin = 0;
    for (std::size_t i = 0; i < index; ++i) begin = line.find(',', begin) + 1;
    return line.substr(begin, line.find(',', begin) - begin);
  };
  const auto columns_before = [&](const std::string& name) {
    const std::string prefix = header.substr(0, header.find("," + name + ","));
    return static_cast<std::size_t>(std::count(prefix.begin(), prefix.end(), ',')) + 1;
  };
  EXPECT_EQ(field(last, columns_before("floor.mode")), "2") << last;
}

}  // namespace
}  // namespace tumble
