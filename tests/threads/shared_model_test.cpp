// What threads share is constant: one SimulationModel (or one parsed scenario, or one modal
// model) used by two threads at the same time gives, byte for byte, what using it on one thread
// gives, through every entry point that takes it constant: a run (prepare_run and
// run_simulation), `tumble modes`' analysis, and a sweep's runs that differ only in their initial
// velocities (VelocityOnlyRuns). Built also under ThreadSanitizer (scripts/test.sh), which checks
// that no thread writes what another reads.
#include <gtest/gtest.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "../test_files.hpp"
#include "tumble/modes/linearisation.hpp"
#include "tumble/modes/modal_analysis.hpp"
#include "tumble/modes/scenario_modes.hpp"
#include "tumble/output/trajectory_csv.hpp"
#include "tumble/scenario/parameter_trace.hpp"
#include "tumble/scenario/scenario.hpp"
#include "tumble/scenario/scenario_document.hpp"
#include "tumble/simulation/simulation.hpp"
#include "tumble/sweep/velocity_only_runs.hpp"

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

// A free body, joints with a motor and a lock, contacts that roll, slide and bounce, and a
// scenario's own event (the planar disk's reversal); each starts moving, so that scaling its
// speeds changes it.
INSTANTIATE_TEST_SUITE_P(Examples, SharedModel,
                         ::testing::Values("tumbling_prism", "cubli", "backspin_disk",
                                           "bouncing_ball", "rolling_coin",
                                           "planar/backspin_disk"));

// Runs `body` on two threads at once; an exception in either is a failure of the test, not an
// abort.
template <typename Body>
void on_two_threads(const Body& body) {
  std::string failures[2];
  std::vector<std::thread> threads;
  for (int i = 0; i < 2; ++i) {
    threads.emplace_back([&, i] {
      try {
        body(i);
      } catch (const std::exception& e) {
        failures[i] = e.what();
      }
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (int i = 0; i < 2; ++i) EXPECT_EQ(failures[i], "") << "thread " << i;
}

// `tumble modes`' analysis. Its entry point takes a scenario and builds the model itself
// (modes_of_scenario): two threads analyse one parsed scenario. What it builds is constant
// (ModalEquations): two threads linearise one and find its modes. Each gives the modes' CSV
// (eigenvalues, frequencies, shapes to 17 digits) that one thread alone gives.
class SharedModes : public ::testing::TestWithParam<const char*> {};

TEST_P(SharedModes, TwoThreadsGiveTheModesOfOne) {
  const std::string example = GetParam();
  const Scenario scenario =
      load_scenario(std::string(TUMBLE_SOURCE_DIR) + "/examples/modes/" + example + ".yaml", {});
  const std::string alone = modes_csv(modes_of_scenario(scenario));
  ASSERT_GT(alone.size(), 200u);
  const std::shared_ptr<const ModalEquations> equations = modal_equations_of(scenario);

  std::string from_scenario[2], from_equations[2];
  on_two_threads([&](int i) {
    from_scenario[i] = modes_csv(modes_of_scenario(scenario));
    ScenarioModes modes;
    modes.equations = equations;
    modes.linearisation = linearise(*equations);
    modes.analysis = analyse_modes(modes.linearisation);
    from_equations[i] = modes_csv(modes);
  });
  for (int i = 0; i < 2; ++i) {
    EXPECT_TRUE(from_scenario[i] == alone) << example << ", thread " << i;
    EXPECT_TRUE(from_equations[i] == alone) << example << ", thread " << i;
  }
}

// Joints (the mast on its hinge, the double pendulum's two modes) and a contact that rolls.
INSTANTIATE_TEST_SUITE_P(Examples, SharedModes,
                         ::testing::Values("inverted_mast", "double_pendulum", "rolling_disk"));

// A run of `model` from the initial state of `scenario` (which differs from the model's own in
// the bodies' velocities only), as a sweep's shared runs go: the state computed on the run's own
// formulation, the columns from the model.
void run_from_scenarios_state(const Scenario& scenario, const SimulationModel& model,
                              const std::filesystem::path& csv) {
  PreparedSimulation run = prepare_run(model);
  run.y0 = initial_state_vector(scenario, *run.formulation);
  TrajectoryCsvWriter writer(csv, column_layout(scenario, model));
  const SimulationResult result = run_simulation(run, writer);
  EXPECT_TRUE(result.report.completed) << result.report.failure;
  writer.finish();
}

// A sweep's velocity-only path: the backspin disk's v0 and w0 reach only its initial state, so
// one model, built from a traced read, serves every run, and a run computes only its scenario
// (VelocityOnlyRuns::scenario_at) and its y0. Two threads, each with its own VelocityOnlyRuns
// over the one model (as each sweep runner has), run it at different values at once; each writes
// the bytes of a run that reads and builds its own scenario at its values.
TEST(SharedModelSweep, VelocityOnlyRunsOnTwoThreadsGiveTheBytesOfTheirOwnReads) {
  const ScenarioDocument document =
      ScenarioDocument::from_file(std::string(TUMBLE_SOURCE_DIR) + "/examples/backspin_disk.yaml");
  const std::vector<std::string> varied = {"v0", "w0"};
  ParameterTrace trace{varied, {}};
  const Scenario traced = document.read({}, true, &trace);
  const std::shared_ptr<const SimulationModel> model = build_simulation_model(traced);
  ASSERT_NE(VelocityOnlyRuns::make(varied, trace, traced, model), nullptr);
  const std::filesystem::path dir = test::fresh_test_dir("SharedModelSweep", "backspin_disk");
  const std::vector<double> values[2] = {{1.5, 50.0}, {2.5, 75.0}};

  for (int i = 0; i < 2; ++i) {
    const Scenario own =
        document.read({{"v0", std::to_string(values[i][0])}, {"w0", std::to_string(values[i][1])}});
    run_from_scenarios_state(own, *build_simulation_model(own),
                             dir / ("own_" + std::to_string(i) + ".csv"));
  }
  on_two_threads([&](int i) {
    const std::unique_ptr<VelocityOnlyRuns> runs =
        VelocityOnlyRuns::make(varied, trace, traced, model);
    run_from_scenarios_state(runs->scenario_at(values[i]), runs->model(),
                             dir / ("shared_" + std::to_string(i) + ".csv"));
  });

  for (int i = 0; i < 2; ++i) {
    const std::string own = read_file(dir / ("own_" + std::to_string(i) + ".csv"));
    const std::string shared = read_file(dir / ("shared_" + std::to_string(i) + ".csv"));
    ASSERT_GT(own.size(), 1000u);
    EXPECT_TRUE(own == shared) << "run " << i;
  }
  EXPECT_TRUE(read_file(dir / "own_0.csv") != read_file(dir / "own_1.csv"));
}

}  // namespace
}  // namespace tumble
