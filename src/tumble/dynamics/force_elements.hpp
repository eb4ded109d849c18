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
const BodyState& state_or_ground(std::span<const BodyState> states, int body);

// What one element does at an instant: the force (at the COM) and moment (about the COM) on each
// of its two bodies, world axes, its stored energy and its power (rate of work on the bodies).
struct ElementLoad {
  Vec3 F_a_W = Vec3::Zero(), M_a_W = Vec3::Zero();
  Vec3 F_b_W = Vec3::Zero(), M_b_W = Vec3::Zero();
  double energy = 0.0;  // J
  double power = 0.0;   // W
};

// A spring whose two points coincide has no direction: it then pushes with no force.
ElementLoad calc_spring_load(const LinearSpring& spring, std::span<const BodyState> states);

// hinge_angle and hinge_rate are used when spring.hinge >= 0 (the angle of B relative to A about
// axis_W, the hinge axis in world axes).
ElementLoad calc_torsional_spring_load(const TorsionalSpring& spring,
                                       std::span<const BodyState> states, double hinge_angle,
                                       double hinge_rate, const Vec3& axis_W);

}  // namespace tumble
