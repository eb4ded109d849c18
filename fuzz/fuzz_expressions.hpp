#pragma once
// One input of the expression fuzz target (fuzz/expression_fuzz.cpp), as the target reads it and
// as tests/fuzz_regression_test.cpp replays its seeds and the inputs found so far: the
// expressions a user adds to a scenario, on an example read and built once a process, so that
// each input costs its expressions and a few steps, not a scenario's reading (the scenario target
// reaches them too, at a hundredth of the rate). Lines:
//   scenario examples/NAME.yaml   the example (fuzz_checkpoint.hpp's named_example)
//   record NAME=REDUCTION         a sweep's --record (Python's record=); max(KE) where none
//   when EXPR                     an `events:` entry's condition, in place of the example's
//   when+ EXPR, when- EXPR        ... counting only its rising (falling) crossings
// Each `when` line is an event e1, e2, ... (at most kMaxEvents). The scenario with those events
// is built (its conditions compiled against the run's columns), the record compiled against the
// same columns, and the run recorded as a sweep's run records it (record_run), stopped after
// kRunSteps steps or kRunWork of work. A refusal is a ScenarioError (a condition that does not
// compile, thrown, located at its event) or a record refused with std::invalid_argument (the
// command line's exit 2, Python's ValueError; max(KE) is recorded instead); anything else
// escaping, from the build, the compilation or the run, is a finding.
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz_checkpoint.hpp"
#include "fuzz_input.hpp"
#include "tumble/sweep/run_recorder.hpp"
#include "tumble/sweep/sweep.hpp"

namespace tumble::fuzzing {

inline constexpr std::size_t kMaxEvents = 4;

// Whether the input was built and run; false where it names no example. Throws ScenarioError
// where its conditions are refused.
inline bool run_expressions(const std::string& text) {
  const std::string name = named_example("\n" + text);
  const ExampleModel* example = name.empty() ? nullptr : example_model(name);
  if (example == nullptr) return false;
  Scenario scenario = example->scenario;
  scenario.events.clear();
  std::string record;
  int line_number = 0;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t end = std::min(text.find('\n', at), text.size());
    const std::string line = text.substr(at, end - at);
    at = end + 1;
    ++line_number;
    if (line.rfind("record ", 0) == 0) {
      record = line.substr(7);
      continue;
    }
    UserEventSpec event;
    std::size_t skip = 0;
    if (line.rfind("when ", 0) == 0) {
      skip = 5;
    } else if (line.rfind("when+ ", 0) == 0 || line.rfind("when- ", 0) == 0) {
      event.direction =
          line[4] == '+' ? UserEventSpec::Direction::Up : UserEventSpec::Direction::Down;
      skip = 6;
    } else {
      continue;
    }
    if (scenario.events.size() == kMaxEvents) continue;
    event.name = "e" + std::to_string(scenario.events.size() + 1);
    event.when = line.substr(skip);
    // Where a refusal points: the input's line, after its `when`.
    event.where = {"fuzz.txt", line_number, 1};
    event.when_where = {"fuzz.txt", line_number, static_cast<int>(skip) + 1};
    scenario.events.push_back(event);
  }
  const auto model = build_simulation_model(scenario);
  SweepSpec spec;
  spec.outcomes = {parse_record("fuzz=max(KE)")};
  if (!record.empty()) {
    try {
      const std::vector<Outcome> given = {parse_record(record)};
      const RunRecorder compiled(given, column_layout(scenario, *model), scenario);
      spec.outcomes = given;
    } catch (const std::invalid_argument&) {
    }
  }
  spec.stop_requested = bounded_run(kRunSteps);
  std::unique_ptr<RunRecorder> recorder;
  RunRecord run;
  record_run(spec, scenario, *model, false, recorder, run);
  return true;
}

}  // namespace tumble::fuzzing
