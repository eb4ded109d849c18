#pragma once
// Force elements between two bodies (or a body and ground), with their potential energy and
// power (section 6.5 of the chapter):
//  - LinearSpring: a spring-damper between two body points; tension k (l - l0) + c dl/dt along
//    the line between them, energy k (l - l0)^2 / 2;
//  - TorsionalSpring: moment -k theta n on the second body (and +k theta n on the first), theta n
//    the rotation vector of its turn relative to the first from rest, energy k theta^2 / 2, and a
//    damping moment -c (omega_b - omega_a). Across a hinge theta is the hinge angle (it may pass
//    pi); elsewhere theta n is log(R_WB R_rest^T R_WA^T), so theta <= pi.
#include <span>
#include <string>

#include "tumble/body/rigid_body.hpp"
#include "tumble/dynamics/joint_model.hpp"

namespace tumble {

struct LinearSpring {
  std::string name;
  int body_a = kGround, body_b = 0;
  Vec3 p_A_A = Vec3::Zero();  // attachment from A's COM, A's axes (world point for ground)
  Vec3 p_B_B = Vec3::Zero();
  double stiffness = 0.0;    // N/m
  double rest_length = 0.0;  // m
  double damping = 0.0;      // N s/m
};

struct TorsionalSpring {
  std::string name;
  int body_a = kGround, body_b = 0;
  double stiffness = 0.0;             // N m/rad
  double damping = 0.0;               // N m s/rad
  Mat3 R_AB_rest = Mat3::Identity();  // rest orientation of B's axes relative to A's
  int hinge = -1;                     // index of the hinge joining the two bodies, if any
  double rest_angle = 0.0;            // rad, across a hinge: the angle at which the moment is zero
};

// The state of one of the bodies a force element joins; ground is at rest at the origin.
// For dual numbers ground is a new state each time, not a shared constant: Eigen's AutoDiff sizes
// an empty derivative vector to its partner's in place, even through const (make_coherent), so a
// shared dual-number ground would keep the size of the last linearisation (the next one, of
// another size, then read past its end) and be written by two threads at once. A run's doubles
// are never written so: they share one, and a call copies nothing.
template <typename S>
BodyStateOf<S> state_or_ground(std::span<const BodyStateOf<S>> states, int body) {
  return body == kGround ? BodyStateOf<S>{} : states[static_cast<std::size_t>(body)];
}
inline const BodyState& state_or_ground(std::span<const BodyState> states, int body) {
  static const BodyState kGroundState{};
  return body == kGround ? kGroundState : states[static_cast<std::size_t>(body)];
}

// What one element does at an instant: the force (at the COM) and moment (about the COM) on each
// of its two bodies, world axes, its stored energy and its power (rate of work on the bodies).
template <typename S>
struct ElementLoadOf {
  Vec3Of<S> F_a_W = Vec3Of<S>::Zero(), M_a_W = Vec3Of<S>::Zero();
  Vec3Of<S> F_b_W = Vec3Of<S>::Zero(), M_b_W = Vec3Of<S>::Zero();
  S energy = S(0.0);  // J
  S power = S(0.0);   // W
};
using ElementLoad = ElementLoadOf<double>;

// The force laws are written once over the scalar (double for a run, Dual for `tumble modes`;
// force_elements.cpp instantiates both).
//
// A spring whose two points coincide has no direction: it then pushes with no force.
template <typename S>
ElementLoadOf<S> calc_spring_load(const LinearSpring& spring,
                                  std::span<const BodyStateOf<S>> states);
inline ElementLoad calc_spring_load(const LinearSpring& spring, std::span<const BodyState> states) {
  return calc_spring_load<double>(spring, states);
}

// hinge_angle and hinge_rate are used when spring.hinge >= 0 (the angle of B relative to A about
// axis_W, the hinge axis in world axes).
template <typename S>
ElementLoadOf<S> calc_torsional_spring_load(const TorsionalSpring& spring,
                                            std::span<const BodyStateOf<S>> states,
                                            const S& hinge_angle, const S& hinge_rate,
                                            const Vec3Of<S>& axis_W);
inline ElementLoad calc_torsional_spring_load(const TorsionalSpring& spring,
                                              std::span<const BodyState> states, double hinge_angle,
                                              double hinge_rate, const Vec3& axis_W) {
  return calc_torsional_spring_load<double>(spring, states, hinge_angle, hinge_rate, axis_W);
}

// A motor's effort across a joint that closes a loop, whose angle and travel are no coordinates
// of the tree (a tree joint's effort is its generalised force instead): a torque about its axis
// (a hinge's or a cylindrical joint's, fixed in B; a universal joint's first, fixed in A, or its
// second, fixed in B) or a force along it at B's joint point (a slider's or a cylindrical
// joint's), on the second body and its opposite on the first, active or not (the caller asks
// JointMotor::active_at). Its power is the effort times the joint's rate about or along the
// axis: the axes a joint holds at right angles make (omega_B - omega_A) . a a universal joint's
// rate about a.
template <typename S>
ElementLoadOf<S> calc_loop_motor_load(const JointModel& joint,
                                      std::span<const BodyStateOf<S>> states);
inline ElementLoad calc_loop_motor_load(const JointModel& joint,
                                        std::span<const BodyState> states) {
  return calc_loop_motor_load<double>(joint, states);
}

}  // namespace tumble
