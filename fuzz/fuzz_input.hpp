#pragma once
// One input of the fuzz target (fuzz/scenario_fuzz.cpp), as the target reads it and as
// tests/fuzz_regression_test.cpp replays the inputs found so far: the bytes are read as a scenario
// and, if valid, built into the model a run would use (its `events:` conditions compiled against
// the columns), linearised as `tumble modes` and Python's tumble.modes do, and run for a few
// steps as a sweep's run (the record's reductions reading its rows, pieces and events). Comment
// lines at the top carry what the command line and Python add to a scenario: the first, if it is
// not a `set` line, is read as a sweep's `--record NAME=REDUCTION` (Python's `record=`) and
// compiled against the same columns, as `tumble sweep` does before its first run; each `# set
// NAME=VALUE` line is an override (`--set`, Python's `set=`) applied as the scenario is read. A
// refusal is a ScenarioError (thrown), an override or a record refused with std::invalid_argument
// (caught here, as the command line turns it into exit 2), or a state with no linearisation
// (NotSteady, caught here: `tumble modes` exits 6); anything else escaping is a finding.
#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bounded_run.hpp"
#include "tumble/modes/scenario_modes.hpp"
#include "tumble/scenario/scenario.hpp"
#include "tumble/simulation/simulation.hpp"
#include "tumble/sweep/outcome.hpp"
#include "tumble/sweep/run_recorder.hpp"
#include "tumble/sweep/sweep.hpp"

namespace tumble::fuzzing {

// The bounded run of a valid scenario (bounded_run.hpp): its steps, and the most rows it may
// have at its output_every.
inline constexpr long kRunSteps = 10;
inline constexpr double kRunRows = 20'000;

// The comment lines at the top, without their "#" and leading blanks.
inline std::vector<std::string> top_comments(const std::string& text) {
  std::vector<std::string> lines;
  for (std::size_t at = 0; at < text.size() && text[at] == '#';) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::string line = text.substr(at + 1, end - at - 1);
    const std::size_t start = line.find_first_not_of(' ');
    lines.push_back(start == std::string::npos ? std::string() : line.substr(start));
    at = end + 1;
  }
  return lines;
}

// Throws ScenarioError where the scenario is refused. `linearise` false leaves out the
// linearisation, which is most of a valid input's cost (scenario_fuzz.cpp says when).
inline void read_input(const std::string& text, const std::string& name, bool linearise = true) {
  std::string record;
  std::vector<ParameterOverride> sets;
  const std::vector<std::string> comments = top_comments(text);
  for (std::size_t i = 0; i < comments.size(); ++i) {
    const std::string& line = comments[i];
    if (line.rfind("set ", 0) == 0) {
      const std::size_t eq = line.find('=');
      // As the command line splits --set NAME=VALUE (a line without '=' sets nothing).
      if (eq != std::string::npos) sets.push_back({line.substr(4, eq - 4), line.substr(eq + 1)});
    } else if (i == 0) {
      record = line;
    }
  }
  std::optional<Scenario> read;
  try {
    read = load_scenario_text(text, name, sets);
  } catch (const std::invalid_argument&) {
    // An override refused (a name that is no parameter): `--set` exits 2, Python raises
    // ValueError. Without overrides nothing may throw it.
    if (sets.empty()) throw;
    return;
  }
  const Scenario& scenario = *read;
  const auto model = build_simulation_model(scenario);
  if (linearise) {
    try {
      (void)modes_of_scenario(scenario);
    } catch (const NotSteady&) {
      // No linearisation: `tumble modes` says why and exits 6.
    }
  }
  // The record, or where there is none or it is refused (as `tumble sweep --record` refuses
  // it), one that reads the run between its rows.
  std::vector<Outcome> outcomes = {parse_record("fuzz=max(KE)")};
  if (!record.empty()) {
    try {
      const std::vector<Outcome> given = {parse_record(record)};
      const RunRecorder compiled(given, column_layout(scenario, *model), scenario);
      outcomes = given;
    } catch (const std::invalid_argument&) {
    }
  }
  // A bounded run, as a sweep's run records it: stopped after kRunSteps steps or kRunWork of
  // work, and only where its rows are few enough to be read within libFuzzer's second (a tiny
  // output_every is many rows a step). A run never throws: what it meets is its record's status.
  const SimulateSpec& simulate = scenario.simulate;
  if (simulate.output_every > 0 && simulate.duration > kRunRows * simulate.output_every) return;
  SweepSpec spec;
  spec.text = text;
  spec.path = name;
  spec.fixed = sets;
  spec.outcomes = outcomes;
  spec.stop_requested = bounded_run(kRunSteps);
  SweepRunner runner(spec);
  (void)runner.run({});
}

}  // namespace tumble::fuzzing
