#pragma once
// Fixed-size linear algebra types used throughout tumble. Every 3-vector carries its frame in
// its name (see docs/notation.md): r_G (COM, world), omega_B (angular velocity, body axes), ...
#include <Eigen/Dense>

namespace Eigen {
template <typename DerivativeType>
class AutoDiffScalar;
}  // namespace Eigen

namespace tumble {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;  // (w, x, y, z); unit quaternions stand for rotations
// A spatial vector (Featherstone): a motion (omega; v) or a force (moment; force), angular first.
using Vec6 = Eigen::Matrix<double, 6, 1>;
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;

// The same in another scalar: the physics that both a run (double) and `tumble modes`
// (math/dual.hpp: numbers with derivatives) evaluate is written once over these.
template <typename S>
using Vec3Of = Eigen::Matrix<S, 3, 1>;
template <typename S>
using Mat3Of = Eigen::Matrix<S, 3, 3>;
template <typename S>
using Vec6Of = Eigen::Matrix<S, 6, 1>;
template <typename S>
using VecXOf = Eigen::Matrix<S, Eigen::Dynamic, 1>;
template <typename S>
using MatXOf = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;

// A number with its derivatives along up to kDualSeeds seeds at once (math/dual.hpp, which
// defines what it needs). The derivatives live inside the number, not on the heap: every
// operation on a dual number made a vector of derivatives, and allocating them was most of a
// Jacobian's cost. A Jacobian of more columns is taken kDualSeeds columns at a time
// (modes/linearisation.hpp, jacobian_at_zero).
inline constexpr int kDualSeeds = 32;
using DualDerivatives = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kDualSeeds, 1>;
using Dual = Eigen::AutoDiffScalar<DualDerivatives>;

// The plain number of a scalar (itself for double; math/dual.hpp adds the dual numbers').
inline double value_of(double x) {
  return x;
}
double value_of(const Dual& x);  // math/dual.cpp

}  // namespace tumble
