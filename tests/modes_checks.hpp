#pragma once
// What the tests of `tumble modes` share: the examples' paths (test::example, test_files.hpp), the
// modes of a scenario file, and the bar for an eigenvalue against its closed form (1e-9 relative,
// the issue's: the Jacobian is exact to round-off, so the eigenvalues are good to ~1e-14).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "test_files.hpp"
#include "tumble/modes/scenario_modes.hpp"

namespace tumble::test {

constexpr double kModesRelative = 1e-9;

inline ScenarioModes modes_of(const std::string& path,
                              const std::vector<ParameterOverride>& sets = {}) {
  return modes_of_scenario(load_scenario(path, sets));
}

inline void expect_relative(double actual, double expected) {
  EXPECT_NEAR(actual, expected, kModesRelative * std::abs(expected)) << "expected " << expected;
}

// Every mode oscillates, and their natural frequencies are `expected` (in any order) to
// `relative`.
inline void expect_oscillating_at(const ModalAnalysis& analysis, std::vector<double> expected,
                                  double relative) {
  std::vector<double> found;
  for (const Mode& mode : analysis.modes) {
    EXPECT_EQ(mode.kind, Mode::Kind::Oscillating);
    found.push_back(mode.natural_frequency);
  }
  std::sort(found.begin(), found.end());
  std::sort(expected.begin(), expected.end());
  ASSERT_EQ(found.size(), expected.size());
  for (std::size_t i = 0; i < found.size(); ++i) {
    EXPECT_NEAR(found[i], expected[i], relative * expected[i]) << "mode " << i;
  }
}

// A system without damping: each growing mode lambda has one decaying twin, -conj(lambda) to
// 1e-9 relative, that names it and has no damping ratio; no mode is called damped.
inline void expect_undamped_twins(const ModalAnalysis& analysis) {
  std::size_t growing = 0, twins = 0;
  for (const Mode& mode : analysis.modes) {
    EXPECT_NE(mode.kind, Mode::Kind::DampedOscillation);
    EXPECT_NE(mode.kind, Mode::Kind::Decaying);
    if (mode.kind == Mode::Kind::Growing) ++growing;
    if (mode.kind != Mode::Kind::DecayingTwin) continue;
    ++twins;
    ASSERT_LT(mode.twin_of, analysis.modes.size());
    const Mode& grows = analysis.modes[mode.twin_of];
    EXPECT_EQ(grows.kind, Mode::Kind::Growing);
    EXPECT_NEAR(std::abs(mode.eigenvalue + std::conj(grows.eigenvalue)), 0.0,
                kModesRelative * std::abs(grows.eigenvalue));
    EXPECT_TRUE(std::isnan(mode.damping_ratio));
  }
  EXPECT_GT(growing, 0U);
  EXPECT_EQ(twins, growing);
}

}  // namespace tumble::test
