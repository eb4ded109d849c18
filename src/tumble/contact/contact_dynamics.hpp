#pragma once
// What contact needs of the dynamics that move the bodies, and nothing more (docs/design.md,
// "Contact"): a body's pose and twist, its acceleration once solved, the response of every body
// to a unit wrench on one, and the jumps of the speeds that impulses cause. The contact
// subsystem (ContactSystem) finds its forces, modes, impacts and projections through this
// alone; it never sees joints, coordinates or the articulated-body passes. The articulated
// formulation implements it for a body anywhere in its tree; a contact between two moving
// bodies would read two bodies' motions and apply equal and opposite wrenches through the same
// calls.
//
// Frames: B a body's axes at its COM G, W the world. Spatial vectors are Featherstone's, angular
// part first: a velocity (omega_B; v_G_B), an acceleration (alpha_B; a_B) whose linear part is
// the spatial one (the classical a_G_B less omega_B x v_G_B), a wrench (moment about G; force).
#include <cstddef>
#include <span>
#include <vector>

#include "tumble/body/rigid_body.hpp"
#include "tumble/math/types.hpp"

namespace tumble {

// A body's motion at the state last evaluated.
struct BodyMotion {
  const Mat3& R_WB;
  const Vec3& r_G_W;         // m
  const Vec6& velocity;      // (omega_B rad/s; v_G_B m/s)
  const Vec6& acceleration;  // after a solve: (alpha_B; a_B); the accelerations lack gravity's g
};

// A wrench (moment about the COM, N m; force, N), or an impulse's (N m s; N s), on one body in
// its own axes.
struct BodyWrench {
  std::size_t body = 0;
  Vec6 wrench_B = Vec6::Zero();
};

// The wrench on a body (moment about its COM; force), in its axes, of a force F_W at its point
// p_B and a pure moment M_W.
inline Vec6 wrench_at(const Mat3& R_WB, const Vec3& p_B, const Vec3& F_W, const Vec3& M_W) {
  const Vec3 F_B = R_WB.transpose() * F_W;
  Vec6 wrench;
  wrench << p_B.cross(F_B) + R_WB.transpose() * M_W, F_B;
  return wrench;
}

class ContactDynamics {
 public:
  virtual ~ContactDynamics() = default;

  // A body's pose and twist (and acceleration after a solve) at the state last evaluated, and
  // its state in the chapter's terms (r_G, R_WB, v_G, omega_W).
  BodyMotion motion(std::size_t body) const {
    const MotionSource& source = motion_sources_[body];
    return {*source.R_WB, *source.r_G_W, *source.velocity, *source.acceleration};
  }
  virtual const BodyState& state(std::size_t body) const = 0;

  // Every body's pose at y, and with `with_velocities` its twist.
  virtual void calc_motion(const VecX& y, bool with_velocities) const = 0;
  // After calc_motion with velocities: the applied loads and force elements at y, kept for the
  // solves below; with `dydt`, their powers written into its ledger entries.
  virtual void gather_loads(const VecX& y) const = 0;
  virtual void gather_loads(const VecX& y, VecX& dydt) const = 0;
  // After the last solve (solve_under_loads_and): dy/dt's coordinates and speeds, and the
  // joints' powers into the ledger (the contacts' entries are the contact subsystem's to write).
  // Contact composes its accelerations and rates from these calls and its own force solve, so
  // the dynamics never call back into contact from inside a contact's question.
  virtual void write_rates(const VecX& y, VecX& dydt) const = 0;

  // After calc_motion with velocities and the loads gathered: the accelerations under the
  // loads alone; then under the loads and these wrenches (the loads are kept between the two).
  virtual void solve_under_loads() const = 0;
  virtual void solve_under_loads_and(std::span<const BodyWrench> wrenches) const = 0;

  // The linear response to a unit wrench on one body: every acceleration it causes, with no
  // velocity terms and no gravity (the impulsive passes). Only the bodies that move with it
  // (moves_with) are solved; the others' accelerations are left as they were.
  virtual void respond_to_unit_wrench(const BodyWrench& unit) const = 0;
  bool moves_with(std::size_t body, std::size_t other) const {
    return motion_group_[body] == motion_group_[other];
  }
  // The group a body moves with (a number below the body count), and whether that group can move
  // at all: an obstacle welded to ground responds to no wrench, so the bodies that touch it are
  // not tied together through it (the contact solve's islands).
  std::size_t motion_group(std::size_t body) const { return motion_group_[body]; }
  bool can_move(std::size_t body) const { return group_moves_[motion_group_[body]] != 0; }
  // The jumps of the speeds under these impulses (impulsive passes, every body); then added to
  // y's speeds, or taken as a small displacement of y's coordinates (a projection's move).
  virtual void respond_to_impulses(std::span<const BodyWrench> impulses) const = 0;
  virtual void apply_speed_jumps(VecX& y) const = 0;
  virtual void apply_displacement(VecX& y) const = 0;

  // Whether the body's own coordinates are its COM's position (a free body), and moving that by
  // delta_W m.
  virtual bool moves_freely(std::size_t body) const = 0;
  virtual void translate(std::size_t body, const Vec3& delta_W, VecX& y) const = 0;
  // y's own coordinates back on their manifold (unit quaternions), before the contacts'.
  virtual void normalise(double t, VecX& y) const = 0;

  // Every body's kinetic energy at the state last evaluated, J.
  virtual double kinetic_energy() const = 0;
  // The work ledger (J): where it starts in y, and the entry of a contact's forces and impulses
  // in it (a ledger's rates are kept in the same order); the contacts' entries are consecutive,
  // in the contacts' order.
  virtual Eigen::Index ledger_start() const = 0;
  virtual Eigen::Index work_entry(std::size_t contact) const = 0;
  // How many entries the contacts have (from work_entry(0) on): fewer than the contacts where
  // some share one (`bodies: all`'s pairs: their group's).
  virtual Eigen::Index contact_ledger_size() const = 0;

 protected:
  // Where each body's motion is kept, and which bodies move together (the same group), set once
  // by the implementation: the contact solve reads a body's motion for every pair of rows, so
  // these two answers are a table lookup rather than a virtual call (a virtual call there cost
  // 7% of a three-body ramp race's instructions).
  struct MotionSource {
    const Mat3* R_WB = nullptr;
    const Vec3* r_G_W = nullptr;
    const Vec6* velocity = nullptr;
    const Vec6* acceleration = nullptr;
  };
  std::vector<MotionSource> motion_sources_;  // per body; the addresses must not change
  std::vector<std::size_t> motion_group_;     // per body
  std::vector<char> group_moves_;             // per group: some joint of it has a freedom
};

}  // namespace tumble
