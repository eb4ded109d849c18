#pragma once
// One simulation from a scenario: the formulation, the integrator and the initial state it
// asks for, run by the driver, with each output row handed over as the bodies' states and the
// system's momenta and energies. The command line, the tests and the benchmarks all go through
// here, so they run the same thing.
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "tumble/body/rigid_body.hpp"
#include "tumble/dynamics/formulation.hpp"
#include "tumble/integrators/driver.hpp"
#include "tumble/scenario/scenario.hpp"

namespace tumble {

struct PreparedSimulation {
  std::unique_ptr<Formulation> formulation;
  std::unique_ptr<Integrator> integrator;
  StepControl control;
  DriverOptions options;
  VecX y0;
  double t0 = 0.0;
  double t_end = 0.0;
};

// Throws std::invalid_argument for a combination the engine cannot run (e.g. rkmk4 on the
// textbook formulation, which has no quaternions to move on the group), and ScenarioError where
// the bodies' given velocities disagree with what their joints allow or a motor prescribes.
PreparedSimulation prepare_simulation(const Scenario& scenario);

// Largest departures from what a free system conserves, over all output rows.
struct ConservationReport {
  double max_relative_energy_drift = 0.0;            // max |E - E0| / |E0|
  double max_relative_angular_momentum_drift = 0.0;  // max | |L| - |L0| | / |L0|, L about origin
  double max_orthonormality_error = 0.0;             // max |R^T R - I| over bodies and rows
  // The same drifts in absolute terms, for runs that start with E0 = 0 or L0 = 0 (where a
  // relative drift means nothing): max |E - E0| in J, max | |L| - |L0| | in kg m^2/s.
  double initial_energy = 0.0, max_energy_change = 0.0;
  double initial_angular_momentum = 0.0, max_angular_momentum_change = 0.0;
  // Work-energy theorem: KE - KE0 = W_gravity + sum of the elements' work (ideal joints do none);
  // the largest departure over the rows, in J, and the largest KE it compares with.
  double max_work_energy_residual = 0.0;
  double max_kinetic_energy = 0.0;
};

using RowObserver = std::function<void(double t, std::span<const BodyState> states,
                                       const SystemQuantities& quantities)>;
// The same with the row's joint reactions, element powers and works (RowExtras).
using FullRowObserver =
    std::function<void(double t, std::span<const BodyState> states,
                       const SystemQuantities& quantities, const RowExtras& extras)>;

struct SimulationResult {
  IntegrationReport report;
  ConservationReport conservation;
  std::size_t rows = 0;
  double wall_seconds = 0.0;  // integration and output, not reading the scenario
  RowExtras last_extras;      // of the last row: the work each element did over the run
  // What happened on the way: the jumps at breakpoints (impulses, locks, motor starts) and the
  // contacts' mode changes and impacts, in time order.
  std::vector<JumpRecord> jumps;
  std::vector<ContactEventRecord> contact_events;
};

SimulationResult run_simulation(PreparedSimulation& simulation, const FullRowObserver& observe);
SimulationResult run_simulation(PreparedSimulation& simulation, const RowObserver& observe);

}  // namespace tumble
