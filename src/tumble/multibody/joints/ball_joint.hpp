#pragma once
// A pivot: q = the unit quaternion of R_PC, speeds the child's angular velocity relative to the
// parent, child axes. The child's COM moves at omega_rel x (r_G - r_J) = [p_CJ]x omega_rel.
#include "tumble/multibody/joints/joint_kind.hpp"

namespace tumble {

class BallJoint final : public JointKind {
 public:
  int coordinate_count() const override;
  int speed_count() const override;
  void set_motion_subspace(TreeJoint& joint) const override;
  void calc_placement(const TreeJoint& joint, const VecX& y, Mat3& R_PC,
                      Vec3& p_PC_P) const override;
  void write_coordinate_rates(const TreeJoint& joint, const VecX& y, const BodyState& child,
                              VecX& dydt) const override;
  void pack(const TreeJoint& joint, const BodyState& parent, const BodyState& child,
            VecX& y) const override;
  void displace(const TreeJoint& joint, const SpeedStep& move, const Mat3& R_WC,
                VecX& y) const override;
  Eigen::Index quaternion_offset(const TreeJoint& joint) const override;
};

}  // namespace tumble
