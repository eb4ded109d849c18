#pragma once
// Joints that close loops (docs/design.md, "Closed loops"): a four-bar's coupler pin, a
// slider-crank's wrist pin, the cross of a Hooke joint between two shafts on their own bearings.
// The other joints form the kinematic tree, whose coordinates hold them by construction; a loop's
// closing joint is a constraint on that tree, held the way contact holds a rolling wheel:
//  - its force is the one that keeps the constraint's acceleration zero, J a + J' v = 0, from
//    the tree's response to unit wrenches at the joint (the articulated-body algorithm's
//    impulsive passes: J M^-1 J^T without forming M);
//  - after every step the positions are put back on the constraint by Newton's method, each move
//    the least in the mass metric (M^-1 J^T mu), and the velocities onto its tangent by the
//    impulses that zero the rows' velocities (one linear solve), so that the loop holds to
//    round-off at every row, whatever the tolerance, with no gains to tune.
// Rows of a joint that the others already hold (a planar four-bar of 3D hinges: three of each
// pin's five rows repeat the plane's) make J M^-1 J^T singular; the solve keeps the independent
// rows and, of the reactions that hold the loop, reports the least-norm one.
//
// Each joint's rows are loop_rows.hpp's, which `tumble modes` linearises on too.
//
// It talks to the tree only through ContactDynamics (contact/contact_dynamics.hpp): poses,
// twists, accelerations, responses to wrenches and impulses.
#include <span>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>
#include "tumble/contact/contact_dynamics.hpp"
#include "tumble/dynamics/model.hpp"
#include "tumble/dynamics/row_extras.hpp"
#include "tumble/multibody/loop_rows.hpp"

#include "tumble/math/types.hpp"

namespace tumble {

class LoopJoints {
 public:
  // The model's joints that close loops (JointModel::closes_loop), moved by `dynamics`. Both
  // must outlive this object.
  LoopJoints(const Model& model, const ContactDynamics& dynamics);

  bool empty() const { return loops_.empty(); }

  // After the dynamics' calc_motion (with velocities) and gather_loads: the loops' forces, and
  // the dynamics' accelerations under the loads and those forces (solve_under_loads_and).
  // Throws std::runtime_error where the rows contradict each other (a singular position).
  void solve_forces(double t) const;
  // After solve_forces: what the joint's first body exerts on its second, at the joint point.
  JointReaction reaction(std::size_t model_joint) const;
  // The positions back on the loops' constraints (Newton's method, each move the least in the
  // mass metric), then the velocities onto their tangent. After the dynamics' own projection.
  void project(double t, VecX& y) const;
  // At a jump: the impulses that take the velocities of y onto the loops' tangent (the least
  // change of kinetic energy), as wrenches on the bodies (valid until the next call), with each
  // loop's resultant as its reaction (an impulse: N s, N m s).
  std::span<const BodyWrench> tangent_impulses(const VecX& y) const;
  // At a run's start and at each breakpoint: locks and motors that start or stop change the
  // tree's freedoms, and with them how many directions the rows hold (a four-bar whose crank and
  // rocker are both locked holds one where it held two). The next force solve takes the rank
  // anew, against which a singular position is then found.
  void retake_rank() const { held_rank_ = -1; }
  // How many of the loops' rows are independent at y (their rank, rows no force moves aside).
  Eigen::Index rank_at(const VecX& y) const;
  // The closing joints' names, quoted, for messages; the first one's model joint.
  std::string joint_names() const;
  std::size_t first_joint() const { return loops_.front().joint; }
  // The loops' errors at the state last evaluated (after calc_motion with velocities).
  LoopErrors errors_now() const;

 private:
  struct Loop {
    std::size_t joint = 0;  // the model joint
    std::string name;
    LoopShape shape;
  };
  // One constraint row (loop_rows.hpp), and its loop.
  struct Row : LoopRowOf<double> {
    std::size_t loop = 0;
  };
  using Side = BodyState;  // ground: at rest at the origin
  Side side(int body, bool with_velocities) const;
  // The loop's joint point on its second body, world (after calc_motion).
  Vec3 joint_point_W(const Loop& loop) const;
  // Every loop's rows at the state last evaluated (calc_motion), into rows_; returns their count.
  Eigen::Index gather_rows(bool with_velocities) const;
  // A row's velocity, and its value's rate under the accelerations of the last solve (with the
  // velocity terms and gravity: psi_0 when no loop force acts).
  double row_velocity(const Row& row) const;
  double row_acceleration(const Row& row) const;
  // The wrenches on loop l's bodies of the force F_W at its joint point and the moment M_W
  // (on its second body; their opposites on its first), into wrenches_ from `count` on; returns
  // the new count.
  std::size_t add_loop_wrenches(std::size_t l, const Vec3& F_W, const Vec3& M_W,
                                std::size_t count) const;
  // Every loop's resultant of the forces x_i along the leading count rows (into resultants_),
  // and their wrenches (into wrenches_); returns their count.
  std::size_t add_row_wrenches(Eigen::Index count, const VecX& x) const;
  // The matrix J M^-1 J^T of the leading `count` rows, from the responses to unit row forces.
  void calc_matrix(Eigen::Index count) const;
  // Solves matrix x = x for the leading count rows (rows no force moves set aside), in place;
  // returns how many of them are independent (not counting those set aside).
  Eigen::Index solve_rows(Eigen::Index count, VecX& x) const;
  // The singular position's error.
  [[noreturn]] void throw_singular(double t, Eigen::Index rank) const;
  // A loop that Newton's method cannot close: its largest error (against the joints' size).
  [[noreturn]] void throw_open(double t, double error) const;
  // The dynamics' response (speed jumps) to impulses x along the rows.
  void respond_to_row_impulses(Eigen::Index count, const VecX& x) const;

  const ContactDynamics& dynamics_;
  std::vector<Loop> loops_;
  std::vector<int> loop_of_joint_;  // per model joint: its loop, or -1
  Vec3 gravity_W_;
  double length_scale_ = 1.0;  // m: the joints' largest offset from a COM (1 if all are 0)
  // Scratch, sized once (a run serves one thread at a time).
  mutable std::vector<Row> rows_;
  mutable std::vector<BodyWrench> wrenches_;
  mutable MatX matrix_;
  mutable VecX x_;
  mutable MatX square_;  // the leading rows' matrix, for the eigensolver
  mutable Eigen::SelfAdjointEigenSolver<MatX> eigen_;
  mutable VecX projected_;
  mutable std::vector<JointReaction> resultants_;  // per loop, of the last add_row_wrenches
  mutable std::vector<JointReaction> reactions_;   // per loop, from the last solve_forces
  // The rows' rank at the first force solve since the run's start or its last breakpoint: the
  // loops' structure, which a singular position lowers (-1 until then).
  mutable Eigen::Index held_rank_ = -1;
};

}  // namespace tumble
