#pragma once
// A hinge: q = the angle theta about axis_C (0 at t = 0, right-hand rule), speed its rate.
// R_PC = R_PC0 Rot(axis_C, theta); the child's COM moves at theta' axis_C x (r_G - r_J).
#include "tumble/multibody/joints/joint_kind.hpp"

namespace tumble {

class HingeJoint final : public JointKind {
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
};

}  // namespace tumble
