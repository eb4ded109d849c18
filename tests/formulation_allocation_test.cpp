// No heap allocation inside a step of a real rigid-body system: every method's step() and
// dense_output() on both formulations, with gravity and scheduled loads at an offset point, after
// start() has sized the workspace.
#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "tumble/dynamics/formulation.hpp"
#include "tumble/integrators/integrator.hpp"
#include "tumble/math/rotation.hpp"

namespace tumble {
namespace {

Model two_loaded_bodies() {
  Model m;
  m.bodies.push_back(RigidBody::make("a", 2.0, Vec3(1.0, 2.0, 2.5).asDiagonal()));
  m.bodies.push_back(RigidBody::make("b", 1.0, Vec3(0.3, 0.3, 0.5).asDiagonal()));
  AppliedLoad force;
  force.body = 0;
  force.value = Vec3(0.0, 1.0, 0.5);
  force.p_GP_B = Vec3(0.2, 0.0, 0.1);
  force.from = 0.1;
  force.to = 0.4;
  AppliedLoad torque;
  torque.kind = AppliedLoad::Kind::Torque;
  torque.body = 1;
  torque.value = Vec3(0.0, 0.0, 0.3);
  torque.body_frame = true;
  m.loads = {force, torque};
  return m;
}

TEST(NoAllocation, StepsOfEveryMethodOnBothFormulations) {
  for (const std::string formulation : {"body", "textbook"}) {
    for (const std::string method : {"dopri5", "dop853", "rk4", "rkmk4"}) {
      if (method == "rkmk4" && formulation == "textbook") continue;
      auto system = make_formulation(formulation, two_loaded_bodies());
      StepControl control;
      control.rtol = 1e-9;
      control.atol = 1e-12;
      control.fixed_step = 0.01;
      auto integrator = make_integrator(method, control);
      BodyState states[2];
      states[0].omega_W = Vec3(0.1, 2.0, 0.3);
      states[1].R_WB = rotation_from_axis_angle(Vec3(1, 1, 0), 0.4);
      states[1].omega_W = Vec3(1.0, 0.0, 5.0);
      states[1].v_G = Vec3(1.0, 0.0, 2.0);
      VecX y0(system->dimension()), y_dense(system->dimension());
      system->pack(states, y0);
      system->begin(0.0, y0);
      integrator->start(*system, 0.0, y0, 1.0);
      integrator->step(1.0);  // first step outside the count: nothing may be lazily sized later
      test::AllocationCounter allocations;
      for (int i = 0; i < 50 && integrator->t() < 1.0; ++i) {
        ASSERT_EQ(integrator->step(1.0), StepOutcome::Ok);
        integrator->dense_output(0.5 * (integrator->t_previous() + integrator->t()), y_dense);
      }
      EXPECT_EQ(allocations.count(), 0) << formulation << " " << method;
    }
  }
}

}  // namespace
}  // namespace tumble
