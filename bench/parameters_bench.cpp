// Reading a scenario of many parameters (10^5 and 10^6): each is evaluated and defined as the
// reader goes, a search of every earlier name once made that quadratic (50,000 parameters took
// 2.0 s, 200,000 took 31 s); by the names' hash it is linear. Timed: the YAML parsed and the
// document read (what `tumble run` does before it builds the model), and the parsed document read
// alone (what each run of a sweep does). Every tenth parameter is an expression of the one above
// it, the rest plain numbers; one body uses the last.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <string>

#include "tumble/scenario/scenario_document.hpp"

namespace tumble {
namespace {

std::string scenario_of_parameters(long count) {
  std::string text = "tumble: 1\nparameters:\n";
  text.reserve(static_cast<std::size_t>(count) * 24);
  for (long i = 0; i < count; ++i) {
    text +=
        i % 10 == 9 ? fmt::format("  p{}: p{} + 1\n", i, i - 1) : fmt::format("  p{}: {}\n", i, i);
  }
  return text + fmt::format(
                    "bodies:\n  ball: {{shape: sphere, radius: 0.1, mass: p{} - p{}}}\n"
                    "simulate: {{duration: 1}}\n",
                    count - 1, count - 2);
}

void check_read(benchmark::State& state, const Scenario& scenario) {
  if (scenario.parameters.size() != static_cast<std::size_t>(state.range(0)) ||
      scenario.bodies.at(0).mass_properties.mass != 1.0) {
    state.SkipWithError("the scenario was not read as written");
  }
}

void BM_ParseAndReadParameters(benchmark::State& state) {
  const std::string text = scenario_of_parameters(state.range(0));
  Scenario scenario;
  for (auto _ : state) {
    scenario = ScenarioDocument::from_text(text, "parameters.yaml").read({});
    benchmark::DoNotOptimize(scenario.parameters);
  }
  check_read(state, scenario);
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_ReadParsedParameters(benchmark::State& state) {
  const ScenarioDocument document =
      ScenarioDocument::from_text(scenario_of_parameters(state.range(0)), "parameters.yaml");
  Scenario scenario;
  for (auto _ : state) {
    scenario = document.read({});
    benchmark::DoNotOptimize(scenario.parameters);
  }
  check_read(state, scenario);
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

}  // namespace

BENCHMARK(BM_ParseAndReadParameters)
    ->Arg(100'000)
    ->Arg(1'000'000)
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadParsedParameters)
    ->Arg(100'000)
    ->Arg(1'000'000)
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond);

}  // namespace tumble
