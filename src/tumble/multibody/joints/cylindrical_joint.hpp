#pragma once
// A cylindrical joint (a shaft in a plain bearing: it turns about and slides along one axis):
// q = (theta, d), the angle about axis_C (right-hand rule) and the travel of the child's joint
// point from the parent's along it, both 0 at t = 0; speeds their rates. R_PC = R_PC0
// Rot(axis_C, theta), and the child's joint point moves d along the axis; S is a hinge's column
// beside a slider's, constant in the child's axes. Columns J.angle J.rate J.travel J.speed; in a
// linearisation J.angle J.travel and J.rate J.speed, signed as the scenario states the joint.
#include "tumble/multibody/joints/joint_kind_of.hpp"

namespace tumble {

class CylindricalJoint final : public JointKindOf<CylindricalJoint> {
 public:
  std::string_view type_name() const override { return "cylindrical"; }
  int coordinate_count() const override { return 2; }
  int speed_count() const override { return 2; }
  void set_motion_subspace(TreeJoint& joint) const override;
  void calc_placement(const TreeJoint& joint, const VecX& y, Mat3& R_PC,
                      Vec3& p_PC_P) const override;
  void write_coordinate_rates(const TreeJoint& joint, const VecX& y, const BodyState& child,
                              VecX& dydt) const override;
  void pack(const TreeJoint& joint, const BodyState& parent, const BodyState& child,
            VecX& y) const override;
  void displace(const TreeJoint& joint, const SpeedStep& move, const Mat3& R_WC,
                VecX& y) const override;

  std::span<const CoordinateName> coordinate_columns() const override;
  void calc_coordinate_columns(const TreeJoint& joint, const VecX& y, const BodyState& a,
                               const BodyState& b, std::span<double> values) const override;

  std::span<const CoordinateName> modal_positions() const override;
  std::span<const CoordinateName> modal_speeds() const override;
  std::span<const int> modal_position_blocks() const override;
  void displace_modal(const TreeJoint& joint, const VecX& z_q, double sign, VecX& y) const override;
  template <typename S>
  void modal_motion(const TreeJoint& joint, const ModalJointPoint<S>& at,
                    JointMotionOf<S>& motion) const;
  template <typename S>
  void modal_rates(const TreeJoint& joint, const ModalJointPoint<S>& at,
                   const JointMotionOf<S>& motion, const VecXOf<S>& u_dot, const Vec3Of<S>& v_G_W,
                   const Vec3Of<S>& a_G_W, VecXOf<S>& z_q_rate, VecXOf<S>& z_u_rate) const;
  template <typename S>
  void modal_world_turn(const TreeJoint& joint, const ModalJointPoint<S>& at, const Vec3& k_W,
                        VecXOf<S>& z_q_field, VecXOf<S>& z_u_field) const;
};
// Compiled for both scalars in cylindrical_joint.cpp.
extern template class JointKindOf<CylindricalJoint>;

}  // namespace tumble
