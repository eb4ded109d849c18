#include "sweep_setup.hpp"

#include <fmt/core.h>
#include <fmt/format.h>
#include <algorithm>
#include <stdexcept>

#include "commands.hpp"
#include "exit_status.hpp"
#include "tumble/scenario/scenario_document.hpp"
#include "tumble/simulation/simulation.hpp"
#include "tumble/sweep/run_recorder.hpp"

namespace tumble::cli {

int prepare_sweep(const char* command, const char* outcome_option, const std::string& scenario,
                  const std::vector<std::string>& sets, const std::vector<VaryRange>& ranges,
                  std::vector<Outcome> outcomes, SweepSpec& spec) {
  const auto bad_argument = [&](const std::string& why) {
    fmt::print(stderr, "{}: {}\n", command, why);
    return kBadCommandLine;
  };
  Scenario base;
  std::shared_ptr<const SimulationModel> model;
  try {
    spec.path = scenario;
    spec.text = read_scenario_file(scenario);
    spec.fixed = parse_overrides(sets);
    base = ScenarioDocument::from_text(spec.text, spec.path).read(spec.fixed);
    model = build_simulation_model(base);
  } catch (const ScenarioError& e) {
    fmt::print(stderr, "{}\n", e.what());
    return kInvalidScenario;
  } catch (const std::invalid_argument& e) {  // a --set that names no parameter
    return bad_argument(e.what());
  }
  std::vector<std::string> parameters;
  for (const auto& [name, value] : base.parameters) parameters.push_back(name);
  for (const VaryRange& range : ranges) {
    if (std::find(parameters.begin(), parameters.end(), range.name) == parameters.end()) {
      return bad_argument(fmt::format(
          "--vary {}: no parameter {} in {}; {}", range.argument, range.name, scenario,
          parameters.empty() ? "it has no parameters: add them under `parameters:` and use them"
                             : fmt::format("its parameters are {}", fmt::join(parameters, ", "))));
    }
    if (std::find(spec.varied.begin(), spec.varied.end(), range.name) != spec.varied.end()) {
      return bad_argument(fmt::format("--vary {}: {} is varied twice", range.argument, range.name));
    }
    spec.varied.push_back(range.name);
  }
  try {
    const PreparedSimulation run = prepare_run(*model);
    const RunRecorder compiles(outcomes, column_layout(base, *run.formulation), base);
  } catch (const std::invalid_argument& e) {
    return bad_argument(fmt::format("{} {}", outcome_option, e.what()));
  }
  spec.outcomes = std::move(outcomes);
  return kDone;
}

}  // namespace tumble::cli
