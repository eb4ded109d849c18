// `integrator: auto` (integrators/auto_switching.hpp): DOP853 where nothing is stiff, step for
// step; radau5 where DOP853's stability holds its steps, and back where that has passed, each
// switch where its test says; the answer against the closed form throughout; a clone and a saved
// copy going on exactly as the original across a switch; no allocation in a step once radau5
// has its workspace.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>

#include "allocation_counter.hpp"
#include "linear_system.hpp"
#include "method_checks.hpp"
#include "tumble/integrators/auto_switching.hpp"
#include "tumble/simulation/text_archive.hpp"

namespace tumble {
namespace {

// Prothero and Robinson's test equation with a stiffness that fades: y' = lambda(t) (y - cos t)
// - sin t, lambda(t) = -1e5 e^(-4 t). From y(0) = 1 the solution is cos t whatever lambda is,
// and a step's error is pulled back onto it at the rate |lambda|: stiff while |lambda| is far
// above 1/h (t below about 1.5 s for these tolerances), not stiff after. Its Jacobian is
// lambda(t); `with_jacobian` false hides it, as a free body under gravity alone has none, and
// `modes_give_jacobian` false hides it in the modes of the moment, as a contact on an edge does.
class FadingStiffness : public OdeSystem {
 public:
  explicit FadingStiffness(bool with_jacobian = true) : with_jacobian_(with_jacobian) {}
  Eigen::Index dimension() const override { return 1; }
  static double lambda(double t) { return -1e5 * std::exp(-4.0 * t); }
  void derivative(double t, const VecX& y, VecX& dydt) const override {
    dydt[0] = lambda(t) * (y[0] - std::cos(t)) - std::sin(t);
  }
  bool jacobian(double t, const VecX& y, MatX& dfdy) const override {
    if (!gives_jacobian_at(t, y)) return false;
    dfdy(0, 0) = lambda(t);
    return true;
  }
  bool gives_jacobian() const override { return with_jacobian_; }
  bool gives_jacobian_at(double /*t*/, const VecX& /*y*/) const override {
    return with_jacobian_ && modes_give_jacobian;
  }
  bool modes_give_jacobian = true;

 private:
  bool with_jacobian_;
};

constexpr double kEnd = 6.0;

TEST(AutoSwitching, TakesRadau5WhereStiffAndDop853BackWhereTheStiffnessHasFaded) {
  FadingStiffness system;
  const double rtol = 1e-8;
  AutoSwitching method(test::tolerances(rtol, rtol));
  method.start(system, 0.0, VecX::Ones(1), kEnd);
  double worst = 0.0;
  while (method.t() < kEnd) {
    ASSERT_EQ(method.step(kEnd), StepOutcome::Ok);
    worst = std::max(worst, std::abs(method.y()[0] - std::cos(method.t())));
  }
  ASSERT_EQ(method.switch_count(), 2);
  const MethodSwitch& to_radau5 = method.switches()[0];
  const MethodSwitch& to_dop853 = method.switches()[1];
  EXPECT_TRUE(to_radau5.to_implicit);
  EXPECT_FALSE(to_dop853.to_implicit);
  // To radau5 after DOP853's fifteen steps at its stability edge, 6.1 / |lambda| = 6.1e-5 s
  // each at the start: within a few milliseconds.
  EXPECT_GT(to_radau5.h_lambda, AutoSwitching::kExplicitStabilityEdge);
  EXPECT_LT(to_radau5.t, 5e-3);
  // Back where radau5's steps h hold |h lambda(t)| <= 3.05 (fifteen of them): lambda has faded
  // by then from 1e5 to a few hundred per second at most, and is well below that at the end.
  EXPECT_LE(to_dop853.h_lambda, 0.5 * AutoSwitching::kExplicitStabilityEdge);
  EXPECT_LT(std::abs(FadingStiffness::lambda(to_dop853.t)), 1e3);
  EXPECT_EQ(method.method_in_use(), "dop853");
  // The solution is cos t throughout; each step's error is held to rtol (atol = rtol on a
  // solution of size 1), and the stiff part pulls what it leaves back onto cos t.
  EXPECT_LT(worst, 10.0 * rtol) << worst;
  const IntegratorStats stats = method.stats();
  EXPECT_EQ(stats.accepted_steps, method.explicit_steps() + method.implicit_steps());
  EXPECT_GT(method.implicit_steps(), 0);
}

TEST(AutoSwitching, WhereNothingIsStiffItIsDop853StepForStep) {
  // An undamped spring of 1e9 N/m on 1 kg over 0.1 s (503 periods): fast, but every step is
  // set by the accuracy of the oscillation, never by stability. At rtol 1e-10 DOP853 ends within
  // 1e-6 of the amplitude (its phase error over the periods is most of it).
  MatX spring(2, 2);
  spring << 0.0, 1.0, -1e9, 0.0;
  test::Linear system(spring);
  const VecX y0 = Eigen::Vector2d(1e-3, 0.0);
  const StepControl control = test::tolerances(1e-10, 1e-13);
  AutoSwitching automatic(control);
  Dop853 dop853(control);
  automatic.start(system, 0.0, y0, 0.1);
  dop853.start(system, 0.0, y0, 0.1);
  while (dop853.t() < 0.1) {
    ASSERT_EQ(dop853.step(0.1), StepOutcome::Ok);
    ASSERT_EQ(automatic.step(0.1), StepOutcome::Ok);
    ASSERT_EQ(automatic.t(), dop853.t());
    ASSERT_EQ(automatic.y(), dop853.y());
  }
  EXPECT_EQ(automatic.switch_count(), 0);
  EXPECT_EQ(automatic.stats().accepted_steps, dop853.stats().accepted_steps);
  EXPECT_EQ(automatic.stats().rhs_evaluations, dop853.stats().rhs_evaluations);
  // Against x0 cos(omega t).
  EXPECT_LT(std::abs(automatic.y()[0] - system.exact(0.1, y0)[0]), 1e-6 * 1e-3);
}

TEST(AutoSwitching, WithoutAJacobianItSaysWhereItWasStiffAndGoesOnWithDop853) {
  FadingStiffness system(false);
  AutoSwitching automatic(test::tolerances(1e-8, 1e-8));
  Dop853 dop853(test::tolerances(1e-8, 1e-8));
  automatic.start(system, 0.0, VecX::Ones(1), 1.0);
  dop853.start(system, 0.0, VecX::Ones(1), 1.0);
  while (dop853.t() < 1.0) {
    ASSERT_EQ(dop853.step(1.0), StepOutcome::Ok);
    ASSERT_EQ(automatic.step(1.0), StepOutcome::Ok);
    ASSERT_EQ(automatic.y(), dop853.y());
  }
  EXPECT_EQ(automatic.switch_count(), 0);
  EXPECT_GT(automatic.stiff_without_jacobian_at(), 0.0);
  EXPECT_LT(automatic.stiff_without_jacobian_at(), 5e-3);
}

TEST(AutoSwitching, AJumpIntoModesWithoutAJacobianHandsTheRunBackToDop853) {
  FadingStiffness system;
  const double rtol = 1e-8;
  AutoSwitching method(test::tolerances(rtol, rtol));
  method.start(system, 0.0, VecX::Ones(1), kEnd);
  while (method.method_in_use() != "radau5" || method.implicit_steps() < 5) {
    ASSERT_EQ(method.step(kEnd), StepOutcome::Ok);
  }
  // A jump (nothing moves) into modes that give no Jacobian: DOP853 takes over there at once.
  const double t_jump = method.t();
  system.modes_give_jacobian = false;
  method.restart(t_jump, method.y());
  ASSERT_EQ(method.switch_count(), 2);
  EXPECT_FALSE(method.switches()[1].to_implicit);
  EXPECT_TRUE(method.switches()[1].modes_without_jacobian());
  EXPECT_EQ(method.switches()[1].t, t_jump);
  EXPECT_EQ(method.method_in_use(), "dop853");
  // Still stiff (|lambda| above 1e4 here): DOP853 finds it so again, says where, and keeps the
  // run.
  const long radau5_steps = method.implicit_steps();
  while (method.t() < t_jump + 0.1) ASSERT_EQ(method.step(kEnd), StepOutcome::Ok);
  EXPECT_EQ(method.switch_count(), 2);
  EXPECT_EQ(method.implicit_steps(), radau5_steps);
  EXPECT_EQ(method.method_in_use(), "dop853");
  EXPECT_GT(method.stiff_without_jacobian_at(), t_jump);
  // Back in modes with one, the next stiffness goes to radau5 again; cos t throughout.
  system.modes_give_jacobian = true;
  method.restart(method.t(), method.y());
  double worst = 0.0;
  while (method.t() < t_jump + 0.3) {
    ASSERT_EQ(method.step(kEnd), StepOutcome::Ok);
    worst = std::max(worst, std::abs(method.y()[0] - std::cos(method.t())));
  }
  EXPECT_EQ(method.switch_count(), 3);
  EXPECT_TRUE(method.switches()[2].to_implicit);
  EXPECT_GT(method.implicit_steps(), radau5_steps);
  EXPECT_LT(worst, 10.0 * rtol) << worst;
}

TEST(AutoSwitching, ACloneAndASavedCopyGoOnExactlyAsTheOriginalAcrossTheSwitches) {
  FadingStiffness system;
  const StepControl control = test::tolerances(1e-8, 1e-8);
  // How many steps take it into radau5's stretch, a few of its steps along.
  AutoSwitching scout(control);
  scout.start(system, 0.0, VecX::Ones(1), kEnd);
  int steps = 0;
  for (; scout.switch_count() == 0 || scout.implicit_steps() < 5; ++steps) {
    ASSERT_EQ(scout.step(kEnd), StepOutcome::Ok);
  }
  ASSERT_EQ(scout.method_in_use(), "radau5");
  // Saved there, the copies go on through the switch back as the original does.
  AutoSwitching method(control);
  AutoSwitching loaded(control);
  test::expect_copies_go_on_as_the_original(method, loaded, system, VecX::Ones(1), kEnd, steps);
  ASSERT_EQ(method.switch_count(), 2);
  EXPECT_EQ(loaded.switch_count(), 2);
  EXPECT_EQ(loaded.switches()[1].t, method.switches()[1].t);
  EXPECT_EQ(loaded.stats().rhs_evaluations, method.stats().rhs_evaluations);
}

TEST(AutoSwitching, ASavedStateThatWouldSwitchWithoutAJacobianIsRefused) {
  // A crafted state (its fields changed by hand) that arms a switch to radau5, or says radau5 has
  // started, on a system that gives no Jacobian: refused at the field, not taken into a step that
  // could not start radau5.
  FadingStiffness system(false);
  const StepControl control = test::tolerances(1e-8, 1e-8);
  AutoSwitching method(control);
  method.start(system, 0.0, VecX::Ones(1), 1.0);
  for (int i = 0; i < 3; ++i) ASSERT_EQ(method.step(1.0), StepOutcome::Ok);
  TextArchiveWriter writer;
  method.archive_memory(writer);
  for (const std::string field : {"switch_armed", "implicit_started"}) {
    std::string text = writer.written();
    const std::size_t at = text.find(field + " 0\n");
    ASSERT_NE(at, std::string::npos) << field;
    text.replace(at, field.size() + 2, field + " 1");
    AutoSwitching loaded(control);
    loaded.start(system, 0.0, VecX::Ones(1), 1.0);
    TextArchiveReader reader(text, "crafted");
    try {
      loaded.archive_memory(reader);
      ADD_FAILURE() << field << " 1 was taken";
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("no Jacobian"), std::string::npos) << e.what();
    }
  }
}

TEST(AutoSwitching, NoStepAllocatesOnceRadau5HasItsWorkspace) {
  // The first switch to radau5 sizes its workspace (once a run); the steps after it, the switch
  // back, the continuous extension and a restart allocate nothing.
  FadingStiffness system;
  AutoSwitching method(test::tolerances(1e-8, 1e-8));
  method.start(system, 0.0, VecX::Ones(1), kEnd);
  while (method.switch_count() == 0) ASSERT_EQ(method.step(kEnd), StepOutcome::Ok);
  VecX y(1);
  test::AllocationCounter counter;
  while (method.t() < kEnd) {
    ASSERT_EQ(method.step(kEnd), StepOutcome::Ok);
    method.dense_output(0.5 * (method.t() + method.t_previous()), y);
  }
  EXPECT_EQ(counter.count(), 0);
  EXPECT_EQ(method.switch_count(), 2);
}

}  // namespace
}  // namespace tumble
