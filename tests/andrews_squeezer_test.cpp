// Andrews' squeezing mechanism (examples/andrews_squeezer.yaml) against the reference solution of
// the Bari test set for IVP solvers (computed there with PSIDE at tolerances 1e-14): its seven
// angles at t = 0.03 s. The reference's angles are the example's tree hinges' angles plus their
// values at t = 0 (each hinge's angle is 0 at t = 0).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "scenario_run.hpp"
#include "test_files.hpp"
#include "tumble/modes/scenario_modes.hpp"

namespace tumble {
namespace {

struct Angle {
  const char* name;
  std::size_t joint;  // the tree hinge whose angle it is, in the example's listing order
  double at_start, reference;
};

// beta, Theta, gamma, Phi, delta, Omega, epsilon: at t = 0 (the test set's), and at t = 0.03.
constexpr std::array<Angle, 7> kAngles{{
    {"beta", 0, -0.0617138900142764496358948458001, 15.81077119629904},
    {"Theta", 1, 0.0, -15.75637105984298},
    {"gamma", 2, 0.455279819163070380255912382449, 0.04082224013073101},
    {"Phi", 4, 0.222668390165885884674473185609, -0.5347301163226948},
    {"delta", 3, 0.487364979543842550225598953530, 0.5244099658805304},
    {"Omega", 6, -0.222668390165885884674473185609, 0.5347301163226948},
    {"epsilon", 5, 1.23054744454982119249735015568, 1.048080741042263},
}};

TEST(AndrewsSqueezer, ItsSevenAnglesAtThirtyMillisecondsAreTheReferences) {
  const test::ScenarioRun run =
      test::run_scenario(load_scenario(test::example("andrews_squeezer.yaml"), {}));
  const test::Row& last = run.rows.back();
  ASSERT_NEAR(last.t, 0.03, 1e-15);
  for (const Angle& angle : kAngles) {
    const double value = angle.at_start + last.extras.coordinates.at(angle.joint).values[0];
    // The bar: 1e-7 of each angle (the reference is good to about 1e-10).
    EXPECT_NEAR(value, angle.reference, 1e-7 * std::abs(angle.reference)) << angle.name;
  }
  const double mom = 0.033;  // N m: the crank's torque
  const double E0 = run.rows.front().quantities.total_energy;
  double largest_energy = 0.0;
  for (const test::Row& row : run.rows) {
    // The three hinges at E hold their points together at round-off of the mechanism's size
    // (its links are centimetres long).
    EXPECT_LE(row.extras.loops.gap, 1e-15) << "t " << row.t;
    largest_energy = std::max(largest_energy, std::abs(row.quantities.total_energy));
  }
  for (const test::Row& row : run.rows) {
    // The hinges do no work: the torque's, mom times the crank's turn, is the change of the
    // kinetic energy and the spring's.
    const double crank_turn = row.extras.coordinates.at(0).values[0];
    EXPECT_NEAR(row.quantities.total_energy - E0, mom * crank_turn, 1e-8 * largest_energy)
        << "t " << row.t;
  }
}

TEST(AndrewsSqueezer, ModesEquationsStartWithTheReferencesAccelerations) {
  // The test set's consistent initial values give the accelerations at t = 0 from rest: beta''
  // and Theta'' (the others are 0). `tumble modes`' equations (the loops' rows by automatic
  // differentiation's scalar) must give them; the reference's digits are good to about 1e-10.
  const std::shared_ptr<const ModalEquations> equations =
      modal_equations_of(load_scenario(test::example("andrews_squeezer.yaml"), {}));
  const VecX rates = equations->rates<double>(VecX::Zero(equations->layout().size()));
  const auto rate_of = [&](std::size_t joint) {
    const auto slot = static_cast<std::size_t>(equations->model().slot_of_joint[joint]);
    return rates(equations->layout().speed_offset[slot]);
  };
  const double beta2 = 14222.4439199541138705911625887;
  const double Theta2 = -10666.8329399655854029433719415;
  EXPECT_NEAR(rate_of(0), beta2, 1e-9 * beta2);
  EXPECT_NEAR(rate_of(1), Theta2, 1e-9 * std::abs(Theta2));
  for (std::size_t joint = 2; joint < kAngles.size(); ++joint) {
    EXPECT_NEAR(rate_of(joint), 0.0, 1e-9 * beta2) << "joint " << joint;
  }
}

}  // namespace
}  // namespace tumble
