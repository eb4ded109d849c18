#include "tumble/multibody/joints/universal_joint.hpp"

#include <cmath>

namespace tumble {

namespace {

constexpr CoordinateName kUniversalPositions[] = {{"angle1", "rad"}, {"angle2", "rad"}};
constexpr CoordinateName kUniversalSpeeds[] = {{"rate1", "rad/s"}, {"rate2", "rad/s"}};
constexpr CoordinateName kUniversalColumns[] = {
    {"angle1", "rad"}, {"rate1", "rad/s"}, {"angle2", "rad"}, {"rate2", "rad/s"}};
// Two turns about different axes: either may be ignorable without the other.
constexpr int kUniversalBlocks[] = {1, 1};

// Which of the joint's coordinates turns about the parent's axis, which about the child's.
struct Order {
  Eigen::Index parent, child;
};
Order order(const TreeJoint& joint) {
  return joint.reversed ? Order{1, 0} : Order{0, 1};
}

// R_PC and the parent's axis in the child's axes, b_P, at the angles (parent's, child's).
template <typename S>
void turns(const TreeJoint& joint, const S& theta_P, const S& theta_C, Mat3Of<S>& R_PC,
           Vec3Of<S>& b_P) {
  const Mat3Of<S> R_C = rotation_from_axis_angle<S>(joint.axis_C, theta_C);
  R_PC = rotation_from_axis_angle<S>(joint.axis_P, theta_P) * joint.R_PC0.cast<S>() * R_C;
  b_P = R_C.transpose() * (joint.R_PC0.transpose() * joint.axis_P).cast<S>();
}

// S's columns, in the order of the joint's speeds, and (dS/dt) u.
template <typename S>
void subspace(const TreeJoint& joint, const Vec3Of<S>& b_P, const S& rate_P, const S& rate_C,
              Eigen::Matrix<S, 6, Eigen::Dynamic>& S_C, Vec6Of<S>& S_rate_u) {
  const Order o = order(joint);
  const Vec3Of<S> p = joint.p_CJ_C.cast<S>();
  const Vec3Of<S> c = joint.axis_C.cast<S>();
  S_C.resize(6, 2);
  S_C.col(o.parent).template head<3>() = b_P;
  S_C.col(o.parent).template tail<3>() = p.cross(b_P);
  S_C.col(o.child).template head<3>() = c;
  S_C.col(o.child).template tail<3>() = p.cross(c);
  const Vec3Of<S> turning = rate_P * rate_C * b_P.cross(c);
  S_rate_u.template head<3>() = turning;
  S_rate_u.template tail<3>() = p.cross(turning);
}

}  // namespace

// Its axes are fixed one in each body: the parent holds the first (or, from the second body, the
// second, each turned the other way so that the angles keep their sign).
void UniversalJoint::set_axes(TreeJoint& joint, const JointModel& model_joint) const {
  joint.axis_P = joint.reversed ? Vec3(-model_joint.axis_B) : model_joint.axis_A;
  joint.axis_C = joint.reversed ? Vec3(-model_joint.axis_A) : model_joint.axis_B;
}

// At zero the parent's axis is R_PC0^T axis_P in the child's axes (the tree keeps S for nothing:
// calc_motion_subspace gives it at each configuration).
void UniversalJoint::set_motion_subspace(TreeJoint& joint) const {
  Vec6 S_rate_u;
  Eigen::Matrix<double, 6, Eigen::Dynamic> S_C;
  subspace<double>(joint, joint.R_PC0.transpose() * joint.axis_P, 0.0, 0.0, S_C, S_rate_u);
  joint.S = S_C;
}

void UniversalJoint::calc_motion_subspace(const TreeJoint& joint, const VecX& y, MotionSubspace& S,
                                          Vec6& S_rate_u) const {
  const Order o = order(joint);
  Mat3 R_PC;
  Vec3 b_P;
  turns<double>(joint, y(joint.q + o.parent), y(joint.q + o.child), R_PC, b_P);
  Eigen::Matrix<double, 6, Eigen::Dynamic> S_C;
  subspace<double>(joint, b_P, y(joint.v + o.parent), y(joint.v + o.child), S_C, S_rate_u);
  S = S_C;
}

void UniversalJoint::calc_placement(const TreeJoint& joint, const VecX& y, Mat3& R_PC,
                                    Vec3& p_PC_P) const {
  const Order o = order(joint);
  Vec3 b_P;
  turns<double>(joint, y(joint.q + o.parent), y(joint.q + o.child), R_PC, b_P);
  p_PC_P = offset_about_joint_point<double>(joint, R_PC);
}

void UniversalJoint::write_coordinate_rates(const TreeJoint& joint, const VecX& y,
                                            const BodyState& /*child*/, VecX& dydt) const {
  dydt.segment<2>(joint.q) = y.segment<2>(joint.v);
}

// With a_P0 = R_PC0^T axis_P, R_PC = R_PC0 Rot(a_P0, theta_P) Rot(axis_C, theta_C), and a_P0 is
// at right angles to axis_C: M = R_PC0^T R_PC turns axis_C about a_P0 by theta_P alone; the rest
// of M is the turn about axis_C. The relative angular velocity b_P theta_P' + axis_C theta_C'
// has b_P at right angles to axis_C too.
void UniversalJoint::pack(const TreeJoint& joint, const BodyState& parent, const BodyState& child,
                          VecX& y) const {
  const Order o = order(joint);
  const Mat3 M = joint.R_PC0.transpose() * parent.R_WB.transpose() * child.R_WB;
  const Vec3 a_P0 = joint.R_PC0.transpose() * joint.axis_P;
  const Vec3& c = joint.axis_C;
  const Vec3 Mc = M * c;
  const double theta_P = std::atan2(a_P0.dot(c.cross(Mc)), c.dot(Mc));
  const double theta_C = c.dot(log_so3(rotation_from_axis_angle(a_P0, theta_P).transpose() * M));
  y(joint.q + o.parent) = theta_P;
  y(joint.q + o.child) = theta_C;
  const Vec3 omega_rel_C = child.R_WB.transpose() * (child.omega_W - parent.omega_W);
  const Vec3 b_P = rotation_from_axis_angle(c, -theta_C) * a_P0;
  y(joint.v + o.parent) = b_P.dot(omega_rel_C);
  y(joint.v + o.child) = c.dot(omega_rel_C);
}

void UniversalJoint::displace(const TreeJoint& joint, const SpeedStep& move, const Mat3& /*R_WC*/,
                              VecX& y) const {
  displace_numbers_by(joint, move, y);
}

std::span<const CoordinateName> UniversalJoint::coordinate_columns() const {
  return kUniversalColumns;
}

void UniversalJoint::calc_coordinate_columns(const TreeJoint& joint, const VecX& y,
                                             const BodyState& /*a*/, const BodyState& /*b*/,
                                             std::span<double> values) const {
  write_number_columns(joint, y, values);
}

std::span<const CoordinateName> UniversalJoint::modal_positions() const {
  return kUniversalPositions;
}
std::span<const CoordinateName> UniversalJoint::modal_speeds() const {
  return kUniversalSpeeds;
}
std::span<const int> UniversalJoint::modal_position_blocks() const {
  return kUniversalBlocks;
}

void UniversalJoint::displace_modal(const TreeJoint& joint, const VecX& z_q, double sign,
                                    VecX& y) const {
  displace_numbers(joint, z_q, sign, y);
}

template <typename S>
void UniversalJoint::modal_motion(const TreeJoint& joint, const ModalJointPoint<S>& at,
                                  JointMotionOf<S>& motion) const {
  const Order o = order(joint);
  modal_numbers<S>(joint, at, motion);
  Vec3Of<S> b_P;
  turns<S>(joint, motion.coordinates(o.parent), motion.coordinates(o.child), motion.R_PC, b_P);
  motion.p_PC_P = offset_about_joint_point<S>(joint, motion.R_PC);
  subspace<S>(joint, b_P, motion.u(o.parent), motion.u(o.child), motion.S_C, motion.S_rate_u);
  motion.S_moves = true;
}

template <typename S>
void UniversalJoint::modal_rates(const TreeJoint& /*joint*/, const ModalJointPoint<S>& at,
                                 const JointMotionOf<S>& motion, const VecXOf<S>& u_dot,
                                 const Vec3Of<S>& /*v_G_W*/, const Vec3Of<S>& /*a_G_W*/,
                                 VecXOf<S>& z_q_rate, VecXOf<S>& z_u_rate) const {
  modal_rates_of_numbers<S>(at, motion, u_dot, z_q_rate, z_u_rate);
}

// Hung from ground with its parent's axis along k, the whole turning about k turns theta_P.
template <typename S>
void UniversalJoint::modal_world_turn(const TreeJoint& joint, const ModalJointPoint<S>& at,
                                      const Vec3& k_W, VecXOf<S>& z_q_field,
                                      VecXOf<S>& /*z_u_field*/) const {
  const Vec3& axis_W = joint.axis_P;  // the parent is ground
  if (axis_W.cross(k_W).norm() < 1e-12) {
    z_q_field(order(joint).parent) = S(at.sign * axis_W.dot(k_W));
  }
}

template class JointKindOf<UniversalJoint>;

}  // namespace tumble
