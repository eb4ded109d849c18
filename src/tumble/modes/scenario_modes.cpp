#include "tumble/modes/scenario_modes.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tumble/multibody/articulated_formulation.hpp"
#include "tumble/output/csv_text.hpp"
#include "tumble/simulation/model_from_scenario.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble {

std::shared_ptr<const ModalEquations> modal_equations_of(const Scenario& scenario) {
  // The checks a run makes of the scenario (the velocities against the joints, ...), then the
  // model in joint coordinates, whatever formulation a run would take.
  const std::shared_ptr<const SimulationModel> simulation = build_simulation_model(scenario);
  auto articulated = std::make_shared<const ArticulatedModel>(
      std::make_shared<const Model>(build_model(scenario)));
  const ArticulatedFormulation formulation(articulated);
  VecX y0(formulation.dimension());
  formulation.pack(initial_states(scenario), y0);
  // Loops given open by the round-off of the scenario's numbers are closed as a run closes them
  // (one that cannot close was refused above, by the run's checks).
  formulation.assemble(y0);
  return std::make_shared<const ModalEquations>(
      articulated, make_modal_layout(*articulated, simulation->t0), y0, simulation->t0);
}

ScenarioModes modes_of_scenario(const Scenario& scenario) {
  ScenarioModes modes;
  modes.equations = modal_equations_of(scenario);
  modes.linearisation = linearise(*modes.equations);
  modes.analysis = analyse_modes(modes.linearisation);
  return modes;
}

std::string modes_csv(const ScenarioModes& modes) {
  std::string text =
      "mode,kind,eigenvalue_real,eigenvalue_imag,natural_frequency_rad_s,frequency_hz,period_s,"
      "damping_ratio,growth_rate";
  for (const ModalCoordinate& c : modes.linearisation.coordinates) {
    text += fmt::format(",{}.amplitude,{}.phase_deg", c.name, c.name);
  }
  text += '\n';
  for (std::size_t i = 0; i < modes.analysis.modes.size(); ++i) {
    const Mode& mode = modes.analysis.modes[i];
    // A mode that does not oscillate has no period, and a decaying twin no damping ratio: their
    // fields are empty, as the summary prints "-".
    const auto number_or_empty = [](bool has, double x) {
      return has ? fmt::format("{:.17g}", x) : std::string();
    };
    text += fmt::format("{},{},{:.17g},{:.17g},{:.17g},{:.17g},{},{},{:.17g}", i + 1,
                        csv_quoted(kind_name(mode.kind)), mode.eigenvalue.real(),
                        mode.eigenvalue.imag(), mode.natural_frequency, mode.frequency_hz(),
                        number_or_empty(mode.damped_frequency > 0.0, mode.period()),
                        number_or_empty(!std::isnan(mode.damping_ratio), mode.damping_ratio),
                        mode.growth_rate);
    for (Eigen::Index j = 0; j < mode.shape.size(); ++j) {
      const double amplitude = std::abs(mode.shape(j));
      const double phase =
          amplitude > 0.0 ? std::arg(mode.shape(j)) * 180.0 / std::numbers::pi : 0.0;
      text += fmt::format(",{:.17g},{:.17g}", amplitude, phase);
    }
    text += '\n';
  }
  return text;
}

}  // namespace tumble
