// Runs per second of one shared SimulationModel on 1 and 2 threads: each iteration is a whole run
// (prepare_run, then the integration from t = 0, rows only at the ends), as a parameter sweep
// will do. items_per_second counts the runs of all threads together, over wall time.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "tumble/scenario/scenario.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble {
namespace {

// Built once per example, before any timed run, and shared by every thread.
const SimulationModel& shared_model(const char* stem) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const SimulationModel>> models;
  const std::lock_guard<std::mutex> lock(mutex);
  std::shared_ptr<const SimulationModel>& model = models[stem];
  if (!model) {
    model = build_simulation_model(
        load_scenario(std::string(TUMBLE_SOURCE_DIR) + "/examples/" + stem + ".yaml", {}));
  }
  return *model;
}

void BM_SharedModelRuns(benchmark::State& state, const char* stem) {
  const SimulationModel& model = shared_model(stem);
  const RowObserver ignore = [](double, std::span<const BodyState>, const SystemQuantities&) {};
  SimulationResult result;
  for (auto _ : state) {
    PreparedSimulation run = prepare_run(model);
    run.options.output_every = run.t_end - run.t0;
    result = run_simulation(run, ignore);
    benchmark::DoNotOptimize(result.rows);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["steps"] = benchmark::Counter(
      static_cast<double>(result.report.stats.accepted_steps), benchmark::Counter::kAvgThreads);
  if (!result.report.completed) state.SkipWithError(result.report.failure.c_str());
}

}  // namespace

BENCHMARK_CAPTURE(BM_SharedModelRuns, tumbling_prism, "tumbling_prism")
    ->Threads(1)
    ->Threads(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SharedModelRuns, backspin_disk, "backspin_disk")
    ->Threads(1)
    ->Threads(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace tumble
