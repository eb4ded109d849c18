#include "tumble/math/rotation.hpp"

#include <cmath>

namespace tumble {

Mat3 hat(const Vec3& a) {
  Mat3 W;
  W << 0.0, -a.z(), a.y(),  //
      a.z(), 0.0, -a.x(),   //
      -a.y(), a.x(), 0.0;
  return W;
}

Vec3 vee(const Mat3& W) {
  return 0.5 * Vec3(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1));
}

Mat3 rotation_from_axis_angle(const Vec3& axis, double angle) {
  const Vec3 n = axis.normalized();
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  return c * Mat3::Identity() + (1.0 - c) * n * n.transpose() + s * hat(n);
}

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

Vec3 log_so3(const Mat3& R) {
  // sin(theta) n = vee(skew part); cos(theta) = (trace - 1) / 2. atan2 of the two is accurate
  // everywhere except for the axis near pi, where the skew part vanishes.
  const Vec3 s_n = vee(R);
  const double sin_theta = s_n.norm();
  const double cos_theta = 0.5 * (R.trace() - 1.0);
  const double theta = std::atan2(sin_theta, cos_theta);
  if (cos_theta > -0.9) {
    // theta / sin(theta) with its series near zero.
    const double factor = sin_theta < 1e-8 ? 1.0 + theta * theta / 6.0 : theta / sin_theta;
    return factor * s_n;
  }
  // Near pi: R + R^T = 2 cos I + 2 (1 - cos) n n^T, so n n^T from the symmetric part; take the
  // largest diagonal entry's column for accuracy, and the sign of n from the skew part.
  const Mat3 B = 0.5 * (R + R.transpose()) - cos_theta * Mat3::Identity();
  Eigen::Index k;
  B.diagonal().maxCoeff(&k);
  Vec3 n = B.col(k) / std::sqrt(B(k, k));
  n.normalize();
  if (n.dot(s_n) < 0.0) n = -n;
  return theta * n;
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

Vec3 velocity_of_point(const Vec3& v_A, const Vec3& omega, const Vec3& r_AB) {
  return v_A + omega.cross(r_AB);
}

Vec3 acceleration_of_point(const Vec3& a_A, const Vec3& omega, const Vec3& alpha,
                           const Vec3& r_AB) {
  return a_A + alpha.cross(r_AB) + omega.cross(omega.cross(r_AB));
}

}  // namespace tumble
