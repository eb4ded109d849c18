#pragma once
// What a kind of joint is: how many coordinates and speeds it has, its motion subspace S, how its
// coordinates place the child relative to the parent, how they change with its speeds, which
// coordinates and speeds give a relative motion, what it calls its coordinates (the CSV's
// columns, a linearisation's coordinates), and how `tumble modes` writes them. One kind per
// JointType, one file each (free_joint.cpp, ball_joint.cpp, hinge_joint.cpp, prismatic_joint.cpp,
// fixed_joint.cpp, cylindrical_joint.cpp, universal_joint.cpp); joint_kind() in joint_kind.cpp is
// the one place that makes them, and nothing else tests a joint's type to know how it moves.
// docs/design.md, "Where a new joint type goes", says what a new kind needs.
//
// The kinematics a run and a linearisation share (where the coordinates put the child, its
// motion subspace) are written once per kind over the scalar: double for a run, Dual for
// `tumble modes` (JointKindOf, joint_kind_of.hpp, compiles both from one template).
//
// Frames: P the parent's axes at its COM (ground: world), C the child's at its COM. A joint's
// point is p_PJ_P on the parent and p_CJ_C on the child; R_PC0 is the child's orientation
// relative to the parent where the coordinates are zero; axis_C the hinge's or slider's axis.
#include <optional>
#include <span>
#include <string_view>

#include "tumble/body/rigid_body.hpp"
#include "tumble/multibody/kinematic_tree.hpp"

namespace tumble {

// A joint's speeds' worth of something (at most six), without heap allocation.
using SpeedStep = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;

// A coordinate's name, after the joint's and a dot ("knee.angle"), and its unit.
struct CoordinateName {
  std::string_view suffix;
  std::string_view unit;
};

// What a joint's coordinates say of its child, relative to its parent, in any scalar.
template <typename S>
struct JointMotionOf {
  Mat3Of<S> R_PC = Mat3Of<S>::Identity();  // the child's axes relative to the parent's
  Vec3Of<S> p_PC_P = Vec3Of<S>::Zero();    // the child's COM from the parent's, parent axes
  // Its coordinates that are numbers (a hinge's angle, a slider's travel; none for a turn held
  // as a rotation).
  VecXOf<S> coordinates;
  VecXOf<S> u;  // its speeds
  // S (6 x nv, child axes at the child's COM) there, and (dS/dt) u, the part of the child's
  // acceleration relative to the parent that comes from S turning in the child's axes (zero
  // where S is constant there).
  Eigen::Matrix<S, 6, Eigen::Dynamic> S_C;
  bool S_moves = false;  // S_rate_u is not zero
  Vec6Of<S> S_rate_u = Vec6Of<S>::Zero();
};

// Where a joint is in a linearisation (`tumble modes`, modes/modal_coordinates.hpp): y0, and the
// small departures z_q, z_u of its modal positions and speeds from it (zero for a joint held or
// driven, which has none); sign is -1 where the scenario states a hinge's or slider's bodies
// the other way round from the tree.
template <typename S>
struct ModalJointPoint {
  const VecX& y0;
  VecXOf<S> z_q, z_u;
  double sign = 1.0;
};

class JointKind {
 public:
  virtual ~JointKind() = default;

  // As a scenario names it ("hinge").
  virtual std::string_view type_name() const = 0;
  virtual int coordinate_count() const = 0;  // nq
  virtual int speed_count() const = 0;       // nv
  // The joint's axes in the tree's bodies' axes (axis_C, axis_P), from the scenario's
  // (JointModel), the tree's parent and child being its bodies in either order (reversed). By
  // default its one axis in the child's axes, turned the other way where the tree holds it from
  // its second body: the first body turns relative to the second by -theta about the same line,
  // so about -axis by +theta, and theta keeps the sign the scenario gave it (a slider's travel
  // likewise).
  virtual void set_axes(TreeJoint& joint, const JointModel& model_joint) const;
  // S (6 x nv): the child's spatial velocity (omega; v_G), child axes, per unit of each speed,
  // where it does not change with the coordinates (the tree keeps it).
  virtual void set_motion_subspace(TreeJoint& joint) const = 0;
  // Whether S turns in the child's axes as the coordinates change (a Hooke joint's first axis as
  // the second angle turns), and then S at y and (dS/dt) u, the child's relative acceleration
  // that S's own turning gives (Featherstone's c_J).
  virtual bool moving_subspace() const { return false; }
  virtual void calc_motion_subspace(const TreeJoint& /*joint*/, const VecX& /*y*/,
                                    MotionSubspace& /*S*/, Vec6& /*S_rate_u*/) const {}
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

  // The CSV's columns of its own coordinates (docs/scenario.md, Output), and their values: y is
  // the state, a and b the states of the scenario's first and second body (world; ground at
  // rest at the origin). As many values as names.
  virtual std::span<const CoordinateName> coordinate_columns() const = 0;
  virtual void calc_coordinate_columns(const TreeJoint& joint, const VecX& y, const BodyState& a,
                                       const BodyState& b, std::span<double> values) const = 0;

  // `tumble modes`: its coordinates in a linearisation, positions then speeds (names after the
  // joint's, or a free body's, name).
  virtual std::span<const CoordinateName> modal_positions() const = 0;
  virtual std::span<const CoordinateName> modal_speeds() const = 0;
  // How its positions split into groups that may be ignorable apart (a free body's place and its
  // turn), counts in order.
  virtual std::span<const int> modal_position_blocks() const = 0;
  // Whether its positions, when nothing depends on them, are symmetries of the whole (a free
  // body's place and turn), rather than a coordinate that nothing restores.
  virtual bool modal_positions_are_symmetries() const { return false; }
  // Whether it lets its child turn every way about its point (ball, free): a body with an axis of
  // symmetry spinning on it may be a steady motion.
  virtual bool turns_freely() const { return false; }
  // The child's motion at a point of the linearisation.
  virtual void calc_modal_motion(const TreeJoint& joint, const ModalJointPoint<double>& at,
                                 JointMotionOf<double>& motion) const = 0;
  virtual void calc_modal_motion(const TreeJoint& joint, const ModalJointPoint<Dual>& at,
                                 JointMotionOf<Dual>& motion) const = 0;
  // dz/dt of its positions and speeds, from its motion there, the rates u_dot of its speeds, and
  // its child's COM velocity and acceleration (world).
  virtual void calc_modal_rates(const TreeJoint& joint, const ModalJointPoint<double>& at,
                                const JointMotionOf<double>& motion, const VecXOf<double>& u_dot,
                                const Vec3Of<double>& v_G_W, const Vec3Of<double>& a_G_W,
                                VecXOf<double>& z_q_rate, VecXOf<double>& z_u_rate) const = 0;
  virtual void calc_modal_rates(const TreeJoint& joint, const ModalJointPoint<Dual>& at,
                                const JointMotionOf<Dual>& motion, const VecXOf<Dual>& u_dot,
                                const Vec3Of<Dual>& v_G_W, const Vec3Of<Dual>& a_G_W,
                                VecXOf<Dual>& z_q_rate, VecXOf<Dual>& z_u_rate) const = 0;
  // The rates of its z while its child turns at unit rate about its own axis e_C (a body's spin,
  // turns_freely() kinds) or, for a joint hung from ground, while the whole turns about the
  // world axis k_W (a turn it does not carry leaves its z alone: zero).
  virtual void calc_modal_body_turn(const TreeJoint& joint, const ModalJointPoint<double>& at,
                                    const Vec3& e_C, VecXOf<double>& z_q_field,
                                    VecXOf<double>& z_u_field) const = 0;
  virtual void calc_modal_body_turn(const TreeJoint& joint, const ModalJointPoint<Dual>& at,
                                    const Vec3& e_C, VecXOf<Dual>& z_q_field,
                                    VecXOf<Dual>& z_u_field) const = 0;
  virtual void calc_modal_world_turn(const TreeJoint& joint, const ModalJointPoint<double>& at,
                                     const Vec3& k_W, VecXOf<double>& z_q_field,
                                     VecXOf<double>& z_u_field) const = 0;
  virtual void calc_modal_world_turn(const TreeJoint& joint, const ModalJointPoint<Dual>& at,
                                     const Vec3& k_W, VecXOf<Dual>& z_q_field,
                                     VecXOf<Dual>& z_u_field) const = 0;
  // y moved by its modal positions z_q (the configuration a mode shape shows).
  virtual void displace_modal(const TreeJoint& joint, const VecX& z_q, double sign,
                              VecX& y) const = 0;
  // How its part of the state y moves with its modal coordinates at z = 0, and back: the columns
  // of dy/dz of its positions (from position_offset in z; -1: none) and speeds (speed_offset)
  // into E, the rows of dz/dy into P (P E = I; a quaternion's direction off the unit sphere has
  // no z). The state's Jacobian is (E dz'/dz + C) P (modes/state_jacobian.hpp). The default: its
  // coordinates and speeds are numbers, y = y0 + sign z (hinge, slider, cylindrical, Hooke).
  virtual void add_modal_tangent(const TreeJoint& joint, const VecX& y, double sign,
                                 Eigen::Index position_offset, Eigen::Index speed_offset, MatX& E,
                                 MatX& P) const;
  // Where its part of y is not linear in z: the second derivative of y(z) at z = 0 along z_rate
  // (the modal equations' dz/dt there), (d^2 y / dz^2)[., z_rate], added into C's rows of y and
  // columns of z. f = (dy/dz) z' gives df/dy = (E dz'/dz + C) P: without C, a free body's speeds
  // in its turning axes would miss terms of the size of omega and of its acceleration. The
  // default: none (y linear in z; a quaternion's second derivative is along the quaternion,
  // off the tangent).
  virtual void add_modal_curvature(const TreeJoint& /*joint*/, const VecX& /*y*/,
                                   Eigen::Index /*position_offset*/, Eigen::Index /*speed_offset*/,
                                   const VecX& /*z_rate*/, MatX& /*C*/) const {}
};

// The one place that makes the kinds: each JointType's of the tree (a distance joint has none:
// std::logic_error).
const JointKind& joint_kind(JointType type);
// The type a scenario names ("hinge", "distance"; nothing for a name that is none), and a type's
// name.
std::optional<JointType> joint_type_named(std::string_view name);
std::string_view joint_type_name(JointType type);
// The names a scenario may give, in the order the documentation lists them.
std::span<const std::string_view> joint_type_names();

// Helpers the kinds share: a unit quaternion (w, x, y, z) at offset o of y, as a rotation; its
// rate q' = q (x) (0, omega) / 2 (linear in q, as the OdeSystem contract asks); and R written as
// a unit quaternion with w >= 0.
Mat3 rotation_at(const VecX& y, Eigen::Index o);
void write_quaternion_rate(const VecX& y, Eigen::Index o, const Vec3& omega, VecX& dydt);
void write_quaternion(const Mat3& R, Eigen::Index o, VecX& y);
// Turns the unit quaternion at o by the small rotation angle_B (body axes): q (x) exp(angle / 2).
void turn_quaternion(VecX& y, Eigen::Index o, const Vec3& angle_B);
// The tangent of that turn at angle 0: dq/dr = q (x) (0, I) / 2 into E's rows o.. and columns
// z_offset.., and its inverse on the tangent, dr/dq = 2 [0 I] (q^-1 (x) .), into P.
void add_turn_tangent(const VecX& y, Eigen::Index o, Eigen::Index z_offset, MatX& E, MatX& P);

}  // namespace tumble
