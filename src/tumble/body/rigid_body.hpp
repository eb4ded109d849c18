#pragma once
// A rigid body's constant properties and its kinematic state in the chapter's terms, with the
// momenta and energies of section 6.6 (table "3D"):
//   p = M v_G,  h_O = (r_G - r_O) x M v_G + I_G omega,  T = M v_G.v_G / 2 + omega . I_G omega / 2,
// where I_G = R I_G_B R^T is the inertia about the COM in world axes.
#include <span>
#include <string>

#include "tumble/math/types.hpp"

namespace tumble {

struct RigidBody {
  std::string name;
  double mass = 1.0;              // kg, > 0
  Mat3 I_G_B = Mat3::Identity();  // inertia about the COM, body axes, kg m^2 (SPD)
  Mat3 I_G_B_inv = Mat3::Identity();

  static RigidBody make(std::string name, double mass, const Mat3& I_G_B);
};

// A body's pose and motion; in a scalar with derivatives where `tumble modes` differentiates the
// physics (math/dual.hpp), in double everywhere else (BodyState).
template <typename S>
struct BodyStateOf {
  Vec3Of<S> r_G = Vec3Of<S>::Zero();       // COM position, world, m
  Mat3Of<S> R_WB = Mat3Of<S>::Identity();  // rotation tensor: body axes -> world
  Vec3Of<S> v_G = Vec3Of<S>::Zero();       // COM velocity, world, m/s
  Vec3Of<S> omega_W = Vec3Of<S>::Zero();   // angular velocity, world, rad/s
};
using BodyState = BodyStateOf<double>;

Mat3 calc_inertia_about_com_W(const RigidBody& body, const Mat3& R_WB);
Vec3 calc_linear_momentum(const RigidBody& body, const BodyState& s);
Vec3 calc_angular_momentum_about_com_W(const RigidBody& body, const BodyState& s);
Vec3 calc_angular_momentum_about_point_W(const RigidBody& body, const BodyState& s,
                                         const Vec3& r_O);
double calc_kinetic_energy(const RigidBody& body, const BodyState& s);
// Potential energy of uniform gravity g (world): U = -M g . r_G (datum at the origin).
double calc_gravity_potential(const RigidBody& body, const BodyState& s, const Vec3& gravity_W);

// Sums over a system of bodies; L about the world origin.
struct SystemQuantities {
  double kinetic_energy = 0.0;                        // J
  double potential_energy = 0.0;                      // J
  double total_energy = 0.0;                          // J
  Vec3 linear_momentum = Vec3::Zero();                // kg m/s
  Vec3 angular_momentum_about_origin = Vec3::Zero();  // kg m^2/s
};
SystemQuantities calc_system_quantities(std::span<const RigidBody> bodies,
                                        std::span<const BodyState> states, const Vec3& gravity_W);

}  // namespace tumble
