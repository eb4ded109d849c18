// A ring sliding down a ramp 1e-6 below its critical friction (examples/sweeps/
// ring_near_critical_friction.yaml), whose small slip makes its friction stiff: `auto` (radau5
// once dop853's steps are held by stability) over the whole 1.5 s. (dop853, held by its
// stability throughout, takes two million steps and a minute: BENCHMARKS.md.) Counters:
// steps, and `slip_error`, the largest departure of the rows' slip (m/s) from the closed form
// g sin(theta) (1 - mu / mu_crit) t.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <span>

#include "example_timing.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble {
namespace {

void BM_RingNearCriticalFriction(benchmark::State& state, const char* integrator, double rtol) {
  Scenario scenario = load_scenario(example_path("sweeps/ring_near_critical_friction"), {});
  scenario.simulate.integrator = integrator;
  scenario.simulate.rtol = rtol;
  PreparedSimulation simulation = prepare_simulation(scenario);
  const double theta = M_PI / 6, R = 0.1, below = 1e-6, g = 9.81;  // the example's
  const Vec3 down(std::cos(theta), 0, -std::sin(theta)), n(std::sin(theta), 0, std::cos(theta));
  double slip_error = 0.0;
  const RowObserver slip = [&](double t, std::span<const BodyState> states,
                               const SystemQuantities&) {
    const Vec3 slip_W = states[0].v_G + states[0].omega_W.cross(-R * n);
    slip_error = std::max(slip_error, std::abs(slip_W.dot(down) - g * std::sin(theta) * below * t));
  };
  SimulationResult result;
  for (auto _ : state) {
    slip_error = 0.0;
    result = run_simulation(simulation, slip);
    benchmark::DoNotOptimize(slip_error);
  }
  if (!result.report.completed) state.SkipWithError(result.report.failure.c_str());
  state.counters["steps"] = static_cast<double>(result.report.stats.accepted_steps);
  state.counters["rejected"] = static_cast<double>(result.report.stats.rejected_steps);
  state.counters["slip_error"] = slip_error;
}

BENCHMARK_CAPTURE(BM_RingNearCriticalFriction, auto_rtol_1e - 9, "auto", 1e-9)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RingNearCriticalFriction, auto_rtol_1e - 10, "auto", 1e-10)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tumble
