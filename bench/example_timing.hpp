#pragma once
// Timing an example as `tumble run` integrates it, shared by the benchmarks of the examples.
#include <benchmark/benchmark.h>

#include <span>
#include <string>

#include "tumble/simulation/simulation.hpp"

namespace tumble {

// A benchmark's argument with the name it is registered under ("1e-7" for 1e-7).
struct NamedValue {
  const char* name;
  double value;
};

inline std::string example_path(const char* stem) {
  return std::string(TUMBLE_SOURCE_DIR) + "/examples/" + stem + ".yaml";
}

// Times whole runs of `simulation` (rows made, not kept) and gives the last one's result; a run
// that fails marks the benchmark as an error.
inline SimulationResult time_runs(benchmark::State& state, PreparedSimulation& simulation) {
  const RowObserver ignore = [](double, std::span<const BodyState>, const SystemQuantities&) {};
  SimulationResult result;
  for (auto _ : state) {
    result = run_simulation(simulation, ignore);
    benchmark::DoNotOptimize(result.rows);
  }
  if (!result.report.completed) state.SkipWithError(result.report.failure.c_str());
  return result;
}

// Prepared once; run_simulation restarts the integrator and the formulation's schedule from y0
// on every call, so each iteration is the whole run from t = 0. (A lock or impulse appends one
// record to the formulation's list of jumps per run: a push_back, nothing the timing sees.)
// `integrator`, if given, replaces the scenario's method (same tolerances).
inline void time_example(benchmark::State& state, const char* stem, bool rows,
                         const char* integrator = nullptr) {
  Scenario scenario = load_scenario(example_path(stem), {});
  if (integrator != nullptr) scenario.simulate.integrator = integrator;
  PreparedSimulation simulation = prepare_simulation(scenario);
  if (!rows) simulation.options.output_every = simulation.t_end - simulation.t0;
  const SimulationResult result = time_runs(state, simulation);
  state.counters["steps"] = static_cast<double>(result.report.stats.accepted_steps);
  state.counters["evaluations"] = static_cast<double>(result.report.stats.rhs_evaluations);
  state.counters["rows"] = static_cast<double>(result.rows);
  state.counters["energy_drift"] = result.conservation.max_relative_energy_drift;
}

}  // namespace tumble
