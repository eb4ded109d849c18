#pragma once
// The kinds of joint, one enum for the scenario, the model and the kinematic tree. Each kind's
// geometry and kinematics live in one file of multibody/joints/ (JointKind), made in one place
// (joint_kind.cpp); a distance joint is a loop's row alone (loop_rows.hpp).
namespace tumble {

enum class JointType {
  Free,         // six freedoms: a body no joint holds (the tree hangs it from ground)
  Ball,         // three: rotation about a point (a pivot)
  Hinge,        // one: rotation about an axis through a point
  Prismatic,    // one: translation along an axis (a slider)
  Fixed,        // none: a weld
  Cylindrical,  // two: rotation about an axis through a point and translation along it
  Universal,    // two: rotations about two axes at right angles, one fixed in each body (Hooke)
  // A massless rod between a point of each body: it holds their distance and nothing else (five
  // freedoms), always as a constraint on the tree the other joints form, never as a joint of it
  // (multibody/loop_rows.hpp). It has no kind in multibody/joints/.
  Distance,
};

// Whether the kind has one axis the scenario states (`axis:`), about or along which its motor
// drives and its coordinates are signed (hinge, prismatic, cylindrical).
constexpr bool has_axis(JointType type) {
  return type == JointType::Hinge || type == JointType::Prismatic || type == JointType::Cylindrical;
}
// Whether a motor can drive it (`motor:`): the kinds with an axis, and a universal joint (a torque
// about either of its axes).
constexpr bool takes_motor(JointType type) {
  return has_axis(type) || type == JointType::Universal;
}
// Whether a lock can make it rigid (`lock: {at: t}`): every kind with freedoms a scenario states.
constexpr bool can_lock(JointType type) {
  return has_axis(type) || type == JointType::Universal;
}

}  // namespace tumble
