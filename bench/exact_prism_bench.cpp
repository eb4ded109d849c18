// The chapter's tumbling prism (examples/tumbling_prism.yaml) to t = 20, 200 and 2000 s by
// `integrator: exact` (the Euler-Poinsot closed form) and by dop853 at rtol 1e-12 (atol 1e-15),
// with rows only at the start and the end, or every 0.05 s as the example writes them. The issue's
// bar: the closed form no slower than dop853 at rtol 1e-12 at any horizon.
//  - BM_ExactPrism/<method>_t<horizon>_<rows>: the whole run (run_simulation), rows made and
//    dropped.
// Counters: steps; error, the largest difference of R_WB and omega_W at the end from the closed
// form's (0 for the closed form itself).
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <span>

#include "example_timing.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble::exact_prism_bench {
namespace {

PreparedSimulation prism(const char* method, double horizon, bool rows) {
  Scenario scenario = load_scenario(example_path("tumbling_prism"), {});
  scenario.simulate.integrator = method;
  scenario.simulate.rtol = 1e-12;
  scenario.simulate.atol = 1e-15;
  scenario.simulate.duration = horizon;
  PreparedSimulation simulation = prepare_simulation(scenario);
  if (!rows) simulation.options.output_every = horizon;
  return simulation;
}

BodyState end_state(PreparedSimulation& simulation) {
  BodyState last;
  run_simulation(simulation, [&](double, std::span<const BodyState> states,
                                 const SystemQuantities&) { last = states[0]; });
  return last;
}

void BM_ExactPrism(benchmark::State& state, const char* method, double horizon, bool rows) {
  PreparedSimulation simulation = prism(method, horizon, rows);
  const SimulationResult result = time_runs(state, simulation);
  PreparedSimulation closed_form = prism("exact", horizon, false);
  const BodyState exact = end_state(closed_form);
  const BodyState last = end_state(simulation);
  state.counters["error"] = std::max((last.R_WB - exact.R_WB).cwiseAbs().maxCoeff(),
                                     (last.omega_W - exact.omega_W).cwiseAbs().maxCoeff());
  state.counters["steps"] = static_cast<double>(result.report.stats.accepted_steps);
}

[[maybe_unused]] const bool kExactPrismRegistered = [] {
  for (const double horizon : {20.0, 200.0, 2000.0}) {
    for (const bool rows : {false, true}) {
      for (const char* method : {"exact", "dop853"}) {
        benchmark::RegisterBenchmark(
            fmt::format("BM_ExactPrism/{}_t{}_{}", method, horizon, rows ? "rows_0.05" : "ends")
                .c_str(),
            BM_ExactPrism, method, horizon, rows)
            ->Unit(benchmark::kMicrosecond);
      }
    }
  }
  return true;
}();

}  // namespace
}  // namespace tumble::exact_prism_bench
