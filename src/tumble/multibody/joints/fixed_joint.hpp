#pragma once
// A weld: no coordinates, no speeds; the child keeps its placement relative to the parent.
#include "tumble/multibody/joints/joint_kind.hpp"

namespace tumble {

class FixedJoint final : public JointKind {
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
