// The broad phase's cost as the bodies grow in number: a hard-sphere gas (balls of radius 0.05 m
// and 0.1 kg on a jittered grid of 0.2 m, up to 1 m/s along each axis, no gravity, elastic and
// frictionless) in a closed box of six walls welded to ground, the box grown with the balls so
// that their density stays the same, over 1 s; one contact, `bodies: all`.
// - BM_BallGas/<n>: n balls, the group's pairs screened (contact/broad_phase.hpp);
// - BM_BallGasEveryPairWatched/<n>: the same with every pair named on its own, which each step
//   watches (the narrow phase of all n (n - 1) / 2 + 6 n pairs at every evaluation), for scale.
// Counters: steps, time per step (s), pairs (the group's contacts), impacts.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "example_timing.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble::broad_phase_bench {
namespace {

constexpr double kRadius = 0.05, kSpacing = 4 * kRadius, kWall = 0.05;

std::string ball_gas(int n, bool every_pair_named) {
  const int per_side = static_cast<int>(std::ceil(std::cbrt(static_cast<double>(n)) - 1e-9));
  const double width = per_side * kSpacing;
  std::uint64_t seed = 2026;
  const auto uniform = [&seed] {  // in [0, 1), the same on every platform
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(seed >> 11) * 0x1.0p-53;
  };
  std::string yaml = "tumble: 1\ngravity: [0, 0, 0]\nbodies:\n";
  std::vector<std::string> names;
  for (int i = 0; i < n; ++i) {
    const int cell[3] = {i % per_side, (i / per_side) % per_side, i / (per_side * per_side)};
    double p[3], v[3];
    for (int k = 0; k < 3; ++k) {
      p[k] = -width / 2 + kSpacing * (cell[k] + 0.5) + kRadius * (uniform() - 0.5);
      v[k] = 2 * uniform() - 1;
    }
    names.push_back(fmt::format("b{}", i));
    yaml += fmt::format(
        "  b{}: {{shape: sphere, radius: {}, mass: 0.1, position: [{}, {}, {}], velocity: [{}, {}, "
        "{}]}}\n",
        i, kRadius, p[0], p[1], p[2], v[0], v[1], v[2]);
  }
  const double at = width / 2 + kWall / 2;
  for (int axis = 0; axis < 3; ++axis) {
    for (const int side : {-1, 1}) {
      double size[3] = {width, width, width}, centre[3] = {0, 0, 0};
      size[axis] = kWall;
      centre[axis] = side * at;
      const std::string wall = fmt::format("wall_{}{}", "xyz"[axis], side < 0 ? "lo" : "hi");
      yaml +=
          fmt::format("  {}: {{shape: box, size: [{}, {}, {}], mass: 9, position: [{}, {}, {}]}}\n",
                      wall, size[0], size[1], size[2], centre[0], centre[1], centre[2]);
      names.push_back(wall);
    }
  }
  yaml += "joints:\n";
  for (std::size_t w = static_cast<std::size_t>(n); w < names.size(); ++w) {
    yaml +=
        fmt::format("  fix_{0}: {{type: fixed, bodies: [ground, {0}], at: [0, 0, 0]}}\n", names[w]);
  }
  yaml += "contacts:\n";
  if (!every_pair_named) {
    yaml += "  - {name: hit, type: bodies, bodies: all, friction: 0, restitution: 1}\n";
  } else {
    for (std::size_t a = 0; a < static_cast<std::size_t>(n); ++a) {
      for (std::size_t b = a + 1; b < names.size(); ++b) {
        yaml += fmt::format(
            "  - {{name: hit_{0}_{1}, type: bodies, bodies: [{0}, {1}], friction: 0, restitution: "
            "1}}\n",
            names[a], names[b]);
      }
    }
  }
  yaml +=
      "simulate: {duration: 1, integrator: dop853, rtol: 1e-10, atol: 1e-12, output_every: 1}\n";
  return yaml;
}

void BM_BallGas(benchmark::State& state, bool every_pair_named) {
  const int n = static_cast<int>(state.range(0));
  const Scenario scenario = load_scenario_text(ball_gas(n, every_pair_named), "ball_gas.yaml", {});
  PreparedSimulation simulation = prepare_simulation(scenario);
  const SimulationResult result = time_runs(state, simulation);
  const auto steps = static_cast<double>(result.report.stats.accepted_steps);
  state.counters["steps"] = steps;
  state.counters["time_per_step"] = benchmark::Counter(
      steps, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["pairs"] = static_cast<double>(scenario.contacts.size());
  state.counters["impacts"] = static_cast<double>(result.contact_events.size());
}

BENCHMARK_CAPTURE(BM_BallGas, screened, false)
    ->Arg(25)
    ->Arg(50)
    ->Arg(100)
    ->Arg(200)
    ->Unit(benchmark::kMillisecond);
// Every pair watched: its contacts' dense scratch grows as their square, so no more than 50.
BENCHMARK_CAPTURE(BM_BallGas, every_pair_watched, true)
    ->Arg(25)
    ->Arg(50)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tumble::broad_phase_bench
