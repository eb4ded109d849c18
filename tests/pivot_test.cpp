// A two-point part (a round body's side, a polyhedron's edge) sliding with friction at each end
// against that end's own slip, and pivoting about one end that sticks while the other slides
// (docs/design.md, "Two-point parts"). The case that needs both: the sleeping top of
// examples/modes/ at 40 rad/s, too slow to stand, leaning at 0.01 rad/s
// (examples/top_lands_on_its_side.yaml). It falls while its apex slides, lands on its side still
// spinning, slides on its side (its base's rim at ~w r = 2 m/s, its apex far slower), pivots
// about its apex once the apex's slip stops, lets go when the apex's friction reaches the cone's
// edge, and rolls on its side once both slips are gone. With the part's friction at its middle
// (one slip, and a moment against the spin) the side's centre of pressure left it at once: the
// cone landed on its side and on its apex, apart between, a thousand times in 2e-7 s, and the
// run failed.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scenario_run.hpp"
#include "tumble/scenario/scenario.hpp"

namespace tumble {
namespace {

constexpr double kTopRadius = 0.05, kTopHeight = 0.04, kTableFriction = 0.5;

test::ScenarioRun top_falling_onto_its_side() {
  return test::run_scenario(
      load_scenario(std::string(TUMBLE_SOURCE_DIR) + "/examples/top_lands_on_its_side.yaml", {}));
}

// The velocity of the body's material point p_B (body axes, from the COM), world axes.
Vec3 material_point_velocity_W(const BodyState& s, const Vec3& p_B) {
  return s.v_G + s.omega_W.cross(s.R_WB * p_B);
}

std::size_t index_of_event(const test::ScenarioRun& run, const std::string& what) {
  for (std::size_t i = 0; i < run.contact_events.size(); ++i) {
    if (run.contact_events[i].what == what) return i;
  }
  ADD_FAILURE() << "no event '" << what << "'";
  return run.contact_events.size();
}

TEST(Pivot, ASpinningTopLandingOnItsSidePivotsAboutItsApexAndRollsOnItsSide) {
  const test::ScenarioRun run = top_falling_onto_its_side();
  // Fewer than a hundred events (not a thousand landings in 2e-7 s), and it runs to its end.
  ASSERT_LT(run.contact_events.size(), 100u);
  ASSERT_TRUE(run.result.report.completed);
  const std::size_t lands = index_of_event(run, "slides on its side");
  const std::size_t pins =
      index_of_event(run, "slides on its side, turning about its apex, which sticks");
  const std::size_t lets_go =
      index_of_event(run, "its apex slides: the friction sticking needs leaves the cone");
  const std::size_t rolls = index_of_event(run, "rolls on its side");
  ASSERT_LT(lands, pins);
  ASSERT_LT(pins, lets_go);
  ASSERT_LT(lets_go, rolls);
  EXPECT_EQ(rolls + 1, run.contact_events.size());  // and it rolls on to the end
  EXPECT_EQ(run.contact_events[pins - 1].what, "slip stops at its apex");
  EXPECT_NEAR(run.contact_events[pins].t, 0.915107, 1e-6);  // where it was first found
  const double t_pins = run.contact_events[pins].t, t_lets_go = run.contact_events[lets_go].t;
  const double t_rolls = run.contact_events[rolls].t;

  // Friction and impacts only take energy out.
  test::expect_energy_never_rises(run, 1e-9);
  const Vec3 apex_B(0, 0, 0.75 * kTopHeight);
  // The speed scale: the rim's speed from the spin, w r = 2 m/s. The projection after every step
  // holds what the mode holds to round-off; between, a step's error is ~rtol (1e-10) of it.
  const double speed_scale = 40.0 * kTopRadius, held = 1e-9 * speed_scale;
  double E_rolling = 0.0;
  int pivot_rows = 0, rolling_rows = 0;
  for (const test::Row& row : run.rows) {
    const BodyState& s = row.states[0];
    const ContactOutput& c = row.extras.contacts[0];
    // Coulomb at every row: the friction within the cone (at each end, so in all).
    EXPECT_LE(c.friction_W.norm(), kTableFriction * c.normal_force * (1.0 + 1e-9)) << "t " << row.t;
    if (row.t > t_pins && row.t < t_lets_go) {
      // Pivoting: the apex stays where it stuck, while the side slides.
      ++pivot_rows;
      EXPECT_EQ(c.mode, 1) << "t " << row.t;
      EXPECT_LT(material_point_velocity_W(s, apex_B).norm(), held) << "t " << row.t;
      EXPECT_GT(c.slip_speed, 1e3 * held) << "t " << row.t;
    }
    if (row.t > t_rolls) {
      // Rolling on its side about its apex: the line of contact at rest, and no work done.
      ++rolling_rows;
      EXPECT_EQ(c.mode, 2) << "t " << row.t;
      EXPECT_LT(material_point_velocity_W(s, apex_B).norm(), held) << "t " << row.t;
      EXPECT_LT(c.slip_speed, held) << "t " << row.t;
      if (E_rolling == 0.0) E_rolling = row.quantities.total_energy;
      EXPECT_NEAR(row.quantities.total_energy, E_rolling, 1e-9 * std::abs(E_rolling))
          << "t " << row.t;
    }
  }
  EXPECT_GT(pivot_rows, 10);
  EXPECT_GT(rolling_rows, 10);
  // The work-energy theorem over the run, friction's and the landing's work included: 1e-9 of
  // the energy scale (0.09 J), from rtol 1e-10 over the run's steps.
  EXPECT_LT(run.result.conservation.max_work_energy_residual, 1e-9 * 0.09);
}

}  // namespace
}  // namespace tumble
