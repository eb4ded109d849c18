#pragma once
// One run of a built model into a RowTable, from the scenario's initial state or from a state a
// run of the same model stopped at: the call behind the Python module's Model.run, and the one
// its overhead is measured against (bench/).
#include <functional>
#include <limits>
#include <optional>

#include "tumble/output/row_table.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble {

struct TableRunOptions {
  // Stop at the end of the first accepted step at or after this time (s), with the state there
  // to go on from; infinity runs to the end.
  double stop_at = std::numeric_limits<double>::infinity();
  // Go on from this state of a run of the same model (null: from the initial state). The rows
  // are those after its time; the report counts the whole run's steps, events and drifts.
  const SimulationCheckpoint* start = nullptr;
  // Asked after each step whether to stop (DriverOptions::stop_requested).
  std::function<bool()> stop_requested;
};

struct TableRun {
  RowTable table;
  SimulationResult result;
  std::optional<SimulationCheckpoint> state;  // where a run with stop_at stopped
};

// `scenario` is the one `model` was built from (its names head the columns).
TableRun run_into_table(const Scenario& scenario, const SimulationModel& model,
                        const TableRunOptions& options = {});

}  // namespace tumble
