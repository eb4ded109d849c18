#pragma once
// What a kind of joint is to the articulated-body algorithm: how many coordinates and speeds it
// has, its motion subspace S, how its coordinates place the child relative to the parent, how
// they change with its speeds, and which coordinates and speeds give a relative motion. One
// implementation per JointType, one file each (free_joint.cpp, ball_joint.cpp, hinge_joint.cpp,
// prismatic_joint.cpp, fixed_joint.cpp); the formulation's passes call these and nothing
// type-specific. A new kind of joint is a new file here, a JointType, and its reading in
// scenario/joints_reader.cpp.
//
// Frames: P the parent's axes at its COM (ground: world), C the child's at its COM. A joint's
// point is p_PJ_P on the parent and p_CJ_C on the child; R_PC0 is the child's orientation
// relative to the parent where the coordinates are zero; axis_C the hinge's or slider's axis.
#include "tumble/body/rigid_body.hpp"
#include "tumble/multibody/kinematic_tree.hpp"

namespace tumble {

// A joint's speeds' worth of something (at most six), without heap allocation.
using SpeedStep = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;

class JointKind {
 public:
  virtual ~JointKind() = default;

  virtual int coordinate_count() const = 0;  // nq
  virtual int speed_count() const = 0;       // nv
  // S (6 x nv): the child's spatial velocity (omega; v_G), child axes, per unit of each speed.
  virtual void set_motion_subspace(TreeJoint& joint) const = 0;
  // The child's orientation relative to the parent and its COM from the parent's COM, parent
  // axes, at the coordinates in y.
  virtual void calc_placement(const TreeJoint& joint, const VecX& y, Mat3& R_PC,
                              Vec3& p_PC_P) const = 0;
  // dq/dt from the speeds in y (and the child's state at y, world), into dydt's coordinate
  // slots.
  virtual void write_coordinate_rates(const TreeJoint& joint, const VecX& y, const BodyState& child,
                                      VecX& dydt) const = 0;
  // The coordinates and speeds that put the child where `child` is relative to `parent` (world
  // states): what the joint allows of it (velocities it forbids are dropped).
  virtual void pack(const TreeJoint& joint, const BodyState& parent, const BodyState& child,
                    VecX& y) const = 0;
  // Moves the coordinates by the small motion `move` of its speeds (a displacement, not a rate;
  // rotations exactly), R_WC the child's orientation: a projection's position step.
  virtual void displace(const TreeJoint& joint, const SpeedStep& move, const Mat3& R_WC,
                        VecX& y) const = 0;
  // Offset in y of the unit quaternion among its coordinates, or -1 if it has none.
  virtual Eigen::Index quaternion_offset(const TreeJoint& /*joint*/) const { return -1; }
};

const JointKind& joint_kind(JointType type);

// Helpers the kinds share: a unit quaternion (w, x, y, z) at offset o of y, as a rotation; its
// rate q' = q (x) (0, omega) / 2 (linear in q, as the OdeSystem contract asks); and R written as
// a unit quaternion with w >= 0.
Mat3 rotation_at(const VecX& y, Eigen::Index o);
void write_quaternion_rate(const VecX& y, Eigen::Index o, const Vec3& omega, VecX& dydt);
void write_quaternion(const Mat3& R, Eigen::Index o, VecX& y);
// Turns the unit quaternion at o by the small rotation angle_B (body axes): q (x) exp(angle / 2).
void turn_quaternion(VecX& y, Eigen::Index o, const Vec3& angle_B);

}  // namespace tumble
