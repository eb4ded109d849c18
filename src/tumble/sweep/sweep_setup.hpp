#pragma once
// What a sweep or a find checks before any run, for the command line and the Python module
// alike: the scenario reads and builds at its own values, each varied name is one of its
// parameters (and is varied once), and each outcome compiles against its columns, parameters and
// events.
#include <span>
#include <string>
#include <vector>

#include "tumble/sweep/parameter_space.hpp"
#include "tumble/sweep/sweep.hpp"

namespace tumble {

// How the caller names the varied parameters and the outcomes, to head messages about them: the
// command line's "--vary" and "--record" (or "--when"), Python's "vary" and "record".
struct SweepArgumentNames {
  std::string vary;
  std::string outcome;
};

// The sweep of the scenario `text` (named `path` in messages) with `fixed` overrides, varying the
// ranges' parameters and recording the outcomes. Throws ScenarioError where the scenario is
// invalid at its own values, and std::invalid_argument (with the message the command line
// prints) for an override or range that names no parameter, a parameter varied twice, or an
// outcome that does not compile.
SweepSpec make_sweep_spec(std::string text, std::string path, std::vector<ParameterOverride> fixed,
                          std::span<const VaryRange> ranges, std::vector<Outcome> outcomes,
                          const SweepArgumentNames& names);

}  // namespace tumble
