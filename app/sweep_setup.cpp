#include "sweep_setup.hpp"

#include <fmt/core.h>
#include <stdexcept>

#include "commands.hpp"
#include "exit_status.hpp"
#include "tumble/scenario/scenario_document.hpp"
#include "tumble/sweep/sweep_setup.hpp"

namespace tumble::cli {

int prepare_sweep(const char* command, const char* outcome_option, const std::string& scenario,
                  const std::vector<std::string>& sets, const std::vector<VaryRange>& ranges,
                  std::vector<Outcome> outcomes, SweepSpec& spec) {
  try {
    std::string text = read_scenario_file(scenario);  // its errors before the overrides'
    std::vector<ParameterOverride> fixed = parse_overrides(sets);
    spec = make_sweep_spec(std::move(text), scenario, std::move(fixed), ranges, std::move(outcomes),
                           {"--vary", outcome_option});
  } catch (const ScenarioError& e) {
    fmt::print(stderr, "{}\n", e.what());
    return kInvalidScenario;
  } catch (const std::invalid_argument& e) {
    fmt::print(stderr, "{}: {}\n", command, e.what());
    return kBadCommandLine;
  }
  return kDone;
}

}  // namespace tumble::cli
