#pragma once
// A body that no joint holds, hung from ground by six freedoms: q = (r_G, world; the unit
// quaternion of R_WC), speeds (omega_C; v_G in the child's axes), S the identity. No columns of
// its own (the body's are its state); in a linearisation B.x B.y B.z (its COM's displacement,
// world), B.rx B.ry B.rz (a small turn about its axes), B.vx B.vy B.vz (its COM's velocity,
// world) and B.wx B.wy B.wz (its angular velocity, its axes).
#include "tumble/multibody/joints/joint_kind_of.hpp"

namespace tumble {

class FreeJoint final : public JointKindOf<FreeJoint> {
 public:
  std::string_view type_name() const override { return "free"; }
  int coordinate_count() const override { return 7; }
  int speed_count() const override { return 6; }
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

  std::span<const CoordinateName> coordinate_columns() const override { return {}; }
  void calc_coordinate_columns(const TreeJoint& /*joint*/, const VecX& /*y*/,
                               const BodyState& /*a*/, const BodyState& /*b*/,
                               std::span<double> /*values*/) const override {}

  std::span<const CoordinateName> modal_positions() const override;
  std::span<const CoordinateName> modal_speeds() const override;
  std::span<const int> modal_position_blocks() const override;
  bool modal_positions_are_symmetries() const override { return true; }
  bool turns_freely() const override { return true; }
  void displace_modal(const TreeJoint& joint, const VecX& z_q, double sign, VecX& y) const override;
  void add_modal_tangent(const TreeJoint& joint, const VecX& y, double sign,
                         Eigen::Index position_offset, Eigen::Index speed_offset, MatX& E,
                         MatX& P) const override;
  // v_C = exp(-[r]x) R0^T (v_G0 + dv): curved in the turn r and in r with dv.
  void add_modal_curvature(const TreeJoint& joint, const VecX& y, Eigen::Index position_offset,
                           Eigen::Index speed_offset, const VecX& z_rate, MatX& C) const override;
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
// Compiled for both scalars in free_joint.cpp.
extern template class JointKindOf<FreeJoint>;

}  // namespace tumble
