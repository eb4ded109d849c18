// No heap allocation in the hot loop: after start() has sized the workspace, step(), restart()
// and dense_output() of every method allocate nothing (a multi-million-step run must not touch
// the allocator). Checked with the counting global operator new of allocation_counter.cpp.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "allocation_counter.hpp"
#include "test_math.hpp"
#include "tumble/integrators/integrator.hpp"

namespace tumble {
namespace {

using test::AllocationCounter;

using test::quaternion_rate;

// Torque-free asymmetric body, state (q (4), omega_B (3)): Euler's equations.
class FreeBody7 : public OdeSystem {
 public:
  Eigen::Index dimension() const override { return 7; }
  std::span<const Eigen::Index> unit_quaternion_offsets() const override { return offsets_; }
  void derivative(double /*t*/, const VecX& y, VecX& dydt) const override {
    const Vec3 inertia(1.0, 2.0, 3.0);  // kg m^2
    const Vec3 omega_B = y.segment<3>(4);
    quaternion_rate(y, 0, omega_B, dydt);
    dydt.segment<3>(4) = (-omega_B.cross(inertia.cwiseProduct(omega_B))).cwiseQuotient(inertia);
  }
  static VecX initial_state() {
    VecX y(7);
    y << 1.0, 0.0, 0.0, 0.0, 0.3, 1.0, -0.2;
    return y;
  }

 private:
  static constexpr Eigen::Index offsets_[1] = {0};
};

// A full rigid body in gravity with a body-fixed torque, state (r_G (3), q (4), v_G (3),
// omega_B (3)): the 13-dimensional state of the benchmarks.
class RigidBody13 : public OdeSystem {
 public:
  Eigen::Index dimension() const override { return 13; }
  std::span<const Eigen::Index> unit_quaternion_offsets() const override { return offsets_; }
  void derivative(double t, const VecX& y, VecX& dydt) const override {
    const Vec3 inertia(0.5, 0.8, 1.1);  // kg m^2
    const Vec3 omega_B = y.segment<3>(10);
    dydt.segment<3>(0) = y.segment<3>(7);
    quaternion_rate(y, 3, omega_B, dydt);
    dydt.segment<3>(7) = Vec3(0.0, 0.0, -9.81);
    const Vec3 torque_B(0.1 * std::sin(t), 0.0, 0.05);
    dydt.segment<3>(10) =
        (torque_B - omega_B.cross(inertia.cwiseProduct(omega_B))).cwiseQuotient(inertia);
  }
  static VecX initial_state() {
    VecX y(13);
    y << 0.0, 0.0, 1.0, 0.9, 0.1, -0.3, 0.2, 1.0, 0.0, 3.0, 2.0, -1.0, 0.5;
    y.segment<4>(3).normalize();
    return y;
  }

 private:
  static constexpr Eigen::Index offsets_[1] = {3};
};

// Runs `steps` steps of `method` with dense output at three points inside each and a restart
// half-way, and returns the allocations counted after start().
long allocations_in_steps_and_restart(const std::string& method, OdeSystem& system, const VecX& y0,
                                      int steps) {
  StepControl control;
  control.rtol = 1e-8;
  control.atol = 1e-10;
  control.fixed_step = 0.01;
  auto integrator = make_integrator(method, control);
  const double t_end = 1e6;  // far away: every step is a normal one
  integrator->start(system, 0.0, y0, t_end);
  VecX y_out(y0.size());
  VecX y_restart(y0.size());

  AllocationCounter counter;
  for (int i = 0; i < steps; ++i) {
    if (integrator->step(t_end) != StepOutcome::Ok) return -1;
    for (const double s : {0.25, 0.5, 0.75}) {
      integrator->dense_output(
          integrator->t_previous() + s * (integrator->t() - integrator->t_previous()), y_out);
    }
    if (i == steps / 2) {
      y_restart = integrator->y();
      y_restart[y_restart.size() - 1] += 0.1;
      integrator->restart(integrator->t(), y_restart);
    }
  }
  // A step that lands on a stop time takes the clipping branch.
  if (integrator->step(integrator->t() + 1e-3) != StepOutcome::Ok) return -1;
  integrator->dense_output(integrator->t(), y_out);
  return counter.count();
}

TEST(NoAllocation, TheCounterSeesAnAllocation) {
  AllocationCounter counter;
  std::vector<double> v(100);
  v[0] = 1.0;
  EXPECT_GE(counter.count(), 1);
  EXPECT_EQ(v[0], 1.0);
}

TEST(NoAllocation, StepRestartAndDenseOutputAllocateNothing) {
  FreeBody7 body7;
  RigidBody13 body13;
  for (const std::string method : {"dopri5", "dop853", "rk4", "rkmk4"}) {
    EXPECT_EQ(allocations_in_steps_and_restart(method, body7, FreeBody7::initial_state(), 200), 0)
        << method;
    EXPECT_EQ(allocations_in_steps_and_restart(method, body13, RigidBody13::initial_state(), 200),
              0)
        << method;
  }
}

}  // namespace
}  // namespace tumble
