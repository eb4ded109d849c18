#pragma once
// The constant part of a system in joint coordinates: the Model, the kinematic tree its joints
// form, and where each joint's coordinates and speeds and each element's work sit in the state
// y = [ joint coordinates | joint speeds | work ledger ]. Built once from a Model and shared
// (std::shared_ptr<const ArticulatedModel>) by every run of it, on any thread: nothing here
// changes during a run. A run's scratch is its ArticulatedData, its modes and records its
// HybridState.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "tumble/dynamics/model.hpp"
#include "tumble/integrators/ode_system.hpp"
#include "tumble/multibody/kinematic_tree.hpp"

namespace tumble {

struct ArticulatedModel {
  // Throws std::invalid_argument if the joints close a loop, or a body a joint holds touches a
  // plane with a round body (a disk, ring, cylinder, tube or cone).
  explicit ArticulatedModel(std::shared_ptr<const Model> model);

  std::shared_ptr<const Model> shared_model;
  const Model& model;  // *shared_model

  std::vector<TreeJoint> tree;            // parents before their children
  std::vector<std::size_t> slot_of_body;  // tree index of each body's inbound joint
  std::vector<bool> has_children;         // per tree joint: another body hangs from its child
  // Per tree joint: a ball joint holding a point mass (no inertia about its COM), whose turn
  // about the line from the pivot through it moves no mass: nothing says how fast it spins about
  // that line, and its joint inertia is singular there (solved by its pseudo-inverse).
  std::vector<bool> holds_point_on_ball;
  std::vector<std::size_t> tree_root;  // per tree joint: its ancestor hung from ground
  // Every tree joint in order, and each tree's joints in order (parents first) for a pass over
  // one tree: those of the tree whose root is k are tree_slots[tree_slots_begin[k] ...
  // tree_slots_begin[k + 1]).
  std::vector<std::size_t> every_slot, tree_slots, tree_slots_begin;
  std::vector<int> slot_of_joint;  // tree index of each model joint
  std::vector<Eigen::Index> quaternion_offsets;
  // Where the speeds and the work ledger start in y, and y's size.
  Eigen::Index speeds = 0, ledger = 0, dimension = 0;
  // Ledger order: loads, springs, torsional springs, motors, impulses, locks, contacts.
  std::vector<std::size_t> motor_joints, lock_joints;
  // Three per contact: touchdown, support (lift-off or tipping), stick-slip.
  std::vector<EventSpec> event_specs;

  std::size_t body_count() const { return model.bodies.size(); }
  // The joints of the tree whose root is `root`, parents first.
  std::span<const std::size_t> slots_of_tree(std::size_t root) const {
    return std::span<const std::size_t>(tree_slots)
        .subspan(tree_slots_begin[root], tree_slots_begin[root + 1] - tree_slots_begin[root]);
  }
  // The ledger's entries by name, in order.
  std::vector<std::string> element_names() const;
  // Locked hinges, hinges driven at a speed, fixed joints: their acceleration is known.
  bool prescribed(std::size_t tree_index, double mode_time) const;
  // Ledger entry of the first motor (after the loads, springs and torsional springs).
  Eigen::Index first_motor_entry() const;
  // The ledger entry of a contact (after the locks).
  Eigen::Index contact_entry(std::size_t contact) const;
  // A hinge's angle or a slider's travel, and its rate, of a model joint (its sign as the
  // scenario states it).
  double hinge_angle(const VecX& y, std::size_t joint) const;
  double joint_rate(const VecX& y, std::size_t joint) const;
};

}  // namespace tumble
