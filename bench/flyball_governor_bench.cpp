// The IFToMM A05 flyball governor (examples/flyball_governor.yaml: stiff couplers of 8e5 N/m and
// 4e4 N s/m between the arms and the slider) over its 5 s, by each method at the tolerance that
// follows the swing, all against one reference: dop853 at rtol 1e-12, atol 1e-14.
//  - BM_FlyballGovernor/auto: the example's own method and tolerances (rtol 1e-8): dop853
//    until its stability holds the steps, then radau5.
//  - BM_FlyballGovernor/radau5: the same tolerances, implicit from the start.
//  - BM_FlyballGovernor/auto_rtol_1e-10: auto a hundred times tighter (atol 1e-12).
//  - BM_FlyballGovernor/dopri5_rtol_1e-4 and dop853_rtol_1e-8: the explicit methods, the first at
//    the loosest tolerance that still follows the swing (tests/stiff_systems_test.cpp), both held
//    to small steps by their stability along the couplers' damping.
// Counters: error, the largest distance (m) of the arms' and the slider's centres from the
// reference's at the rows (the arms are 1 m long); steps.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <algorithm>
#include <span>
#include <vector>

#include "example_timing.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble::flyball_governor_bench {
namespace {

// The arms' and the slider's centres at every row (the shaft turns about its fixed axis).
using Positions = std::vector<Vec3>;

Scenario governor(const char* method, double rtol, double atol) {
  Scenario scenario = load_scenario(example_path("flyball_governor"), {});
  scenario.simulate.integrator = method;
  scenario.simulate.rtol = rtol;
  scenario.simulate.atol = atol;
  return scenario;
}

Positions positions_of(PreparedSimulation& simulation) {
  Positions positions;
  run_simulation(simulation,
                 [&](double, std::span<const BodyState> states, const SystemQuantities&) {
                   for (std::size_t body = 1; body < states.size(); ++body) {
                     positions.push_back(states[body].r_G);
                   }
                 });
  return positions;
}

const Positions& reference() {
  static const Positions positions = [] {
    PreparedSimulation simulation = prepare_simulation(governor("dop853", 1e-12, 1e-14));
    return positions_of(simulation);
  }();
  return positions;
}

void BM_FlyballGovernor(benchmark::State& state, const char* method, double rtol, double atol) {
  PreparedSimulation simulation = prepare_simulation(governor(method, rtol, atol));
  const Positions& exact = reference();
  const SimulationResult result = time_runs(state, simulation);
  const Positions positions = positions_of(simulation);
  if (positions.size() != exact.size()) state.SkipWithError("not the reference's rows");
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(positions.size(), exact.size()); ++i) {
    worst = std::max(worst, (positions[i] - exact[i]).cwiseAbs().maxCoeff());
  }
  state.counters["error"] = worst;
  state.counters["steps"] = static_cast<double>(result.report.stats.accepted_steps);
}

[[maybe_unused]] const bool kFlyballRegistered = [] {
  struct Run {
    const char* name;
    const char* method;
    double rtol, atol;
  };
  // auto and radau5 at the example's tolerances.
  for (const Run& run :
       {Run{"auto", "auto", 1e-8, 1e-10}, Run{"radau5", "radau5", 1e-8, 1e-10},
        Run{"auto_rtol_1e-10", "auto", 1e-10, 1e-12}, Run{"dopri5_rtol_1e-4", "dopri5", 1e-4, 1e-6},
        Run{"dop853_rtol_1e-8", "dop853", 1e-8, 1e-10}}) {
    benchmark::RegisterBenchmark(fmt::format("BM_FlyballGovernor/{}", run.name).c_str(),
                                 BM_FlyballGovernor, run.method, run.rtol, run.atol)
        ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace
}  // namespace tumble::flyball_governor_bench
