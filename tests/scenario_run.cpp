#include "scenario_run.hpp"

#include "tumble/multibody/articulated_formulation.hpp"

namespace tumble::test {

ScenarioRun run_inline_scenario(const std::string& yaml, const std::string& name) {
  ScenarioRun run;
  run.scenario = load_inline_scenario(yaml, name);
  PreparedSimulation simulation = prepare_simulation(run.scenario);
  run.result = run_simulation(simulation, [&](double t, std::span<const BodyState> states,
                                              const SystemQuantities& q, const RowExtras& e) {
    run.rows.push_back({t, std::vector<BodyState>(states.begin(), states.end()), q, e});
  });
  EXPECT_TRUE(run.result.report.completed) << run.result.report.failure;
  if (const auto* a = dynamic_cast<const ArticulatedFormulation*>(simulation.formulation.get())) {
    run.jumps = a->jumps();
  }
  return run;
}

}  // namespace tumble::test
