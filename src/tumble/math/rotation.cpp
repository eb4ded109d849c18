#include "tumble/math/rotation.hpp"

#include <cmath>

namespace tumble {

Mat3 exp_so3(const Vec3& phi) {
  const double theta2 = phi.squaredNorm();
  const double theta = std::sqrt(theta2);
  // R = I + a [phi]x + b [phi]x^2 with a = sin(t)/t, b = (1 - cos(t))/t^2; Taylor series below
  // 1e-4 rad, where the next terms are below 1e-17 relative.
  double a, b;
  if (theta < 1e-4) {
    a = 1.0 - theta2 / 6.0;
    b = 0.5 - theta2 / 24.0;
  } else {
    a = std::sin(theta) / theta;
    b = (1.0 - std::cos(theta)) / theta2;
  }
  const Mat3 P = hat(phi);
  return Mat3::Identity() + a * P + b * P * P;
}

Mat3 rotation_from_quaternion(const Quat& q) {
  return q.normalized().toRotationMatrix();
}

Quat quaternion_from_rotation(const Mat3& R) {
  Quat q(R);
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  return q.normalized();
}

Mat3 nearest_rotation(const Mat3& R) {
  Eigen::JacobiSVD<Mat3> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 D = Mat3::Identity();
  D(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  return svd.matrixU() * D * svd.matrixV().transpose();
}

double orthonormality_error(const Mat3& R) {
  return (R.transpose() * R - Mat3::Identity()).cwiseAbs().maxCoeff();
}

Vec3 acceleration_of_point(const Vec3& a_A, const Vec3& omega, const Vec3& alpha,
                           const Vec3& r_AB) {
  return a_A + alpha.cross(r_AB) + omega.cross(omega.cross(r_AB));
}

}  // namespace tumble
