#include "tumble/multibody/kinematic_tree.hpp"

#include <algorithm>
#include <deque>
#include <stdexcept>

#include "tumble/multibody/joints/joint_kind.hpp"

namespace tumble {

namespace {

void set_subspace(TreeJoint& joint) {
  joint.kind = &joint_kind(joint.type);
  joint.nq = joint.kind->coordinate_count();
  joint.nv = joint.kind->speed_count();
  joint.kind->set_motion_subspace(joint);
}

TreeJoint from_model_joint(const JointModel& joint, int index, bool reversed) {
  TreeJoint t;
  t.type = joint.type;
  t.model_joint = index;
  t.reversed = reversed;
  if (!reversed) {
    t.parent = joint.body_a;
    t.child = static_cast<std::size_t>(joint.body_b);
    t.p_PJ_P = joint.p_AJ_A;
    t.p_CJ_C = joint.p_BJ_B;
    t.R_PC0 = joint.R_AB0;
  } else {
    // B is the parent.
    t.parent = joint.body_b;
    t.child = static_cast<std::size_t>(joint.body_a);
    t.p_PJ_P = joint.p_BJ_B;
    t.p_CJ_C = joint.p_AJ_A;
    t.R_PC0 = joint.R_AB0.transpose();
  }
  joint_kind(joint.type).set_axes(t, joint);
  set_subspace(t);
  return t;
}

}  // namespace

std::vector<TreeJoint> build_kinematic_tree(const Model& model) {
  const std::size_t n = model.bodies.size();
  std::vector<bool> reached(n, false), joint_used(model.joints.size(), false);
  std::vector<TreeJoint> tree;
  std::deque<int> frontier;
  // The joints at each body (ground's first), in the model's order: the tree is grown in time
  // linear in the joints, not in bodies times joints.
  std::vector<std::vector<std::size_t>> joints_at(n + 1);
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    joints_at[static_cast<std::size_t>(model.joints[j].body_a + 1)].push_back(j);
    if (model.joints[j].body_b != model.joints[j].body_a) {
      joints_at[static_cast<std::size_t>(model.joints[j].body_b + 1)].push_back(j);
    }
  }

  // Breadth first from ground, then from each body not yet reached (hung from ground by a free
  // joint), so parents always precede children.
  const auto grow = [&](int start) {
    frontier.push_back(start);
    while (!frontier.empty()) {
      const int body = frontier.front();
      frontier.pop_front();
      for (const std::size_t j : joints_at[static_cast<std::size_t>(body + 1)]) {
        const JointModel& joint = model.joints[j];
        // A loop's closing joint is a constraint on the tree (loop_joints.hpp), not a branch.
        if (joint_used[j] || joint.closes_loop) continue;
        const bool reversed = joint.body_b == body;
        const int other = reversed ? joint.body_a : joint.body_b;
        joint_used[j] = true;
        if (other == kGround || reached[static_cast<std::size_t>(other)]) {
          throw std::invalid_argument("joint '" + joint.name +
                                      "' closes a loop (its bodies are already connected through "
                                      "other joints); tumble solves tree-structured systems");
        }
        reached[static_cast<std::size_t>(other)] = true;
        tree.push_back(from_model_joint(joint, static_cast<int>(j), reversed));
        frontier.push_back(other);
      }
    }
  };
  grow(kGround);
  // A group of bodies that no joint holds to ground hangs from its root by a free joint: the
  // first body (in the model's order) that touches a plane, else its first body, so that a body
  // in contact is held by a joint only where it must be.
  std::vector<std::size_t> root_order;
  for (const PlaneContact& contact : model.contacts) root_order.push_back(contact.body);
  std::sort(root_order.begin(), root_order.end());
  for (std::size_t b = 0; b < n; ++b) root_order.push_back(b);
  for (const std::size_t b : root_order) {
    if (reached[b]) continue;
    TreeJoint free;
    free.type = JointType::Free;
    free.parent = kGround;
    free.child = b;
    set_subspace(free);
    reached[b] = true;
    tree.push_back(free);
    grow(static_cast<int>(b));
  }

  Eigen::Index q = 0;
  for (TreeJoint& joint : tree) {
    joint.q = q;
    q += joint.nq;
  }
  for (TreeJoint& joint : tree) {
    joint.v = q;
    q += joint.nv;
  }
  return tree;
}

}  // namespace tumble
