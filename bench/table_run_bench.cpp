// What Python's Model.run costs in C++ alone: run_into_table (prepare_run, the integration, every
// row into a RowTable) of a model built once. bench/python_bench.py times Model.run on the same
// examples and reports its overhead over these figures.
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "tumble/scenario/scenario.hpp"
#include "tumble/simulation/table_run.hpp"

namespace tumble {
namespace {

void BM_RunIntoTable(benchmark::State& state, const char* stem) {
  const Scenario scenario =
      load_scenario(std::string(TUMBLE_SOURCE_DIR) + "/examples/" + stem + ".yaml", {});
  const std::shared_ptr<const SimulationModel> model = build_simulation_model(scenario);
  std::size_t rows = 0;
  for (auto _ : state) {
    TableRun run = run_into_table(scenario, *model);
    rows = run.table.rows();
    benchmark::DoNotOptimize(run.table.values().data());
  }
  state.counters["rows"] = static_cast<double>(rows);
}

}  // namespace

BENCHMARK_CAPTURE(BM_RunIntoTable, tumbling_prism, "tumbling_prism")->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_RunIntoTable, backspin_disk, "backspin_disk")->Unit(benchmark::kMicrosecond);

}  // namespace tumble
