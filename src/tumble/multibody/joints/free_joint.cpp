#include "tumble/multibody/joints/free_joint.hpp"

namespace tumble {

namespace {

constexpr CoordinateName kFreePositions[] = {{"x", "m"},    {"y", "m"},    {"z", "m"},
                                             {"rx", "rad"}, {"ry", "rad"}, {"rz", "rad"}};
constexpr CoordinateName kFreeSpeeds[] = {{"vx", "m/s"},   {"vy", "m/s"},   {"vz", "m/s"},
                                          {"wx", "rad/s"}, {"wy", "rad/s"}, {"wz", "rad/s"}};
// Where its COM is, and how it is turned.
constexpr int kFreeBlocks[] = {3, 3};

// Its COM's velocity at y0, world.
Vec3 v_G0_W(const TreeJoint& joint, const VecX& y0) {
  return rotation_at(y0, joint.q + 3) * y0.segment<3>(joint.v + 3);
}

}  // namespace

void FreeJoint::set_motion_subspace(TreeJoint& joint) const {
  joint.S = Mat6::Identity();
}

void FreeJoint::calc_placement(const TreeJoint& joint, const VecX& y, Mat3& R_PC,
                               Vec3& p_PC_P) const {
  R_PC = rotation_at(y, joint.q + 3);
  p_PC_P = y.segment<3>(joint.q);
}

void FreeJoint::write_coordinate_rates(const TreeJoint& joint, const VecX& y,
                                       const BodyState& child, VecX& dydt) const {
  dydt.segment<3>(joint.q) = child.v_G;
  write_quaternion_rate(y, joint.q + 3, y.segment<3>(joint.v), dydt);
}

void FreeJoint::pack(const TreeJoint& joint, const BodyState& /*parent*/, const BodyState& child,
                     VecX& y) const {
  y.segment<3>(joint.q) = child.r_G;
  write_quaternion(child.R_WB, joint.q + 3, y);
  y.segment<3>(joint.v) = child.R_WB.transpose() * child.omega_W;
  y.segment<3>(joint.v + 3) = child.R_WB.transpose() * child.v_G;
}

Eigen::Index FreeJoint::quaternion_offset(const TreeJoint& joint) const {
  return joint.q + 3;
}

void FreeJoint::displace(const TreeJoint& joint, const SpeedStep& move, const Mat3& R_WC,
                         VecX& y) const {
  y.segment<3>(joint.q) += R_WC * move.tail<3>();
  turn_quaternion(y, joint.q + 3, move.head<3>());
}

std::span<const CoordinateName> FreeJoint::modal_positions() const {
  return kFreePositions;
}
std::span<const CoordinateName> FreeJoint::modal_speeds() const {
  return kFreeSpeeds;
}
std::span<const int> FreeJoint::modal_position_blocks() const {
  return kFreeBlocks;
}

void FreeJoint::displace_modal(const TreeJoint& joint, const VecX& z_q, double /*sign*/,
                               VecX& y) const {
  y.segment<3>(joint.q) += z_q.head<3>();
  turn_quaternion(y, joint.q + 3, z_q.tail<3>());
}

// Its place and turn as a ball's; its speeds (omega_C, v_C) against the modal (v_G world,
// omega_C): v_C = R^T v_G with R = R0 (I + [r]x), so dv_C = R0^T dv_G + [v_C]x dr, and back,
// dv_G = R0 (dv_C - [v_C]x dr).
void FreeJoint::add_modal_tangent(const TreeJoint& joint, const VecX& y, double /*sign*/,
                                  Eigen::Index position_offset, Eigen::Index speed_offset, MatX& E,
                                  MatX& P) const {
  if (position_offset >= 0) {
    E.block<3, 3>(joint.q, position_offset).setIdentity();
    P.block<3, 3>(position_offset, joint.q).setIdentity();
    add_turn_tangent(y, joint.q + 3, position_offset + 3, E, P);
  }
  if (speed_offset < 0) return;
  E.block<3, 3>(joint.v, speed_offset + 3).setIdentity();
  P.block<3, 3>(speed_offset + 3, joint.v).setIdentity();
  const Mat3 R0 = rotation_at(y, joint.q + 3);
  const Vec3 v_C = y.segment<3>(joint.v + 3);
  E.block<3, 3>(joint.v + 3, speed_offset) = R0.transpose();
  P.block<3, 3>(speed_offset, joint.v + 3) = R0;
  if (position_offset >= 0) {
    E.block<3, 3>(joint.v + 3, position_offset + 3) = hat(v_C);
    P.block<3, 4>(speed_offset, joint.q + 3) =
        -R0 * hat(v_C) * P.block<3, 4>(position_offset + 3, joint.q + 3);
  }
}

void FreeJoint::add_modal_curvature(const TreeJoint& joint, const VecX& y,
                                    Eigen::Index position_offset, Eigen::Index speed_offset,
                                    const VecX& z_rate, MatX& C) const {
  if (position_offset < 0 || speed_offset < 0) return;
  const Mat3 R0 = rotation_at(y, joint.q + 3);
  const Vec3 v_C = y.segment<3>(joint.v + 3);
  const Vec3 turn_rate = z_rate.segment<3>(position_offset + 3);  // omega_C at z = 0
  const Vec3 a_G_W = z_rate.segment<3>(speed_offset);
  // With exp(-[r]x) = I - [r]x + [r]x^2 / 2 + ...: along (dr, w), the turn twice gives
  // ([dr]x [w]x + [w]x [dr]x) v_C / 2, the turn and the speed -[dr]x R0^T a - [w]x R0^T ddv.
  C.block<3, 3>(joint.v + 3, position_offset + 3) +=
      -0.5 * (hat(Vec3(turn_rate.cross(v_C))) + hat(turn_rate) * hat(v_C)) +
      hat(Vec3(R0.transpose() * a_G_W));
  C.block<3, 3>(joint.v + 3, speed_offset) += -hat(turn_rate) * R0.transpose();
}

template <typename S>
void FreeJoint::modal_motion(const TreeJoint& joint, const ModalJointPoint<S>& at,
                             JointMotionOf<S>& motion) const {
  motion.R_PC = turned<S>(rotation_at(at.y0, joint.q + 3), Vec3Of<S>(at.z_q.template tail<3>()));
  motion.p_PC_P = at.y0.template segment<3>(joint.q).template cast<S>();
  motion.p_PC_P += at.z_q.template head<3>();
  motion.coordinates.resize(0);
  // Speeds (omega_C, v_C) in the child's axes; the modal speed is v_G in world axes.
  motion.u = at.y0.segment(joint.v, 6).template cast<S>();
  motion.u.template head<3>() += at.z_u.template tail<3>();
  motion.u.template tail<3>() = motion.R_PC.transpose() * (v_G0_W(joint, at.y0).template cast<S>() +
                                                           at.z_u.template head<3>());
  motion.S_C = joint.S.cast<S>();
}

template <typename S>
void FreeJoint::modal_rates(const TreeJoint& /*joint*/, const ModalJointPoint<S>& at,
                            const JointMotionOf<S>& motion, const VecXOf<S>& u_dot,
                            const Vec3Of<S>& v_G_W, const Vec3Of<S>& a_G_W, VecXOf<S>& z_q_rate,
                            VecXOf<S>& z_u_rate) const {
  z_q_rate.template head<3>() = v_G_W;
  z_q_rate.template tail<3>() =
      turn_rate<S>(Vec3Of<S>(at.z_q.template tail<3>()), Vec3Of<S>(motion.u.template head<3>()));
  z_u_rate.template head<3>() = a_G_W;
  z_u_rate.template tail<3>() = u_dot.template head<3>();
}

// R -> R exp(beta [e]x): the turn grows along e, the angular velocity in its axes turns back.
template <typename S>
void FreeJoint::modal_body_turn(const TreeJoint& joint, const ModalJointPoint<S>& at,
                                const Vec3& e_C, VecXOf<S>& z_q_field, VecXOf<S>& z_u_field) const {
  const Vec3Of<S> e = e_C.cast<S>();
  z_q_field.template tail<3>() = turn_rate<S>(Vec3Of<S>(at.z_q.template tail<3>()), e);
  const Vec3Of<S> omega =
      at.y0.template segment<3>(joint.v).template cast<S>() + Vec3Of<S>(at.z_u.template tail<3>());
  z_u_field.template tail<3>() = -e.cross(omega);
}

// The whole turned about k: its COM and velocity turn with it (world), and its axes (in them, a
// turn about R_WC^T k).
template <typename S>
void FreeJoint::modal_world_turn(const TreeJoint& joint, const ModalJointPoint<S>& at,
                                 const Vec3& k_W, VecXOf<S>& z_q_field,
                                 VecXOf<S>& z_u_field) const {
  const Vec3Of<S> k = k_W.cast<S>();
  const Vec3Of<S> r = at.z_q.template tail<3>();
  const Mat3Of<S> R_WC = turned<S>(rotation_at(at.y0, joint.q + 3), r);
  z_q_field.template tail<3>() = turn_rate<S>(r, Vec3Of<S>(R_WC.transpose() * k));
  const Vec3Of<S> r_G =
      at.y0.template segment<3>(joint.q).template cast<S>() + Vec3Of<S>(at.z_q.template head<3>());
  z_q_field.template head<3>() = k.cross(r_G);
  const Vec3Of<S> v_G =
      v_G0_W(joint, at.y0).template cast<S>() + Vec3Of<S>(at.z_u.template head<3>());
  z_u_field.template head<3>() = k.cross(v_G);
}

template class JointKindOf<FreeJoint>;

}  // namespace tumble
