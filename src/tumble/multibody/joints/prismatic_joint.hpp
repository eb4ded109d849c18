#pragma once
// A slider: q = the travel d of the child's joint point from the parent's along axis_C (0 at
// t = 0), speed its rate. The child keeps its orientation relative to the parent (R_PC = R_PC0)
// and moves at d' axis_C.
#include "tumble/multibody/joints/joint_kind.hpp"

namespace tumble {

class PrismaticJoint final : public JointKind {
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
