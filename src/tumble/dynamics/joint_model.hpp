#pragma once
// Joints as the scenario states them (docs/scenario.md, `joints:`), with their geometry fixed to
// the bodies from the configuration at t = 0, and the instantaneous loads (impulses) that act
// through them. Body index -1 is ground (the world frame, at rest).
#include <limits>
#include <string>

#include "tumble/dynamics/joint_type.hpp"
#include "tumble/math/types.hpp"

namespace tumble {

inline constexpr int kGround = -1;

// A motor on one freedom of a joint (a hinge's angle, a slider's travel, a cylindrical joint's
// turn or slide): while active (from <= t < to) it prescribes the relative speed (rad/s about a
// hinge, m/s along a slider) or applies the effort (a torque in N m about the axis, a force in N
// along it), on the second body and against the first. A speed is prescribed only on a joint of
// one freedom.
struct JointMotor {
  enum class Kind { None, Speed, Effort } kind = Kind::None;
  double value = 0.0;
  int freedom = 0;  // which of the joint's speeds it drives (a cylindrical joint's 1: the slide)
  double from = -std::numeric_limits<double>::infinity();  // s
  double to = std::numeric_limits<double>::infinity();     // s

  bool active_at(double t) const { return kind != Kind::None && from <= t && t < to; }
};

struct JointModel {
  JointType type = JointType::Ball;  // not Free: that is the tree's, for bodies no joint holds
  std::string name;
  int body_a = kGround;        // the first body listed (may be ground)
  int body_b = 0;              // the second: reactions are what body_a exerts on body_b
  Vec3 p_AJ_A = Vec3::Zero();  // joint point from A's COM, A's axes (world point when A is ground)
  Vec3 p_BJ_B = Vec3::Zero();  // joint point from B's COM, B's axes
  // Distance: the rod's length, m (its ends' distance at t = 0); p_AJ_A is its end on A, p_BJ_B
  // its end on B.
  double rod_length = 0.0;
  Mat3 R_AB0 = Mat3::Identity();  // B's axes relative to A's at t = 0: R_WA^T R_WB
  // Hinge: the unit axis in B's axes; the angle theta turns B relative to A about it, positive
  // by the right-hand rule, zero at t = 0. Prismatic: the unit axis in B's axes; the travel d
  // moves B's joint point from A's along it, zero at t = 0. Cylindrical: both about and along it.
  Vec3 axis_B = Vec3::UnitZ();
  // Universal: the first axis, fixed in A (A's axes, unit; world when A is ground); axis_B is
  // the second, fixed in B. At right angles.
  Vec3 axis_A = Vec3::UnitX();
  JointMotor motor;
  double lock_at = std::numeric_limits<double>::infinity();  // s: the joint is rigid from then
  // It closes a loop: its bodies are already joined through the joints listed before it (and
  // ground). It is not part of the kinematic tree but a constraint on it (multibody/loop_joints).
  bool closes_loop = false;
};

// An impulse (a jump of momentum) at a body point at one instant.
struct ImpulseLoad {
  std::string name;
  std::size_t body = 0;
  Vec3 value = Vec3::Zero();  // N s: world axes, or body axes when body_frame
  bool body_frame = false;
  Vec3 p_GP_B = Vec3::Zero();  // point of application from the COM, body axes, m
  double time = 0.0;           // s
};

}  // namespace tumble
