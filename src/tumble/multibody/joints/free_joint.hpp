#pragma once
// A body that no joint holds, hung from ground by six freedoms: q = (r_G, world; the unit
// quaternion of R_WC), speeds (omega_C; v_G in the child's axes), S the identity.
#include "tumble/multibody/joints/joint_kind.hpp"

namespace tumble {

class FreeJoint final : public JointKind {
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
