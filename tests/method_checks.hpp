#pragma once
// What the tests of every adaptive method check the same way: its order as the step halves, a
// clone and a saved-and-loaded copy going on exactly as the original, no allocation in a step.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <memory>

#include "allocation_counter.hpp"
#include "linear_system.hpp"
#include "tumble/integrators/integrator.hpp"
#include "tumble/simulation/text_archive.hpp"

namespace tumble::test {

inline StepControl tolerances(double rtol, double atol) {
  StepControl control;
  control.rtol = rtol;
  control.atol = atol;
  return control;
}

// Where a run ends, and what it took.
struct Finish {
  VecX y;
  IntegratorStats stats;
};

// `method` from (0, y0) to t_end, every step expected to succeed.
inline Finish integrate_to(Integrator& method, OdeSystem& system, const VecX& y0, double t_end) {
  method.start(system, 0.0, y0, t_end);
  while (method.t() < t_end) {
    EXPECT_EQ(method.step(t_end), StepOutcome::Ok);
  }
  return {method.y(), method.stats()};
}

// Steps held at each h (initial and largest step h, tolerances no step can fail) from (0, y0) to
// t_end: the error there against the closed form falls by 2^order as h halves, within 0.1 in
// the exponent.
template <typename Method>
void expect_order_as_the_step_halves(const Linear& system, const VecX& y0, double t_end,
                                     std::initializer_list<double> steps, double order) {
  Linear copy = system;
  double previous = 0.0;
  for (const double h : steps) {
    StepControl control = tolerances(0.5, 1e3);
    control.initial_step = h;
    control.max_step = h;
    Method method(control);
    const Finish run = integrate_to(method, copy, y0, t_end);
    EXPECT_EQ(run.stats.accepted_steps, std::lround(t_end / h)) << h;
    EXPECT_EQ(run.stats.rejected_steps, 0) << h;
    const double error = (run.y - system.exact(t_end, y0)).cwiseAbs().maxCoeff();
    if (previous > 0.0) {
      EXPECT_NEAR(std::log2(previous / error), order, 0.1) << h << ": " << error;
    }
    previous = error;
  }
}

// Starts `method` and `loaded` (the same method and control) at (0, y0) towards t_end, takes
// `steps` steps with `method`, then clones it and saves its memory into `loaded`; the three then
// step to t_end side by side, and every step must agree to the bit.
inline void expect_copies_go_on_as_the_original(Integrator& method, Integrator& loaded,
                                                OdeSystem& system, const VecX& y0, double t_end,
                                                int steps) {
  method.start(system, 0.0, y0, t_end);
  for (int i = 0; i < steps; ++i) ASSERT_EQ(method.step(t_end), StepOutcome::Ok);
  std::unique_ptr<Integrator> clone = method.clone_onto(system);
  TextArchiveWriter writer;
  method.archive_memory(writer);
  loaded.start(system, 0.0, y0, t_end);
  TextArchiveReader reader(writer.written(), "saved");
  loaded.archive_memory(reader);
  EXPECT_TRUE(reader.at_end());
  while (method.t() < t_end) {
    ASSERT_EQ(method.step(t_end), StepOutcome::Ok);
    ASSERT_EQ(clone->step(t_end), StepOutcome::Ok);
    ASSERT_EQ(loaded.step(t_end), StepOutcome::Ok);
    ASSERT_EQ(clone->t(), method.t());
    ASSERT_EQ(loaded.t(), method.t());
    ASSERT_EQ(clone->y(), method.y());
    ASSERT_EQ(loaded.y(), method.y());
  }
}

// The heap allocations in up to 50 steps of `method` from (0, y0) towards t_end, each with the
// continuous extension read at its middle, then a restart and one more step.
inline long allocations_in_steps(Integrator& method, OdeSystem& system, const VecX& y0,
                                 double t_end) {
  method.start(system, 0.0, y0, t_end);
  VecX y(y0.size());
  AllocationCounter counter;
  for (int i = 0; i < 50 && method.t() < t_end; ++i) {
    method.step(t_end);
    method.dense_output(0.5 * (method.t() + method.t_previous()), y);
  }
  method.restart(method.t(), method.y());
  method.step(t_end);
  return counter.count();
}

}  // namespace tumble::test
