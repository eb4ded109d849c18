#pragma once
// A universal (Hooke) joint: a cross whose two arms turn in bearings, one fixed in each body, at
// right angles. q = (theta_1, theta_2), the turns about the first axis (fixed in the scenario's
// first body) and about the second (fixed in its second), right-hand rule, 0 at t = 0; speeds
// their rates. With the tree's parent P holding axis_P and its child C holding axis_C,
//   R_PC = Rot(axis_P, theta_P) R_PC0 Rot(axis_C, theta_C),
//   omega_rel,C = b_P theta_P' + axis_C theta_C',  b_P = Rot(axis_C, -theta_C) R_PC0^T axis_P,
// the parent's axis seen from the child. S's column for theta_P follows b_P, which turns in the
// child's axes as theta_C does: (dS/dt) u = theta_P' theta_C' (b_P x axis_C; p_CJ x (b_P x
// axis_C)) (Featherstone, RBDA 2008, section 4.4, c_J). Where the tree holds the joint from its
// second body (reversed), P holds the second axis and the angles keep the scenario's order and
// sign: theta_1 is y's first coordinate either way. Columns J.angle1 J.rate1 J.angle2 J.rate2;
// in a linearisation J.angle1 J.angle2 and J.rate1 J.rate2.
#include "tumble/multibody/joints/joint_kind_of.hpp"

namespace tumble {

class UniversalJoint final : public JointKindOf<UniversalJoint> {
 public:
  std::string_view type_name() const override { return "universal"; }
  int coordinate_count() const override { return 2; }
  int speed_count() const override { return 2; }
  void set_axes(TreeJoint& joint, const JointModel& model_joint) const override;
  void set_motion_subspace(TreeJoint& joint) const override;
  bool moving_subspace() const override { return true; }
  void calc_motion_subspace(const TreeJoint& joint, const VecX& y, MotionSubspace& S,
                            Vec6& S_rate_u) const override;
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
// Compiled for both scalars in universal_joint.cpp.
extern template class JointKindOf<UniversalJoint>;

}  // namespace tumble
