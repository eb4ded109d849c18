#include "tumble/multibody/articulated_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tumble/multibody/joints/joint_kind.hpp"

namespace tumble {

ArticulatedModel::ArticulatedModel(std::shared_ptr<const Model> model_in)
    : shared_model(std::move(model_in)), model(*shared_model), tree(build_kinematic_tree(model)) {
  slot_of_body.assign(body_count(), 0);
  slot_of_joint.assign(model.joints.size(), -1);
  Eigen::Index coordinates = 0, speed_count = 0;
  for (std::size_t k = 0; k < tree.size(); ++k) {
    const TreeJoint& joint = tree[k];
    slot_of_body[joint.child] = k;
    if (joint.model_joint >= 0)
      slot_of_joint[static_cast<std::size_t>(joint.model_joint)] = static_cast<int>(k);
    if (const Eigen::Index o = joint.kind->quaternion_offset(joint); o >= 0) {
      quaternion_offsets.push_back(o);
    }
    coordinates += joint.nq;
    speed_count += joint.nv;
  }
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const JointModel& joint = model.joints[j];
    if (joint.motor.kind != JointMotor::Kind::None) {
      if (!takes_motor(joint.type)) {
        throw std::logic_error("a motor needs a joint it can drive; the reader checks this");
      }
      motor_joints.push_back(j);
    }
    if (std::isfinite(joint.lock_at)) {
      if (!can_lock(joint.type)) {
        throw std::logic_error("a lock needs a joint with freedoms; the reader checks this");
      }
      lock_joints.push_back(j);
    }
  }
  speeds = coordinates;
  ledger = coordinates + speed_count;
  dimension = ledger + static_cast<Eigen::Index>(element_names().size());

  has_children.assign(tree.size(), false);
  holds_point_on_ball.assign(tree.size(), false);
  tree_root.assign(tree.size(), 0);
  for (std::size_t k = 0; k < tree.size(); ++k) {  // parents come before their children
    const TreeJoint& joint = tree[k];
    holds_point_on_ball[k] =
        joint.type == JointType::Ball && model.bodies[joint.child].I_G_B.isZero(0.0);
    if (joint.parent == kGround) {
      tree_root[k] = k;
    } else {
      const std::size_t parent = slot_of_body[static_cast<std::size_t>(joint.parent)];
      has_children[parent] = true;
      tree_root[k] = tree_root[parent];
    }
  }
  every_slot.resize(tree.size());
  tree_slots.resize(tree.size());
  tree_slots_begin.assign(tree.size() + 1, 0);
  for (std::size_t k = 0; k < tree.size(); ++k) {
    every_slot[k] = k;
    ++tree_slots_begin[tree_root[k] + 1];
  }
  for (std::size_t k = 0; k < tree.size(); ++k) tree_slots_begin[k + 1] += tree_slots_begin[k];
  std::vector<std::size_t> next(tree_slots_begin.begin(), tree_slots_begin.end() - 1);
  for (std::size_t k = 0; k < tree.size(); ++k) tree_slots[next[tree_root[k]]++] = k;

  // On a body a joint holds, a contact's rows may be redundant with the joint (the solve allows
  // that): every surface touches on every body.
  for (const PlaneContact& contact : model.contacts) {
    event_specs.push_back({contact.name + " touchdown", EventDirection::Falling});
    event_specs.push_back({contact.name + " lift-off", EventDirection::Falling});
    event_specs.push_back({contact.name + " stick-slip", EventDirection::Falling});
  }
}

std::vector<std::string> ArticulatedModel::element_names() const {
  std::vector<std::string> names;
  for (const AppliedLoad& load : model.loads) names.push_back(load.name);
  for (const LinearSpring& spring : model.springs) names.push_back(spring.name);
  for (const TorsionalSpring& spring : model.torsional_springs) names.push_back(spring.name);
  for (const std::size_t j : motor_joints) names.push_back(model.joints[j].name + ".motor");
  for (const ImpulseLoad& impulse : model.impulses) names.push_back(impulse.name);
  for (const std::size_t j : lock_joints) names.push_back(model.joints[j].name + ".lock");
  for (std::size_t i = 0; i < model.contact_ledger_size(); ++i) {
    names.push_back(model.contact_ledger_name(i));
  }
  return names;
}

bool ArticulatedModel::prescribed(std::size_t k, double mode_time) const {
  const TreeJoint& joint = tree[k];
  if (joint.nv == 0) return true;
  if (joint.model_joint < 0) return false;
  const JointModel& model_joint = model.joints[static_cast<std::size_t>(joint.model_joint)];
  if (mode_time >= model_joint.lock_at) return true;
  return model_joint.motor.kind == JointMotor::Kind::Speed &&
         model_joint.motor.active_at(mode_time);
}

Eigen::Index ArticulatedModel::first_motor_entry() const {
  return static_cast<Eigen::Index>(model.loads.size() + model.springs.size() +
                                   model.torsional_springs.size());
}

Eigen::Index ArticulatedModel::contact_entry(std::size_t contact) const {
  return first_motor_entry() +
         static_cast<Eigen::Index>(motor_joints.size() + model.impulses.size() +
                                   lock_joints.size() + model.contact_ledger_entry(contact));
}

double ArticulatedModel::hinge_angle(const VecX& y, std::size_t joint) const {
  return y(tree[static_cast<std::size_t>(slot_of_joint[joint])].q);
}

double ArticulatedModel::joint_rate(const VecX& y, std::size_t joint) const {
  return y(tree[static_cast<std::size_t>(slot_of_joint[joint])].v);
}

}  // namespace tumble
