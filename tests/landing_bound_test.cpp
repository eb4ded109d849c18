// The bound on how long a flying body stays clear of a plane (contact/landing_bound.hpp): exact
// for a falling sphere; for a turning box and a turning disk never later than the true first time
// (found by following their points exactly, a steady turn about a principal axis, on a fine grid
// of times) and not less than 0.4 of it (0.44 to 0.97 here), so that steps it bounds do not crawl.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "test_constants.hpp"
#include "tumble/contact/landing_bound.hpp"

namespace tumble {
namespace {

using test::kG;

PlaneContact floor_with(ContactSurface surface) {
  PlaneContact floor;
  floor.surface = std::move(surface);
  return floor;  // the plane z = 0, normal +z
}

TEST(LandingBound, AFallingSphereReachesTheDepthWhenItsParabolaDoes) {
  // Lowest point r below the centre: h - r - v t - g t^2 / 2 = -depth.
  ContactSurface ball;
  ball.kind = ContactSurface::Kind::Sphere;
  ball.radius = 0.1;
  const double h = 0.7, v = 1.5, depth = 1e-7;
  SurfaceMotion motion;
  motion.r_G_W = Vec3(0.3, -0.2, h);
  motion.v_G_W = Vec3(0.4, 0, -v);
  motion.omega_W = Vec3(3, -7, 20);  // turning moves no point of a sphere lower
  const double t = time_to_reach_depth(floor_with(ball), motion, kG, depth);
  const double c = h - ball.radius + depth;
  EXPECT_NEAR(t, (-v + std::sqrt(v * v + 2 * kG * c)) / kG, 1e-15);
  // Rising with no turning towards the plane: never.
  motion.v_G_W = Vec3(0, 0, 1);
  EXPECT_EQ(time_to_reach_depth(floor_with(ball), motion, 0.0, depth),
            std::numeric_limits<double>::infinity());
}

// The least height over `points_B` of a body at rest turning steadily at w about the world x axis
// from R0, at time t.
double lowest_height(const std::vector<Vec3>& points_B, const Vec3& r_G, const Mat3& R0, double w,
                     double t) {
  const Mat3 R = Eigen::AngleAxisd(w * t, Vec3::UnitX()).toRotationMatrix() * R0;
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec3& p : points_B) lowest = std::min(lowest, (r_G + R * p).z());
  return lowest;
}

// The first time on a grid of n steps up to t_end at which the lowest point is `depth` deep.
double first_time_at_depth(const std::vector<Vec3>& points_B, const Vec3& r_G, const Mat3& R0,
                           double w, double depth, double t_end, int n) {
  for (int k = 0; k <= n; ++k) {
    const double t = t_end * k / n;
    if (lowest_height(points_B, r_G, R0, w, t) <= -depth) return t;
  }
  return std::numeric_limits<double>::infinity();
}

TEST(LandingBound, ATurningBoxOrDiskNeverReachesTheDepthBeforeTheBound) {
  // No gravity; a steady turn about x (a principal axis of both). The turning bound is
  // (|alpha| + |omega|^2) r = w^2 r for the farthest point r, as the formulation gives it
  // (without its margin).
  const double depth = 1e-6;
  ContactSurface box;
  box.kind = ContactSurface::Kind::Polyhedron;
  for (const double x : {-0.2, 0.2})
    for (const double y : {-0.15, 0.15})
      for (const double z : {-0.1, 0.1}) box.vertices.emplace_back(x, y, z);
  ContactSurface disk;
  disk.kind = ContactSurface::Kind::Circle;
  disk.radius = 0.25;
  std::vector<Vec3> rim_B;
  for (int k = 0; k < 3600; ++k) {
    const double a = 2 * std::numbers::pi * k / 3600;
    rim_B.emplace_back(disk.radius * std::cos(a), disk.radius * std::sin(a), 0.0);
  }
  const Mat3 R0 = Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  for (const double w : {5.0, 30.0}) {
    for (const double above : {0.05, 0.001}) {
      SCOPED_TRACE(::testing::Message() << "w " << w << ", lowest point " << above << " m up");
      // The box, its COM placed so its lowest vertex is `above` the plane.
      const double box_reach = Vec3(0.2, 0.15, 0.1).norm();
      Vec3 r_G(0, 0, 0);
      r_G.z() = above - lowest_height(box.vertices, r_G, R0, w, 0.0);
      SurfaceMotion motion{r_G, R0, Vec3::Zero(), Vec3(w, 0, 0)};
      const double bound = time_to_reach_depth(floor_with(box), motion, w * w * box_reach, depth);
      ASSERT_GT(bound, 0.0);
      const double t_true =
          first_time_at_depth(box.vertices, r_G, R0, w, depth, 2 * std::numbers::pi / w, 200000);
      EXPECT_LE(bound, t_true);
      EXPECT_GE(bound, 0.4 * t_true);  // and not so early that it would crawl
      // The disk: its rim, `above` the plane at its lowest.
      r_G.z() = 0.0;
      r_G.z() = above - lowest_height(rim_B, r_G, R0, w, 0.0);
      motion.r_G_W = r_G;
      const double disk_bound =
          time_to_reach_depth(floor_with(disk), motion, w * w * disk.radius, depth);
      ASSERT_GT(disk_bound, 0.0);
      const double disk_true =
          first_time_at_depth(rim_B, r_G, R0, w, depth, 2 * std::numbers::pi / w, 20000);
      EXPECT_LE(disk_bound, disk_true);
      EXPECT_GE(disk_bound, 0.4 * disk_true);
    }
  }
}

}  // namespace
}  // namespace tumble
