#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_constants.hpp"
#include "tumble/math/rotation.hpp"

namespace tumble {
namespace {

using test::kPi;

Vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Vec3 v;
  do {
    v = Vec3(n(rng), n(rng), n(rng));
  } while (v.norm() < 1e-3);  // reject degenerate draws
  return v.normalized();
}

TEST(Rotation, HatVeeRoundTripAndCrossProduct) {
  const Vec3 a(0.3, -1.2, 2.5), b(-0.7, 0.4, 1.1);
  EXPECT_LT((hat(a) * b - a.cross(b)).norm(), 1e-15);
  EXPECT_LT((vee(hat(a)) - a).norm(), 1e-15);
  EXPECT_LT((hat(a) + hat(a).transpose()).norm(), 0.0 + 1e-300);
}

TEST(Rotation, RodriguesMatchesTheChapterFormulaAndIsARotation) {
  std::mt19937 rng(7);
  for (int i = 0; i < 200; ++i) {
    const Vec3 n = random_unit(rng);
    const double theta = std::uniform_real_distribution<double>(-kPi, kPi)(rng);
    const Mat3 R = rotation_from_axis_angle(n, theta);
    const Mat3 chapter = std::cos(theta) * Mat3::Identity() +
                         (1 - std::cos(theta)) * n * n.transpose() + std::sin(theta) * hat(n);
    EXPECT_LT((R - chapter).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_LT(orthonormality_error(R), 1e-15);
    EXPECT_NEAR(R.determinant(), 1.0, 1e-15);
    // The axis is fixed by the rotation.
    EXPECT_LT((R * n - n).norm(), 1e-15);
  }
}

TEST(Rotation, LogExpRoundTripsEverywhereIncludingNearZeroAndPi) {
  std::mt19937 rng(11);
  const double angles[] = {0.0, 1e-300, 1e-12,      1e-8,       1e-4,        0.3,
                           2.0, 3.0,    kPi - 1e-3, kPi - 1e-6, kPi - 1e-10, kPi};
  for (double theta : angles) {
    for (int i = 0; i < 50; ++i) {
      const Vec3 n = random_unit(rng);
      const Mat3 R = rotation_from_axis_angle(n, theta);
      const Vec3 phi = log_so3(R);
      // Round trip of the rotation to 1e-14 for every angle.
      EXPECT_LT((exp_so3(phi) - R).cwiseAbs().maxCoeff(), 1e-14) << "theta " << theta;
      EXPECT_NEAR(phi.norm(), theta, 1e-14 + 1e-15 * theta) << "theta " << theta;
      // Away from pi the rotation vector itself is recovered (at pi, -n is the same rotation).
      if (theta < kPi - 1e-6) {
        EXPECT_LT((phi - theta * n).norm(), 2e-14) << "theta " << theta;
      }
    }
  }
}

TEST(Rotation, ExactlyPiGivesTheAxisUpToSign) {
  const Vec3 n = Vec3(1.0, 2.0, -2.0) / 3.0;
  const Vec3 phi = log_so3(rotation_from_axis_angle(n, kPi));
  EXPECT_NEAR(phi.norm(), kPi, 1e-14);
  EXPECT_NEAR(std::abs(phi.normalized().dot(n)), 1.0, 1e-14);
}

TEST(Rotation, QuaternionRoundTrip) {
  std::mt19937 rng(3);
  for (int i = 0; i < 500; ++i) {
    const Vec3 n = random_unit(rng);
    const double theta = std::uniform_real_distribution<double>(0.0, kPi)(rng);
    const Mat3 R = rotation_from_axis_angle(n, theta);
    const Quat q = quaternion_from_rotation(R);
    EXPECT_GE(q.w(), 0.0);
    EXPECT_NEAR(q.norm(), 1.0, 1e-15);
    EXPECT_LT((rotation_from_quaternion(q) - R).cwiseAbs().maxCoeff(), 1e-14);
    // q = (cos(theta/2), sin(theta/2) n)
    EXPECT_NEAR(q.w(), std::cos(theta / 2), 1e-14);
    EXPECT_LT((q.vec() - std::sin(theta / 2) * n).norm(), 1e-14);
  }
}

TEST(Rotation, NearestRotationRestoresOrthonormality) {
  const Mat3 R = rotation_from_axis_angle(Vec3(1, 1, 0), 0.7);
  Mat3 drifted = R;
  drifted(0, 1) += 1e-6;
  drifted(2, 2) -= 3e-7;
  EXPECT_GT(orthonormality_error(drifted), 1e-7);
  const Mat3 fixed = nearest_rotation(drifted);
  EXPECT_LT(orthonormality_error(fixed), 1e-15);
  EXPECT_NEAR(fixed.determinant(), 1.0, 1e-15);
  EXPECT_LT((fixed - R).cwiseAbs().maxCoeff(), 2e-6);
}

TEST(Rotation, PointVelocityAndAccelerationMatchFiniteDifferences) {
  // A body spinning about a moving, tilting axis: differentiate the world position of a body
  // point numerically and compare with the chapter's transfer formulas.
  const Vec3 r_AB_body(0.4, -0.2, 0.9);
  auto omega_of = [](double t) { return Vec3(0.3 * t, 1.0 + 0.1 * t * t, -0.5); };
  // R(t) integrated to high accuracy with small exact-exponential steps.
  auto R_of = [&](double t) {
    Mat3 R = Mat3::Identity();
    const int n = 4000;
    const double h = t / n;
    for (int i = 0; i < n; ++i) R = exp_so3(omega_of((i + 0.5) * h) * h) * R;
    return R;
  };
  auto r_A = [](double t) { return Vec3(t, 0.5 * t * t, std::sin(t)); };
  auto r_B = [&](double t) { return Vec3(r_A(t) + R_of(t) * r_AB_body); };
  const double t = 0.8, d = 1e-4;
  const Vec3 vB_fd = (r_B(t + d) - r_B(t - d)) / (2 * d);
  const Vec3 aB_fd = (r_B(t + d) - 2 * r_B(t) + r_B(t - d)) / (d * d);
  const Vec3 r_AB = R_of(t) * r_AB_body;
  const Vec3 v_A(1.0, t, std::cos(t)), a_A(0.0, 1.0, -std::sin(t));
  const Vec3 alpha(0.3, 0.2 * t, 0.0);
  // Midpoint exponential products are second-order accurate in h = t/4000: error ~1e-8; the
  // central differences add ~d^2 = 1e-8 and round-off ~eps/d^2 = 2e-8 for the acceleration.
  EXPECT_LT((velocity_of_point(v_A, omega_of(t), r_AB) - vB_fd).norm(), 1e-6);
  EXPECT_LT((acceleration_of_point(a_A, omega_of(t), alpha, r_AB) - aB_fd).norm(), 1e-4);
}

}  // namespace
}  // namespace tumble
