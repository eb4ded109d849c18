#pragma once
// Runs a scenario written inline in a test through the same path as `tumble run` (read, prepare,
// integrate) and keeps every output row, for tests of whole problems.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "tumble/multibody/articulated_formulation.hpp"
#include "tumble/scenario/scenario.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble::test {

struct Row {
  double t = 0.0;
  std::vector<BodyState> states;
  SystemQuantities quantities;
  RowExtras extras;
};

struct ScenarioRun {
  Scenario scenario;
  std::vector<Row> rows;
  SimulationResult result;
  std::vector<JumpRecord> jumps;  // articulated systems only
  std::vector<ContactEventRecord> contact_events;
  std::vector<RigidBody> bodies;       // the model's, as the run integrated them
  std::vector<PlaneContact> contacts;  // the model's
};

// The file goes into a directory of the running test's own: ctest runs tests in parallel.
inline Scenario load_inline_scenario(const std::string& yaml, const std::string& name) {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "tumble_scenario_run" /
      (test != nullptr ? std::string(test->test_suite_name()) + "." + test->name() : "none");
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / (name + ".yaml");
  std::ofstream(path) << yaml;
  return load_scenario(path.string(), {});
}

ScenarioRun run_inline_scenario(const std::string& yaml, const std::string& name);
// Prepares and runs a loaded scenario; a run that does not complete is a test failure.
ScenarioRun run_scenario(Scenario scenario);

// No row's total energy above the one before it by more than `relative` of the first's: impacts
// and friction never add energy.
void expect_energy_never_rises(const ScenarioRun& run, double relative);

// The first body rolling down a plane from rest at the closed form's acceleration a along down_W:
// at each row its travel a t^2 / 2 and speed a t, its turn about axle_W alone at v /
// rolling_radius, every contact rolling (mode 2), E conserved; each to 1e-10 of the closed form's
// values (runs at rtol 1e-12: their error is ~1e-12 of them). M is the whole mass.
void expect_rolls_down_from_rest(const ScenarioRun& run, double a, const Vec3& down_W,
                                 const Vec3& axle_W, double rolling_radius, double M);

// Times where x(t) crosses zero upwards, from rows (t, x, x') by cubic Hermite interpolation on x
// and its rate (error ~ h^4 x'''' / 384: below 1e-12 of a period at 2000 rows a period).
std::vector<double> upward_zero_crossings(const std::vector<double>& t,
                                          const std::vector<double>& x,
                                          const std::vector<double>& rate);

// `text` with its first `from` replaced by `to` (which must be there: a test failure if not).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// Reads and prepares an inline scenario that must fail with a ScenarioError at line:column, for
// key, whose reason contains `why`.
void expect_error(const std::string& yaml, int line, int column, const std::string& key,
                  const std::string& why);

}  // namespace tumble::test
