#include "tumble/simulation/table_run.hpp"

namespace tumble {

TableRun run_into_table(const Scenario& scenario, const SimulationModel& model,
                        const TableRunOptions& options) {
  PreparedSimulation run = prepare_run(model);
  const SimulateSpec& sim = scenario.simulate;
  TableRun out{RowTable(column_layout(scenario, *run.formulation),
                        expected_rows(sim.duration, sim.output_every, sim.max_rows)),
               {},
               std::nullopt};
  run.options.stop_requested = options.stop_requested;
  CheckpointCallback keep_state;
  if (options.stop_at < std::numeric_limits<double>::infinity()) {
    run.options.checkpoint_after = options.stop_at;
    run.options.stop_at_checkpoint = true;
    keep_state = [&out](SimulationCheckpoint state) { out.state = std::move(state); };
  }
  const FullRowObserver rows = [&out](double t, std::span<const BodyState> states,
                                      const SystemQuantities& q, const RowExtras& extras) {
    out.table.write_row({t, states, &q, &extras});
  };
  out.result = options.start != nullptr ? resume_simulation(run, *options.start, rows, keep_state)
                                        : run_simulation(run, rows, keep_state);
  return out;
}

}  // namespace tumble
