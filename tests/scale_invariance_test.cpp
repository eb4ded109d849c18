// Scale-invariant error control (docs/integrators.md, "How the tolerances are scaled"): the same
// motion at any mass takes the same steps. The coordinates and speeds do not change with the
// masses, and the work ledger, which does, is held to atol in units of what the energy changes by
// when the state is off by a unit (ledger_unit); before, it was held to atol joules, and a cone
// of 1e9 kg rolling on its side took 265,000 steps where 0.5 kg took 124.
//  - Masses scaled by 2^30 scale every force, energy and work by exactly 2^30 in floating point:
//    the runs are the same step for step, the positions the same to the last bit.
//  - Scaled by 1e9 or 1e-6 (not powers of two), round-off differs: the steps agree to a few.
//  - Gravity scaled by 1e5 with time rescaled by its square root (the same motion, faster): the
//    speeds are 316 times larger in m/s while their atol stays in m/s, so the steps agree to 10%.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "scenario_run.hpp"

namespace tumble {
namespace {

using test::Row;

test::ScenarioRun run_cone(const std::vector<ParameterOverride>& overrides) {
  return test::run_scenario(load_scenario(
      std::string(TUMBLE_SOURCE_DIR) + "/examples/cone_rolling_on_its_side.yaml", overrides));
}

TEST(ScaleInvariance, TheSameMotionAtAnyMassTakesTheSameSteps) {
  const auto base = run_cone({});
  const long steps = base.result.report.stats.accepted_steps;
  const double two_30 = std::ldexp(1.0, 30);
  const auto heavy = run_cone({{"M", "0.5 * 2^30"}});
  EXPECT_EQ(heavy.result.report.stats.accepted_steps, steps);
  ASSERT_EQ(heavy.rows.size(), base.rows.size());
  for (std::size_t i = 0; i < base.rows.size(); ++i) {
    EXPECT_EQ(heavy.rows[i].states[0].r_G, base.rows[i].states[0].r_G) << base.rows[i].t;
    EXPECT_EQ(heavy.rows[i].quantities.total_energy, two_30 * base.rows[i].quantities.total_energy);
  }
  for (const char* mass : {"0.5e9", "0.5e-6"}) {
    const auto scaled = run_cone({{"M", mass}});
    EXPECT_NEAR(static_cast<double>(scaled.result.report.stats.accepted_steps),
                static_cast<double>(steps), 2.0)
        << "M = " << mass;
    // The same relative accuracy: the energy's drift against its own scale.
    EXPECT_NEAR(scaled.result.conservation.max_relative_energy_drift,
                base.result.conservation.max_relative_energy_drift, 1e-12)
        << "M = " << mass;
  }
}

TEST(ScaleInvariance, TheSameMotionUnderStrongerGravityTakesAboutTheSameSteps) {
  const auto base = run_cone({});
  // g 9.81 -> 9.81e5: time runs sqrt(1e5) faster; Omega (and with it the duration) rescaled.
  const auto fast = run_cone({{"g", "9.81e5"}, {"Omega", "2 * sqrt(1e5)"}});
  const double steps = static_cast<double>(base.result.report.stats.accepted_steps);
  EXPECT_NEAR(static_cast<double>(fast.result.report.stats.accepted_steps), steps, 0.1 * steps);
  // Its motion is the base's at t sqrt(1e5): the apex stays put, the COM at the same height.
  EXPECT_NEAR(fast.rows.back().states[0].r_G.z(), base.rows.back().states[0].r_G.z(), 1e-9);
}

}  // namespace
}  // namespace tumble
