// The benchmark bicycle (examples/bicycle_benchmark.yaml): what `tumble modes` does at the eleven
// speeds v = 0, 1, ..., 10 m/s (read the scenario with v set, linearise by automatic
// differentiation, take the eigenvalues), and a 20 s run from a lean rate of 0.5 rad/s at 5 m/s,
// at the example's tolerances and rows. Counters: the modes' `largest_growth` over the speeds
// (the weave's at 0 m/s, 5.53 1/s: a check that they ran), and the run's steps and energy drift.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>

#include "example_timing.hpp"
#include "tumble/modes/scenario_modes.hpp"

namespace tumble {
namespace {

void BM_BicycleModesAtElevenSpeeds(benchmark::State& state) {
  const std::string path = example_path("bicycle_benchmark");
  double largest_growth = 0.0;
  for (auto _ : state) {
    largest_growth = 0.0;
    for (int v = 0; v <= 10; ++v) {
      const ScenarioModes modes =
          modes_of_scenario(load_scenario(path, {{"v", std::to_string(v)}, {"phidot0", "0"}}));
      for (const Mode& mode : modes.analysis.modes) {
        largest_growth = std::max(largest_growth, mode.growth_rate);
      }
    }
    benchmark::DoNotOptimize(largest_growth);
  }
  state.counters["largest_growth"] = largest_growth;
}
BENCHMARK(BM_BicycleModesAtElevenSpeeds)->Unit(benchmark::kMillisecond);

void BM_BicycleRun20s(benchmark::State& state) {
  Scenario scenario = load_scenario(example_path("bicycle_benchmark"), {});
  scenario.simulate.duration = 20.0;
  PreparedSimulation simulation = prepare_simulation(scenario);
  const SimulationResult result = time_runs(state, simulation);
  state.counters["steps"] = static_cast<double>(result.report.stats.accepted_steps);
  state.counters["rows"] = static_cast<double>(result.rows);
  state.counters["energy_drift"] = result.conservation.max_relative_energy_drift;
}
BENCHMARK(BM_BicycleRun20s)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tumble
