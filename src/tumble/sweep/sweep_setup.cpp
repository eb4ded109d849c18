#include "tumble/sweep/sweep_setup.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <unordered_set>

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
  // Each outcome heads a column of sweep.csv beside run, the varied parameters and the run's
  // status columns: a second column of one name would be read as the first by Python and plots.
  std::unordered_set<std::string> columns = {"run",     "status",  "steps",
                                             "E_drift", "L_drift", "message"};
  for (const auto& [name, value] : base.parameters) columns.insert(name);
  for (const Outcome& outcome : outcomes) {
    if (!columns.insert(outcome.name).second) {
      const bool parameter = base.parameters.contains(outcome.name);
      const bool repeated = std::count_if(outcomes.begin(), outcomes.end(), [&](const Outcome& o) {
                              return o.name == outcome.name;
                            }) > 1;
      throw std::invalid_argument(fmt::format(
          "{} {}={}: '{}' {}; give the outcome a name of its own", names.outcome, outcome.name,
          outcome.text, outcome.name,
          repeated    ? "is given twice"
          : parameter ? "is a parameter of " + spec.path + " (a column of sweep.csv when varied)"
                      : "heads one of sweep.csv's own columns (run, status, steps, E_drift, "
                        "L_drift, message)"));
    }
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
