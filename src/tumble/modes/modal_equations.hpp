#pragma once
// The equations of motion written in the modal coordinates (modal_coordinates.hpp): dz/dt as a
// function of z, the departure from the initial state y0, for a linearisation by automatic
// differentiation. Templated on the scalar: double for values, Eigen's AutoDiffScalar for the
// Jacobian, which is then exact to round-off (no step size to choose, as finite differences
// would need).
//
// The equations are the chapter's Newton-Euler equations for each body (m a_G = F,
// I_G alpha + omega x I_G omega = M_G), projected onto the joints' speeds u (Kane's form):
//     sum_b  J_v,b^T (m_b a_G,b - F_b) + J_w,b^T (I_G,b alpha_b + omega_b x I_G,b omega_b - M_G,b)
//         = tau (the motors' efforts),
// with a_G,b = J_v,b u' + (the velocity terms) and alpha_b likewise, J_v,b and J_w,b the
// body's COM velocity and angular velocity per unit of each speed (world axes). That is the
// mass matrix M(q) u' = the generalised forces: an algorithm independent of the articulated-body
// passes that integrate the same model, which a test holds to the same accelerations.
//
// The physics is the run's, written once over the scalar: each joint's placement, speeds and
// motion subspace from its coordinates (JointKind::calc_modal_motion, its kind's file in
// multibody/joints/), the applied loads' and the force elements' laws (calc_load_on_body,
// calc_spring_load, calc_torsional_spring_load), the contact point's geometry
// (contact/contact_point.hpp). What is this file's own is the algorithm: Kane's projection, the
// mass matrix and the Schur complement.
//
// What acts: gravity, the loads active at t0, linear springs and dampers, torsional springs and
// dampers, the motors' efforts at t0; joints held or driven at t0 keep their speed. Contacts
// touching at t0 hold their point (modal_contacts.hpp): rolling, or frictionless on the plane, by
// the forces lambda that keep the constraints' accelerations zero (G u' + kappa = 0), found from
// the Schur complement of the mass matrix, G M^-1 G^T lambda = -kappa - G M^-1 Q. (A run's sliding
// contact holds its normal row with a force along n - mu s, s the slip's direction: its column of
// G^T becomes that force's, D^T, and the complement G M^-1 D^T.) The flow keeps
// the constraints, so the state stays on them; linearise() takes the modes on their tangent
// space. Impulses and later schedule changes are not part of a linearisation about t0. Joints
// that close loops are held the same way, by their rows (multibody/loop_rows.hpp, the run's):
// of those, the forces' solve takes the ones independent at t0 (a planar linkage of 3D hinges
// repeats three rows a pin), and the tangent space all of them.
//
// A rotation's coordinates are a small turn r about the body's axes, R = R0 exp([r]x), taken to
// first order (joint_kind_of.hpp, `turned`): evaluate only at z = 0 for that reason.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "tumble/math/dual.hpp"
#include "tumble/modes/modal_contacts.hpp"
#include "tumble/modes/modal_coordinates.hpp"
#include "tumble/multibody/joints/joint_kind.hpp"
#include "tumble/multibody/loop_rows.hpp"

namespace tumble {

// A continuous symmetry the steady motions may turn along: the whole system turned about a world
// axis (about the vertical, which leaves gravity unchanged), or one body turned about its own
// axis of symmetry (two equal principal moments) through its joint.
struct Symmetry {
  enum class Kind { WorldTurn, BodySpin } kind = Kind::WorldTurn;
  Vec3 axis = Vec3::UnitZ();   // unit: world axes (WorldTurn) or the body's axes (BodySpin)
  std::size_t tree_joint = 0;  // BodySpin: the joint holding the body (one that turns freely)
  std::string description;     // "a turn of the whole about the vertical", ...
};

template <typename Scalar>
struct ModalKinematics;
template <typename Scalar>
struct ContactRowsOf;

class ModalEquations {
 public:
  ModalEquations(std::shared_ptr<const ArticulatedModel> model, ModalLayout layout, VecX y0,
                 double t0);
  // The same about a run's state, its contacts held as the run's modes hold them (`holds`, one
  // per contact: contact/contact_hold.hpp) rather than those touching: a sliding contact keeps
  // its normal row and carries Coulomb's friction (the run's Jacobian, state_jacobian.hpp).
  // A hold on several points holds each as a point of the body, and rows the others already
  // hold are left out (the accelerations are the same; the forces, which the Jacobian does not
  // give, are then not determined).
  ModalEquations(std::shared_ptr<const ArticulatedModel> model, ModalLayout layout, VecX y0,
                 double t0, std::span<const ContactHold> holds);

  const ArticulatedModel& model() const { return *model_; }
  const std::shared_ptr<const ArticulatedModel>& shared_model() const { return model_; }
  const ModalLayout& layout() const { return layout_; }
  const VecX& y0() const { return y0_; }

  // dz/dt at z.
  template <typename Scalar>
  VecXOf<Scalar> rates(const VecXOf<Scalar>& z) const;
  // The contacts touching at t0, which the equations hold.
  const std::vector<ModalContact>& contacts() const { return contacts_; }
  // Whether the equations hold constraints (contacts, loops): the modes are then on their
  // tangent space.
  bool holds_constraints() const { return !contacts_.empty() || !loops_.empty(); }
  // Per held contact: its point's height over the plane (m; a pair's gap), then the point's
  // velocity (world, m/s; a pair's: relative; a frictionless contact: its normal component); then
  // every loop row's error (m or rad), then their velocities. Zero on the constraints.
  template <typename Scalar>
  VecXOf<Scalar> constraints(const VecXOf<Scalar>& z) const;
  // Per held contact at z = 0: the plane's (or the other body's) force on the body (world, N).
  std::vector<Vec3> contact_forces() const;
  // The rates of z while the state turns along `symmetry` at unit rate.
  template <typename Scalar>
  VecXOf<Scalar> symmetry_field(const Symmetry& symmetry, const VecXOf<Scalar>& z) const;
  // How fast z moves the bodies (world, one per body in the scenario's order): each one's v_G and
  // omega_W in `states`, to first order in z as the equations are (their turns are; the
  // positions a mode shape shows come from displace_positions, exactly).
  void calc_body_velocities(const VecX& z, std::span<BodyState> states) const;

 private:
  // Where tree joint k is in the linearisation at z.
  template <typename Scalar>
  ModalJointPoint<Scalar> point_of(std::size_t k, const VecXOf<Scalar>& z) const;
  template <typename Scalar>
  std::vector<ModalKinematics<Scalar>> kinematics(const VecXOf<Scalar>& z) const;
  // Per tree joint's child: its COM velocity and angular velocity per unit of the unknown speeds
  // (world), J_v and J_w.
  template <typename Scalar>
  void calc_body_jacobians(const std::vector<ModalKinematics<Scalar>>& kin,
                           std::vector<Eigen::Matrix<Scalar, 3, Eigen::Dynamic>>& J_v,
                           std::vector<Eigen::Matrix<Scalar, 3, Eigen::Dynamic>>& J_w) const;
  // Of the contact forces that solve schur lambda = rhs where its rows repeat (eigen: schur's
  // eigen-decomposition), the one whose friction is least.
  VecX least_friction_forces(const MatX& schur, const Eigen::SelfAdjointEigenSolver<MatX>& eigen,
                             const VecX& rhs) const;
  // z' from the unknowns' accelerations u_dot (the joints' rates in the modal coordinates).
  template <typename Scalar>
  VecXOf<Scalar> z_rates_of(const std::vector<ModalKinematics<Scalar>>& kin,
                            const std::vector<Eigen::Matrix<Scalar, 3, Eigen::Dynamic>>& J_v,
                            const VecXOf<Scalar>& u_dot, const VecXOf<Scalar>& z) const;
  // What both constructors do: the unknowns, the contacts (those touching, or as `holds` hold
  // them where given) and the loops.
  void set_up(const std::span<const ContactHold>* holds);
  // Of the loops' rows, the independent ones at z = 0, into loop_rows_held_.
  void select_loop_rows();
  // A body's pose and twist for the loops' rows and a touching pair's (ground: at rest).
  template <typename Scalar>
  BodyStateOf<Scalar> loop_side(const std::vector<ModalKinematics<Scalar>>& kin, int body) const;
  // Every loop row's velocity per unit of the unknown speeds (into G from `row` on) and its
  // acceleration with their rates zero (into kappa).
  template <typename Scalar>
  void calc_loop_rows(const std::vector<ModalKinematics<Scalar>>& kin,
                      const std::vector<Eigen::Matrix<Scalar, 3, Eigen::Dynamic>>& J_v,
                      const std::vector<Eigen::Matrix<Scalar, 3, Eigen::Dynamic>>& J_w,
                      MatXOf<Scalar>& G, VecXOf<Scalar>& kappa) const;
  // A held contact's point: its height (a pair's gap), its velocity (a pair's: the body's point
  // less the other's) and, where J_v and J_w are given, its velocity per unit of the unknown
  // speeds and its acceleration with their rates zero.
  template <typename Scalar>
  ContactRowsOf<Scalar> contact_rows(
      const ModalContact& held, const std::vector<ModalKinematics<Scalar>>& kin,
      const std::vector<Eigen::Matrix<Scalar, 3, Eigen::Dynamic>>& J_v,
      const std::vector<Eigen::Matrix<Scalar, 3, Eigen::Dynamic>>& J_w) const;
  // dz/dt, and the contacts' forces into `contact_forces_W` where given.
  template <typename Scalar>
  VecXOf<Scalar> evaluate(const VecXOf<Scalar>& z, std::vector<Vec3>* contact_forces_W) const;

  std::shared_ptr<const ArticulatedModel> model_;
  ModalLayout layout_;
  VecX y0_;
  double t0_;
  // Per tree joint: where its speeds' rates start among the unknowns (-1: held or driven).
  std::vector<Eigen::Index> unknown_;
  Eigen::Index unknowns_ = 0;
  std::vector<ModalContact> contacts_;
  // On a run's holds: rows that others already hold (a face's fourth corner, both ends of a line
  // a body rolls on, a point the joints hold) are left out, where `tumble modes` refuses them.
  bool drops_dependent_rows_ = false;
  std::vector<LoopShape> loops_;
  Eigen::Index loop_rows_ = 0;                // all of the loops' rows
  std::vector<Eigen::Index> loop_rows_held_;  // the independent ones at z = 0, in order
};

}  // namespace tumble
