// Loops' closing joints as constraints on the kinematic tree: their rows, forces and projection
// (loop_joints.hpp; docs/design.md, "Closed loops").
#include "tumble/multibody/loop_joints.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace tumble {

namespace {

// A row whose response to its own force is below this fraction of the largest row's is one no
// force moves: the tree already holds that motion (a Hooke joint's centre on a bearing's axis).
constexpr double kDeadResponse = 1e-12;
// An eigenvalue of J M^-1 J^T this small against its largest is a direction the rows repeat.
constexpr double kRedundantRow = 1e-12;
// Newton's method on the positions stops once the largest error is this small against the
// joints' size (or against a radian), or after this many moves, or when a move gains nothing.
constexpr double kClosedLoop = 1e-15;
constexpr int kMostMoves = 8;
// A loop whose largest error stays above this (against the joints' size, or a radian) once
// Newton's method has done what it can does not close: the run stops.
constexpr double kLoopBound = 1e-9;

// A loop's second body's acceleration less its first's at the joint point p_W, and the same of
// their angular accelerations (world), from the dynamics' last solve: impulsive, the response
// alone; else with the velocity terms and with gravity, which the passes leave out (ground
// accelerates at -g there).
struct RelativeAcceleration {
  Vec3 alpha_W = Vec3::Zero();
  Vec3 a_W = Vec3::Zero();
};

RelativeAcceleration relative_acceleration(const ContactDynamics& dynamics, const LoopShape& loop,
                                           const Vec3& p_W, const Vec3& gravity_W, bool impulsive) {
  const auto angular = [&](int body) -> Vec3 {
    if (body == kGround) return Vec3::Zero();
    const BodyMotion w = dynamics.motion(static_cast<std::size_t>(body));
    return w.R_WB * w.acceleration.head<3>();
  };
  const auto linear = [&](int body) -> Vec3 {
    if (body == kGround) return Vec3::Zero();
    const BodyMotion w = dynamics.motion(static_cast<std::size_t>(body));
    const Vec3 p_B = w.R_WB.transpose() * (p_W - w.r_G_W);
    const Vec3 alpha_B = w.acceleration.head<3>();
    Vec3 a_B = w.acceleration.tail<3>() + alpha_B.cross(p_B);
    if (impulsive) return w.R_WB * a_B;
    const Vec3 omega_B = w.velocity.head<3>();
    a_B += omega_B.cross(w.velocity.tail<3>() + omega_B.cross(p_B));
    return w.R_WB * a_B + gravity_W;
  };
  return {angular(loop.body_b) - angular(loop.body_a), linear(loop.body_b) - linear(loop.body_a)};
}

}  // namespace

LoopJoints::LoopJoints(const Model& model, const ContactDynamics& dynamics)
    : dynamics_(dynamics), gravity_W_(model.gravity_W) {
  loop_of_joint_.assign(model.joints.size(), -1);
  double largest_offset = 0.0;
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const JointModel& joint = model.joints[j];
    if (!joint.closes_loop) continue;
    Loop loop;
    loop.joint = j;
    loop.name = joint.name;
    loop.shape = loop_shape_of(joint);
    loop_of_joint_[j] = static_cast<int>(loops_.size());
    loops_.push_back(loop);
    largest_offset = std::max({largest_offset, loop.shape.p_AJ_A.norm(), loop.shape.p_BJ_B.norm()});
  }
  if (largest_offset > 0.0) length_scale_ = largest_offset;
  const std::size_t most_rows = 6 * loops_.size();
  rows_.resize(most_rows);
  wrenches_.resize(2 * loops_.size());
  matrix_ = MatX::Zero(static_cast<Eigen::Index>(most_rows), static_cast<Eigen::Index>(most_rows));
  x_ = VecX::Zero(static_cast<Eigen::Index>(most_rows));
  // Every row of every loop is always there: the solve's size is fixed, so its eigensolver's
  // room is taken once.
  Eigen::Index rows = 0;
  for (const Loop& loop : loops_) rows += loop.shape.rows();
  square_ = MatX::Zero(rows, rows);
  eigen_ = Eigen::SelfAdjointEigenSolver<MatX>(rows);
  projected_ = VecX::Zero(rows);
  reactions_.resize(loops_.size());
  resultants_.resize(loops_.size());
}

Vec3 LoopJoints::joint_point_W(const Loop& loop) const {
  return loop_point_W(loop.shape, side(loop.shape.body_b, false));
}

LoopJoints::Side LoopJoints::side(int body, bool with_velocities) const {
  Side s;
  if (body == kGround) return s;
  const BodyMotion w = dynamics_.motion(static_cast<std::size_t>(body));
  s.R_WB = w.R_WB;
  s.r_G = w.r_G_W;
  if (with_velocities) {
    s.omega_W = w.R_WB * w.velocity.head<3>();
    s.v_G = w.R_WB * w.velocity.tail<3>();
  }
  return s;
}

Eigen::Index LoopJoints::gather_rows(bool with_velocities) const {
  Eigen::Index count = 0;
  for (std::size_t l = 0; l < loops_.size(); ++l) {
    const LoopShape& shape = loops_[l].shape;
    for_each_loop_row(shape, side(shape.body_a, with_velocities),
                      side(shape.body_b, with_velocities), [&](const LoopRowOf<double>& of) {
                        Row& row = rows_[static_cast<std::size_t>(count++)];
                        static_cast<LoopRowOf<double>&>(row) = of;
                        row.loop = l;
                      });
  }
  return count;
}

double LoopJoints::row_velocity(const Row& row) const {
  const LoopShape& shape = loops_[row.loop].shape;
  return loop_row_velocity(shape, row, side(shape.body_a, true), side(shape.body_b, true));
}

double LoopJoints::row_acceleration(const Row& row) const {
  const LoopShape& loop = loops_[row.loop].shape;
  const Side a = side(loop.body_a, true);
  const Side b = side(loop.body_b, true);
  const RelativeAcceleration relative =
      relative_acceleration(dynamics_, loop, loop_point_W(loop, b), gravity_W_, false);
  const double response = row.direction_W.dot(row.turn ? relative.alpha_W : relative.a_W);
  return loop_row_acceleration(loop, row, a, b, response);
}

std::size_t LoopJoints::add_loop_wrenches(std::size_t l, const Vec3& F_W, const Vec3& M_W,
                                          std::size_t count) const {
  const LoopShape& loop = loops_[l].shape;
  const Side b = side(loop.body_b, false);
  const Vec3 p_W = loop_point_W(loop, b);
  // On B: F at its joint point and M; on A the opposite, at the same point.
  if (loop.body_b != kGround) {
    const Vec3 F_B = b.R_WB.transpose() * F_W;
    Vec6 wrench;
    wrench << loop.p_BJ_B.cross(F_B) + b.R_WB.transpose() * M_W, F_B;
    wrenches_[count++] = {static_cast<std::size_t>(loop.body_b), wrench};
  }
  if (loop.body_a != kGround) {
    const Side a = side(loop.body_a, false);
    const Vec3 F_A = -(a.R_WB.transpose() * F_W);
    const Vec3 p_A = a.R_WB.transpose() * (p_W - a.r_G);
    Vec6 wrench;
    wrench << p_A.cross(F_A) - a.R_WB.transpose() * M_W, F_A;
    wrenches_[count++] = {static_cast<std::size_t>(loop.body_a), wrench};
  }
  return count;
}

std::size_t LoopJoints::add_row_wrenches(Eigen::Index count, const VecX& x) const {
  // Each loop's resultant: the forces along its point rows, the moments about its turn rows.
  for (JointReaction& r : resultants_) r = {};
  for (Eigen::Index i = 0; i < count; ++i) {
    const Row& row = rows_[static_cast<std::size_t>(i)];
    JointReaction& r = resultants_[row.loop];
    (row.turn ? r.M_J_W : r.F_W) += x(i) * row.direction_W;
  }
  std::size_t wrenches = 0;
  for (std::size_t l = 0; l < loops_.size(); ++l) {
    wrenches = add_loop_wrenches(l, resultants_[l].F_W, resultants_[l].M_J_W, wrenches);
  }
  return wrenches;
}

void LoopJoints::calc_matrix(Eigen::Index count) const {
  for (Eigen::Index j = 0; j < count; ++j) {
    const Row& unit = rows_[static_cast<std::size_t>(j)];
    const Vec3 zero = Vec3::Zero();
    const std::size_t wrenches = add_loop_wrenches(unit.loop, unit.turn ? zero : unit.direction_W,
                                                   unit.turn ? unit.direction_W : zero, 0);
    dynamics_.respond_to_impulses(std::span<const BodyWrench>(wrenches_.data(), wrenches));
    // Each loop's relative response once for all its rows (they are together in rows_): the
    // rows' own, without a pass over the bodies per row.
    for (Eigen::Index i = 0; i < count;) {
      const std::size_t l = rows_[static_cast<std::size_t>(i)].loop;
      const RelativeAcceleration relative = relative_acceleration(
          dynamics_, loops_[l].shape, joint_point_W(loops_[l]), gravity_W_, true);
      for (; i < count && rows_[static_cast<std::size_t>(i)].loop == l; ++i) {
        const Row& row = rows_[static_cast<std::size_t>(i)];
        matrix_(i, j) = row.direction_W.dot(row.turn ? relative.alpha_W : relative.a_W);
      }
    }
  }
}

Eigen::Index LoopJoints::solve_rows(Eigen::Index count, VecX& x) const {
  double largest = 0.0;
  for (Eigen::Index i = 0; i < count; ++i) largest = std::max(largest, std::abs(matrix_(i, i)));
  // A row no force moves carries no force: the tree holds that motion already, and its entries
  // are round-off.
  for (Eigen::Index i = 0; i < count; ++i) {
    if (matrix_.row(i).head(count).cwiseAbs().maxCoeff() > kDeadResponse * largest) continue;
    matrix_.row(i).head(count).setZero();
    matrix_.col(i).head(count).setZero();
    x(i) = 0.0;
  }
  // J M^-1 J^T is symmetric and positive semi-definite: its pseudo-inverse gives, of the forces
  // that best meet the rows, the least-norm one. Where rows repeat, off the constraints'
  // manifold (a stage of a step, before its projection) they agree only to the state's drift:
  // the pseudo-inverse meets them in the least-squares sense, continuously in the state, so that
  // the error control sees a smooth right-hand side. What would make them contradict, a singular
  // position or drives that ask for motions the loops do not allow, shows as a drop of the rank
  // (solve_forces) or as a loop the projection cannot close (project).
  square_ = matrix_.topLeftCorner(count, count);
  eigen_.compute(square_);
  const VecX& values = eigen_.eigenvalues();
  const double floor = kRedundantRow * values.cwiseAbs().maxCoeff();
  Eigen::Index rank = 0;
  projected_.noalias() = eigen_.eigenvectors().transpose() * x.head(count);
  for (Eigen::Index k = 0; k < count; ++k) {
    if (values(k) > floor) {
      projected_(k) /= values(k);
      ++rank;
    } else {
      projected_(k) = 0.0;
    }
  }
  x.head(count).noalias() = eigen_.eigenvectors() * projected_;
  return rank;
}

std::string LoopJoints::joint_names() const {
  std::string joints;
  for (const Loop& loop : loops_) {
    if (!joints.empty()) joints += ", ";
    joints += "'" + loop.name + "'";
  }
  return joints;
}

void LoopJoints::throw_singular(double t, Eigen::Index rank) const {
  throw std::runtime_error(fmt::format(
      "at t = {:.17g} s the loops that {} close reached a singular position: their rows hold "
      "{} independent direction{} where they held {} (a dead centre or a change point, where the "
      "joints' constraints lose rank and neither the motion nor the reactions are determined)",
      t, joint_names(), rank, rank == 1 ? "" : "s", held_rank_));
}

void LoopJoints::throw_open(double t, double error) const {
  throw std::runtime_error(fmt::format(
      "at t = {:.17g} s the loops that {} close cannot be closed: their joints stay {:.3g} of "
      "their size apart (drives that ask for motions the loops do not allow, or a singular "
      "position)",
      t, joint_names(), error));
}

void LoopJoints::solve_forces(double t) const {
  dynamics_.solve_under_loads();
  const Eigen::Index count = gather_rows(true);
  for (Eigen::Index i = 0; i < count; ++i) {
    x_(i) = -row_acceleration(rows_[static_cast<std::size_t>(i)]);
  }
  calc_matrix(count);
  const Eigen::Index rank = solve_rows(count, x_);
  // The rows' rank is the loops' structure (a planar linkage of 3D hinges repeats three rows a
  // pin), constant along the motion; where it drops, the loops have lost a direction they held
  // (a dead centre, a change point), where neither the motion nor the forces are determined.
  if (held_rank_ < 0) held_rank_ = rank;
  if (rank < held_rank_) throw_singular(t, rank);
  const std::size_t wrenches = add_row_wrenches(count, x_);
  for (std::size_t l = 0; l < loops_.size(); ++l) reactions_[l] = resultants_[l];
  dynamics_.solve_under_loads_and(std::span<const BodyWrench>(wrenches_.data(), wrenches));
}

JointReaction LoopJoints::reaction(std::size_t model_joint) const {
  return reactions_[static_cast<std::size_t>(loop_of_joint_[model_joint])];
}

void LoopJoints::respond_to_row_impulses(Eigen::Index count, const VecX& x) const {
  const std::size_t wrenches = add_row_wrenches(count, x);
  dynamics_.respond_to_impulses(std::span<const BodyWrench>(wrenches_.data(), wrenches));
}

void LoopJoints::project(double t, VecX& y) const {
  // Positions: Newton's method, each move the least in the mass metric that closes the rows to
  // first order; it converges quadratically from a step's drift.
  double previous = std::numeric_limits<double>::infinity();
  for (int move = 0;; ++move) {
    dynamics_.calc_motion(y, false);
    const Eigen::Index count = gather_rows(false);
    // A gap is measured against the joints' size, or against where they are if that is
    // larger: far from the origin, the positions' own round-off is larger than the joints'.
    double where = length_scale_;
    for (const Loop& loop : loops_) {
      where = std::max(where, joint_point_W(loop).cwiseAbs().maxCoeff());
    }
    double worst = 0.0;
    for (Eigen::Index i = 0; i < count; ++i) {
      const Row& row = rows_[static_cast<std::size_t>(i)];
      worst = std::max(worst, std::abs(row.error) / (row.turn ? 1.0 : where));
      x_(i) = -row.error;
    }
    if (worst <= kClosedLoop) break;
    // Where Newton's method has stopped gaining (or run out of moves), the loops are closed to
    // the round-off of the positions' own size, or cannot close at all (drives that ask for
    // motions the loops do not allow, a singular position).
    if (!(worst < previous) || move == kMostMoves) {
      if (worst > kLoopBound) throw_open(t, worst);
      break;
    }
    previous = worst;
    calc_matrix(count);
    solve_rows(count, x_);
    respond_to_row_impulses(count, x_);
    dynamics_.apply_displacement(y);
    dynamics_.normalise(t, y);
  }
  // Velocities: the impulses that zero every row's velocity (linear: one solve).
  dynamics_.respond_to_impulses(tangent_impulses(y));
  dynamics_.apply_speed_jumps(y);
}

std::span<const BodyWrench> LoopJoints::tangent_impulses(const VecX& y) const {
  dynamics_.calc_motion(y, true);
  const Eigen::Index count = gather_rows(true);
  for (Eigen::Index i = 0; i < count; ++i) {
    x_(i) = -row_velocity(rows_[static_cast<std::size_t>(i)]);
  }
  calc_matrix(count);
  solve_rows(count, x_);
  const std::size_t wrenches = add_row_wrenches(count, x_);
  for (std::size_t l = 0; l < loops_.size(); ++l) reactions_[l] = resultants_[l];
  return {wrenches_.data(), wrenches};
}

Eigen::Index LoopJoints::rank_at(const VecX& y) const {
  dynamics_.calc_motion(y, true);
  const Eigen::Index count = gather_rows(true);
  x_.head(count).setZero();
  calc_matrix(count);
  return solve_rows(count, x_);
}

LoopErrors LoopJoints::errors_now() const {
  LoopErrors errors;
  const Eigen::Index count = gather_rows(true);
  for (Eigen::Index i = 0; i < count; ++i) {
    const Row& row = rows_[static_cast<std::size_t>(i)];
    double& error = row.turn ? errors.turn : errors.gap;
    error = std::max(error, std::abs(row.error));
    errors.speed = std::max(errors.speed, std::abs(row_velocity(row)));
  }
  return errors;
}

}  // namespace tumble
