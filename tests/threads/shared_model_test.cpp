// One SimulationModel shared by two threads that run it from different initial states at the
// same time gives, byte for byte, the CSVs that running them one after the other gives: the
// model is constant, and each run's scratch and hybrid state are its own. Built also under
// ThreadSanitizer (scripts/test.sh), which checks that no run writes what another reads.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "../test_files.hpp"
#include "tumble/output/trajectory_csv.hpp"
#include "tumble/scenario/scenario.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble {
namespace {

using test::read_file;

// Runs the shared model from its initial state with every body's velocity and angular velocity
// scaled by `speed_scale` (a different problem for each scale), writing the trajectory CSV.
void run_to_csv(const Scenario& scenario, const SimulationModel& model, double speed_scale,
                const std::filesystem::path& csv) {
  PreparedSimulation run = prepare_run(model);
  std::vector<BodyState> states(run.formulation->body_count());
  run.formulation->unpack_all(model.y0, states);
  for (BodyState& s : states) {
    s.v_G *= speed_scale;
    s.omega_W *= speed_scale;
  }
  run.formulation->pack(states, run.y0);
  TrajectoryCsvWriter writer(csv, column_layout(scenario, *run.formulation));
  const SimulationResult result = run_simulation(run, writer);
  EXPECT_TRUE(result.report.completed) << result.report.failure;
  writer.finish();
}

class SharedModel : public ::testing::TestWithParam<const char*> {};

TEST_P(SharedModel, TwoThreadsGiveTheBytesOfTwoRunsInTurn) {
  const std::string example = GetParam();
  const Scenario scenario =
      load_scenario(std::string(TUMBLE_SOURCE_DIR) + "/examples/" + example + ".yaml", {});
  const std::shared_ptr<const SimulationModel> model = build_simulation_model(scenario);
  const std::filesystem::path dir = test::fresh_test_dir("SharedModel", example);
  const double scales[2] = {1.0, 0.9};

  for (int i = 0; i < 2; ++i) {
    run_to_csv(scenario, *model, scales[i], dir / ("in_turn_" + std::to_string(i) + ".csv"));
  }
  std::vector<std::thread> threads;
  for (int i = 0; i < 2; ++i) {
    threads.emplace_back([&, i] {
      run_to_csv(scenario, *model, scales[i], dir / ("together_" + std::to_string(i) + ".csv"));
    });
  }
  for (std::thread& thread : threads) thread.join();

  for (int i = 0; i < 2; ++i) {
    const std::string in_turn = read_file(dir / ("in_turn_" + std::to_string(i) + ".csv"));
    const std::string together = read_file(dir / ("together_" + std::to_string(i) + ".csv"));
    ASSERT_GT(in_turn.size(), 1000u);
    EXPECT_TRUE(in_turn == together) << example << ", run " << i;
  }
  // The two runs are different problems: the test would see one run's state leak into the other.
  EXPECT_TRUE(read_file(dir / "in_turn_0.csv") != read_file(dir / "in_turn_1.csv"));
}

// A free body, joints with a motor and a lock, and contacts that roll, slide and bounce; each
// starts moving, so that scaling its speeds changes it.
INSTANTIATE_TEST_SUITE_P(Examples, SharedModel,
                         ::testing::Values("tumbling_prism", "cubli", "backspin_disk",
                                           "bouncing_ball", "rolling_coin"));

}  // namespace
}  // namespace tumble
