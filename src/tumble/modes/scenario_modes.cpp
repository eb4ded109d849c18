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

RecordedTrajectory mode_shape_rows(const ScenarioModes& modes, double size,
                                   std::vector<ShownMode>& shown) {
  const ModalEquations& eq = *modes.equations;
  const ArticulatedModel& model = eq.model();
  const ModalLayout& layout = eq.layout();
  const Linearisation& lin = modes.linearisation;
  const ArticulatedFormulation formulation(eq.shared_model());
  RecordedTrajectory rows(model.body_count());
  std::vector<BodyState> states(model.body_count());
  shown.clear();
  double t = 0.0;
  constexpr int kRowsPerCycle = 48;
  constexpr int kCycles = 3;
  for (std::size_t m = 0; m < modes.analysis.modes.size(); ++m) {
    const Mode& mode = modes.analysis.modes[m];
    if (mode.kind == Mode::Kind::Neutral) continue;
    // The shape over all of z: kept entries as they are; a position set aside or without its
    // own entry moves by its speed / lambda.
    Eigen::VectorXcd shape = Eigen::VectorXcd::Zero(layout.size());
    for (std::size_t i = 0; i < lin.kept.size(); ++i) {
      shape(lin.kept[i]) = mode.shape(static_cast<Eigen::Index>(i));
    }
    for (std::size_t k = 0; k < model.tree.size(); ++k) {
      const Eigen::Index po = layout.position_offset[k];
      if (po < 0) continue;
      const Eigen::Index count = layout.speed_offset[k] - po;
      for (Eigen::Index i = 0; i < model.tree[k].nv; ++i) {
        const bool kept = std::find(lin.kept.begin(), lin.kept.end(), po + i) != lin.kept.end();
        if (!kept) shape(po + i) = shape(po + count + i) / mode.eigenvalue;
      }
    }
    double turn = 0.0, shift = 0.0;  // the largest angle (rad) and displacement (m)
    for (Eigen::Index i = 0; i < layout.position_count; ++i) {
      double& largest =
          layout.coordinates[static_cast<std::size_t>(i)].unit == "rad" ? turn : shift;
      largest = std::max(largest, std::abs(shape(i)));
    }
    const double scale =
        std::min(turn > 0.0 ? 0.2 / turn : INFINITY, shift > 0.0 ? 0.1 * size / shift : INFINITY);
    if (!std::isfinite(scale)) continue;
    const bool oscillates = mode.damped_frequency > 0.0;
    const double cycle = oscillates ? mode.period() : 2.0;
    shown.push_back({m, t});
    for (int row = 0; row <= kCycles * kRowsPerCycle; ++row) {
      const double phase = 2.0 * std::numbers::pi * row / kRowsPerCycle;
      const std::complex<double> swing =
          oscillates ? std::exp(std::complex<double>(0.0, phase)) : std::sin(phase);
      VecX z = VecX::Zero(layout.size());
      for (Eigen::Index i = 0; i < layout.position_count; ++i) {
        z(i) = scale * (shape(i) * swing).real();
      }
      formulation.unpack_all(displace_positions(model, layout, eq.y0(), z), states);
      rows.record(t + cycle * row / kRowsPerCycle, states,
                  calc_system_quantities(model.model.bodies, states, model.model.gravity_W));
    }
    t += cycle * kCycles + cycle / kRowsPerCycle;
  }
  return rows;
}

}  // namespace tumble
