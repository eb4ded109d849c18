#pragma once
// Rotation kinematics of the chapter's section 6.7.3: spin tensors, the Rodrigues formula and its
// inverse, unit quaternions, re-orthonormalisation, and the rigid-body velocity and acceleration
// transfer between two points of one body.
//
// What the equations of motion use is written once over the scalar (double for a run, Dual for
// `tumble modes`, math/dual.hpp); the double forms below are those templates at double.
#include <cmath>
#include <type_traits>

#include "tumble/math/types.hpp"

namespace tumble {

// Spin (skew) tensor of a vector: hat(a) b = a x b.
template <typename S>
Mat3Of<S> hat(const Vec3Of<S>& a) {
  Mat3Of<S> W;
  W << S(0.0), -a.z(), a.y(),  //
      a.z(), S(0.0), -a.x(),   //
      -a.y(), a.x(), S(0.0);
  return W;
}
inline Mat3 hat(const Vec3& a) {
  return hat<double>(a);
}

// The vector of a spin tensor; uses the skew part only, so it is exact for W = dR/dt R^T.
template <typename S>
Vec3Of<S> vee(const Mat3Of<S>& W) {
  return S(0.5) * Vec3Of<S>(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1));
}
inline Vec3 vee(const Mat3& W) {
  return vee<double>(W);
}

// Rodrigues: rotation by angle theta (rad) about the unit axis n,
//   R = cos(theta) I + (1 - cos(theta)) n n^T + sin(theta) [n]x.
// The axis is normalised here; a zero axis is a programming error (checked by callers that take
// user input). The angle may carry derivatives; the axis is a constant of the model.
template <typename S>
requires(!std::is_arithmetic_v<S> || std::is_same_v<S, double>)  // not an int's angle
    Mat3Of<S> rotation_from_axis_angle(const Vec3& axis, const S& angle) {
  using std::cos;
  using std::sin;
  const Vec3 n = axis.normalized();
  const S c = cos(angle);
  const S s = sin(angle);
  return c * Mat3Of<S>::Identity() +
         (S(1.0) - c) * n.template cast<S>() * n.transpose().template cast<S>() +
         s * hat(n).template cast<S>();
}
inline Mat3 rotation_from_axis_angle(const Vec3& axis, double angle) {
  return rotation_from_axis_angle<double>(axis, angle);
}

// atan2 over the scalar. Eigen's for dual numbers gives its result heap-held derivatives of any
// count (VectorXd): this one keeps the Dual's own (math/dual.cpp).
inline double atan2_of(double y, double x) {
  return std::atan2(y, x);
}
Dual atan2_of(const Dual& y, const Dual& x);

// The rotation vector phi = theta n of R (theta in [0, pi]); the inverse of exp_so3.
// Accurate to round-off near theta = 0 (series) and near theta = pi (axis from the symmetric
// part). Near theta = 0 the series is taken without |sin(theta) n|, whose derivatives do not
// exist at R = 1 (a spring at rest, where `tumble modes` differentiates it).
template <typename S>
Vec3Of<S> log_so3(const Mat3Of<S>& R) {
  using std::sqrt;
  // sin(theta) n = vee(skew part); cos(theta) = (trace - 1) / 2. atan2 of the two is accurate
  // everywhere except for the axis near pi, where the skew part vanishes.
  const Vec3Of<S> s_n = vee<S>(R);
  const S sin_squared = s_n.squaredNorm();
  const S cos_theta = S(0.5) * (R.trace() - S(1.0));
  if (value_of(cos_theta) > -0.9) {
    // theta / sin(theta) = 1 + theta^2 / 6 + ...: 1 to round-off below sin(theta) = 1e-8.
    if (std::sqrt(value_of(sin_squared)) < 1e-8) return (S(1.0) + sin_squared / S(6.0)) * s_n;
    const S sin_theta = sqrt(sin_squared);
    return atan2_of(sin_theta, cos_theta) / sin_theta * s_n;
  }
  // Near pi: R + R^T = 2 cos I + 2 (1 - cos) n n^T, so n n^T from the symmetric part; take the
  // largest diagonal entry's column for accuracy, and the sign of n from the skew part.
  const S theta = atan2_of(S(sqrt(sin_squared)), cos_theta);
  const Mat3Of<S> B = S(0.5) * (R + R.transpose()) - cos_theta * Mat3Of<S>::Identity();
  Eigen::Index k = 0;
  for (Eigen::Index i = 1; i < 3; ++i) {
    if (value_of(B(i, i)) > value_of(B(k, k))) k = i;
  }
  Vec3Of<S> n = B.col(k) / sqrt(B(k, k));
  n.normalize();
  if (value_of(n.dot(s_n)) < 0.0) n = -n;
  return theta * n;
}
inline Vec3 log_so3(const Mat3& R) {
  return log_so3<double>(R);
}

// exp([phi]x): the rotation by |phi| about phi / |phi|, with the series near phi = 0.
Mat3 exp_so3(const Vec3& phi);

// Unit quaternion <-> rotation tensor. quaternion_from_rotation picks the sign with w >= 0.
Mat3 rotation_from_quaternion(const Quat& q);
Quat quaternion_from_rotation(const Mat3& R);

// The orthonormal matrix nearest to R (polar decomposition, by SVD); the determinant is +1 for
// any R near a rotation.
Mat3 nearest_rotation(const Mat3& R);
// max |(R^T R - I)_ij|: how far R has drifted from a rotation.
double orthonormality_error(const Mat3& R);

// Velocity of body point B from body point A: v_B = v_A + omega x r_AB (all in one frame).
template <typename S>
Vec3Of<S> velocity_of_point(const Vec3Of<S>& v_A, const Vec3Of<S>& omega, const Vec3Of<S>& r_AB) {
  return v_A + omega.cross(r_AB);
}
inline Vec3 velocity_of_point(const Vec3& v_A, const Vec3& omega, const Vec3& r_AB) {
  return velocity_of_point<double>(v_A, omega, r_AB);
}
// Acceleration of body point B from A: a_B = a_A + alpha x r_AB + omega x (omega x r_AB).
Vec3 acceleration_of_point(const Vec3& a_A, const Vec3& omega, const Vec3& alpha, const Vec3& r_AB);

}  // namespace tumble
