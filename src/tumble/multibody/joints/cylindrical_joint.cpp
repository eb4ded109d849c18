#include "tumble/multibody/joints/cylindrical_joint.hpp"

namespace tumble {

namespace {

constexpr CoordinateName kCylindricalPositions[] = {{"angle", "rad"}, {"travel", "m"}};
constexpr CoordinateName kCylindricalSpeeds[] = {{"rate", "rad/s"}, {"speed", "m/s"}};
constexpr CoordinateName kCylindricalColumns[] = {
    {"angle", "rad"}, {"rate", "rad/s"}, {"travel", "m"}, {"speed", "m/s"}};
// The turn and the slide may be ignorable apart.
constexpr int kCylindricalBlocks[] = {1, 1};

// Turned by theta about the axis through the joint point, and slid along it by d: the child's
// joint point is d along the axis from the parent's (the axis is the same line in both bodies'
// axes, R_PC axis_C = R_PC0 axis_C).
template <typename S>
void place_cylindrical(const TreeJoint& joint, const S& angle, const S& travel, Mat3Of<S>& R_PC,
                       Vec3Of<S>& p_PC_P) {
  R_PC = joint.R_PC0.cast<S>() * rotation_from_axis_angle<S>(joint.axis_C, angle);
  p_PC_P =
      joint.p_PJ_P.cast<S>() - R_PC * (joint.p_CJ_C.cast<S>() - travel * joint.axis_C.cast<S>());
}

}  // namespace

void CylindricalJoint::set_motion_subspace(TreeJoint& joint) const {
  joint.S.resize(6, 2);
  joint.S.col(0).head<3>() = joint.axis_C;
  joint.S.col(0).tail<3>() = joint.p_CJ_C.cross(joint.axis_C);
  joint.S.col(1).head<3>() = Vec3::Zero();
  joint.S.col(1).tail<3>() = joint.axis_C;
}

void CylindricalJoint::calc_placement(const TreeJoint& joint, const VecX& y, Mat3& R_PC,
                                      Vec3& p_PC_P) const {
  place_cylindrical<double>(joint, y(joint.q), y(joint.q + 1), R_PC, p_PC_P);
}

void CylindricalJoint::write_coordinate_rates(const TreeJoint& joint, const VecX& y,
                                              const BodyState& /*child*/, VecX& dydt) const {
  dydt.segment<2>(joint.q) = y.segment<2>(joint.v);
}

// theta as a hinge's, d as a slider's: the turn moves the child's COM across the axis, so the
// axis' component of its velocity relative to the parent is the slide's alone.
void CylindricalJoint::pack(const TreeJoint& joint, const BodyState& parent, const BodyState& child,
                            VecX& y) const {
  const Mat3 R_PC = parent.R_WB.transpose() * child.R_WB;
  const Vec3 omega_rel_C = child.R_WB.transpose() * (child.omega_W - parent.omega_W);
  y(joint.q) = joint.axis_C.dot(log_so3(joint.R_PC0.transpose() * R_PC));
  y(joint.v) = joint.axis_C.dot(omega_rel_C);
  const Vec3 p_PC_W = child.r_G - parent.r_G;
  const Vec3 p_PC_P = parent.R_WB.transpose() * p_PC_W;
  y(joint.q + 1) = joint.axis_C.dot(R_PC.transpose() * (p_PC_P - joint.p_PJ_P) + joint.p_CJ_C);
  const Vec3 v_rel_W = child.v_G - parent.v_G - parent.omega_W.cross(p_PC_W);
  y(joint.v + 1) = joint.axis_C.dot(child.R_WB.transpose() * v_rel_W);
}

void CylindricalJoint::displace(const TreeJoint& joint, const SpeedStep& move, const Mat3& /*R_WC*/,
                                VecX& y) const {
  displace_numbers_by(joint, move, y);
}

std::span<const CoordinateName> CylindricalJoint::coordinate_columns() const {
  return kCylindricalColumns;
}

void CylindricalJoint::calc_coordinate_columns(const TreeJoint& joint, const VecX& y,
                                               const BodyState& /*a*/, const BodyState& /*b*/,
                                               std::span<double> values) const {
  write_number_columns(joint, y, values);
}

std::span<const CoordinateName> CylindricalJoint::modal_positions() const {
  return kCylindricalPositions;
}
std::span<const CoordinateName> CylindricalJoint::modal_speeds() const {
  return kCylindricalSpeeds;
}
std::span<const int> CylindricalJoint::modal_position_blocks() const {
  return kCylindricalBlocks;
}

void CylindricalJoint::displace_modal(const TreeJoint& joint, const VecX& z_q, double sign,
                                      VecX& y) const {
  displace_numbers(joint, z_q, sign, y);
}

template <typename S>
void CylindricalJoint::modal_motion(const TreeJoint& joint, const ModalJointPoint<S>& at,
                                    JointMotionOf<S>& motion) const {
  modal_numbers<S>(joint, at, motion);
  place_cylindrical<S>(joint, motion.coordinates(0), motion.coordinates(1), motion.R_PC,
                       motion.p_PC_P);
}

template <typename S>
void CylindricalJoint::modal_rates(const TreeJoint& /*joint*/, const ModalJointPoint<S>& at,
                                   const JointMotionOf<S>& motion, const VecXOf<S>& u_dot,
                                   const Vec3Of<S>& /*v_G_W*/, const Vec3Of<S>& /*a_G_W*/,
                                   VecXOf<S>& z_q_rate, VecXOf<S>& z_u_rate) const {
  modal_rates_of_numbers<S>(at, motion, u_dot, z_q_rate, z_u_rate);
}

template <typename S>
void CylindricalJoint::modal_world_turn(const TreeJoint& joint, const ModalJointPoint<S>& at,
                                        const Vec3& k_W, VecXOf<S>& z_q_field,
                                        VecXOf<S>& /*z_u_field*/) const {
  modal_turn_about_axis<S>(*this, joint, at, k_W, 0, z_q_field);
}

template class JointKindOf<CylindricalJoint>;

}  // namespace tumble
