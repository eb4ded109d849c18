// What the contact subsystem asks of the articulated formulation (contact/contact_dynamics.hpp),
// for a body anywhere in the tree. A body's pose, twist and acceleration are its inbound joint's
// workspace (child axes at the child's COM); a unit wrench's or an impulse's response is the
// impulsive passes (no velocity terms, no gravity), in which locked and speed-driven joints keep
// their rate; a projection's move is those passes' speed jumps taken as a small displacement of
// each joint's coordinates.
#include "tumble/multibody/articulated_formulation.hpp"

#include "tumble/multibody/joints/joint_kind.hpp"

namespace tumble {

ArticulatedFormulation::ContactBodies::ContactBodies(const ArticulatedFormulation& f) : f_(f) {
  // A body's motion is its inbound joint's workspace (sized once: the addresses hold); the bodies
  // hung from the same ground joint move together.
  const std::size_t bodies = f_.m_.body_count();
  motion_sources_.resize(bodies);
  motion_group_.resize(bodies);
  group_moves_.assign(bodies, 0);
  for (std::size_t body = 0; body < bodies; ++body) {
    const std::size_t slot = f_.m_.slot_of_body[body];
    const Workspace& w = f_.d_.work[slot];
    motion_sources_[body] = {&w.R_WC, &w.r_G_W, &w.velocity, &w.acceleration};
    motion_group_[body] = f_.m_.tree_root[slot];
    if (f_.m_.tree[slot].type != JointType::Fixed) group_moves_[f_.m_.tree_root[slot]] = 1;
  }
}

const BodyState& ArticulatedFormulation::ContactBodies::state(std::size_t body) const {
  return f_.d_.states[body];
}

void ArticulatedFormulation::ContactBodies::calc_motion(const VecX& y, bool with_velocities) const {
  f_.calc_kinematics(y, with_velocities);
}

void ArticulatedFormulation::ContactBodies::gather_loads(const VecX& y) const {
  f_.accumulate_element_loads(y, f_.s_.schedule_time, f_.d_.rates, 0, nullptr);
}

void ArticulatedFormulation::ContactBodies::gather_loads(const VecX& y, VecX& dydt) const {
  f_.accumulate_element_loads(y, f_.s_.schedule_time, dydt, f_.m_.ledger, nullptr);
}

void ArticulatedFormulation::ContactBodies::write_rates(const VecX& y, VecX& dydt) const {
  f_.write_state_rates(y, dydt);
}

void ArticulatedFormulation::ContactBodies::solve_under_loads() const {
  for (Workspace& w : f_.d_.work) w.applied = w.external;
  f_.solve(f_.s_.schedule_time, false);
}

void ArticulatedFormulation::ContactBodies::solve_under_loads_and(
    std::span<const BodyWrench> wrenches) const {
  for (Workspace& w : f_.d_.work) w.external = w.applied;
  for (const BodyWrench& wrench : wrenches) {
    f_.d_.work[f_.m_.slot_of_body[wrench.body]].external += wrench.wrench_B;
  }
  f_.solve(f_.s_.schedule_time, false);
}

void ArticulatedFormulation::ContactBodies::respond_to_unit_wrench(const BodyWrench& unit) const {
  // Only the pushed body's tree is solved (a bin's ball, not the hundred others), so only its
  // wrenches are cleared: a solve of every tree sets them all first.
  const std::size_t slot = f_.m_.slot_of_body[unit.body];
  const std::size_t root = f_.m_.tree_root[slot];
  for (const std::size_t k : f_.m_.slots_of_tree(root)) {
    Workspace& w = f_.d_.work[k];
    w.external.setZero();
    w.qdd.setZero();
  }
  f_.d_.work[slot].external += unit.wrench_B;
  f_.solve(f_.s_.schedule_time, true, root);
}

void ArticulatedFormulation::ContactBodies::respond_to_impulses(
    std::span<const BodyWrench> impulses) const {
  for (Workspace& w : f_.d_.work) {
    w.external.setZero();
    w.qdd.setZero();
  }
  for (const BodyWrench& impulse : impulses) {
    f_.d_.work[f_.m_.slot_of_body[impulse.body]].external += impulse.wrench_B;
  }
  f_.solve(f_.s_.schedule_time, true);
}

void ArticulatedFormulation::ContactBodies::apply_speed_jumps(VecX& y) const {
  for (std::size_t k = 0; k < f_.m_.tree.size(); ++k) {
    const TreeJoint& joint = f_.m_.tree[k];
    if (joint.nv > 0) y.segment(joint.v, joint.nv) += f_.d_.work[k].qdd;
  }
}

void ArticulatedFormulation::ContactBodies::apply_displacement(VecX& y) const {
  for (std::size_t k = 0; k < f_.m_.tree.size(); ++k) {
    const TreeJoint& joint = f_.m_.tree[k];
    joint.kind->displace(joint, f_.d_.work[k].qdd, f_.d_.work[k].R_WC, y);
  }
}

bool ArticulatedFormulation::ContactBodies::moves_freely(std::size_t body) const {
  return f_.m_.tree[f_.m_.slot_of_body[body]].type == JointType::Free;
}

void ArticulatedFormulation::ContactBodies::translate(std::size_t body, const Vec3& delta_W,
                                                      VecX& y) const {
  // A free joint's first three coordinates are its COM's position, world axes.
  y.segment<3>(f_.m_.tree[f_.m_.slot_of_body[body]].q) += delta_W;
}

void ArticulatedFormulation::ContactBodies::normalise(double t, VecX& y) const {
  f_.OdeSystem::project(t, y);
}

double ArticulatedFormulation::ContactBodies::kinetic_energy() const {
  return f_.kinetic_energy();
}

Eigen::Index ArticulatedFormulation::ContactBodies::ledger_start() const {
  return f_.m_.ledger;
}

Eigen::Index ArticulatedFormulation::ContactBodies::work_entry(std::size_t contact) const {
  return f_.m_.contact_entry(contact);
}

Eigen::Index ArticulatedFormulation::ContactBodies::contact_ledger_size() const {
  return static_cast<Eigen::Index>(f_.model_.contact_ledger_size());
}

}  // namespace tumble
