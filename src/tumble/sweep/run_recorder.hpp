#pragma once
// The outcomes of one run (outcome.hpp), accumulated row by row as the run goes: no row is kept.
// A recorder is made once for a scenario's columns and parameters, its expressions compiled
// then, and reused for each run of a sweep on its thread.
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "tumble/output/columns.hpp"
#include "tumble/output/row_variables.hpp"
#include "tumble/scenario/expression.hpp"
#include "tumble/scenario/scenario.hpp"
#include "tumble/sweep/outcome.hpp"

namespace tumble {

class RunRecorder {
 public:
  // Throws std::invalid_argument, naming the outcome, for an expression that does not compile
  // (a name that is neither a column nor a parameter) or an event the scenario cannot have.
  RunRecorder(std::span<const Outcome> outcomes, const ColumnLayout& layout,
              const Scenario& scenario);
  ~RunRecorder();

  // Whether runs of this scenario have the columns and parameters the recorder was made for.
  bool fits(const ColumnLayout& layout, const Scenario& scenario) const;
  // A new run of it: its parameter values, and nothing accumulated.
  void start(const Scenario& scenario);
  void observe(const OutputRow& row);
  // Each outcome's value, after the last row, with the run's events and, where an outcome reads
  // them, the modes of its initial state (nan without).
  std::vector<double> finish(std::span<const ContactEventRecord> events,
                             std::span<const JumpRecord> jumps,
                             std::span<const UserEventRecord> user_events,
                             const ModesOutcome* modes = nullptr) const;

 private:
  struct RowReduction;
  ColumnLayout layout_;
  RowVariables row_;  // the columns the reductions read, and the run's parameters
  std::vector<std::unique_ptr<RowReduction>> row_reductions_;
  // Per outcome: its expression over its reductions' values, and where each value comes from
  // (an index into row_reductions_, or an event reduction).
  struct OutcomeSlots {
    std::unique_ptr<BoundExpression> expression;
    std::unique_ptr<std::vector<double>> values;  // what the expression reads, __r0, __r1, ...
    std::vector<Reduction> reductions;
    std::vector<std::size_t> row_reduction;  // for reductions over rows
    std::vector<int> jump_field;             // for jump(): which number of the jump (jump_field)
  };
  std::vector<OutcomeSlots> outcomes_;
};

}  // namespace tumble
