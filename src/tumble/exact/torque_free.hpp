#pragma once
// The exact motion of a torque-free rigid body (Euler-Poinsot): body-frame angular velocity from
// Jacobi elliptic functions, orientation from the fixed angular momentum by a series (a
// quadrature on the separatrix itself).
// Reference solution for tests and the `integrator: exact` of free bodies.
#include <memory>

#include "tumble/math/types.hpp"

namespace tumble {

class TorqueFreeMotion {
 public:
  // I_G_B: inertia about the COM in body axes (symmetric positive definite, any ordering, may be
  // axisymmetric or spherical); R_WB0: orientation at t = 0; omega_W0: angular velocity at t = 0,
  // world frame.
  TorqueFreeMotion(const Mat3& I_G_B, const Mat3& R_WB0, const Vec3& omega_W0);

  Vec3 omega_B(double t) const;  // angular velocity, body axes
  Mat3 R_WB(double t) const;     // orientation, body axes -> world
  Vec3 omega_W(double t) const;  // angular velocity, world
  // The orientation and the world angular velocity at t from one evaluation of the elliptic
  // functions (what R_WB and omega_W give, bit for bit, at a third of their cost together).
  void calc_rotation(double t, Mat3& R_WB_out, Vec3& omega_W_out) const;

  Vec3 angular_momentum_W() const;  // about the COM, world; constant
  double kinetic_energy() const;    // rotational, constant
  // Period of omega_B (s); +infinity on the separatrix and for a body at rest.
  double period() const;

 private:
  struct Impl;
  // Held by value through a small fixed-size block would hide the algebra; a pointer keeps the
  // header light. Constructed once per scenario, never inside a step.
  std::shared_ptr<const Impl> impl_;
};

}  // namespace tumble
