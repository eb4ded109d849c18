// Reading and building a scenario of many bodies: a chain of n boxes on hinges (each joint names
// the body before it) and a swarm of n free spheres. What `tumble run` does
// before its first step: the YAML parsed, the document read, the model built and a run prepared.
// A chain of 1,000 / 3,000 / 10,000 bodies once took 0.29 / 2.27 / 25.7 s (searches of every
// body by name, and a union-find without path halving, made it quadratic); it is now n log n.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <string>

#include "tumble/scenario/scenario_document.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble {
namespace {

std::string chain_of_bodies(long count) {
  std::string text = "tumble: 1\ngravity: [0, 0, -9.81]\nbodies:\n";
  for (long i = 0; i < count; ++i) {
    text +=
        fmt::format("  b{}: {{shape: box, size: [1, 0.1, 0.1], mass: 1, position: [{}, 0, 0]}}\n",
                    i, static_cast<double>(i) + 0.5);
  }
  text += "joints:\n";
  for (long i = 0; i < count; ++i) {
    text +=
        fmt::format("  j{}: {{type: hinge, bodies: [{}, b{}], at: [{}, 0, 0], axis: [0, 1, 0]}}\n",
                    i, i == 0 ? std::string("ground") : fmt::format("b{}", i - 1), i, i);
  }
  return text + "simulate: {duration: 1e-6}\n";
}

std::string swarm_of_bodies(long count) {
  std::string text = "tumble: 1\ngravity: [0, 0, -9.81]\nbodies:\n";
  for (long i = 0; i < count; ++i) {
    text += fmt::format(
        "  s{}: {{shape: sphere, radius: 0.1, mass: 1, position: [{}, 0, 0], velocity: [0, 0, 1], "
        "angular_velocity: [0, 0, 1]}}\n",
        i, i);
  }
  return text + "simulate: {duration: 1e-6}\n";
}

void read_and_build(benchmark::State& state, const std::string& text) {
  std::size_t bodies = 0;
  for (auto _ : state) {
    const Scenario scenario = ScenarioDocument::from_text(text, "many.yaml").read({});
    PreparedSimulation run = prepare_simulation(scenario);
    benchmark::DoNotOptimize(run.y0.data());
    bodies = scenario.bodies.size();
  }
  if (bodies != static_cast<std::size_t>(state.range(0))) {
    state.SkipWithError("the scenario was not read as written");
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_ReadAndBuildChain(benchmark::State& state) {
  read_and_build(state, chain_of_bodies(state.range(0)));
}

void BM_ReadAndBuildSwarm(benchmark::State& state) {
  read_and_build(state, swarm_of_bodies(state.range(0)));
}

}  // namespace

BENCHMARK(BM_ReadAndBuildChain)
    ->Arg(1'000)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadAndBuildSwarm)
    ->Arg(1'000)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace tumble
