#pragma once
// The joints of a Model arranged as a tree rooted at ground, each body reached from its parent by
// one joint; a body that no joint connects to ground hangs from it by a free joint (six degrees
// of freedom). Every joint's generalized coordinates and speeds have their place in the state.
#include <vector>

#include "tumble/dynamics/model.hpp"
#include "tumble/multibody/spatial.hpp"

namespace tumble {

// The motion subspace of a joint: at most six columns, stored without heap allocation.
using MotionSubspace = Eigen::Matrix<double, 6, Eigen::Dynamic, Eigen::ColMajor, 6, 6>;

class JointKind;

struct TreeJoint {
  // Free: q = (r_G world, quaternion of R_WC), speeds (omega_C, v_C) in the child's axes.
  // Ball: q = quaternion of R_PC, speeds omega of the child relative to the parent, child axes.
  // Hinge: q = the angle theta (0 at t = 0), speed its rate. Prismatic: q = the travel d along
  // the axis (0 at t = 0), speed its rate. Cylindrical: both. Universal: the two turns. Fixed:
  // none. (multibody/joints/, one file each.)
  JointType type = JointType::Free;
  int parent = kGround;        // model body index, or ground
  std::size_t child = 0;       // model body index
  int model_joint = -1;        // index into Model::joints; -1 for a free joint
  bool reversed = false;       // the model joint lists the child first: its reactions change sign
  Vec3 p_PJ_P = Vec3::Zero();  // joint point from the parent's COM, parent axes (world: ground)
  Vec3 p_CJ_C = Vec3::Zero();  // joint point from the child's COM, child axes
  Mat3 R_PC0 = Mat3::Identity();    // child axes relative to the parent's at theta = 0
  Vec3 axis_C = Vec3::UnitZ();      // hinge, slider or cylindrical axis, child axes
  Vec3 axis_P = Vec3::UnitX();      // a universal joint's axis fixed in the parent, parent axes
  const JointKind* kind = nullptr;  // its type's geometry and kinematics (joint_kind(type))
  Eigen::Index q = 0, v = 0;        // offsets of the coordinates and speeds in the state
  int nq = 0, nv = 0;
  MotionSubspace S;  // 6 x nv, child axes at the child's COM (at zero where it moves)
};

// Tree joints in an order where every parent comes before its children. A group of bodies joined
// to each other but not to ground hangs from ground by a free joint at its first body that
// touches a plane (else its first body). Throws std::invalid_argument naming a joint that closes
// a loop.
std::vector<TreeJoint> build_kinematic_tree(const Model& model);

}  // namespace tumble
