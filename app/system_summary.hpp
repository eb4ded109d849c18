#pragma once
// The part of `tumble run`'s summary about joints and force elements: the work each element did,
// the work-energy balance, and what happened at each impulse, lock and motor start.
#include "tumble/scenario/scenario.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble::cli {

// Whether anything in the scenario does work on the bodies besides gravity and conservative
// springs (so E is not expected to stay constant).
bool energy_changes(const Scenario& scenario);
// Whether anything outside the bodies exerts a moment on them (gravity, loads, impulses, joints,
// springs to ground, contacts), so |L| about the origin is not expected to stay constant. Motors,
// locks and springs between bodies are internal.
bool external_moments_act(const Scenario& scenario);

void print_system_summary(const Scenario& scenario, const PreparedSimulation& simulation,
                          const SimulationResult& result);

}  // namespace tumble::cli
