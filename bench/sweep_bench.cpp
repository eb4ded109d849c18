// tumble sweep's throughput: runs per second of a 1,000-run sweep (run_points, which each run
// reads the scenario from its thread's parsed document, builds the run's model, integrates and
// records the outcomes) on 1 and 2 threads, and the same 1,000 runs' integration alone (the models
// built beforehand, rows made and dropped, as tumble run makes them for its CSV): the sweep's cost
// per run over that is what reading, building and recording add.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "tumble/scenario/scenario_document.hpp"
#include "tumble/simulation/simulation.hpp"
#include "tumble/sweep/parameter_space.hpp"
#include "tumble/sweep/sweep.hpp"

namespace tumble {
namespace {

struct SweepCase {
  const char* stem;
  const char* vary;    // NAME=START:STOP:1000
  const char* record;  // NAME=REDUCTION
};
const SweepCase kPrism{"tumbling_prism", "a=3.9:4.1:1000", "w3=min(prism.w3)"};
const SweepCase kBackspin{"backspin_disk", "v0=1.5:2.5:1000", "roll=first(floor.rolls)"};

struct PreparedSweep {
  SweepSpec spec;
  std::vector<std::vector<double>> points;
  std::vector<std::shared_ptr<const SimulationModel>> models;  // one per point
};

const PreparedSweep& prepared(const SweepCase& c) {
  static std::map<std::string, PreparedSweep> sweeps;
  PreparedSweep& p = sweeps[c.stem];
  if (p.points.empty()) {
    p.spec.path = std::string(TUMBLE_SOURCE_DIR) + "/examples/" + c.stem + ".yaml";
    p.spec.text = read_scenario_file(p.spec.path);
    const VaryRange range = parse_vary(c.vary, true);
    p.spec.varied = {range.name};
    p.spec.outcomes = {parse_record(c.record)};
    p.points = grid_points(std::vector<VaryRange>{range}, 1000);
    const ScenarioDocument document = ScenarioDocument::from_text(p.spec.text, p.spec.path);
    for (const std::vector<double>& point : p.points) {
      p.models.push_back(
          build_simulation_model(document.read({{range.name, std::to_string(point[0])}})));
    }
  }
  return p;
}

void BM_Sweep1000(benchmark::State& state, const SweepCase& c) {
  const PreparedSweep& p = prepared(c);
  const int threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const std::vector<RunRecord> records = run_points(p.spec, p.points, threads);
    benchmark::DoNotOptimize(records.data());
    if (records.front().status != RunStatus::Ok) state.SkipWithError("a run failed");
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(p.points.size()));
}

void BM_Integration1000(benchmark::State& state, const SweepCase& c) {
  const PreparedSweep& p = prepared(c);
  const RowObserver ignore = [](double, std::span<const BodyState>, const SystemQuantities&) {};
  for (auto _ : state) {
    for (const auto& model : p.models) {
      PreparedSimulation run = prepare_run(*model);
      const SimulationResult result = run_simulation(run, ignore);
      benchmark::DoNotOptimize(result.rows);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(p.points.size()));
}

}  // namespace

BENCHMARK_CAPTURE(BM_Integration1000, tumbling_prism, kPrism)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Sweep1000, tumbling_prism, kPrism)
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Integration1000, backspin_disk, kBackspin)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Sweep1000, backspin_disk, kBackspin)
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace tumble
