#include "tumble/multibody/joints/fixed_joint.hpp"

namespace tumble {

void FixedJoint::set_motion_subspace(TreeJoint& joint) const {
  joint.S.resize(6, 0);
}

void FixedJoint::calc_placement(const TreeJoint& joint, const VecX& /*y*/, Mat3& R_PC,
                                Vec3& p_PC_P) const {
  R_PC = joint.R_PC0;
  p_PC_P = offset_about_joint_point<double>(joint, R_PC);
}

template <typename S>
void FixedJoint::modal_motion(const TreeJoint& joint, const ModalJointPoint<S>& /*at*/,
                              JointMotionOf<S>& motion) const {
  motion.R_PC = joint.R_PC0.cast<S>();
  motion.p_PC_P = offset_about_joint_point<S>(joint, motion.R_PC);
  motion.coordinates.resize(0);
  motion.u.resize(0);
  motion.S_C.resize(6, 0);
}

template class JointKindOf<FixedJoint>;

}  // namespace tumble
