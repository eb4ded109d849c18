#pragma once
// `tumble find`: the value of one parameter at which a yes/no outcome of the run changes (the
// critical friction, wheel speed or spring), bracketed by bisection. Bisection needs nothing but
// the outcome's sign at each end, so it cannot be misled by an outcome that jumps; each halving
// is one run.
#include <functional>
#include <stdexcept>

#include "tumble/sweep/sweep.hpp"

namespace tumble {

struct FindResult {
  double lo = 0.0, hi = 0.0;          // the final bracket: the outcome differs at its ends
  bool at_lo = false, at_hi = false;  // the outcome at each end
  int runs = 0;
};

// Why a find could not go on: the outcome is the same at both ends (kSameAtBothEnds), or a run
// failed or was invalid (its record says how).
class FindError : public std::runtime_error {
 public:
  FindError(const std::string& what, RunRecord record, bool same_at_both_ends)
      : std::runtime_error(what), record_(std::move(record)), same_(same_at_both_ends) {}
  const RunRecord& record() const { return record_; }
  bool same_at_both_ends() const { return same_; }

 private:
  RunRecord record_;
  bool same_;
};

// Called after each run with the parameter's value and the outcome there.
using FindProgress = std::function<void(double value, bool outcome, const RunRecord& record)>;

// `spec` varies one parameter and records one outcome, the condition: true where its value is
// neither 0 nor NaN. Halves [lo, hi] until it is no wider than `tolerance`.
FindResult find_change(const SweepSpec& spec, double lo, double hi, double tolerance,
                       const FindProgress& progress = {});

}  // namespace tumble
