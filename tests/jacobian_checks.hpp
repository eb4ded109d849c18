#pragma once
// The run's Jacobian (modes/state_jacobian.hpp) against its own equations by central differences,
// for the tests of the implicit methods' systems.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>

#include "scenario_run.hpp"
#include "tumble/modes/state_jacobian.hpp"
#include "tumble/multibody/articulated_formulation.hpp"
#include "tumble/simulation/simulation.hpp"

namespace tumble::test {

// The largest departure, over the modal directions d_i = E e_i, of P J d_i (the Jacobian's
// motion along d_i, read in the modal coordinates) from P (f(y + eps d_i) - f(y - eps d_i)) /
// (2 eps), the run's own equations by central differences, against the largest of them.
// Central differences: truncation about eps^2 of the scale, round-off about 1e-16 / eps.
inline double largest_jacobian_departure(const std::string& yaml, const std::string& name,
                                         double eps = 1e-6) {
  const Scenario scenario = load_inline_scenario(yaml, name);
  const std::shared_ptr<const SimulationModel> model = build_simulation_model(scenario);
  std::unique_ptr<Formulation> run = model->formulation.new_run();
  const VecX& y = model->y0;
  run->begin(0.0, y);
  const Eigen::Index n = y.size();
  MatX J(n, n);
  EXPECT_TRUE(run->jacobian(0.0, y, J)) << name;
  const auto& articulated = dynamic_cast<const ArticulatedFormulation&>(*run);
  const ArticulatedModel& tree = *articulated.shared_articulated_model();
  const ModalLayout layout = make_modal_layout(tree, 0.0);
  MatX E, P;
  calc_modal_tangent(tree, layout, y, E, P);
  EXPECT_TRUE((P * E - MatX::Identity(layout.size(), layout.size())).isZero(1e-14)) << name;
  double departure = 0.0, largest = 0.0;
  VecX f_plus(n), f_minus(n);
  for (Eigen::Index i = 0; i < layout.size(); ++i) {
    const VecX d = E.col(i);
    run->derivative(0.0, y + eps * d, f_plus);
    run->derivative(0.0, y - eps * d, f_minus);
    const VecX by_differences = P * (f_plus - f_minus) / (2.0 * eps);
    const VecX by_jacobian = P * J * d;
    departure = std::max(departure, (by_differences - by_jacobian).cwiseAbs().maxCoeff());
    largest = std::max(largest, by_jacobian.cwiseAbs().maxCoeff());
  }
  return departure / largest;
}

}  // namespace tumble::test
