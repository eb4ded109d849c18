#include "tumble/multibody/joints/ball_joint.hpp"

namespace tumble {

namespace {

constexpr CoordinateName kBallPositions[] = {{"rx", "rad"}, {"ry", "rad"}, {"rz", "rad"}};
constexpr CoordinateName kBallSpeeds[] = {{"wx", "rad/s"}, {"wy", "rad/s"}, {"wz", "rad/s"}};
constexpr int kBallBlocks[] = {3};

}  // namespace

void BallJoint::set_motion_subspace(TreeJoint& joint) const {
  joint.S.resize(6, 3);
  joint.S.topRows<3>() = Mat3::Identity();
  joint.S.bottomRows<3>() = hat(joint.p_CJ_C);
}

void BallJoint::calc_placement(const TreeJoint& joint, const VecX& y, Mat3& R_PC,
                               Vec3& p_PC_P) const {
  R_PC = rotation_at(y, joint.q);
  p_PC_P = offset_about_joint_point<double>(joint, R_PC);
}

void BallJoint::write_coordinate_rates(const TreeJoint& joint, const VecX& y,
                                       const BodyState& /*child*/, VecX& dydt) const {
  write_quaternion_rate(y, joint.q, y.segment<3>(joint.v), dydt);
}

void BallJoint::pack(const TreeJoint& joint, const BodyState& parent, const BodyState& child,
                     VecX& y) const {
  const Mat3 R_PC = parent.R_WB.transpose() * child.R_WB;
  write_quaternion(R_PC, joint.q, y);
  y.segment<3>(joint.v) = child.R_WB.transpose() * (child.omega_W - parent.omega_W);
}

Eigen::Index BallJoint::quaternion_offset(const TreeJoint& joint) const {
  return joint.q;
}

void BallJoint::displace(const TreeJoint& joint, const SpeedStep& move, const Mat3& /*R_WC*/,
                         VecX& y) const {
  turn_quaternion(y, joint.q, move.head<3>());
}

std::span<const CoordinateName> BallJoint::coordinate_columns() const {
  return kBallPositions;
}

// R_AB = R_WA^T R_WB, as a rotation vector in A's axes.
void BallJoint::calc_coordinate_columns(const TreeJoint& /*joint*/, const VecX& /*y*/,
                                        const BodyState& a, const BodyState& b,
                                        std::span<double> values) const {
  const Eigen::AngleAxisd turn(a.R_WB.transpose() * b.R_WB);
  const Vec3 rotation = turn.angle() * turn.axis();
  for (int k = 0; k < 3; ++k) values[static_cast<std::size_t>(k)] = rotation(k);
}

std::span<const CoordinateName> BallJoint::modal_positions() const {
  return kBallPositions;
}
std::span<const CoordinateName> BallJoint::modal_speeds() const {
  return kBallSpeeds;
}
std::span<const int> BallJoint::modal_position_blocks() const {
  return kBallBlocks;
}

void BallJoint::displace_modal(const TreeJoint& joint, const VecX& z_q, double /*sign*/,
                               VecX& y) const {
  turn_quaternion(y, joint.q, z_q.head<3>());
}

// The turn to its quaternion; the speeds are the same numbers.
void BallJoint::add_modal_tangent(const TreeJoint& joint, const VecX& y, double /*sign*/,
                                  Eigen::Index position_offset, Eigen::Index speed_offset, MatX& E,
                                  MatX& P) const {
  if (position_offset >= 0) add_turn_tangent(y, joint.q, position_offset, E, P);
  if (speed_offset >= 0) {
    E.block<3, 3>(joint.v, speed_offset).setIdentity();
    P.block<3, 3>(speed_offset, joint.v).setIdentity();
  }
}

template <typename S>
void BallJoint::modal_motion(const TreeJoint& joint, const ModalJointPoint<S>& at,
                             JointMotionOf<S>& motion) const {
  const Mat3 R_PC0 = rotation_at(at.y0, joint.q);
  motion.R_PC = turned<S>(R_PC0, Vec3Of<S>(at.z_q.template head<3>()));
  motion.p_PC_P = offset_about_joint_point<S>(joint, motion.R_PC);
  motion.coordinates.resize(0);
  motion.u = at.y0.segment(joint.v, 3).template cast<S>();
  motion.u += at.z_u;
  motion.S_C = joint.S.cast<S>();
}

template <typename S>
void BallJoint::modal_rates(const TreeJoint& /*joint*/, const ModalJointPoint<S>& at,
                            const JointMotionOf<S>& motion, const VecXOf<S>& u_dot,
                            const Vec3Of<S>& /*v_G_W*/, const Vec3Of<S>& /*a_G_W*/,
                            VecXOf<S>& z_q_rate, VecXOf<S>& z_u_rate) const {
  z_q_rate = turn_rate<S>(Vec3Of<S>(at.z_q.template head<3>()), Vec3Of<S>(motion.u));
  z_u_rate = u_dot;
}

// R -> R exp(beta [e]x): the turn grows along e, the speeds in its axes turn back.
template <typename S>
void BallJoint::modal_body_turn(const TreeJoint& joint, const ModalJointPoint<S>& at,
                                const Vec3& e_C, VecXOf<S>& z_q_field, VecXOf<S>& z_u_field) const {
  const Vec3Of<S> e = e_C.cast<S>();
  z_q_field = turn_rate<S>(Vec3Of<S>(at.z_q.template head<3>()), e);
  const Vec3Of<S> omega =
      at.y0.template segment<3>(joint.v).template cast<S>() + Vec3Of<S>(at.z_u.template head<3>());
  z_u_field = -e.cross(omega);
}

// Hung from ground, R_WC -> exp(beta [k]x) R_WC: in the child's axes a turn about R_WC^T k.
template <typename S>
void BallJoint::modal_world_turn(const TreeJoint& joint, const ModalJointPoint<S>& at,
                                 const Vec3& k_W, VecXOf<S>& z_q_field,
                                 VecXOf<S>& /*z_u_field*/) const {
  const Vec3Of<S> r = at.z_q.template head<3>();
  const Mat3Of<S> R_WC = turned<S>(rotation_at(at.y0, joint.q), r);
  z_q_field = turn_rate<S>(r, Vec3Of<S>(R_WC.transpose() * k_W.cast<S>()));
}

template class JointKindOf<BallJoint>;

}  // namespace tumble
