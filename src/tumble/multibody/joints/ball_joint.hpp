#pragma once
// A ball joint (a pivot): q = the unit quaternion of R_PC, speeds omega of the child relative to
// the parent, child axes. The child's COM stays at its distance from the joint point. Columns
// J.rx J.ry J.rz (the rotation vector of the second body relative to the first, the first's
// axes); in a linearisation a small turn r of the child about its axes (R = R0 exp([r]x)) and
// J.wx J.wy J.wz.
#include "tumble/multibody/joints/joint_kind_of.hpp"

namespace tumble {

class BallJoint final : public JointKindOf<BallJoint> {
 public:
  std::string_view type_name() const override { return "ball"; }
  int coordinate_count() const override { return 4; }
  int speed_count() const override { return 3; }
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

  std::span<const CoordinateName> coordinate_columns() const override;
  void calc_coordinate_columns(const TreeJoint& joint, const VecX& y, const BodyState& a,
                               const BodyState& b, std::span<double> values) const override;

  std::span<const CoordinateName> modal_positions() const override;
  std::span<const CoordinateName> modal_speeds() const override;
  std::span<const int> modal_position_blocks() const override;
  bool turns_freely() const override { return true; }
  void displace_modal(const TreeJoint& joint, const VecX& z_q, double sign, VecX& y) const override;
  void add_modal_tangent(const TreeJoint& joint, const VecX& y, double sign,
                         Eigen::Index position_offset, Eigen::Index speed_offset, MatX& E,
                         MatX& P) const override;
  template <typename S>
  void modal_motion(const TreeJoint& joint, const ModalJointPoint<S>& at,
                    JointMotionOf<S>& motion) const;
  template <typename S>
  void modal_rates(const TreeJoint& joint, const ModalJointPoint<S>& at,
                   const JointMotionOf<S>& motion, const VecXOf<S>& u_dot, const Vec3Of<S>& v_G_W,
                   const Vec3Of<S>& a_G_W, VecXOf<S>& z_q_rate, VecXOf<S>& z_u_rate) const;
  template <typename S>
  void modal_body_turn(const TreeJoint& joint, const ModalJointPoint<S>& at, const Vec3& e_C,
                       VecXOf<S>& z_q_field, VecXOf<S>& z_u_field) const;
  template <typename S>
  void modal_world_turn(const TreeJoint& joint, const ModalJointPoint<S>& at, const Vec3& k_W,
                        VecXOf<S>& z_q_field, VecXOf<S>& z_u_field) const;
};
// Compiled for both scalars in ball_joint.cpp.
extern template class JointKindOf<BallJoint>;

}  // namespace tumble
