#pragma once
// The linearisation of a model about its initial state (`tumble modes`): an equilibrium, where
// every rate of the modal coordinates vanishes, or a steady motion, where the state only turns
// along symmetries of the model: a body spinning about a principal axis, a wheel spinning on its
// axle while the whole precesses about the vertical, a top spinning upright.
//
// 1. The Jacobian J = d(dz/dt)/dz at z = 0, by automatic differentiation (modal_equations.hpp).
// 2. Ignorable coordinates are set aside: a position on which no other rate depends (a free
//    body's place, the turn of a body that nothing pulls back, the angle of a wheel symmetric
//    about its axle). They only drift; what is left evolves on its own, as Euler's equations
//    do for the free prism.
// 3. What is left must be steady: its rates zero (an equilibrium), or equal to the rates of a
//    turn along symmetries, sum_i c_i X_i (found by least squares: the spins of symmetric bodies
//    first, then a turn about the vertical), where each X_i commutes with the motion
//    ([X_i, f] = 0). Otherwise NotSteady says which rate is off and by how much.
// 4. The linearisation is then A = J - sum_i c_i dX_i/dz: the equations seen from a frame that
//    moves with the steady motion, so A is constant. Directions along which the motion is only
//    turned (X_i) are a neutral family of the same steady motion; they are taken out (the
//    quotient), so a change of spin is not mistaken for a growing drift. So are the turns the
//    state does not move along that carry its motion over unchanged (a rolling wheel's heading).
// With contacts touching (modal_contacts.hpp) or loops closed, the modes are those on the
// constraints' tangent space T, which the flow keeps (A T in T): the quotient is taken within it.
#include <functional>
#include <string>
#include <vector>

#include "tumble/modes/modal_equations.hpp"
#include "tumble/modes/not_steady.hpp"

namespace tumble {

// An ignorable position that moves at the initial state, at a constant rate.
struct DriftingCoordinate {
  std::string name;
  std::string unit;   // of the position: "rad" or "m"
  double rate = 0.0;  // unit/s
};

struct Linearisation {
  std::vector<ModalCoordinate> coordinates;  // the ones kept, in z's order
  std::vector<Eigen::Index> kept;            // their places in z
  std::vector<std::string> ignorable;        // positions set aside (step 2)
  std::vector<std::string> unrestored;       // those of joints (not of free bodies)
  MatX A;                                    // d(ds/dt)/ds, s the kept coordinates
  std::vector<Symmetry> symmetries;          // the steady motion's turns (none: an equilibrium)
  VecX symmetry_rates;                       // c_i: rad/s
  // Turns the state does not move along that leave its motion as it is (a rolling wheel's
  // heading): taken out with the orbit, at no rate.
  std::vector<Symmetry> neutral_symmetries;
  MatX tangent;      // T: an orthonormal basis of the changes of s the constraints allow (all: I)
  MatX orbit;        // columns: the directions, in s, along which the motion only turns (or could)
  MatX orbit_basis;  // P: an orthonormal basis of their span
  MatX quotient;     // Q: one of the rest of T; A's modes are those of Q^T A Q
  double largest_rate = 0.0;  // the largest rate of s that the steadiness leaves (round-off)
  // The ignorable positions that move at the initial state, each at its constant rate (unit/s):
  // a free prism's turn about its spin axis. Set aside, they leave a steady motion, not an
  // equilibrium, though the kept coordinates' rates are all zero.
  std::vector<DriftingCoordinate> drifting;
  bool equilibrium() const { return symmetries.empty() && drifting.empty(); }
};

// Throws NotSteady.
Linearisation linearise(const ModalEquations& equations);

// The Jacobian of a function of z at z = 0 by forward-mode automatic differentiation, and its
// value: kDualSeeds columns an evaluation, the other coordinates held as plain numbers.
MatX jacobian_at_zero(const std::function<VecXOf<Dual>(const VecXOf<Dual>&)>& f, Eigen::Index n,
                      VecX* value = nullptr);

}  // namespace tumble
