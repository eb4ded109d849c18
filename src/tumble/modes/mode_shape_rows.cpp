#include "tumble/modes/mode_shape_rows.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "tumble/modes/modal_equations.hpp"
#include "tumble/multibody/articulated_formulation.hpp"

namespace tumble {

RecordedTrajectory mode_shape_rows(const ScenarioModes& modes, double size,
                                   std::vector<ShownMode>& shown) {
  const ModalEquations& eq = *modes.equations;
  const ArticulatedModel& model = eq.model();
  const ModalLayout& layout = eq.layout();
  const Linearisation& lin = modes.linearisation;
  const ArticulatedFormulation formulation(eq.shared_model());
  RecordedTrajectory rows(model.body_count());
  // The page's plot of each body's speed, as a run's page has by default: the mode's speeds.
  ColumnLayout bodies;
  AnimationPlot speeds{"speed of the COM (m/s)", {}};
  for (const RigidBody& body : model.model.bodies) {
    bodies.bodies.push_back(body.name);
    speeds.columns.push_back(body.name + ".speed");
  }
  rows.record_plots(bodies, {std::move(speeds)});
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
      // Positions and speeds alike, so that the rows' speeds, angular velocities and KE move with
      // the shape instead of staying at y0's: the configuration exactly (turns as rotations), the
      // velocities as the linearisation has them.
      VecX z(layout.size());
      for (Eigen::Index i = 0; i < layout.size(); ++i) z(i) = scale * (shape(i) * swing).real();
      formulation.unpack_all(displace_positions(model, layout, eq.y0(), z), states);
      eq.calc_body_velocities(z, states);
      const SystemQuantities q =
          calc_system_quantities(model.model.bodies, states, model.model.gravity_W);
      rows.write_row({t + cycle * row / kRowsPerCycle, states, &q, nullptr});
    }
    t += cycle * kCycles + cycle / kRowsPerCycle;
  }
  return rows;
}

}  // namespace tumble
