#include "tumble/multibody/joints/free_joint.hpp"

namespace tumble {

int FreeJoint::coordinate_count() const {
  return 7;
}
int FreeJoint::speed_count() const {
  return 6;
}

void FreeJoint::set_motion_subspace(TreeJoint& joint) const {
  joint.S = Mat6::Identity();
}

void FreeJoint::calc_placement(const TreeJoint& joint, const VecX& y, Mat3& R_PC,
                               Vec3& p_PC_P) const {
  R_PC = rotation_at(y, joint.q + 3);
  p_PC_P = y.segment<3>(joint.q);
}

void FreeJoint::write_coordinate_rates(const TreeJoint& joint, const VecX& y,
                                       const BodyState& child, VecX& dydt) const {
  dydt.segment<3>(joint.q) = child.v_G;
  write_quaternion_rate(y, joint.q + 3, y.segment<3>(joint.v), dydt);
}

void FreeJoint::pack(const TreeJoint& joint, const BodyState& /*parent*/, const BodyState& child,
                     VecX& y) const {
  y.segment<3>(joint.q) = child.r_G;
  write_quaternion(child.R_WB, joint.q + 3, y);
  y.segment<3>(joint.v) = child.R_WB.transpose() * child.omega_W;
  y.segment<3>(joint.v + 3) = child.R_WB.transpose() * child.v_G;
}

Eigen::Index FreeJoint::quaternion_offset(const TreeJoint& joint) const {
  return joint.q + 3;
}

void FreeJoint::displace(const TreeJoint& joint, const SpeedStep& move, const Mat3& R_WC,
                         VecX& y) const {
  y.segment<3>(joint.q) += R_WC * move.tail<3>();
  turn_quaternion(y, joint.q + 3, move.head<3>());
}

}  // namespace tumble
