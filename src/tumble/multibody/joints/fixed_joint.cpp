#include "tumble/multibody/joints/fixed_joint.hpp"

namespace tumble {

int FixedJoint::coordinate_count() const {
  return 0;
}
int FixedJoint::speed_count() const {
  return 0;
}

void FixedJoint::set_motion_subspace(TreeJoint& joint) const {
  joint.S.resize(6, 0);
}

void FixedJoint::calc_placement(const TreeJoint& joint, const VecX& /*y*/, Mat3& R_PC,
                                Vec3& p_PC_P) const {
  R_PC = joint.R_PC0;
  p_PC_P = joint.p_PJ_P - R_PC * joint.p_CJ_C;
}

void FixedJoint::write_coordinate_rates(const TreeJoint& /*joint*/, const VecX& /*y*/,
                                        const BodyState& /*child*/, VecX& /*dydt*/) const {}

void FixedJoint::pack(const TreeJoint& /*joint*/, const BodyState& /*parent*/,
                      const BodyState& /*child*/, VecX& /*y*/) const {}

void FixedJoint::displace(const TreeJoint& /*joint*/, const SpeedStep& /*move*/,
                          const Mat3& /*R_WC*/, VecX& /*y*/) const {}

}  // namespace tumble
