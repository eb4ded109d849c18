// A sphere inside a shell (a bowl), touching its inside, each against its closed form. The bowl
// (radius R) is fixed; the ball (radius r, mass m, I = 2 m r^2 / 5) has its centre on the circle
// of radius rho = R - r about the bowl's centre, at the angle theta from the bottom.
//  - Rolling without slip (examples/ball_in_a_bowl.yaml, from rest at theta0): omega r = rho
//    theta', the kinetic energy (7/10) m rho^2 theta'^2, so rho theta'^2 = (10/7) g (cos theta -
//    cos theta0); the radial equation N - m g cos theta = m rho theta'^2 gives N = m g (17 cos
//    theta - 10 cos theta0) / 7, the tangential one the friction (2/7) m g sin theta. A pendulum
//    of length rho in the gravity 5g/7: its half period to 1e-9 s.
//  - Sent round from the bottom at v0, frictionless: v^2 = v0^2 - 2 g rho (1 - cos theta), and N
//    = m (g cos theta + v^2 / rho) falls to zero where cos theta = (2 - v0^2 / (g rho)) / 3;
//    rolling, v^2 = v0^2 - (10/7) g rho (1 - cos theta), where cos theta = (10 - 7 v0^2 /
//    (g rho)) / 17. Past the bowl's rim height the ball lets go of its wall and falls.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "scenario_run.hpp"
#include "test_constants.hpp"
#include "test_files.hpp"

namespace tumble {
namespace {

TEST(Bowl, ABallRollingInABowlSwingsAsAPendulumInFiveSeventhsOfGravity) {
  const double R = 0.5, r = 0.05, m = 0.2, g = 9.81, rho = R - r;
  const double theta0 = 40 * std::numbers::pi / 180;
  const test::ScenarioRun run =
      test::run_scenario(load_scenario(test::example("ball_in_a_bowl.yaml"), {}));
  // The ball is the contact's body, though `bodies:` names the bowl first.
  EXPECT_EQ(run.contacts[0].body, 1u);
  EXPECT_TRUE(run.contacts[0].other_surface.touched_inside);
  ASSERT_EQ(run.contact_events.size(), 1u);
  EXPECT_EQ(run.contact_events[0].what, "rolls");
  // The exact pendulum's period: 2 pi / AGM(1, cos(theta0 / 2)) sqrt(rho / g'), g' = 5g/7.
  double a = 1.0, b = std::cos(theta0 / 2);
  for (int i = 0; i < 8; ++i) {
    const double mean = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = mean;
  }
  const double period = 2 * std::numbers::pi / a * std::sqrt(7 * rho / (5 * g));
  const std::vector<UserEventRecord>& ends = run.result.user_events;
  ASSERT_EQ(ends.size(), 3u);
  for (std::size_t k = 0; k < ends.size(); ++k) {
    EXPECT_EQ(ends[k].name, k % 2 == 0 ? "far_side" : "back");
    EXPECT_NEAR(ends[k].t, 0.5 * period * static_cast<double>(k + 1), 1e-9);
  }
  const Vec3 bowl_centre(0, 0, R);
  for (const test::Row& row : run.rows) {
    const BodyState& ball = row.states[1];
    const Vec3 from_centre = ball.r_G - bowl_centre;
    EXPECT_NEAR(from_centre.norm(), rho, 1e-12 * rho) << row.t;
    const double cos_theta = -from_centre.z() / rho, sin_theta = from_centre.x() / rho;
    EXPECT_EQ(row.extras.contacts[0].mode, 2) << row.t;
    EXPECT_LT(row.extras.contacts[0].slip_speed, 1e-12) << row.t;
    // Rolling on the wall: the centre's speed is omega r.
    EXPECT_NEAR(ball.v_G.norm(), std::abs(ball.omega_W.y()) * r, 1e-12) << row.t;
    EXPECT_NEAR(ball.v_G.squaredNorm(), 10.0 / 7.0 * g * rho * (cos_theta - std::cos(theta0)),
                1e-11 * g * rho)
        << row.t;
    EXPECT_NEAR(row.extras.contacts[0].normal_force,
                m * g * (17 * cos_theta - 10 * std::cos(theta0)) / 7, 1e-10 * m * g)
        << row.t;
    EXPECT_NEAR(row.extras.contacts[0].friction_W.norm(), 2.0 / 7.0 * m * g * std::abs(sin_theta),
                1e-10 * m * g)
        << row.t;
    EXPECT_NEAR(row.quantities.total_energy, run.rows.front().quantities.total_energy,
                1e-11 * m * g * rho)
        << row.t;
  }
}

// The ball at the bottom of a fixed shell (R 0.5) moving at v0 (an expression) along x (rolling:
// turning at v0 / r about y, as on a floor), named in `bodies:` in the order given.
std::string sent_round(const std::string& v0, const std::string& friction,
                       const std::string& bodies) {
  return "tumble: 1\n"
         "parameters: {R: 0.5, r: 0.05, g: " +
         std::to_string(test::kG) + ", v0: " + v0 +
         "}\n"
         "gravity: [0, 0, -g]\n"
         "bodies:\n"
         "  bowl: {shape: shell, radius: R, mass: 2, position: [0, 0, R]}\n"
         "  ball: {shape: sphere, radius: r, mass: 0.2, position: [0, 0, r], velocity: [v0, 0, "
         "0], angular_velocity: [0, v0 / r, 0]}\n"
         "joints:\n"
         "  stand: {type: fixed, bodies: [ground, bowl], at: [0, 0, 0]}\n"
         "contacts:\n"
         "  - {name: in_bowl, type: bodies, bodies: " +
         bodies + ", friction: " + friction +
         ", restitution: 0}\n"
         "simulate: {duration: 0.6, integrator: dop853, rtol: 1e-12, atol: 1e-14, output_every: "
         "0.01}\n";
}

TEST(Bowl, ABallSentRoundLetsGoOfTheWallWhereItsPushFallsToZero) {
  const double g = test::kG, rho = 0.45;
  const double v0 = std::sqrt(3 * g * rho);
  struct Case {
    const char* friction;
    const char* mode;
    double cos_off;
  };
  for (const Case& c : {Case{"0", "slides", (2 - v0 * v0 / (g * rho)) / 3},
                        Case{"inf", "rolls", (10 - 7 * v0 * v0 / (g * rho)) / 17}}) {
    for (const char* bodies : {"[ball, bowl]", "[bowl, ball]"}) {
      const test::ScenarioRun run = test::run_inline_scenario(
          sent_round("sqrt(3 * g * (R - r))", c.friction, bodies), "round");
      ASSERT_GE(run.contact_events.size(), 2u) << c.friction << bodies;
      EXPECT_EQ(run.contact_events[0].t, 0.0);
      EXPECT_EQ(run.contact_events[0].what, c.mode);
      EXPECT_EQ(run.contact_events[1].what, "lifts off");
      // The normal runs from the ball's centre outwards to the wall (from the bowl, the second
      // body, towards the ball, the first): its z at theta from the bottom is cos theta.
      const Vec3& n = run.contact_events[1].normal_W;
      EXPECT_NEAR(n.z(), c.cos_off, 1e-9) << c.friction << bodies;
      EXPECT_NEAR(n.y(), 0.0, 1e-12);
      EXPECT_LT(n.x(), 0.0);
    }
  }
}

TEST(Bowl, ABallThroughTheShellsWallAtTheStartIsRefused) {
  // The ball's centre 0.47 from the shell's, its radius 0.05: through the wall by 0.02 m.
  test::expect_error(test::replaced(sent_round("1", "0", "[ball, bowl]"), "position: [0, 0, r]",
                                    "position: [0.47, 0, R]"),
                     10, 5, "contacts[0]",
                     "overlapping by 0.02 m (the sphere is inside the shell, its centre 0.47 m "
                     "from the shell's; its radius 0.05 m, the shell's 0.5 m)");
}

}  // namespace
}  // namespace tumble
