#pragma once
// One simulation from a scenario: the formulation, the integrator and the initial state it
// asks for, run by the driver, with each output row handed over as the bodies' states and the
// system's momenta and energies. The command line, the tests and the benchmarks all go through
// here, so they run the same thing.
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "tumble/body/rigid_body.hpp"
#include "tumble/dynamics/formulation.hpp"
#include "tumble/integrators/driver.hpp"
#include "tumble/output/columns.hpp"
#include "tumble/output/output_row.hpp"
#include "tumble/scenario/scenario.hpp"
#include "tumble/simulation/make_formulation.hpp"
#include "tumble/simulation/piece_rows.hpp"
#include "tumble/simulation/user_events.hpp"

namespace tumble {

struct PreparedSimulation {
  std::unique_ptr<Formulation> formulation;
  // The scenario's events on the formulation, when it has any: what the driver then runs.
  std::unique_ptr<UserEventSystem> user_events;
  std::unique_ptr<Integrator> integrator;
  StepControl control;
  DriverOptions options;
  VecX y0;
  double t0 = 0.0;
  double t_end = 0.0;
  bool planar = false;  // the rows carry each body's angle about z (RowExtras::planar_angles)
  // Whether the rows serve the conservation report's energy and momentum drifts alone (a sweep
  // that reads no row): its other checks (orthonormality, loops, the work ledger) are not kept.
  bool drifts_only = false;
  // Where set, handed the row of the state just after each event, jump or change of the
  // contacts' modes (DriverOptions::on_event_state), as run_simulation's rows are: what a sweep's
  // after(EVENT, X) reads. Several may come at one instant; the last is the state the run goes
  // on from. These rows are not the trajectory's and are not counted in it.
  std::function<void(double t, std::span<const BodyState> states,
                     const SystemQuantities& quantities, const RowExtras& extras)>
      on_event_state;
  // Where set, handed each smooth piece of the run as rows (DriverOptions::on_piece): what a
  // sweep's max, min, mean and conditions read between the rows. Not the trajectory's rows.
  std::function<void(PieceRows& piece)> on_piece;
};

// One problem, built once from a scenario and then run any number of times, on any number of
// threads at once. It is constant data only, no run object: the Model (and, for joints and
// contacts, the ArticulatedModel) and which formulation runs it, the method's name and settings,
// the initial state and the events' definitions. Each run gets its own formulation (scratch and
// hybrid state) and integrator from prepare_run(), which is safe to call from any thread.
struct SimulationModel {
  explicit SimulationModel(FormulationModel formulation_model)
      : formulation(std::move(formulation_model)) {}

  FormulationModel formulation;  // makes each run's; its name, elements, dimension
  std::string integrator;        // the scenario's name for the method
  StepControl control;
  DriverOptions options;
  VecX y0;  // the scenario's initial state
  double t0 = 0.0;
  double t_end = 0.0;
  std::shared_ptr<const UserEventDefinitions> user_events;  // null when it has none
  bool planar = false;                                      // Scenario::planar
};

// Throws ScenarioError, under the key of the part that is wrong, for a combination the engine
// cannot run (e.g. rkmk4 on the textbook formulation, which has no quaternions to move on the
// group), where the bodies' given velocities disagree with what their joints allow or a motor
// prescribes, or where a body starts inside a contact's plane.
std::shared_ptr<const SimulationModel> build_simulation_model(const Scenario& scenario);
// The state vector of the scenario's initial bodies' states, checked as build_simulation_model
// checks them: its y0. A model built from a scenario that differs only in the bodies' initial
// velocities runs from this as that scenario's model would (a sweep's shared model). It
// evaluates the formulation, which writes its scratch: give it the run's own (prepare_run's).
VecX initial_state_vector(const Scenario& scenario, const Formulation& formulation);
// A run of the model from its initial state (set y0 for another).
PreparedSimulation prepare_run(const SimulationModel& model);
// build_simulation_model, then prepare_run: for a model that runs once.
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
  double max_angular_momentum = 0.0;  // the largest |L| over the rows, kg m^2/s
  // Work-energy theorem: KE - KE0 = W_gravity + sum of the elements' work (ideal joints do none);
  // the largest departure over the rows, in J, and the largest KE it compares with.
  double max_work_energy_residual = 0.0;
  double max_kinetic_energy = 0.0;
  // The largest |work| any contact's forces and impulses had done at any row, J: rolling and
  // sticking contacts do none (it is then the integration's error), sliding and impacts do.
  double max_contact_work = 0.0;
  // The largest errors of the joints that close loops over the rows (each row is taken after the
  // step's projection, so these are what the rows report: round-off where the loops hold).
  LoopErrors max_loop_error;

  // The scales the summary's drifts are measured against, never round-off: E0 may be zero or
  // tiny (a pendulum released level with its pivot, a chain lying flat), so E's is the larger of
  // |E0| and the largest KE (J), and |L|'s the largest |L| (kg m^2/s). 0 where nothing moved.
  double energy_scale() const { return std::max(std::abs(initial_energy), max_kinetic_energy); }
  double angular_momentum_scale() const {
    return std::max(initial_angular_momentum, max_angular_momentum);
  }
  // max |E - E0| and max ||L| - |L0|| over those scales (0 where the scale is).
  double scaled_energy_drift() const {
    return energy_scale() > 0.0 ? max_energy_change / energy_scale() : 0.0;
  }
  double scaled_angular_momentum_drift() const {
    return angular_momentum_scale() > 0.0 ? max_angular_momentum_change / angular_momentum_scale()
                                          : 0.0;
  }
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
  std::vector<UserEventRecord> user_events;  // the scenario's `events:` where they happened
};

// The first row's energy and momenta, which the conservation report measures against.
struct RowBaseline {
  double E0 = 0.0, L0 = 0.0, KE0 = 0.0, gravity_potential0 = 0.0;
};

// A run stopped part way, with all it needs to go on as if it had not stopped: y, the step size
// and last step (in the integrator's copy), the hybrid state (contact modes, features, anchors,
// slip timers, the load schedule's position, the jumps and events so far), the driver's position
// (the next row, the event functions), and the conservation report so far. A run of the same
// model resumed from it writes, after the checkpoint's time, the rows of the run that never
// stopped, bit for bit. Copyable; it holds nothing of the run it came from.
struct SimulationCheckpoint {
  DriverCheckpoint driver;
  HybridState hybrid;
  RowBaseline baseline;
  ConservationReport conservation;
  std::size_t rows = 0;
  RowExtras last_extras;
  double t() const { return driver.integrator->t(); }
};
using CheckpointCallback = std::function<void(SimulationCheckpoint checkpoint)>;

// Runs from the initial state; with simulation.options.checkpoint_after set, hands on_checkpoint
// the run's checkpoint there (and ends the run there with options.stop_at_checkpoint).
SimulationResult run_simulation(PreparedSimulation& simulation, const FullRowObserver& observe,
                                const CheckpointCallback& on_checkpoint = {});
SimulationResult run_simulation(PreparedSimulation& simulation, const RowObserver& observe);
// The same, each row to a sink (the trajectory CSV, the animation's recording, several at once).
SimulationResult run_simulation(PreparedSimulation& simulation, RowSink& sink,
                                const CheckpointCallback& on_checkpoint = {});
// A row's system quantities: the bodies' energies and momenta (about the world origin), with the
// springs' energy (extras.elastic_energy) in PE and E, as the trajectory has them; the potential
// energy of gravity alone in *gravity_potential, if given.
SystemQuantities row_quantities(const Model& model, std::span<const BodyState> states,
                                const RowExtras& extras, double* gravity_potential = nullptr);
// The columns a run of this scenario writes: its bodies', joints', contacts' and the
// formulation's elements'.
ColumnLayout column_layout(const Scenario& scenario, const Formulation& formulation);
// The same for the model built from it (without making a run).
ColumnLayout column_layout(const Scenario& scenario, const SimulationModel& model);
// The system a run of `simulation` integrates: the formulation, or the scenario's events on it.
OdeSystem& ode_system_of(PreparedSimulation& simulation);

// Goes on from a checkpoint of a run of the same model (prepare_run() of it gives `simulation`;
// its formulation and integrator are replaced by the checkpoint's).
SimulationResult resume_simulation(PreparedSimulation& simulation,
                                   const SimulationCheckpoint& checkpoint,
                                   const FullRowObserver& observe,
                                   const CheckpointCallback& on_checkpoint = {});
// The same, each row to a sink.
SimulationResult resume_simulation(PreparedSimulation& simulation,
                                   const SimulationCheckpoint& checkpoint, RowSink& sink,
                                   const CheckpointCallback& on_checkpoint = {});

}  // namespace tumble
