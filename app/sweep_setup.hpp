#pragma once
// What `tumble sweep` and `tumble find` check before any run: the scenario reads and builds at
// its own values (else exit 3, as for tumble run), each varied name is one of its parameters, and
// each outcome compiles against its columns, parameters and events (else exit 2).
#include <string>
#include <vector>

#include "tumble/sweep/parameter_space.hpp"
#include "tumble/sweep/sweep.hpp"

namespace tumble::cli {

// Fills `spec` from the scenario file, the --set overrides, the ranges and the outcomes; on a
// problem prints it, prefixed by `command` ("tumble sweep") where it is the command line's, and
// returns the exit status (kDone when all is well). `outcome_option` ("--record", "--when") heads
// a message about an outcome.
int prepare_sweep(const char* command, const char* outcome_option, const std::string& scenario,
                  const std::vector<std::string>& sets, const std::vector<VaryRange>& ranges,
                  std::vector<Outcome> outcomes, SweepSpec& spec);

}  // namespace tumble::cli
