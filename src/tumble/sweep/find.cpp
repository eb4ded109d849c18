#include "tumble/sweep/find.hpp"

#include <fmt/format.h>
#include <cmath>

namespace tumble {

FindResult find_change(const SweepSpec& spec, double lo, double hi, double tolerance,
                       const FindProgress& progress) {
  SweepRunner runner(spec);
  FindResult result;
  const auto outcome_at = [&](double value) {
    const double values[] = {value};
    RunRecord record = runner.run(values);
    ++result.runs;
    if (record.status != RunStatus::Ok) {
      const std::string what =
          fmt::format("the run at {} = {:.17g} {}: {}", spec.varied[0], value,
                      record.status == RunStatus::Failed ? "failed" : "is invalid", record.message);
      throw FindError(what, std::move(record), false);
    }
    const double condition = record.values.at(0);
    const bool yes = condition != 0.0 && !std::isnan(condition);
    if (progress) progress(value, yes, record);
    return yes;
  };
  result.lo = lo;
  result.hi = hi;
  result.at_lo = outcome_at(lo);
  result.at_hi = outcome_at(hi);
  if (result.at_lo == result.at_hi) {
    throw FindError(
        fmt::format("'{}' is {} at both ends, {} = {:.17g} and {:.17g}: nothing changes in "
                    "between that bisection can find; widen the range or check the condition",
                    spec.outcomes[0].text, result.at_lo ? "true" : "false", spec.varied[0], lo, hi),
        RunRecord{}, true);
  }
  while (result.hi - result.lo > tolerance) {
    const double mid = result.lo + 0.5 * (result.hi - result.lo);
    if (mid <= result.lo || mid >= result.hi) break;  // no double between them
    if (outcome_at(mid) == result.at_lo) {
      result.lo = mid;
    } else {
      result.hi = mid;
    }
  }
  return result;
}

}  // namespace tumble
