#include "tumble/simulation/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "tumble/math/rotation.hpp"
#include "tumble/multibody/joints/joint_kind.hpp"
#include "tumble/simulation/exact_integrator.hpp"
#include "tumble/simulation/make_formulation.hpp"
#include "tumble/simulation/model_from_scenario.hpp"
#include "tumble/simulation/planar_angles.hpp"

namespace tumble {

namespace {

// The state packs what the joints allow; a given velocity that differs was not what the user
// meant, and running anyway would silently change the problem.
void check_initial_velocities(const Scenario& scenario, const Formulation& formulation,
                              std::span<const BodyState> given, const VecX& y0) {
  std::vector<BodyState> allowed(given.size());
  formulation.unpack_all(y0, allowed);
  const auto differ = [](const Vec3& a, const Vec3& b) {
    return (a - b).norm() > 1e-9 * (a.norm() + b.norm()) + 1e-12;
  };
  for (std::size_t i = 0; i < given.size(); ++i) {
    const BodySpec& body = scenario.bodies[i];
    const auto fail = [&](const SourceLocation& where, const std::string& key, const Vec3& value,
                          const Vec3& wanted, const char* unit) {
      throw ScenarioError(
          where, "bodies." + body.name + "." + key,
          fmt::format("[{:.6g}, {:.6g}, {:.6g}] {} is not a motion the joints allow (or a motor "
                      "prescribes); they give [{:.9g}, {:.9g}, {:.9g}]: correct it, or leave {} "
                      "out to take what the joints allow",
                      value.x(), value.y(), value.z(), unit, wanted.x(), wanted.y(), wanted.z(),
                      key));
    };
    if (body.angular_velocity_where.line > 0 && differ(given[i].omega_W, allowed[i].omega_W)) {
      fail(body.angular_velocity_where, "angular_velocity", given[i].omega_W, allowed[i].omega_W,
           "rad/s");
    }
    if (body.velocity_where.line > 0 && differ(given[i].v_G, allowed[i].v_G)) {
      fail(body.velocity_where, "velocity", given[i].v_G, allowed[i].v_G, "m/s");
    }
  }
  // A speed motor running from the start fixes its joint's rate from the start.
  for (std::size_t j = 0; j < scenario.joints.size(); ++j) {
    const MotorSpec& motor = scenario.joints[j].motor;
    if (motor.kind != MotorSpec::Kind::Speed || !(motor.from <= 0.0 && 0.0 < motor.to)) continue;
    const double rate = formulation.joint_rate(y0, j);
    if (std::abs(rate - motor.value) > 1e-9 * (std::abs(rate) + std::abs(motor.value)) + 1e-12) {
      const bool slider = scenario.joints[j].type == JointType::Prismatic;
      throw ScenarioError(
          motor.where, "joints." + scenario.joints[j].name + ".motor",
          slider ? fmt::format("the motor drives the slider at {:.9g} m/s from the start, but the "
                               "bodies' velocities move it at {:.9g} m/s; give them velocities "
                               "that agree, or start the motor later (from: ...)",
                               motor.value, rate)
                 : fmt::format("the motor drives the hinge at {:.9g} rad/s from the start, but "
                               "the bodies' angular velocities turn it at {:.9g} rad/s; give "
                               "them angular velocities that agree, or start the motor later "
                               "(from: ...)",
                               motor.value, rate));
    }
  }
}

// Values each finite but whose products overflow (a mass of 1e-300 kg or 1e200 kg, whose inertia
// has no inverse in double precision; an angular velocity of 1e308 rad/s, whose kinetic energy is
// infinite) would fail at the first step with NaN rows: refused here, at the body.
void check_initial_state_finite(const Scenario& scenario, const Model& model,
                                std::span<const BodyState> given) {
  for (std::size_t i = 0; i < given.size(); ++i) {
    const BodySpec& body = scenario.bodies[i];
    const RigidBody& rigid = model.bodies[i];
    const auto fail = [&](const SourceLocation& where, const std::string& key,
                          const std::string& why) {
      throw ScenarioError(where.line > 0 ? where : body.where, "bodies." + body.name + key, why);
    };
    // A slender body (a rod, a point) has no inverse at all: its joints make it well-posed
    // (check_slender_bodies), and nothing inverts its inertia.
    if (!body.slender && (!rigid.I_G_B_inv.allFinite() || !(rigid.I_G_B_inv.norm() < 1e300))) {
      fail(body.where, "",
           fmt::format("its mass ({:.3g} kg) and size give an inertia that double precision "
                       "cannot invert (its determinant, the cube of its size, overflows or "
                       "underflows): keep the inertia between about 1e-100 and 1e100 kg m^2, in "
                       "other units if need be",
                       rigid.mass));
    }
    const double kinetic_energy = calc_kinetic_energy(rigid, given[i]);
    const double momentum = calc_angular_momentum_about_com_W(rigid, given[i]).norm() +
                            calc_linear_momentum(rigid, given[i]).norm();
    if (!std::isfinite(kinetic_energy) || !std::isfinite(momentum) || !(kinetic_energy < 1e300)) {
      const bool spin = given[i].omega_W.norm() * given[i].omega_W.norm() * rigid.I_G_B.norm() >=
                        given[i].v_G.squaredNorm() * rigid.mass;
      fail(spin ? body.angular_velocity_where : body.velocity_where,
           spin ? ".angular_velocity" : ".velocity",
           "its kinetic energy or momentum overflows double precision: give a speed that the "
           "equations can carry (the products of mass, inertia and speeds must stay below about "
           "1e300)");
    }
  }
}

}  // namespace

namespace {

// Whether the method is implicit: its runs need the equations' Jacobian.
bool integrator_needs_jacobian(std::string_view name) {
  return name == "radau5" || name == "trbdf2";
}

// The scenario's integrator for one run. Throws std::invalid_argument for a control that does
// not fit the method.
std::unique_ptr<Integrator> make_run_integrator(const SimulationModel& model) {
  if (model.integrator == "exact") return std::make_unique<ExactIntegrator>();
  return make_integrator(model.integrator, model.control);
}

}  // namespace

std::shared_ptr<const SimulationModel> build_simulation_model(const Scenario& scenario) {
  const SimulateSpec& sim = scenario.simulate;
  // An error here is the part of the scenario's own that it names: the formulation's (or the
  // model's, which the reader has checked), then the integrator's.
  const auto formulation_model = [&] {
    try {
      return FormulationModel(sim.formulation, std::make_shared<const Model>(build_model(scenario)),
                              integrator_needs_jacobian(sim.integrator));
    } catch (const std::invalid_argument& e) {
      throw ScenarioError(sim.where, "simulate.formulation", e.what());
    }
  };
  auto m = std::make_shared<SimulationModel>(formulation_model());
  m->integrator = sim.integrator;
  m->control.rtol = sim.rtol;
  m->control.atol = sim.atol;
  m->control.fixed_step = sim.step;
  m->control.max_step = sim.max_step;
  m->control.initial_step = sim.initial_step;
  try {
    if (sim.integrator == "rkmk4" && !m->formulation.has_unit_quaternions()) {
      throw std::invalid_argument(
          "rkmk4 moves orientations on the rotation group and needs formulation: body");
    }
    // The reader refuses forces and joints with it; this keeps any model it cannot run from a
    // run (where the integrator would throw).
    if (sim.integrator == "exact" && !ExactIntegrator::fits(m->formulation.model())) {
      throw std::invalid_argument(
          "exact is for free bodies on which no force or torque acts (gravity is allowed); "
          "remove forces, joints and contacts or choose dopri5");
    }
    if (integrator_needs_jacobian(sim.integrator) && !m->formulation.gives_jacobian()) {
      throw std::invalid_argument(
          sim.integrator +
          ", an implicit method for stiff systems, needs its equations' Jacobian, which tumble "
          "takes in formulation: body (bodies free or on joints, springs, dampers, loads and "
          "contacts in every mode), not in formulation: textbook");
    }
    make_run_integrator(*m);  // refuses a control that does not fit, before any run
  } catch (const std::invalid_argument& e) {
    throw ScenarioError(sim.where, "simulate.integrator", e.what());
  }
  m->options.output_every = sim.output_every;
  m->options.max_steps = sim.max_steps;
  m->options.max_rows = sim.max_rows;
  m->t0 = 0.0;
  m->t_end = sim.duration;
  m->planar = scenario.planar;
  // The initial state's checks evaluate a formulation: a run's, dropped when the model is built.
  const std::unique_ptr<Formulation> run = m->formulation.new_run();
  m->y0 = initial_state_vector(scenario, *run);
  if (!scenario.events.empty()) {
    m->user_events = std::make_shared<UserEventDefinitions>(
        UserEventDefinitions{scenario.events, column_layout(scenario, *m), scenario.parameters});
    // Compiles them, refusing a name that is neither a column nor a parameter, before any run.
    const UserEventSystem check(*run, m->user_events);
  }
  return m;
}

VecX initial_state_vector(const Scenario& scenario, const Formulation& formulation) {
  VecX y0(formulation.dimension());
  const std::vector<BodyState> given = initial_states(scenario);
  check_initial_state_finite(scenario, formulation.model(), given);
  formulation.pack(given, y0);
  check_initial_velocities(scenario, formulation, given, y0);
  formulation.assemble(y0);
  if (const auto problem = formulation.start_problem(y0)) {
    if (problem->joint >= 0) {
      const JointSpec& joint = scenario.joints[static_cast<std::size_t>(problem->joint)];
      throw ScenarioError(joint.where, "joints." + joint.name, problem->why);
    }
    const ContactSpec& contact = scenario.contacts[problem->contact];
    throw ScenarioError(contact.where, fmt::format("contacts[{}]", problem->contact), problem->why);
  }
  return y0;
}

PreparedSimulation prepare_run(const SimulationModel& model) {
  PreparedSimulation p;
  p.formulation = model.formulation.new_run();
  if (model.user_events) {
    p.user_events = std::make_unique<UserEventSystem>(*p.formulation, model.user_events);
  }
  p.integrator = make_run_integrator(model);
  p.control = model.control;
  p.options = model.options;
  p.y0 = model.y0;
  p.t0 = model.t0;
  p.t_end = model.t_end;
  p.planar = model.planar;
  return p;
}

PreparedSimulation prepare_simulation(const Scenario& scenario) {
  return prepare_run(*build_simulation_model(scenario));
}

SimulationResult run_simulation(PreparedSimulation& simulation, const RowObserver& observe) {
  return run_simulation(simulation,
                        [&](double t, std::span<const BodyState> states, const SystemQuantities& q,
                            const RowExtras&) { observe(t, states, q); });
}

namespace {

// One run's rows: each is handed over with its quantities and booked into the conservation
// report against the first row's baseline; from a checkpoint, against the baseline of the run
// it was taken from.
SimulationResult run_or_resume(PreparedSimulation& simulation, const FullRowObserver& observe,
                               const CheckpointCallback& on_checkpoint,
                               const SimulationCheckpoint* from) {
  const Formulation& formulation = *simulation.formulation;
  const Model& model = formulation.model();
  std::vector<BodyState> states(formulation.body_count());
  RowExtras extras;        // the row's, and after the run the last row's
  bool rows_here = false;  // whether this run (not the one resumed from) made a row
  SimulationResult result;
  RowBaseline base;
  if (from != nullptr) {
    base = from->baseline;
    result.conservation = from->conservation;
    result.rows = from->rows;
    result.last_extras = from->last_extras;
  }

  if (from != nullptr && simulation.planar) {
    // The angles run on from the last row before the checkpoint.
    extras.planar_angles = from->last_extras.planar_angles;
    extras.planar_rates = from->last_extras.planar_rates;
    extras.planar_t = from->last_extras.planar_t;
  }
  const auto on_row = [&](double t, const VecX& y) {
    formulation.unpack_all(y, states);
    formulation.calc_row_extras(t, y, extras);
    if (simulation.planar) continue_planar_angles(t, states, extras);
    double gravity_potential = 0.0;
    const SystemQuantities q = row_quantities(model, states, extras, &gravity_potential);
    const double L = q.angular_momentum_about_origin.norm();
    if (result.rows == 0) {
      base.E0 = q.total_energy;
      base.L0 = L;
      base.KE0 = q.kinetic_energy;
      base.gravity_potential0 = gravity_potential;
    }
    const double E0 = base.E0, L0 = base.L0;
    ConservationReport& c = result.conservation;
    if (!simulation.drifts_only) {
      double work = -(gravity_potential - base.gravity_potential0);
      for (const ElementWork& e : extras.elements) work += e.work;
      // The contacts' entries are the ledger's last (ArticulatedModel::element_names).
      const std::size_t contacts = std::min(model.contact_ledger_size(), extras.elements.size());
      for (std::size_t i = extras.elements.size() - contacts; i < extras.elements.size(); ++i) {
        c.max_contact_work = std::max(c.max_contact_work, std::abs(extras.elements[i].work));
      }
      c.max_work_energy_residual =
          std::max(c.max_work_energy_residual, std::abs(q.kinetic_energy - base.KE0 - work));
      c.max_loop_error.gap = std::max(c.max_loop_error.gap, extras.loops.gap);
      c.max_loop_error.turn = std::max(c.max_loop_error.turn, extras.loops.turn);
      c.max_loop_error.speed = std::max(c.max_loop_error.speed, extras.loops.speed);
      for (const BodyState& s : states) {
        c.max_orthonormality_error =
            std::max(c.max_orthonormality_error, orthonormality_error(s.R_WB));
      }
    }
    c.max_kinetic_energy = std::max(c.max_kinetic_energy, q.kinetic_energy);
    c.initial_energy = E0;
    c.initial_angular_momentum = L0;
    c.max_energy_change = std::max(c.max_energy_change, std::abs(q.total_energy - E0));
    c.max_angular_momentum_change = std::max(c.max_angular_momentum_change, std::abs(L - L0));
    c.max_angular_momentum = std::max(c.max_angular_momentum, L);
    if (E0 != 0.0) {
      c.max_relative_energy_drift =
          std::max(c.max_relative_energy_drift, std::abs(q.total_energy - E0) / std::abs(E0));
    }
    if (L0 != 0.0) {
      c.max_relative_angular_momentum_drift =
          std::max(c.max_relative_angular_momentum_drift, std::abs(L - L0) / L0);
    }
    ++result.rows;
    observe(t, states, q, extras);
    rows_here = true;
  };
  CheckpointObserver on_driver_checkpoint;
  if (on_checkpoint) {
    on_driver_checkpoint = [&](DriverCheckpoint driver) {
      on_checkpoint({std::move(driver), formulation.hybrid_state(), base, result.conservation,
                     result.rows, rows_here ? extras : result.last_extras});
    };
  }

  // The states just after events: computed as a row is, into buffers of their own (the rows'
  // planar angles run on from the last row's), only for a run that asks for them.
  DriverOptions options = simulation.options;
  std::optional<StateRows> event_rows;
  if (simulation.on_event_state) {
    event_rows.emplace(formulation, simulation.planar);
    options.on_event_state = [&](double t, const VecX& y) {
      event_rows->continue_from(extras);
      const OutputRow row = event_rows->row_of(t, y, true, true);
      simulation.on_event_state(t, row.states, *row.quantities, *row.extras);
    };
  }

  // The run's pieces as rows, only for a run that reads between its rows.
  std::optional<PieceRows> piece_rows;
  if (simulation.on_piece) {
    piece_rows.emplace(formulation, simulation.planar);
    options.on_piece = [&](const SolutionPiece& piece) {
      piece_rows->set_piece(piece, extras);
      simulation.on_piece(*piece_rows);
    };
  }

  OdeSystem& system = ode_system_of(simulation);
  const auto start = std::chrono::steady_clock::now();
  if (from == nullptr) {
    result.report = integrate(*simulation.integrator, system, simulation.t0, simulation.y0,
                              simulation.t_end, options, on_row, on_driver_checkpoint);
  } else {
    simulation.formulation->set_hybrid_state(from->hybrid);
    simulation.integrator = from->driver.integrator->clone_onto(system);
    result.report = resume_integration(*simulation.integrator, system, from->driver.position,
                                       simulation.t_end, options, on_row, on_driver_checkpoint);
  }
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // The last row's extras (the work each element did over the run), copied once here rather than
  // at every row (the copy was 3.6% of the tumbling prism's run).
  if (rows_here) result.last_extras = extras;
  const HybridState& hybrid = simulation.formulation->hybrid_state();
  result.jumps = hybrid.jumps;
  result.contact_events = hybrid.contact.events;
  if (simulation.user_events) {
    result.user_events = simulation.user_events->occurrences(result.report.events);
  }
  return result;
}

}  // namespace

SimulationResult run_simulation(PreparedSimulation& simulation, const FullRowObserver& observe,
                                const CheckpointCallback& on_checkpoint) {
  return run_or_resume(simulation, observe, on_checkpoint, nullptr);
}

namespace {

FullRowObserver rows_to(RowSink& sink) {
  return [&sink](double t, std::span<const BodyState> states, const SystemQuantities& q,
                 const RowExtras& extras) {
    sink.write_row({t, states, &q, &extras});
  };
}

}  // namespace

SimulationResult run_simulation(PreparedSimulation& simulation, RowSink& sink,
                                const CheckpointCallback& on_checkpoint) {
  return run_simulation(simulation, rows_to(sink), on_checkpoint);
}

SystemQuantities row_quantities(const Model& model, std::span<const BodyState> states,
                                const RowExtras& extras, double* gravity_potential) {
  SystemQuantities q = calc_system_quantities(model.bodies, states, model.gravity_W);
  if (gravity_potential != nullptr) *gravity_potential = q.potential_energy;
  q.potential_energy += extras.elastic_energy;
  q.total_energy += extras.elastic_energy;
  return q;
}

namespace {

ColumnLayout layout_with_elements(const Scenario& scenario,
                                  std::vector<std::string> element_names) {
  ColumnLayout layout;
  for (const BodySpec& b : scenario.bodies) layout.bodies.push_back(b.name);
  for (const JointSpec& j : scenario.joints) {
    layout.joints.push_back(j.name);
    std::vector<std::string>& names = layout.joint_coordinates.emplace_back();
    // A loop's closing joint is a constraint, not a coordinate of the state: no columns.
    if (j.closes_loop) continue;
    for (const CoordinateName& name : joint_kind(j.type).coordinate_columns()) {
      names.emplace_back(name.suffix);
    }
  }
  for (const ContactSpec& c : scenario.contacts) {
    layout.contacts.push_back(c.name);
    layout.contact_columns.push_back(c.pool.empty() ? 1 : 0);
  }
  layout.elements = std::move(element_names);
  layout.planar = scenario.planar;
  return layout;
}

}  // namespace

ColumnLayout column_layout(const Scenario& scenario, const Formulation& formulation) {
  return layout_with_elements(scenario, formulation.element_names());
}

ColumnLayout column_layout(const Scenario& scenario, const SimulationModel& model) {
  return layout_with_elements(scenario, model.formulation.element_names());
}

OdeSystem& ode_system_of(PreparedSimulation& simulation) {
  return simulation.user_events ? static_cast<OdeSystem&>(*simulation.user_events)
                                : static_cast<OdeSystem&>(*simulation.formulation);
}

SimulationResult resume_simulation(PreparedSimulation& simulation,
                                   const SimulationCheckpoint& checkpoint,
                                   const FullRowObserver& observe,
                                   const CheckpointCallback& on_checkpoint) {
  return run_or_resume(simulation, observe, on_checkpoint, &checkpoint);
}

SimulationResult resume_simulation(PreparedSimulation& simulation,
                                   const SimulationCheckpoint& checkpoint, RowSink& sink,
                                   const CheckpointCallback& on_checkpoint) {
  return run_or_resume(simulation, rows_to(sink), on_checkpoint, &checkpoint);
}

}  // namespace tumble
