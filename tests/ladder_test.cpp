// A ladder against a frictionless wall on a frictionless floor, released from rest: the wall's
// force falls to zero and the ladder leaves the wall, never pulled back to it. For a rod of
// length L (thickness b = 0) it leaves where cos(theta) = (2/3) cos(theta0), theta from the
// vertical (e.g. Meriam and Kraige, Engineering Mechanics: Dynamics, the sliding ladder).
//
// The ladder here is a box of thickness b, which touches the floor and the wall with its two
// corners on the wall's side, both at x_B = -b/2: its COM is at X = (b/2) cos(theta) +
// (L/2) sin(theta) from the wall and Z = (b/2) sin(theta) + (L/2) cos(theta) above the floor.
// Energy, with I = M (L^2 + b^2) / 12 about the COM, gives the turning rate; the wall, the only
// horizontal force, is M X'', so it lets go where X' = f(theta) theta' is largest
// (f = dX/dtheta): the root of d/dtheta [f^2 theta'^2], found here to round-off (bisection on a
// derivative taken by the complex step, exact to round-off). At b = 0 it is the rod's
// (2/3) cos(theta0).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include "scenario_run.hpp"

namespace tumble {
namespace {

struct Ladder {
  double L = 4.0, b = 0.02, M = 20.0, g = 9.81, theta0 = 0.0;

  // f(theta)^2 theta'(theta)^2, the square of the COM's speed away from the wall.
  template <typename T>
  T away_speed_squared(T theta) const {
    const T s = std::sin(theta), c = std::cos(theta);
    const T f = -b / 2 * s + L / 2 * c;
    const T Z = b / 2 * s + L / 2 * c;
    const double Z0 = b / 2 * std::sin(theta0) + L / 2 * std::cos(theta0);
    const T inertia = (L * L + b * b) / 4 - L * b * s * c + (L * L + b * b) / 12;
    return f * f * 2.0 * g * (Z0 - Z) / inertia;
  }

  // The angle where the wall lets go.
  double lift_off_angle() const {
    const auto slope = [&](double theta) {
      constexpr double kStep = 1e-30;
      return std::imag(away_speed_squared(std::complex<double>(theta, kStep))) / kStep;
    };
    // Rising from the release, falling to zero where f is (where the wall corner is straight
    // above the floor corner).
    double lo = theta0 + 1e-6, hi = std::atan2(L, b);
    for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) {
      const double mid = 0.5 * (lo + hi);
      (slope(mid) > 0.0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }

  std::string scenario(double duration) const {
    return fmt::format(R"(tumble: 1
parameters: {{L: {}, b: {}, th0: {}}}
gravity: [0, 0, -{}]
bodies:
  ladder:
    shape: box
    size: [b, 0.3, L]
    mass: {}
    position: [L/2*sin(th0) + b/2*cos(th0), 0, L/2*cos(th0) + b/2*sin(th0)]
    orientation: {{axis: [0, 1, 0], angle: -th0}}
contacts:
  - {{name: floor, type: plane, body: ladder, plane: {{point: [0, 0, 0], normal: [0, 0, 1]}}, friction: 0}}
  - {{name: wall, type: plane, body: ladder, plane: {{point: [0, 0, 0], normal: [1, 0, 0]}}, friction: 0}}
simulate: {{duration: {}, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: 0.005}}
)",
                       L, b, theta0, g, M, duration);
  }
};

// Before, at theta0 = 45 deg the wall's edge "tipped onto a vertex" at the lift-off (N = +6e-13
// N at the located zero) and that vertex then pulled the ladder to the wall, N down to -197 N,
// until a touchdown. Now it lifts off there, at every angle and thickness.
TEST(Ladder, LeavesTheFrictionlessWallWhereItsForceReachesZero) {
  for (const double degrees : {20.0, 45.0, 60.0}) {
    for (const double b : {0.001, 0.02}) {
      Ladder ladder;
      ladder.b = b;
      ladder.theta0 = degrees * std::numbers::pi / 180;
      const std::string what = fmt::format("theta0 {} deg, b {}", degrees, b);
      const test::ScenarioRun run = test::run_inline_scenario(ladder.scenario(1.0), "ladder");
      // The wall's one event: it lets go.
      double t_off = -1.0;
      for (const ContactEventRecord& event : run.contact_events) {
        if (event.contact != 1 || event.t == 0.0) continue;  // t = 0: how it starts
        EXPECT_EQ(event.what, "lifts off") << what;
        if (t_off < 0.0) t_off = event.t;
      }
      ASSERT_GT(t_off, 0.0) << what;
      // Never a pull; and from the lift-off on no horizontal force, so the horizontal momentum
      // holds (the floor is frictionless, and its landing's impulse is vertical).
      double px_off = std::nan("");
      for (const test::Row& row : run.rows) {
        EXPECT_GE(row.extras.contacts[1].normal_force, 0.0) << what << ", t " << row.t;
        if (row.t <= t_off) continue;
        if (std::isnan(px_off)) px_off = row.quantities.linear_momentum.x();
        EXPECT_NEAR(row.quantities.linear_momentum.x(), px_off, 1e-12 * std::abs(px_off))
            << what << ", t " << row.t;
      }
      // The angle there: the run's last row, ended at the lift-off's time.
      const test::ScenarioRun to_off = test::run_inline_scenario(ladder.scenario(t_off), "to_off");
      const double cos_theta = to_off.rows.back().states[0].R_WB(2, 2);
      EXPECT_NEAR(cos_theta, std::cos(ladder.lift_off_angle()), 1e-9) << what;
    }
  }
}

// The bisection above against the rod's closed form: at b = 0, cos(theta) = (2/3) cos(theta0).
TEST(Ladder, TheBoxsLiftOffAngleIsTheRodsAtZeroThickness) {
  Ladder rod;
  rod.b = 0.0;
  rod.theta0 = 0.5;
  EXPECT_NEAR(std::cos(rod.lift_off_angle()), 2.0 / 3.0 * std::cos(rod.theta0), 1e-14);
}

}  // namespace
}  // namespace tumble
