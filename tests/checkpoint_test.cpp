// Checkpoint and resume: a run stopped at t1, whose checkpoint (y, the integrator's memory, the
// hybrid state: contact modes, features, anchors, slip timers, the load schedule) goes on in a
// new run of the same model, writes after t1 exactly the bytes of the run that never stopped.
// The first run is gone before the second starts, so nothing can be shared but the checkpoint;
// through its file (simulation/checkpoint_file.hpp), nothing but the file's text.
#include <gtest/gtest.h>

#include <algorithm>

#include <filesystem>
#include <fstream>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "test_files.hpp"
#include "tumble/output/trajectory_csv.hpp"
#include "tumble/scenario/scenario.hpp"
#include "tumble/simulation/checkpoint_file.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble {
namespace {

using test::read_file;

class Csv {
 public:
  Csv(const Scenario& scenario, const PreparedSimulation& run, std::filesystem::path path) {
    writer_.emplace(std::move(path), column_layout(scenario, *run.formulation));
  }
  FullRowObserver observer() {
    return [this](double t, std::span<const BodyState> s, const SystemQuantities& q,
                  const RowExtras& extras) {
      writer_->write_row({t, s, &q, &extras});
    };
  }
  std::string finish() {
    const std::filesystem::path path = writer_->path();
    writer_->finish();
    return read_file(path);
  }

 private:
  std::optional<TrajectoryCsvWriter> writer_;
};

std::string without_header(const std::string& csv) {
  return csv.substr(csv.find('\n') + 1);
}

struct CheckpointCase {
  const char* example;
  double t1;  // s: the run stops at the first step end at or after it
  const char* what;
  // A method in place of the example's (a fixed-step one with steps of 0.01 s).
  const char* method = nullptr;
  const char* added = "";  // appended to the example's text (an `events:` section)
};

// An example's name as a test's or a directory's ("planar/backspin_disk": planar_backspin_disk).
std::string test_name_of(std::string example) {
  std::replace(example.begin(), example.end(), '/', '_');
  return example;
}

void PrintTo(const CheckpointCase& c, std::ostream* os) {
  *os << c.example << " at t = " << c.t1;
  if (c.method != nullptr) *os << " by " << c.method;
}

class Checkpoint : public ::testing::TestWithParam<CheckpointCase> {};

TEST_P(Checkpoint, ResumedRowsAreTheUninterruptedRunsBytes) {
  const CheckpointCase c = GetParam();
  const std::string path = std::string(TUMBLE_SOURCE_DIR) + "/examples/" + c.example + ".yaml";
  Scenario scenario = load_scenario_text(read_file(path) + c.added, path, {});
  if (c.method != nullptr) {
    scenario.simulate.integrator = c.method;
    scenario.simulate.step = 0.01;
  }
  const std::shared_ptr<const SimulationModel> model = build_simulation_model(scenario);
  // ctest runs the cases in parallel: one directory each.
  const std::filesystem::path dir =
      test::fresh_test_dir("Checkpoint", test_name_of(c.example) + "_" + std::to_string(c.t1) +
                                             (c.method != nullptr ? c.method : ""));

  PreparedSimulation whole = prepare_run(*model);
  Csv whole_csv(scenario, whole, dir / "whole.csv");
  const SimulationResult whole_result = run_simulation(whole, whole_csv.observer());
  ASSERT_TRUE(whole_result.report.completed) << whole_result.report.failure;
  const std::string expected = whole_csv.finish();

  std::optional<SimulationCheckpoint> checkpoint;
  std::string before;
  {
    PreparedSimulation first = prepare_run(*model);
    first.options.checkpoint_after = c.t1;
    first.options.stop_at_checkpoint = true;
    Csv csv(scenario, first, dir / "before.csv");
    run_simulation(first, csv.observer(), [&](SimulationCheckpoint k) { checkpoint = k; });
    before = csv.finish();
  }
  ASSERT_TRUE(checkpoint.has_value()) << "no checkpoint at t = " << c.t1;
  EXPECT_GE(checkpoint->t(), c.t1);
  const SimulationCheckpoint saved = *checkpoint;  // a copy: the checkpoint is a value
  checkpoint.reset();

  // Resumed from the checkpoint itself, and from it written to a file and read back into a run
  // that shares nothing with the first.
  const std::filesystem::path file = dir / "stopped.checkpoint";
  write_checkpoint_file(file, saved, CheckpointOrigin{});
  for (const bool through_file : {false, true}) {
    SCOPED_TRACE(through_file ? "resumed from the file" : "resumed from the checkpoint");
    PreparedSimulation second = prepare_run(*model);
    const SimulationCheckpoint from =
        through_file ? read_checkpoint_file(file, second).checkpoint : saved;
    Csv csv(scenario, second, dir / (through_file ? "after_file.csv" : "after.csv"));
    const SimulationResult resumed = resume_simulation(second, from, csv.observer());
    ASSERT_TRUE(resumed.report.completed) << resumed.report.failure;
    const std::string after = csv.finish();

    EXPECT_LT(before.size(), expected.size());
    EXPECT_TRUE(before + without_header(after) == expected)
        << c.example << " stopped at t = " << saved.t() << " (" << c.what << ")";
    // The resumed run reports the whole run: its steps, events, jumps and conservation.
    EXPECT_EQ(resumed.report.stats.accepted_steps, whole_result.report.stats.accepted_steps);
    EXPECT_EQ(resumed.report.stats.rejected_steps, whole_result.report.stats.rejected_steps);
    EXPECT_EQ(resumed.report.stats.rhs_evaluations, whole_result.report.stats.rhs_evaluations);
    EXPECT_EQ(resumed.report.events.size(), whole_result.report.events.size());
    ASSERT_EQ(resumed.contact_events.size(), whole_result.contact_events.size());
    for (std::size_t i = 0; i < resumed.contact_events.size(); ++i) {
      EXPECT_EQ(resumed.contact_events[i].t, whole_result.contact_events[i].t);
      EXPECT_EQ(resumed.contact_events[i].what, whole_result.contact_events[i].what);
      EXPECT_EQ(resumed.contact_events[i].kinetic_energy_after,
                whole_result.contact_events[i].kinetic_energy_after);
    }
    ASSERT_EQ(resumed.jumps.size(), whole_result.jumps.size());
    for (std::size_t i = 0; i < resumed.jumps.size(); ++i) {
      EXPECT_EQ(resumed.jumps[i].t, whole_result.jumps[i].t);
      EXPECT_EQ(resumed.jumps[i].kinetic_energy_after, whole_result.jumps[i].kinetic_energy_after);
    }
    ASSERT_EQ(resumed.user_events.size(), whole_result.user_events.size());
    for (std::size_t i = 0; i < resumed.user_events.size(); ++i) {
      EXPECT_EQ(resumed.user_events[i].t, whole_result.user_events[i].t);  // the disk's reversal
    }
    EXPECT_EQ(resumed.rows, whole_result.rows);
    EXPECT_EQ(resumed.conservation.max_energy_change, whole_result.conservation.max_energy_change);
    EXPECT_EQ(resumed.conservation.max_work_energy_residual,
              whole_result.conservation.max_work_energy_residual);
    EXPECT_EQ(resumed.conservation.max_orthonormality_error,
              whole_result.conservation.max_orthonormality_error);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Examples, Checkpoint,
    ::testing::Values(
        CheckpointCase{"tumbling_prism", 9.0, "before the flip"},
        CheckpointCase{"backspin_disk", 0.7, "in mid-slide, before the slip stops at 1.36 s"},
        CheckpointCase{"bouncing_ball", 0.8, "in flight between the first two bounces"},
        CheckpointCase{"box_slides_to_rest", 0.5, "a box sliding on its face"},
        CheckpointCase{"cubli", 0.0005, "before the lock at 1 ms"},
        CheckpointCase{"cubli", 0.7, "after the lock"},
        CheckpointCase{"cubli_falls_back", 0.3, "a held box in flight, before it lands"},
        CheckpointCase{"cubli_falls_back", 0.55, "between its first two bounces"},
        CheckpointCase{"rolling_coin", 1.0, "a coin rolling on its rim"},
        CheckpointCase{"top_lands_on_its_side", 1.0,
                       "a cone pivoting about its apex on its side, its rim sliding"},
        CheckpointCase{"planar/backspin_disk", 0.7,
                       "in the plane, before its event (it reverses at 1.02 s)"},
        CheckpointCase{"gyroscope", 0.5, "a fast spin by dop853, between rows"},
        CheckpointCase{"tumbling_prism", 9.0, "by rk4's fixed steps", "rk4"},
        CheckpointCase{"tumbling_prism", 9.0, "by rkmk4's steps on the rotation group", "rkmk4"},
        // The implicit method's memory: the Jacobian it keeps, its factorisations' step.
        CheckpointCase{"stiff_mount", 0.002, "by radau5, as the mount creeps back"},
        CheckpointCase{"inverted_mast", 5.0, "by radau5's steps on a hinge", "radau5"},
        CheckpointCase{"stiff_mount", 0.002, "by trbdf2, as the mount creeps back", "trbdf2"},
        // auto's two methods' memories, stopped after its switch to radau5 (at 0.15 ms) and before.
        CheckpointCase{"stiff_mount", 0.002, "by auto, after its switch to radau5", "auto"},
        CheckpointCase{"stiff_mount", 0.00005, "by auto, before its switch", "auto"},
        CheckpointCase{"tumbling_prism", 9.0, "by auto, never stiff", "auto"},
        // With an event to watch, the closed form steps an eighth of a turn at most.
        CheckpointCase{"tumbling_prism", 9.0, "by the closed form", "exact",
                       "events:\n  - {name: flips, when: prism.w3 < 0}\n"}),
    [](const ::testing::TestParamInfo<CheckpointCase>& param) {
      return test_name_of(param.param.example) + "_" + std::to_string(param.index);
    });

}  // namespace
}  // namespace tumble
