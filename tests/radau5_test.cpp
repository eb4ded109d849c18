// Radau IIA of order 5 (integrators/radau5.hpp) against closed-form solutions of stiff and
// non-stiff linear systems: the steps a stiff system takes are set by its slow motion, not by
// its fast one; the error follows the tolerance; the continuous extension is as accurate as the
// steps; a clone and a saved-and-loaded copy go on exactly as the original; no step allocates.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "linear_system.hpp"
#include "method_checks.hpp"
#include "tumble/integrators/radau5.hpp"

namespace tumble {
namespace {

// A body of 1 kg on a spring k = 1e9 N/m with a damper c = 1e6 N s/m, as (x, v): overdamped,
// its modes at -k/c (about -1000 s^-1) and -c/m (about -1e6 s^-1).
MatX stiff_spring() {
  MatX a(2, 2);
  a << 0.0, 1.0, -1e9, -1e6;
  return a;
}

TEST(Radau5, AStiffSystemTakesTheStepsOfItsSlowMode) {
  // An explicit method is stable only for h |lambda| below about 3.3: over 10 s the fast mode
  // alone would hold it to 3 million steps. Radau IIA is L-stable: its steps follow the slow
  // mode's accuracy, and the fast mode, gone after a few microseconds, is damped at any step.
  test::Linear system(test::two_rates());
  const VecX y0 = Eigen::Vector2d(1.0, 0.5);
  for (const double rtol : {1e-6, 1e-9}) {
    Radau5 method(test::tolerances(rtol, rtol * 1e-2));
    const test::Finish run = test::integrate_to(method, system, y0, 10.0);
    const VecX exact = system.exact(10.0, y0);
    // Decayed to exp(-10) of its start, where atol holds the local error more than rtol does:
    // the global error of a decaying motion stays within a few of the last steps' tolerance.
    const double atol = rtol * 1e-2;
    EXPECT_LT((run.y - exact).cwiseAbs().maxCoeff(),
              10.0 * (atol + rtol * exact.cwiseAbs().maxCoeff()))
        << rtol;
    // A thousandth of what stability alone would hold an explicit method to.
    EXPECT_LT(run.stats.accepted_steps, 3000) << rtol;
  }
}

TEST(Radau5, TheStiffSpringDamperFollowsItsClosedForm) {
  test::Linear system(stiff_spring());
  const VecX y0 = Eigen::Vector2d(1e-3, 0.0);
  const double t_end = 5e-3;  // five time constants of the slow mode
  for (const double rtol : {1e-6, 1e-9}) {
    Radau5 method(test::tolerances(rtol, 1e-3 * rtol * 1e-3));
    const test::Finish run = test::integrate_to(method, system, y0, t_end);
    const VecX exact = system.exact(t_end, y0);
    EXPECT_LT(std::abs(run.y[0] - exact[0]), 10.0 * rtol * std::abs(exact[0])) << rtol;
    EXPECT_LT(std::abs(run.y[1] - exact[1]), 10.0 * rtol * std::abs(exact[1])) << rtol;
  }
  // Over a second (a thousand of the slow mode's time constants) an explicit method's stability
  // along the damper's rate, 1e6 s^-1, would take 300,000 steps at least; this takes a hundredth.
  Radau5 method(test::tolerances(1e-9, 1e-15));
  const test::Finish run = test::integrate_to(method, system, y0, 1.0);
  EXPECT_LT(run.stats.accepted_steps, 3000);
  EXPECT_LT(std::abs(run.y[0]), 1e-12 * y0[0]);  // the mount has settled (exp(-1000))
}

TEST(Radau5, TheErrorOnANonStiffSystemFollowsTheTolerance) {
  // Two turns of an oscillator: the error is a small multiple of rtol, and falls with it.
  test::Linear system(test::oscillator());
  const VecX y0 = Eigen::Vector2d(1.0, 0.0);
  const double t_end = 4.0 * M_PI;
  double previous = 1.0;
  for (const double rtol : {1e-4, 1e-6, 1e-8, 1e-10}) {
    Radau5 method(test::tolerances(rtol, rtol));
    const test::Finish run = test::integrate_to(method, system, y0, t_end);
    const double error = (run.y - system.exact(t_end, y0)).norm();
    EXPECT_LT(error, 10.0 * rtol) << rtol;
    EXPECT_LT(error, previous) << rtol;
    previous = error;
  }
}

TEST(Radau5, OnAStiffSystemTheErrorFallsAsTheFifthPowerOfTheStep) {
  // The stiff system of two rates, -1 and -1e6 s^-1, with every step held at h (initial and
  // largest step h, tolerances no step can fail; the system is linear and its Jacobian exact, so
  // each step's Newton solves its stages exactly): the error at t = 2 s falls by 2^5 = 32 as h
  // halves, the method's order 5 (R(-h)^(2/h) - e^-2, R the method's (2, 3) Pade approximant of
  // e^z, falls by 2^4.96, 2^4.98, 2^4.99 over these h). The fast mode, h |lambda| = 5e4 to 4e5,
  // is damped to nothing at every step (L-stability: R(z) ~ 1/z) and leaves the slow one's order.
  // The errors, 3e-7 down to 1e-11, stay well above the round-off each step leaves through the
  // stiff mode's solve (about eps |h lambda| of the state: taken to t = 1 with h = 0.025, it was
  // half the error, and the ratio read 2^6.25).
  test::expect_order_as_the_step_halves<Radau5>(
      test::Linear(test::two_rates()), Eigen::Vector2d(1.0, 0.5), 2.0, {0.4, 0.2, 0.1, 0.05}, 5.0);
}

TEST(Radau5, TheContinuousExtensionIsAsAccurateAsTheSteps) {
  test::Linear system(test::oscillator());
  const VecX y0 = Eigen::Vector2d(1.0, 0.0);
  const double rtol = 1e-8;
  Radau5 method(test::tolerances(rtol, rtol));
  method.start(system, 0.0, y0, 10.0);
  VecX y(2);
  double worst = 0.0;
  while (method.t() < 10.0) {
    ASSERT_EQ(method.step(10.0), StepOutcome::Ok);
    for (int k = 0; k <= 10; ++k) {
      const double t = method.t_previous() + 0.1 * k * (method.t() - method.t_previous());
      method.dense_output(t, y);
      worst = std::max(worst, (y - system.exact(t, y0)).norm());
    }
  }
  // The collocation cubic's error is of order h^4, as the error estimate's, which is held to
  // rtol: between the steps too the error is a small multiple of rtol (radau5.hpp).
  EXPECT_LT(worst, 10.0 * rtol) << worst;
  method.dense_output(method.t(), y);
  EXPECT_EQ(y, method.y());
}

TEST(Radau5, LandsOnTheStopAndRestartsFromANewState) {
  test::Linear system(stiff_spring());
  const VecX y0 = Eigen::Vector2d(1e-3, 0.0);
  Radau5 method(test::tolerances(1e-8, 1e-14));
  method.start(system, 0.0, y0, 1e-2);
  while (method.t() < 1e-3) ASSERT_EQ(method.step(1e-3), StepOutcome::Ok);
  EXPECT_EQ(method.t(), 1e-3);
  // A blow at 1 ms: the body's speed jumps to 1 m/s.
  VecX jumped = method.y();
  jumped[1] = 1.0;
  method.restart(1e-3, jumped);
  const long steps_before = method.stats().accepted_steps;
  while (method.t() < 1e-2) ASSERT_EQ(method.step(1e-2), StepOutcome::Ok);
  EXPECT_GT(method.stats().accepted_steps, steps_before);
  const VecX exact = system.exact(1e-2 - 1e-3, jumped);
  EXPECT_LT(std::abs(method.y()[0] - exact[0]), 1e-7 * std::abs(exact[0]));
}

TEST(Radau5, ACloneAndASavedCopyGoOnExactlyAsTheOriginal) {
  test::Linear system(test::two_rates());
  Radau5 method(test::tolerances(1e-8, 1e-10));
  Radau5 loaded(test::tolerances(1e-8, 1e-10));
  test::expect_copies_go_on_as_the_original(method, loaded, system, Eigen::Vector2d(1.0, 0.5), 10.0,
                                            12);
}

TEST(Radau5, AStepAllocatesNothing) {
  test::Linear system(test::two_rates());
  Radau5 method(test::tolerances(1e-8, 1e-10));
  EXPECT_EQ(test::allocations_in_steps(method, system, Eigen::Vector2d(1.0, 0.5), 10.0), 0);
}

TEST(Radau5, RefusesASystemWithoutAJacobian) {
  test::DecayWithoutJacobian system;
  Radau5 method(test::tolerances(1e-6, 1e-8));
  const VecX y0 = VecX::Ones(1);
  EXPECT_THROW(method.start(system, 0.0, y0, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace tumble
