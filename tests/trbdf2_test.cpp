// TR-BDF2 (integrators/trbdf2.hpp) against closed-form solutions of stiff and non-stiff linear
// systems: its order 2 seen as the step halves on a stiff system, its steps set by the slow
// motion, the error following the tolerance, the continuous extension as accurate as the steps,
// a clone and a saved copy going on exactly as the original, no allocation in a step.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "linear_system.hpp"
#include "method_checks.hpp"
#include "tumble/integrators/trbdf2.hpp"

namespace tumble {
namespace {

TEST(TrBdf2, OnAStiffSystemTheErrorFallsAsTheSquareOfTheStep) {
  // Steps held at h (a loose tolerance, max_step = initial_step = h) on the two rates to t = 2:
  // the fast mode, h |lambda| = 5e4 to 4e5, is damped at every step (L-stability), and the slow
  // one's error falls as h^2 as h halves.
  test::expect_order_as_the_step_halves<TrBdf2>(test::Linear(test::two_rates()),
                                                Eigen::Vector2d(1.0, 0.5), 2.0,
                                                {0.2, 0.1, 0.05, 0.025}, 2.0);
}

TEST(TrBdf2, AStiffSystemTakesTheStepsOfItsSlowMode) {
  // Over 10 s the fast mode alone would hold an explicit method to 3 million steps.
  test::Linear system(test::two_rates());
  const VecX y0 = Eigen::Vector2d(1.0, 0.5);
  for (const double rtol : {1e-4, 1e-6}) {
    const double atol = rtol * 1e-2;
    TrBdf2 method(test::tolerances(rtol, atol));
    const test::Finish run = test::integrate_to(method, system, y0, 10.0);
    const VecX exact = system.exact(10.0, y0);
    EXPECT_LT((run.y - exact).cwiseAbs().maxCoeff(),
              10.0 * (atol + rtol * exact.cwiseAbs().maxCoeff()))
        << rtol;
    EXPECT_LT(run.stats.accepted_steps, 3000) << rtol;
  }
}

TEST(TrBdf2, TheErrorOnANonStiffSystemFollowsTheTolerance) {
  // Each step's error is held to rtol (atol = rtol on a solution of size 1: sk <= 2 rtol per
  // component); an oscillation damps none of it, so the global error is at most the sum of the
  // steps' (and a step of order 2 has steps as many as rtol^(-1/3)).
  test::Linear system(test::oscillator());
  const VecX y0 = Eigen::Vector2d(1.0, 0.0);
  double previous = 0.0;
  for (const double rtol : {1e-4, 1e-6, 1e-8}) {
    TrBdf2 method(test::tolerances(rtol, rtol));
    const test::Finish run = test::integrate_to(method, system, y0, 2.0);
    const double error = (run.y - system.exact(2.0, y0)).norm();
    EXPECT_LT(error, static_cast<double>(run.stats.accepted_steps) * 2.0 * std::sqrt(2.0) * rtol)
        << rtol << " " << run.stats.accepted_steps << " " << error;
    // And it falls with the tolerance: the steps' error as rtol, their number as rtol^(-1/3),
    // so the global error as rtol^(2/3), 100 ^ (2/3) = 21.5 times for each hundredth.
    if (previous > 0.0) {
      EXPECT_GT(previous / error, 10.0) << rtol;
    }
    previous = error;
  }
}

TEST(TrBdf2, TheContinuousExtensionIsAsAccurateAsTheSteps) {
  test::Linear system(test::oscillator());
  const VecX y0 = Eigen::Vector2d(1.0, 0.0);
  const double rtol = 1e-6;
  TrBdf2 method(test::tolerances(rtol, rtol));
  method.start(system, 0.0, y0, 2.0);
  VecX y(2);
  double worst_between = 0.0, worst_at_ends = 0.0;
  while (method.t() < 2.0) {
    ASSERT_EQ(method.step(2.0), StepOutcome::Ok);
    worst_at_ends = std::max(worst_at_ends, (method.y() - system.exact(method.t(), y0)).norm());
    for (int k = 1; k < 10; ++k) {
      const double t = method.t_previous() + 0.1 * k * (method.t() - method.t_previous());
      method.dense_output(t, y);
      worst_between = std::max(worst_between, (y - system.exact(t, y0)).norm());
    }
  }
  // The Hermite cubic's own error is O(h^4), below the steps' O(h^3) a step: between the ends
  // the error is that of the ends around it.
  EXPECT_LT(worst_between, 2.0 * worst_at_ends) << worst_between << " " << worst_at_ends;
  method.dense_output(method.t(), y);
  EXPECT_EQ(y, method.y());
}

TEST(TrBdf2, ACloneAndASavedCopyGoOnExactlyAsTheOriginal) {
  test::Linear system(test::two_rates());
  TrBdf2 method(test::tolerances(1e-6, 1e-8));
  TrBdf2 loaded(test::tolerances(1e-6, 1e-8));
  test::expect_copies_go_on_as_the_original(method, loaded, system, Eigen::Vector2d(1.0, 0.5), 10.0,
                                            12);
}

TEST(TrBdf2, AStepAllocatesNothing) {
  test::Linear system(test::two_rates());
  TrBdf2 method(test::tolerances(1e-6, 1e-8));
  EXPECT_EQ(test::allocations_in_steps(method, system, Eigen::Vector2d(1.0, 0.5), 10.0), 0);
}

TEST(TrBdf2, RefusesASystemWithoutAJacobian) {
  test::DecayWithoutJacobian system;
  TrBdf2 method(test::tolerances(1e-6, 1e-8));
  const VecX y0 = VecX::Ones(1);
  EXPECT_THROW(method.start(system, 0.0, y0, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace tumble
