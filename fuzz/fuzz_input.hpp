#pragma once
// One input of the fuzz target (fuzz/scenario_fuzz.cpp), as the target reads it and as
// tests/fuzz_regression_test.cpp replays the inputs found so far: the bytes are read as a scenario
// and, if valid, built into the model a run would use (its `events:` conditions compiled against
// the columns). If the first line is a YAML comment, its text is also read as a sweep's `--record
// NAME=REDUCTION` and compiled against the same columns, as `tumble sweep` does before its first
// run. A refusal is a ScenarioError (thrown) or a record refused with std::invalid_argument
// (caught here, as `tumble sweep` turns it into exit 2); anything else escaping is a finding.
#include <stdexcept>
#include <string>
#include <vector>

#include "tumble/scenario/scenario.hpp"
#include "tumble/simulation/simulation.hpp"
#include "tumble/sweep/outcome.hpp"
#include "tumble/sweep/run_recorder.hpp"

namespace tumble::fuzzing {

// "# x=max(prism.w3)" -> "x=max(prism.w3)"; empty when the first line is no comment.
inline std::string first_comment(const std::string& text) {
  if (text.rfind('#', 0) != 0) return {};
  const std::string line = text.substr(1, text.find('\n') - 1);
  const std::size_t start = line.find_first_not_of(' ');
  return start == std::string::npos ? std::string() : line.substr(start);
}

// Throws ScenarioError where the scenario is refused.
inline void read_input(const std::string& text, const std::string& name) {
  const Scenario scenario = load_scenario_text(text, name, {});
  const auto model = build_simulation_model(scenario);
  const std::string record = first_comment(text);
  if (record.empty()) return;
  try {
    const std::vector<Outcome> outcomes = {parse_record(record)};
    const RunRecorder compiled(outcomes, column_layout(scenario, *model), scenario);
  } catch (const std::invalid_argument&) {
    // A record refused, as `tumble sweep --record` refuses it.
  }
}

}  // namespace tumble::fuzzing
