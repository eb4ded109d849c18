#pragma once
// The part of `tumble run`'s summary about joints and force elements: the work each element did,
// the work-energy balance, and what happened at each impulse, lock and motor start.
#include "tumble/scenario/scenario.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble::cli {

// Whether anything in the scenario does work on the bodies besides gravity and conservative
// springs (so E is not expected to stay constant).
bool energy_changes(const Scenario& scenario);
// Whether the only elements that may change E are contacts (no loads, impulses, motors, locks or
// dampers): if they did no work (they rolled or stuck), E is conserved.
bool only_contacts_may_do_work(const Scenario& scenario);
// The contacts did no work when their largest |work| is within this factor of the work-energy
// balance's residual (the integration's own error in the books).
inline constexpr double kWorklessFactor = 10.0;
// Whether anything outside the bodies exerts a moment on them (gravity, loads, impulses, joints,
// springs to ground, contacts), so |L| about the origin is not expected to stay constant. Motors,
// locks and springs between bodies are internal.
bool external_moments_act(const Scenario& scenario);

// The work-energy check and each element's work (where the formulation keeps the ledger), then
// the run's contact events, jumps and occurrences of the scenario's `events:` in time order.
// Values to `digits` significant digits.
void print_system_summary(const Scenario& scenario, const PreparedSimulation& simulation,
                          const SimulationResult& result, int digits);
// The scenario's `events:` that never happened.
void print_scenario_events(const Scenario& scenario, const SimulationResult& result);

}  // namespace tumble::cli
