#include "tumble/multibody/joints/joint_kind.hpp"

#include <array>
#include <stdexcept>
#include <vector>

#include "tumble/multibody/joints/ball_joint.hpp"
#include "tumble/multibody/joints/cylindrical_joint.hpp"
#include "tumble/multibody/joints/fixed_joint.hpp"
#include "tumble/multibody/joints/free_joint.hpp"
#include "tumble/multibody/joints/hinge_joint.hpp"
#include "tumble/multibody/joints/prismatic_joint.hpp"
#include "tumble/multibody/joints/universal_joint.hpp"

namespace tumble {

namespace {

// Every kind, once; the scenario's names in the order docs/scenario.md lists them.
struct Registered {
  JointType type;
  const JointKind& kind;
};

template <typename Kind>
const JointKind& one() {
  static const Kind kind;
  return kind;
}

const std::array<Registered, 7>& registry() {
  static const std::array<Registered, 7> kinds = {{
      {JointType::Ball, one<BallJoint>()},
      {JointType::Hinge, one<HingeJoint>()},
      {JointType::Prismatic, one<PrismaticJoint>()},
      {JointType::Fixed, one<FixedJoint>()},
      {JointType::Cylindrical, one<CylindricalJoint>()},
      {JointType::Universal, one<UniversalJoint>()},
      {JointType::Free, one<FreeJoint>()},
  }};
  return kinds;
}

// A distance joint is a loop's row alone (multibody/loop_rows.hpp): it has a name but no kind.
constexpr std::string_view kDistanceName = "distance";

}  // namespace

const JointKind& joint_kind(JointType type) {
  for (const Registered& r : registry()) {
    if (r.type == type) return r.kind;
  }
  // A distance joint is a loop's row, never a joint of the tree.
  throw std::logic_error("a JointType without a kind: register it in joint_kind.cpp");
}

std::optional<JointType> joint_type_named(std::string_view name) {
  if (name == kDistanceName) return JointType::Distance;
  for (const Registered& r : registry()) {
    // A free joint is the tree's, for a body no joint holds: a scenario does not state one.
    if (r.type != JointType::Free && r.kind.type_name() == name) return r.type;
  }
  return std::nullopt;
}

std::string_view joint_type_name(JointType type) {
  return type == JointType::Distance ? kDistanceName : joint_kind(type).type_name();
}

std::span<const std::string_view> joint_type_names() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> out;
    for (const Registered& r : registry()) {
      if (r.type != JointType::Free) out.push_back(r.kind.type_name());
    }
    out.push_back(kDistanceName);
    return out;
  }();
  return names;
}

void JointKind::set_axes(TreeJoint& joint, const JointModel& model_joint) const {
  joint.axis_C =
      joint.reversed ? Vec3(-(model_joint.R_AB0 * model_joint.axis_B)) : model_joint.axis_B;
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

void add_turn_tangent(const VecX& y, Eigen::Index o, Eigen::Index z_offset, MatX& E, MatX& P) {
  const double w = y(o), x = y(o + 1), yy = y(o + 2), z = y(o + 3);
  // q (x) p = L p, and L^T L = |q|^2 I.
  Eigen::Matrix4d L;
  L << w, -x, -yy, -z,  //
      x, w, -z, yy,     //
      yy, z, w, -x,     //
      z, -yy, x, w;
  E.block<4, 3>(o, z_offset) = 0.5 * L.rightCols<3>();
  P.block<3, 4>(z_offset, o) = (2.0 / L.col(0).squaredNorm()) * L.transpose().bottomRows<3>();
}

void JointKind::add_modal_tangent(const TreeJoint& joint, const VecX& /*y*/, double sign,
                                  Eigen::Index position_offset, Eigen::Index speed_offset, MatX& E,
                                  MatX& P) const {
  if (position_offset >= 0) {
    for (Eigen::Index i = 0; i < joint.nq; ++i) {
      E(joint.q + i, position_offset + i) = sign;
      P(position_offset + i, joint.q + i) = sign;
    }
  }
  if (speed_offset >= 0) {
    for (Eigen::Index i = 0; i < joint.nv; ++i) {
      E(joint.v + i, speed_offset + i) = sign;
      P(speed_offset + i, joint.v + i) = sign;
    }
  }
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
