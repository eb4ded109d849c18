#pragma once
// A hinge: q = the angle theta about axis_C (0 at t = 0, right-hand rule), speed its rate.
// R_PC = R_PC0 Rot(axis_C, theta); the child's COM moves at theta' axis_C x (r_G - r_J).
// Columns J.angle J.rate; in a linearisation the same, signed as the scenario states the joint.
#include "tumble/multibody/joints/joint_kind_of.hpp"

namespace tumble {

class HingeJoint final : public JointKindOf<HingeJoint> {
 public:
  std::string_view type_name() const override { return "hinge"; }
  int coordinate_count() const override { return 1; }
  int speed_count() const override { return 1; }
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
// Compiled for both scalars in hinge_joint.cpp.
extern template class JointKindOf<HingeJoint>;

}  // namespace tumble
