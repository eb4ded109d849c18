#pragma once
// What the tests of `tumble modes` share: the examples' paths, the modes of a scenario file, and
// the bar for an eigenvalue against its closed form (1e-9 relative, the issue's: the Jacobian is
// exact to round-off, so the eigenvalues are good to ~1e-14).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "tumble/modes/scenario_modes.hpp"

namespace tumble::test {

constexpr double kModesRelative = 1e-9;

inline std::string example(const std::string& name) {
  return std::string(TUMBLE_SOURCE_DIR) + "/examples/" + name;
}

inline ScenarioModes modes_of(const std::string& path,
                              const std::vector<ParameterOverride>& sets = {}) {
  return modes_of_scenario(load_scenario(path, sets));
}

inline void expect_relative(double actual, double expected) {
  EXPECT_NEAR(actual, expected, kModesRelative * std::abs(expected)) << "expected " << expected;
}

}  // namespace tumble::test
