#pragma once
// Small computations that several tests share, defined once (tumble_tests is a unity build).
#include "tumble/math/types.hpp"

namespace tumble::test {

// The largest absolute entry of a matrix or a vector; an expression is first evaluated into its
// matrix (as the Mat3 or Vec3 it stands for).
template <typename Derived>
double max_abs(const Eigen::MatrixBase<Derived>& m) {
  return m.eval().cwiseAbs().maxCoeff();
}

// q (x) (0, omega_B) / 2, the rate of the unit quaternion q = y[offset .. offset + 3] (w, x, y, z),
// written into dydt at the same offset.
inline void quaternion_rate(const VecX& y, Eigen::Index offset, const Vec3& omega_B, VecX& dydt) {
  const double w = y[offset];
  const Vec3 v = y.segment<3>(offset + 1);
  dydt[offset] = -0.5 * v.dot(omega_B);
  dydt.segment<3>(offset + 1) = 0.5 * (w * omega_B + v.cross(omega_B));
}

}  // namespace tumble::test
