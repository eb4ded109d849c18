#include "tumble/multibody/joints/ball_joint.hpp"

#include "tumble/math/rotation.hpp"

namespace tumble {

int BallJoint::coordinate_count() const {
  return 4;
}
int BallJoint::speed_count() const {
  return 3;
}

void BallJoint::set_motion_subspace(TreeJoint& joint) const {
  joint.S.resize(6, 3);
  joint.S.topRows<3>() = Mat3::Identity();
  joint.S.bottomRows<3>() = hat(joint.p_CJ_C);
}

void BallJoint::calc_placement(const TreeJoint& joint, const VecX& y, Mat3& R_PC,
                               Vec3& p_PC_P) const {
  R_PC = rotation_at(y, joint.q);
  p_PC_P = joint.p_PJ_P - R_PC * joint.p_CJ_C;
}

void BallJoint::write_coordinate_rates(const TreeJoint& joint, const VecX& y,
                                       const BodyState& /*child*/, VecX& dydt) const {
  write_quaternion_rate(y, joint.q, y.segment<3>(joint.v), dydt);
}

void BallJoint::pack(const TreeJoint& joint, const BodyState& parent, const BodyState& child,
                     VecX& y) const {
  const Mat3 R_PC = parent.R_WB.transpose() * child.R_WB;
  write_quaternion(R_PC, joint.q, y);
  y.segment<3>(joint.v) = child.R_WB.transpose() * (child.omega_W - parent.omega_W);
}

Eigen::Index BallJoint::quaternion_offset(const TreeJoint& joint) const {
  return joint.q;
}

void BallJoint::displace(const TreeJoint& joint, const SpeedStep& move, const Mat3& /*R_WC*/,
                         VecX& y) const {
  turn_quaternion(y, joint.q, move.head<3>());
}

}  // namespace tumble
