#include "tumble/sweep/sweep_setup.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "tumble/scenario/expression.hpp"
#include "tumble/scenario/scenario_document.hpp"
#include "tumble/simulation/simulation.hpp"
#include "tumble/sweep/run_recorder.hpp"

namespace tumble {

SweepSpec make_sweep_spec(std::string text, std::string path, std::vector<ParameterOverride> fixed,
                          std::span<const VaryRange> ranges, std::vector<Outcome> outcomes,
                          const SweepArgumentNames& names) {
  SweepSpec spec;
  spec.text = std::move(text);
  spec.path = std::move(path);
  spec.fixed = std::move(fixed);
  const Scenario base = ScenarioDocument::from_text(spec.text, spec.path).read(spec.fixed);
  const std::shared_ptr<const SimulationModel> model = build_simulation_model(base);
  for (const VaryRange& range : ranges) {
    if (!base.parameters.contains(range.name)) {
      std::vector<std::string> parameters;
      for (const auto& [name, value] : base.parameters) parameters.push_back(name);
      throw std::invalid_argument(fmt::format(
          "{} {}: no parameter {} in {}; {}", names.vary, range.argument, range.name, spec.path,
          parameters.empty() ? "it has no parameters: add them under `parameters:` and use them"
                             : "its parameters are " + listed_names(parameters)));
    }
    if (std::find(spec.varied.begin(), spec.varied.end(), range.name) != spec.varied.end()) {
      throw std::invalid_argument(
          fmt::format("{} {}: {} is varied twice", names.vary, range.argument, range.name));
    }
    spec.varied.push_back(range.name);
  }
  try {
    const RunRecorder compiles(outcomes, column_layout(base, *model), base);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("{} {}", names.outcome, e.what()));
  }
  spec.outcomes = std::move(outcomes);
  return spec;
}

}  // namespace tumble
