#include "tumble/multibody/joints/prismatic_joint.hpp"

namespace tumble {

int PrismaticJoint::coordinate_count() const {
  return 1;
}
int PrismaticJoint::speed_count() const {
  return 1;
}

void PrismaticJoint::set_motion_subspace(TreeJoint& joint) const {
  joint.S.resize(6, 1);
  joint.S.col(0).head<3>() = Vec3::Zero();
  joint.S.col(0).tail<3>() = joint.axis_C;
}

// The child's COM from the parent's: out to the parent's joint point, along the axis by the
// travel d, back from the child's joint point to its COM.
void PrismaticJoint::calc_placement(const TreeJoint& joint, const VecX& y, Mat3& R_PC,
                                    Vec3& p_PC_P) const {
  R_PC = joint.R_PC0;
  p_PC_P = joint.p_PJ_P - R_PC * (joint.p_CJ_C - y(joint.q) * joint.axis_C);
}

void PrismaticJoint::write_coordinate_rates(const TreeJoint& joint, const VecX& y,
                                            const BodyState& /*child*/, VecX& dydt) const {
  dydt(joint.q) = y(joint.v);
}

// d is the child's joint point's offset from the parent's, along the axis; d' the child's COM
// velocity relative to the parent's material point there, along the axis (child axes).
void PrismaticJoint::pack(const TreeJoint& joint, const BodyState& parent, const BodyState& child,
                          VecX& y) const {
  const Vec3 p_PC_W = child.r_G - parent.r_G;
  const Vec3 p_PC_P = parent.R_WB.transpose() * p_PC_W;
  y(joint.q) = joint.axis_C.dot(joint.R_PC0.transpose() * (p_PC_P - joint.p_PJ_P) + joint.p_CJ_C);
  const Vec3 v_rel_W = child.v_G - parent.v_G - parent.omega_W.cross(p_PC_W);
  y(joint.v) = joint.axis_C.dot(child.R_WB.transpose() * v_rel_W);
}

void PrismaticJoint::displace(const TreeJoint& joint, const SpeedStep& move, const Mat3& /*R_WC*/,
                              VecX& y) const {
  y(joint.q) += move(0);
}

}  // namespace tumble
