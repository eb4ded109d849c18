#include "tumble/multibody/joints/joint_kind.hpp"

#include "tumble/multibody/joints/ball_joint.hpp"
#include "tumble/multibody/joints/fixed_joint.hpp"
#include "tumble/multibody/joints/free_joint.hpp"
#include "tumble/multibody/joints/hinge_joint.hpp"
#include "tumble/multibody/joints/prismatic_joint.hpp"

namespace tumble {

const JointKind& joint_kind(JointType type) {
  static const FreeJoint free;
  static const BallJoint ball;
  static const HingeJoint hinge;
  static const PrismaticJoint prismatic;
  static const FixedJoint fixed;
  switch (type) {
    case JointType::Free:
      return free;
    case JointType::Ball:
      return ball;
    case JointType::Hinge:
      return hinge;
    case JointType::Prismatic:
      return prismatic;
    case JointType::Fixed:
      return fixed;
  }
  return fixed;
}

Mat3 rotation_at(const VecX& y, Eigen::Index o) {
  return Quat(y(o), y(o + 1), y(o + 2), y(o + 3)).normalized().toRotationMatrix();
}

void write_quaternion_rate(const VecX& y, Eigen::Index o, const Vec3& omega, VecX& dydt) {
  const Vec3 q_vec = y.segment<3>(o + 1);
  dydt(o) = -0.5 * q_vec.dot(omega);
  dydt.segment<3>(o + 1) = 0.5 * (y(o) * omega + q_vec.cross(omega));
}

void write_quaternion(const Mat3& R, Eigen::Index o, VecX& y) {
  Quat q(R);
  q.normalize();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  y.segment<4>(o) << q.w(), q.x(), q.y(), q.z();
}

void turn_quaternion(VecX& y, Eigen::Index o, const Vec3& angle_B) {
  const double angle = angle_B.norm();
  if (angle == 0.0) return;
  Quat q(y(o), y(o + 1), y(o + 2), y(o + 3));
  q = (q * Quat(Eigen::AngleAxisd(angle, angle_B / angle))).normalized();
  y(o) = q.w();
  y(o + 1) = q.x();
  y(o + 2) = q.y();
  y(o + 3) = q.z();
}

}  // namespace tumble
