#pragma once
// JointKindOf<Joint>: a JointKind whose scalar-generic parts are member templates of Joint,
// compiled here for double and for Dual (the virtual functions cannot be templates). A kind
// writes, over a scalar S:
//   modal_motion<S>(joint, at, motion)                   its child's motion at a modal point
//   modal_rates<S>(joint, at, motion, u_dot, v_G_W, a_G_W, z_q_rate, z_u_rate)
//   modal_world_turn<S>(joint, at, k_W, z_q_field, z_u_field)
// and, if it turns freely, modal_body_turn<S>(joint, at, e_C, z_q_field, z_u_field).
// Included by the kinds' files only: it brings in the dual numbers.
#include "tumble/math/dual.hpp"
#include "tumble/math/rotation.hpp"
#include "tumble/multibody/joints/joint_kind.hpp"

namespace tumble {

// A turn held as a rotation, in a linearisation: R = R0 exp([r]x) with r a small turn about the
// child's axes, taken to first order (R0 (1 + [r]x)): a linearisation differentiates once, at
// r = 0, where the two have the same value and derivative.
template <typename S>
Mat3Of<S> turned(const Mat3& R0, const Vec3Of<S>& r) {
  return R0.cast<S>() * (Mat3Of<S>::Identity() + hat<S>(r));
}
// The rate of such a turn while the child turns at omega (its axes):
// dr/dt = omega + r x omega / 2 + O(|r|^2).
template <typename S>
Vec3Of<S> turn_rate(const Vec3Of<S>& r, const Vec3Of<S>& omega) {
  return omega + S(0.5) * r.cross(omega);
}

// Where a joint about a point puts the child: its joint point on the parent's, turned by R_PC.
template <typename S>
Vec3Of<S> offset_about_joint_point(const TreeJoint& joint, const Mat3Of<S>& R_PC) {
  return joint.p_PJ_P.cast<S>() - R_PC * joint.p_CJ_C.cast<S>();
}

template <typename Joint>
class JointKindOf : public JointKind {
 public:
  void calc_modal_motion(const TreeJoint& joint, const ModalJointPoint<double>& at,
                         JointMotionOf<double>& motion) const final {
    self().template modal_motion<double>(joint, at, motion);
  }
  void calc_modal_motion(const TreeJoint& joint, const ModalJointPoint<Dual>& at,
                         JointMotionOf<Dual>& motion) const final {
    self().template modal_motion<Dual>(joint, at, motion);
  }
  void calc_modal_rates(const TreeJoint& joint, const ModalJointPoint<double>& at,
                        const JointMotionOf<double>& motion, const VecXOf<double>& u_dot,
                        const Vec3Of<double>& v_G_W, const Vec3Of<double>& a_G_W,
                        VecXOf<double>& z_q_rate, VecXOf<double>& z_u_rate) const final {
    self().template modal_rates<double>(joint, at, motion, u_dot, v_G_W, a_G_W, z_q_rate, z_u_rate);
  }
  void calc_modal_rates(const TreeJoint& joint, const ModalJointPoint<Dual>& at,
                        const JointMotionOf<Dual>& motion, const VecXOf<Dual>& u_dot,
                        const Vec3Of<Dual>& v_G_W, const Vec3Of<Dual>& a_G_W,
                        VecXOf<Dual>& z_q_rate, VecXOf<Dual>& z_u_rate) const final {
    self().template modal_rates<Dual>(joint, at, motion, u_dot, v_G_W, a_G_W, z_q_rate, z_u_rate);
  }
  void calc_modal_body_turn(const TreeJoint& joint, const ModalJointPoint<double>& at,
                            const Vec3& e_C, VecXOf<double>& z_q_field,
                            VecXOf<double>& z_u_field) const final {
    self().template modal_body_turn<double>(joint, at, e_C, z_q_field, z_u_field);
  }
  void calc_modal_body_turn(const TreeJoint& joint, const ModalJointPoint<Dual>& at,
                            const Vec3& e_C, VecXOf<Dual>& z_q_field,
                            VecXOf<Dual>& z_u_field) const final {
    self().template modal_body_turn<Dual>(joint, at, e_C, z_q_field, z_u_field);
  }
  void calc_modal_world_turn(const TreeJoint& joint, const ModalJointPoint<double>& at,
                             const Vec3& k_W, VecXOf<double>& z_q_field,
                             VecXOf<double>& z_u_field) const final {
    self().template modal_world_turn<double>(joint, at, k_W, z_q_field, z_u_field);
  }
  void calc_modal_world_turn(const TreeJoint& joint, const ModalJointPoint<Dual>& at,
                             const Vec3& k_W, VecXOf<Dual>& z_q_field,
                             VecXOf<Dual>& z_u_field) const final {
    self().template modal_world_turn<Dual>(joint, at, k_W, z_q_field, z_u_field);
  }

  // A kind that does not turn freely: a body's spin does not move its coordinates.
  template <typename S>
  void modal_body_turn(const TreeJoint& /*joint*/, const ModalJointPoint<S>& /*at*/,
                       const Vec3& /*e_C*/, VecXOf<S>& /*z_q_field*/,
                       VecXOf<S>& /*z_u_field*/) const {}

 private:
  const Joint& self() const { return static_cast<const Joint&>(*this); }
};

// Kinds whose coordinates are numbers (angles, travels: hinge, slider, cylindrical, universal),
// one per speed: their modal positions and speeds are departures of those numbers from y0,
// signed as the scenario states the joint. motion's coordinates, u and (constant) S from them.
template <typename S>
void modal_numbers(const TreeJoint& joint, const ModalJointPoint<S>& at, JointMotionOf<S>& motion) {
  const S sign(at.sign);
  motion.coordinates = at.y0.segment(joint.q, joint.nq).template cast<S>() + sign * at.z_q;
  motion.u = at.y0.segment(joint.v, joint.nv).template cast<S>() + sign * at.z_u;
  motion.S_C = joint.S.cast<S>();
}
template <typename S>
void modal_rates_of_numbers(const ModalJointPoint<S>& at, const JointMotionOf<S>& motion,
                            const VecXOf<S>& u_dot, VecXOf<S>& z_q_rate, VecXOf<S>& z_u_rate) {
  const S sign(at.sign);
  z_q_rate = sign * motion.u;
  z_u_rate = sign * u_dot;
}
inline void displace_numbers(const TreeJoint& joint, const VecX& z_q, double sign, VecX& y) {
  y.segment(joint.q, joint.nq) += sign * z_q;
}
// Their CSV columns: each coordinate, then its rate (J.angle J.rate, J.travel J.speed, ...).
inline void write_number_columns(const TreeJoint& joint, const VecX& y, std::span<double> values) {
  for (int i = 0; i < joint.nq; ++i) {
    values[2 * static_cast<std::size_t>(i)] = y(joint.q + i);
    values[2 * static_cast<std::size_t>(i) + 1] = y(joint.v + i);
  }
}
// A projection's small move of their speeds moves the numbers by as much.
inline void displace_numbers_by(const TreeJoint& joint, const SpeedStep& move, VecX& y) {
  y.segment(joint.q, joint.nq) += move.head(joint.nq);
}
// A kind that turns its child about axis_C by its coordinate `index` (hinge, cylindrical), hung
// from ground with that axis along k: the whole turning about k turns that coordinate.
template <typename S>
void modal_turn_about_axis(const JointKind& kind, const TreeJoint& joint,
                           const ModalJointPoint<S>& at, const Vec3& k_W, Eigen::Index index,
                           VecXOf<S>& z_q_field) {
  Mat3 R_PC0;
  Vec3 p_PC_P;
  kind.calc_placement(joint, at.y0, R_PC0, p_PC_P);
  const Vec3 axis_W = R_PC0 * joint.axis_C;
  if (axis_W.cross(k_W).norm() < 1e-12) z_q_field(index) = S(at.sign * axis_W.dot(k_W));
}

}  // namespace tumble
