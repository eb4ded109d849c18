#pragma once
// The kinds of joint, one enum for the scenario, the model and the kinematic tree. Each kind's
// geometry and kinematics live in one file of multibody/joints/ (JointKind).
namespace tumble {

enum class JointType {
  Free,       // six freedoms: a body no joint holds (the tree hangs it from ground)
  Ball,       // three: rotation about a point (a pivot)
  Hinge,      // one: rotation about an axis through a point
  Prismatic,  // one: translation along an axis (a slider)
  Fixed,      // none: a weld
};

// Whether the kind has one freedom along or about an axis, which a motor can drive and a lock
// can hold (hinge, prismatic).
constexpr bool has_axis(JointType type) {
  return type == JointType::Hinge || type == JointType::Prismatic;
}

}  // namespace tumble
