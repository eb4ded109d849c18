#pragma once
// Rotation kinematics of the chapter's section 6.7.3: spin tensors, the Rodrigues formula and its
// inverse, unit quaternions, re-orthonormalisation, and the rigid-body velocity and acceleration
// transfer between two points of one body.
#include "tumble/math/types.hpp"

namespace tumble {

// Spin (skew) tensor of a vector: hat(a) b = a x b.
Mat3 hat(const Vec3& a);
// The vector of a spin tensor; uses the skew part only, so it is exact for W = dR/dt R^T.
Vec3 vee(const Mat3& W);

// Rodrigues: rotation by angle theta (rad) about the unit axis n,
//   R = cos(theta) I + (1 - cos(theta)) n n^T + sin(theta) [n]x.
// The axis is normalised here; a zero axis is a programming error (checked by callers that take
// user input).
Mat3 rotation_from_axis_angle(const Vec3& axis, double angle);

// The rotation vector phi = theta n of R (theta in [0, pi]); the inverse of exp_so3.
// Accurate to round-off near theta = 0 (series) and near theta = pi (axis from the symmetric part).
Vec3 log_so3(const Mat3& R);
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
Vec3 velocity_of_point(const Vec3& v_A, const Vec3& omega, const Vec3& r_AB);
// Acceleration of body point B from A: a_B = a_A + alpha x r_AB + omega x (omega x r_AB).
Vec3 acceleration_of_point(const Vec3& a_A, const Vec3& omega, const Vec3& alpha, const Vec3& r_AB);

}  // namespace tumble
