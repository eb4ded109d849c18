#include "tumble/multibody/joints/prismatic_joint.hpp"

namespace tumble {

namespace {

constexpr CoordinateName kPrismaticPositions[] = {{"travel", "m"}};
constexpr CoordinateName kPrismaticSpeeds[] = {{"speed", "m/s"}};
constexpr CoordinateName kPrismaticColumns[] = {{"travel", "m"}, {"speed", "m/s"}};
constexpr int kPrismaticBlocks[] = {1};

// The child's COM from the parent's: out to the parent's joint point, along the axis by the
// travel d, back from the child's joint point to its COM.
template <typename S>
void place_prismatic(const TreeJoint& joint, const S& travel, Mat3Of<S>& R_PC, Vec3Of<S>& p_PC_P) {
  R_PC = joint.R_PC0.cast<S>();
  p_PC_P =
      joint.p_PJ_P.cast<S>() - R_PC * (joint.p_CJ_C.cast<S>() - travel * joint.axis_C.cast<S>());
}

}  // namespace

void PrismaticJoint::set_motion_subspace(TreeJoint& joint) const {
  joint.S.resize(6, 1);
  joint.S.col(0).head<3>() = Vec3::Zero();
  joint.S.col(0).tail<3>() = joint.axis_C;
}

void PrismaticJoint::calc_placement(const TreeJoint& joint, const VecX& y, Mat3& R_PC,
                                    Vec3& p_PC_P) const {
  place_prismatic<double>(joint, y(joint.q), R_PC, p_PC_P);
}

void PrismaticJoint::write_coordinate_rates(const TreeJoint& joint, const VecX& y,
                                            const BodyState& /*child*/, VecX& dydt) const {
  dydt(joint.q) = y(joint.v);
}

// d is the child's joint point's offset from the parent's, along the axis; d' the child's COM
// velocity relative to the parent's material point there, along the axis (child axes).
void PrismaticJoint::pack(const TreeJoint& joint, const BodyState& parent, const BodyState& child,
                          VecX& y) const {
  const Vec3 p_PC_W = child.r_G - parent.r_G;
  const Vec3 p_PC_P = parent.R_WB.transpose() * p_PC_W;
  y(joint.q) = joint.axis_C.dot(joint.R_PC0.transpose() * (p_PC_P - joint.p_PJ_P) + joint.p_CJ_C);
  const Vec3 v_rel_W = child.v_G - parent.v_G - parent.omega_W.cross(p_PC_W);
  y(joint.v) = joint.axis_C.dot(child.R_WB.transpose() * v_rel_W);
}

void PrismaticJoint::displace(const TreeJoint& joint, const SpeedStep& move, const Mat3& /*R_WC*/,
                              VecX& y) const {
  displace_numbers_by(joint, move, y);
}

std::span<const CoordinateName> PrismaticJoint::coordinate_columns() const {
  return kPrismaticColumns;
}

void PrismaticJoint::calc_coordinate_columns(const TreeJoint& joint, const VecX& y,
                                             const BodyState& /*a*/, const BodyState& /*b*/,
                                             std::span<double> values) const {
  write_number_columns(joint, y, values);
}

std::span<const CoordinateName> PrismaticJoint::modal_positions() const {
  return kPrismaticPositions;
}
std::span<const CoordinateName> PrismaticJoint::modal_speeds() const {
  return kPrismaticSpeeds;
}
std::span<const int> PrismaticJoint::modal_position_blocks() const {
  return kPrismaticBlocks;
}

void PrismaticJoint::displace_modal(const TreeJoint& joint, const VecX& z_q, double sign,
                                    VecX& y) const {
  displace_numbers(joint, z_q, sign, y);
}

template <typename S>
void PrismaticJoint::modal_motion(const TreeJoint& joint, const ModalJointPoint<S>& at,
                                  JointMotionOf<S>& motion) const {
  modal_numbers<S>(joint, at, motion);
  place_prismatic<S>(joint, motion.coordinates(0), motion.R_PC, motion.p_PC_P);
}

template <typename S>
void PrismaticJoint::modal_rates(const TreeJoint& /*joint*/, const ModalJointPoint<S>& at,
                                 const JointMotionOf<S>& motion, const VecXOf<S>& u_dot,
                                 const Vec3Of<S>& /*v_G_W*/, const Vec3Of<S>& /*a_G_W*/,
                                 VecXOf<S>& z_q_rate, VecXOf<S>& z_u_rate) const {
  modal_rates_of_numbers<S>(at, motion, u_dot, z_q_rate, z_u_rate);
}

// A slide does not turn its child.
template <typename S>
void PrismaticJoint::modal_world_turn(const TreeJoint& /*joint*/, const ModalJointPoint<S>& /*at*/,
                                      const Vec3& /*k_W*/, VecXOf<S>& /*z_q_field*/,
                                      VecXOf<S>& /*z_u_field*/) const {}

template class JointKindOf<PrismaticJoint>;

}  // namespace tumble
