#include "tumble/simulation/simulation.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "tumble/math/rotation.hpp"
#include "tumble/simulation/exact_integrator.hpp"
#include "tumble/simulation/model_from_scenario.hpp"

namespace tumble {

PreparedSimulation prepare_simulation(const Scenario& scenario) {
  const SimulateSpec& sim = scenario.simulate;
  PreparedSimulation p;
  p.formulation = make_formulation(sim.formulation, build_model(scenario));
  p.control.rtol = sim.rtol;
  p.control.atol = sim.atol;
  p.control.fixed_step = sim.step;
  p.control.max_step = sim.max_step;
  p.control.initial_step = sim.initial_step;
  if (sim.integrator == "exact") {
    p.integrator = std::make_unique<ExactIntegrator>();
  } else {
    if (sim.integrator == "rkmk4" && p.formulation->unit_quaternion_offsets().empty()) {
      throw std::invalid_argument(
          "rkmk4 moves orientations on the rotation group and needs formulation: body");
    }
    p.integrator = make_integrator(sim.integrator, p.control);
  }
  p.options.output_every = sim.output_every;
  p.options.max_steps = sim.max_steps;
  p.t0 = 0.0;
  p.t_end = sim.duration;
  p.y0.resize(p.formulation->dimension());
  p.formulation->pack(initial_states(scenario), p.y0);
  return p;
}

SimulationResult run_simulation(PreparedSimulation& simulation, const RowObserver& observe) {
  const Formulation& formulation = *simulation.formulation;
  const Model& model = formulation.model();
  std::vector<BodyState> states(formulation.body_count());
  SimulationResult result;
  double E0 = 0.0, L0 = 0.0;

  const auto on_row = [&](double t, const VecX& y) {
    for (std::size_t i = 0; i < states.size(); ++i) states[i] = formulation.unpack(y, i);
    const SystemQuantities q = calc_system_quantities(model.bodies, states, model.gravity_W);
    const double L = q.angular_momentum_about_origin.norm();
    if (result.rows == 0) {
      E0 = q.total_energy;
      L0 = L;
    }
    ConservationReport& c = result.conservation;
    if (E0 != 0.0) {
      c.max_relative_energy_drift =
          std::max(c.max_relative_energy_drift, std::abs(q.total_energy - E0) / std::abs(E0));
    }
    if (L0 != 0.0) {
      c.max_relative_angular_momentum_drift =
          std::max(c.max_relative_angular_momentum_drift, std::abs(L - L0) / L0);
    }
    for (const BodyState& s : states) {
      c.max_orthonormality_error =
          std::max(c.max_orthonormality_error, orthonormality_error(s.R_WB));
    }
    ++result.rows;
    observe(t, states, q);
  };

  const auto start = std::chrono::steady_clock::now();
  result.report = integrate(*simulation.integrator, *simulation.formulation, simulation.t0,
                            simulation.y0, simulation.t_end, simulation.options, on_row);
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace tumble
