#include "tumble/multibody/joints/hinge_joint.hpp"

#include "tumble/math/rotation.hpp"

namespace tumble {

int HingeJoint::coordinate_count() const {
  return 1;
}
int HingeJoint::speed_count() const {
  return 1;
}

void HingeJoint::set_motion_subspace(TreeJoint& joint) const {
  joint.S.resize(6, 1);
  joint.S.col(0).head<3>() = joint.axis_C;
  joint.S.col(0).tail<3>() = joint.p_CJ_C.cross(joint.axis_C);
}

void HingeJoint::calc_placement(const TreeJoint& joint, const VecX& y, Mat3& R_PC,
                                Vec3& p_PC_P) const {
  R_PC = joint.R_PC0 * rotation_from_axis_angle(joint.axis_C, y(joint.q));
  p_PC_P = joint.p_PJ_P - R_PC * joint.p_CJ_C;
}

void HingeJoint::write_coordinate_rates(const TreeJoint& joint, const VecX& y,
                                        const BodyState& /*child*/, VecX& dydt) const {
  dydt(joint.q) = y(joint.v);
}

void HingeJoint::pack(const TreeJoint& joint, const BodyState& parent, const BodyState& child,
                      VecX& y) const {
  const Mat3 R_PC = parent.R_WB.transpose() * child.R_WB;
  const Vec3 omega_rel_C = child.R_WB.transpose() * (child.omega_W - parent.omega_W);
  y(joint.q) = joint.axis_C.dot(log_so3(joint.R_PC0.transpose() * R_PC));
  y(joint.v) = joint.axis_C.dot(omega_rel_C);
}

void HingeJoint::displace(const TreeJoint& joint, const SpeedStep& move, const Mat3& /*R_WC*/,
                          VecX& y) const {
  y(joint.q) += move(0);
}

}  // namespace tumble
