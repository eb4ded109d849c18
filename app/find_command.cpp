// tumble find: the value of one parameter where a yes/no outcome of the run changes.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "commands.hpp"
#include "exit_status.hpp"
#include "sweep_setup.hpp"
#include "tumble/sweep/find.hpp"

namespace tumble::cli {

int find_command(const FindArguments& args) {
  const auto bad_argument = [&](const std::string& why) {
    fmt::print(stderr, "tumble find: {}\n", why);
    return kBadCommandLine;
  };
  VaryRange range;
  std::vector<Outcome> outcomes;
  try {
    range = parse_vary(args.vary, false);
    try {
      outcomes.push_back(parse_outcome("condition", args.when));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("--when " + std::string(e.what()));
    }
  } catch (const std::invalid_argument& e) {
    return bad_argument(e.what());
  }
  const double tolerance =
      args.tol > 0.0 ? args.tol : 1e-9 * std::max(std::abs(range.start), std::abs(range.stop));
  if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
    return bad_argument(fmt::format("--tol {}: give a positive width", args.tol));
  }
  SweepSpec spec;
  if (const int status =
          prepare_sweep("tumble find", "--when", args.scenario, args.sets, {range}, outcomes, spec);
      status != kDone) {
    return status;
  }
  spec.max_steps = args.max_steps;
  fmt::print("find {} in [{:.17g}, {:.17g}] where '{}' changes ({})\n", range.name, range.start,
             range.stop, args.when, args.scenario);
  try {
    const FindResult found =
        find_change(spec, range.start, range.stop, tolerance,
                    [&](double value, bool outcome, const RunRecord& record) {
                      fmt::print("  {} = {:<24.17g} {:<5}  ({} steps)\n", range.name, value,
                                 outcome ? "true" : "false", record.steps);
                      // Each run's line as it ends, to a file or a pipe too: a bisection near a
                      // critical value can take minutes.
                      std::fflush(stdout);
                    });
    fmt::print("  bracket        [{:.17g}, {:.17g}]: {} at the low end, {} at the high end\n",
               found.lo, found.hi, found.at_lo ? "true" : "false", found.at_hi ? "true" : "false");
    fmt::print("  width          {:.3e} (tolerance {:.3e})\n", found.hi - found.lo, tolerance);
    fmt::print("  {:<14} {:.17g} (the bracket's middle)\n", range.name,
               found.lo + 0.5 * (found.hi - found.lo));
    fmt::print("  runs           {}\n", found.runs);
  } catch (const FindError& e) {
    fmt::print(stderr, "tumble find: {}\n", e.what());
    if (e.same_at_both_ends()) return kBadCommandLine;
    return e.record().status == RunStatus::Failed ? kIntegrationFailed : kInvalidScenario;
  }
  return kDone;
}

}  // namespace tumble::cli
