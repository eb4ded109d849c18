// No heap allocation inside a step of a real rigid-body system: every method's step() and
// dense_output() on both formulations, with gravity and scheduled loads at an offset point, after
// start() has sized the workspace.
#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "allocation_counter.hpp"
#include "tumble/dynamics/formulation.hpp"
#include "tumble/integrators/integrator.hpp"
#include "tumble/math/rotation.hpp"
#include "tumble/simulation/make_formulation.hpp"
#include "tumble/simulation/simulation.hpp"

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

// Every kind of joint and element: a ball-jointed body, a hinged one under a torque motor and a
// torsional spring, a welded one, a free one on a spring, and a hinge driven at a speed.
Model jointed_system() {
  Model m;
  for (const char* name : {"b0", "b1", "b2", "b3", "b4"}) {
    const double i = static_cast<double>(m.bodies.size());
    m.bodies.push_back(RigidBody::make(name, 1.0 + i, Vec3(0.3, 0.4 + 0.1 * i, 0.5).asDiagonal()));
  }
  JointModel ball;
  ball.type = JointType::Ball;
  ball.body_a = kGround;
  ball.body_b = 0;
  ball.p_BJ_B = Vec3(0.0, 0.0, 0.5);
  JointModel hinge;
  hinge.type = JointType::Hinge;
  hinge.body_a = 0;
  hinge.body_b = 1;
  hinge.p_AJ_A = Vec3(0.0, 0.0, -0.5);
  hinge.p_BJ_B = Vec3(0.3, 0.0, 0.0);
  hinge.axis_B = Vec3(0.0, 1.0, 0.0);
  hinge.motor.kind = JointMotor::Kind::Effort;
  hinge.motor.value = 0.2;
  JointModel weld;
  weld.type = JointType::Fixed;
  weld.body_a = 1;
  weld.body_b = 2;
  weld.p_AJ_A = Vec3(-0.3, 0.0, 0.0);
  JointModel driven = hinge;
  driven.motor.kind = JointMotor::Kind::Speed;
  driven.motor.value = 3.0;
  driven.body_a = 2;
  driven.body_b = 4;
  m.joints = {ball, hinge, weld, driven};
  LinearSpring spring;
  spring.body_a = kGround;
  spring.body_b = 3;
  spring.stiffness = 10.0;
  spring.damping = 0.1;
  spring.rest_length = 0.2;
  spring.p_A_A = Vec3(1.0, 0.0, 0.0);
  m.springs = {spring};
  TorsionalSpring twist;
  twist.body_a = 0;
  twist.body_b = 1;
  twist.stiffness = 2.0;
  twist.damping = 0.05;
  twist.hinge = 1;
  TorsionalSpring free_twist = twist;
  free_twist.body_a = 3;
  free_twist.body_b = 4;
  free_twist.hinge = -1;
  m.torsional_springs = {twist, free_twist};
  return m;
}

// Allocations during 50 steps of `method` on `system` from `states`, each with a dense output and
// the event functions (their refresh too), after start() and one step: nothing may be sized
// lazily later.
long allocations_in_steps(OdeSystem& system, const std::string& method, const VecX& y0) {
  StepControl control;
  control.rtol = 1e-9;
  control.atol = 1e-12;
  control.fixed_step = 0.01;
  auto integrator = make_integrator(method, control);
  VecX y_dense(system.dimension());
  VecX g(static_cast<Eigen::Index>(system.events().size()));
  system.begin(0.0, y0);
  integrator->start(system, 0.0, y0, 1.0);
  integrator->step(1.0);
  test::AllocationCounter allocations;
  for (int i = 0; i < 50 && integrator->t() < 1.0; ++i) {
    // As the driver: the step within the system's limit (the contacts' landing bound, a broad
    // phase's screening), and its events evaluated again where that asks for it.
    integrator->bound_next_step(system.step_limit(integrator->t(), integrator->y()));
    if (system.events_rescreened()) system.event_functions(integrator->t(), integrator->y(), g);
    if (integrator->step(1.0) != StepOutcome::Ok) {
      ADD_FAILURE() << method << ": a step failed at t = " << integrator->t();
      break;
    }
    integrator->dense_output(0.5 * (integrator->t_previous() + integrator->t()), y_dense);
    system.event_functions(integrator->t(), integrator->y(), g);
    system.refresh_event_functions(integrator->t(), integrator->y());
  }
  return allocations.count();
}

long allocations_in_steps(Formulation& system, const std::string& method,
                          std::span<const BodyState> states) {
  VecX y0(system.dimension());
  system.pack(states, y0);
  return allocations_in_steps(static_cast<OdeSystem&>(system), method, y0);
}

// A scenario's own events, evaluated on the row at each step's end: the crate sliding on the
// floor with a condition on its position and one on its energy (which needs the row's extras).
TEST(NoAllocation, StepsWithTheScenariosEvents) {
  const Scenario scenario = load_scenario_text(R"(tumble: 1
parameters: {d: 1}
bodies:
  crate: {shape: box, size: [0.4, 0.4, 0.4], mass: 5, position: [0, 0, 0.2], velocity: [3, 0, 0]}
contacts:
  - {name: floor, type: plane, body: crate, plane: {point: [0, 0, 0], normal: [0, 0, 1]}, friction: 0.3}
events:
  - {name: slid_d, when: crate.x > d}
  - {name: slow, when: E < 10}
simulate: {duration: 1}
)",
                                               "events.yaml", {});
  for (const std::string method : {"dopri5", "dop853", "rk4"}) {
    PreparedSimulation run = prepare_simulation(scenario);
    ASSERT_TRUE(run.user_events);
    EXPECT_EQ(allocations_in_steps(*run.user_events, method, run.y0), 0) << method;
  }
}

TEST(NoAllocation, StepsOfAJointedSystem) {
  for (const std::string method : {"dopri5", "dop853", "rk4", "rkmk4"}) {
    auto system = make_formulation("body", jointed_system());
    std::vector<BodyState> states(5);
    for (std::size_t k = 0; k < states.size(); ++k) {
      const double i = static_cast<double>(k);
      states[k].R_WB = rotation_from_axis_angle(Vec3(1, 0.5 * i, 0), 0.2 * i);
      states[k].r_G = Vec3(0.1 * i, 0.0, -0.5 * i);
    }
    EXPECT_EQ(allocations_in_steps(*system, method, states), 0) << method;
  }
}

// Closed loops: a slider-crank driven at a speed (a hinge closing a planar loop, three of its
// rows repeating the plane's) and two shafts on a Hooke joint, whose steps solve for the loops'
// forces and project onto them.
TEST(NoAllocation, StepsOfClosedLoops) {
  for (const char* example : {"slider_crank.yaml", "hooke_shafts.yaml"}) {
    const Scenario scenario =
        load_scenario(std::string(TUMBLE_SOURCE_DIR) + "/examples/" + example, {});
    for (const std::string method : {"dopri5", "dop853", "rk4"}) {
      PreparedSimulation run = prepare_simulation(scenario);
      EXPECT_EQ(allocations_in_steps(*run.formulation, method, run.y0), 0)
          << example << " " << method;
    }
  }
}

// A sphere rolling down a ramp, a disk sliding on the floor, a box sliding and spinning on its
// face and a cone rolling on its side: both contact modes, whose steps solve for the contact
// forces, project onto the constraints and evaluate the events.
TEST(NoAllocation, StepsOfBodiesInContact) {
  Model m;
  m.bodies.push_back(RigidBody::make("ball", 1.0, Vec3(0.004, 0.004, 0.004).asDiagonal()));
  m.bodies.push_back(RigidBody::make("disk", 0.2, Vec3(0.0005, 0.0005, 0.001).asDiagonal()));
  m.bodies.push_back(RigidBody::make("box", 1.0, Vec3(0.002, 0.004, 0.004).asDiagonal()));
  m.bodies.push_back(RigidBody::make("cone", 0.5, Vec3(9.375e-4, 9.375e-4, 3.75e-4).asDiagonal()));
  PlaneContact ramp;
  ramp.body = 0;
  ramp.surface = {ContactSurface::Kind::Sphere, 0.1, 0.0, {}};
  ramp.normal_W = Vec3(0.5, 0.0, std::sqrt(0.75));
  ramp.friction = 0.9;
  PlaneContact floor;
  floor.body = 1;
  floor.surface = {ContactSurface::Kind::Circle, 0.1, 0.0, {}};
  floor.point_W = Vec3(0.0, 0.0, -1.0);
  floor.friction = 0.2;
  PlaneContact box_floor;
  box_floor.body = 2;
  box_floor.surface.kind = ContactSurface::Kind::Polyhedron;
  for (const double z : {-0.05, 0.05}) {
    for (const double y : {-0.05, 0.05}) {
      for (const double x : {-0.1, 0.1}) box_floor.surface.vertices.emplace_back(x, y, z);
    }
  }
  box_floor.point_W = Vec3(0.0, 0.0, -3.0);
  box_floor.friction = 0.3;
  PlaneContact cone_floor;  // r 0.05, h 0.2
  cone_floor.body = 3;
  cone_floor.surface.kind = ContactSurface::Kind::Cone;
  cone_floor.surface.radius = 0.05;
  cone_floor.surface.vertices = {Vec3(0.0, 0.0, 0.15)};
  cone_floor.surface.rim_centre_B = Vec3(0.0, 0.0, -0.05);
  cone_floor.point_W = Vec3(0.0, 0.0, -5.0);
  cone_floor.friction = 0.8;
  m.contacts = {ramp, floor, box_floor, cone_floor};
  for (const std::string method : {"dopri5", "dop853", "rk4", "rkmk4"}) {
    auto system = make_formulation("body", m);
    std::vector<BodyState> states(4);
    states[0].r_G = 0.1 * ramp.normal_W;
    states[1].r_G = Vec3(0.0, 0.0, -0.9);
    states[1].R_WB = rotation_from_axis_angle(Vec3::UnitX(), 1.5707963267948966);
    states[1].v_G = Vec3(2.0, 0.0, 0.0);
    states[1].omega_W = Vec3(0.0, -60.0, 0.0);
    states[2].r_G = Vec3(0.0, 0.0, -2.95);
    states[2].v_G = Vec3(3.0, 0.0, 0.0);
    states[2].omega_W = Vec3(0.0, 0.0, 2.0);
    // On its side, apex at (0, 0, -5), turning about the line it touches along (cone_contact_test).
    const double alpha = std::atan(0.25);
    states[3].r_G = Vec3(0.15 * std::cos(alpha), 0.0, -5.0 + 0.15 * std::sin(alpha));
    states[3].R_WB = rotation_from_axis_angle(Vec3::UnitY(), -(1.5707963267948966 + alpha));
    states[3].omega_W = Vec3(-8.0, 0.0, 0.0);
    states[3].v_G = Vec3(0.0, 8.0 * 0.15 * std::sin(alpha), 0.0);
    EXPECT_EQ(allocations_in_steps(*system, method, states), 0) << method;
  }
}

// A group of balls in a closed box (`bodies: all`): the broad phase screens its pairs at each
// step's start, and the steps watch only those near (contact/broad_phase.hpp).
TEST(NoAllocation, StepsOfAGroupThroughTheBroadPhase) {
  std::string yaml = "tumble: 1\ngravity: [0, 0, -9.81]\nbodies:\n";
  for (int i = 0; i < 8; ++i) {
    yaml += "  b" + std::to_string(i) + ": {shape: sphere, radius: 0.05, mass: 0.1, position: [" +
            std::to_string(-0.3 + 0.2 * (i % 4)) + ", " + std::to_string(-0.1 + 0.2 * (i / 4)) +
            ", " + std::to_string(0.1 + 0.03 * i) + "], velocity: [" +
            std::to_string(0.5 - 0.13 * i) + ", 0.3, 0]}\n";
  }
  yaml +=
      "  floor: {shape: box, size: [1, 1, 0.1], mass: 9, position: [0, 0, -0.05]}\n"
      "  wall: {shape: box, size: [0.1, 1, 0.5], mass: 9, position: [0.45, 0, 0.25]}\n"
      "joints:\n"
      "  f1: {type: fixed, bodies: [ground, floor], at: [0, 0, 0]}\n"
      "  f2: {type: fixed, bodies: [ground, wall], at: [0, 0, 0]}\n"
      "contacts:\n"
      "  - {name: hit, type: bodies, bodies: all, friction: 0.5, restitution: 0.5}\n"
      "simulate: {duration: 1}\n";
  const Scenario scenario = load_scenario_text(yaml, "group.yaml", {});
  for (const std::string method : {"dopri5", "dop853", "rk4"}) {
    PreparedSimulation run = prepare_simulation(scenario);
    EXPECT_EQ(allocations_in_steps(*run.formulation, method, run.y0), 0) << method;
  }
}

TEST(NoAllocation, StepsOfEveryMethodOnBothFormulations) {
  for (const std::string formulation : {"body", "textbook"}) {
    for (const std::string method : {"dopri5", "dop853", "rk4", "rkmk4"}) {
      if (method == "rkmk4" && formulation == "textbook") continue;
      auto system = make_formulation(formulation, two_loaded_bodies());
      BodyState states[2];
      states[0].omega_W = Vec3(0.1, 2.0, 0.3);
      states[1].R_WB = rotation_from_axis_angle(Vec3(1, 1, 0), 0.4);
      states[1].omega_W = Vec3(1.0, 0.0, 5.0);
      states[1].v_G = Vec3(1.0, 0.0, 2.0);
      EXPECT_EQ(allocations_in_steps(*system, method, states), 0) << formulation << " " << method;
    }
  }
}

}  // namespace
}  // namespace tumble
