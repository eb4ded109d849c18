#include "tumble/multibody/joints/hinge_joint.hpp"

namespace tumble {

namespace {

constexpr CoordinateName kHingePositions[] = {{"angle", "rad"}};
constexpr CoordinateName kHingeSpeeds[] = {{"rate", "rad/s"}};
constexpr CoordinateName kHingeColumns[] = {{"angle", "rad"}, {"rate", "rad/s"}};
constexpr int kHingeBlocks[] = {1};

// Where the angle puts the child: turned about the axis through the joint point.
template <typename S>
void place_hinge(const TreeJoint& joint, const S& angle, Mat3Of<S>& R_PC, Vec3Of<S>& p_PC_P) {
  R_PC = joint.R_PC0.cast<S>() * rotation_from_axis_angle<S>(joint.axis_C, angle);
  p_PC_P = offset_about_joint_point<S>(joint, R_PC);
}

}  // namespace

void HingeJoint::set_motion_subspace(TreeJoint& joint) const {
  joint.S.resize(6, 1);
  joint.S.col(0).head<3>() = joint.axis_C;
  joint.S.col(0).tail<3>() = joint.p_CJ_C.cross(joint.axis_C);
}

void HingeJoint::calc_placement(const TreeJoint& joint, const VecX& y, Mat3& R_PC,
                                Vec3& p_PC_P) const {
  place_hinge<double>(joint, y(joint.q), R_PC, p_PC_P);
}

void HingeJoint::write_coordinate_rates(const TreeJoint& joint, const VecX& y,
                                        const BodyState& /*child*/, VecX& dydt) const {
  dydt(joint.q) = y(joint.v);
}

void HingeJoint::pack(const TreeJoint& joint, const BodyState& parent, const BodyState& child,
                      VecX& y) const {
  const Mat3 R_PC = parent.R_WB.transpose() * child.R_WB;
  const Vec3 omega_rel_C = child.R_WB.transpose() * (child.omega_W - parent.omega_W);
  y(joint.q) = joint.axis_C.dot(log_so3(joint.R_PC0.transpose() * R_PC));
  y(joint.v) = joint.axis_C.dot(omega_rel_C);
}

void HingeJoint::displace(const TreeJoint& joint, const SpeedStep& move, const Mat3& /*R_WC*/,
                          VecX& y) const {
  displace_numbers_by(joint, move, y);
}

std::span<const CoordinateName> HingeJoint::coordinate_columns() const {
  return kHingeColumns;
}

void HingeJoint::calc_coordinate_columns(const TreeJoint& joint, const VecX& y,
                                         const BodyState& /*a*/, const BodyState& /*b*/,
                                         std::span<double> values) const {
  write_number_columns(joint, y, values);
}

std::span<const CoordinateName> HingeJoint::modal_positions() const {
  return kHingePositions;
}
std::span<const CoordinateName> HingeJoint::modal_speeds() const {
  return kHingeSpeeds;
}
std::span<const int> HingeJoint::modal_position_blocks() const {
  return kHingeBlocks;
}

void HingeJoint::displace_modal(const TreeJoint& joint, const VecX& z_q, double sign,
                                VecX& y) const {
  displace_numbers(joint, z_q, sign, y);
}

template <typename S>
void HingeJoint::modal_motion(const TreeJoint& joint, const ModalJointPoint<S>& at,
                              JointMotionOf<S>& motion) const {
  modal_numbers<S>(joint, at, motion);
  place_hinge<S>(joint, motion.coordinates(0), motion.R_PC, motion.p_PC_P);
}

template <typename S>
void HingeJoint::modal_rates(const TreeJoint& /*joint*/, const ModalJointPoint<S>& at,
                             const JointMotionOf<S>& motion, const VecXOf<S>& u_dot,
                             const Vec3Of<S>& /*v_G_W*/, const Vec3Of<S>& /*a_G_W*/,
                             VecXOf<S>& z_q_rate, VecXOf<S>& z_u_rate) const {
  modal_rates_of_numbers<S>(at, motion, u_dot, z_q_rate, z_u_rate);
}

template <typename S>
void HingeJoint::modal_world_turn(const TreeJoint& joint, const ModalJointPoint<S>& at,
                                  const Vec3& k_W, VecXOf<S>& z_q_field,
                                  VecXOf<S>& /*z_u_field*/) const {
  modal_turn_about_axis<S>(*this, joint, at, k_W, 0, z_q_field);
}

template class JointKindOf<HingeJoint>;

}  // namespace tumble
