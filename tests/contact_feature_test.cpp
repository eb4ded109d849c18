// The touching feature of a polyhedron on a plane: its polygon, its torsional friction radius,
// and where its centre of pressure stands.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tumble/contact/contact_feature.hpp"

namespace tumble {
namespace {

const Vec3 kUp = Vec3::UnitZ();

// The bottom corners of a cube of side 2 at the origin, then its top ones.
std::vector<Vec3> cube_corners() {
  std::vector<Vec3> v;
  for (const double z : {-1.0, 1.0}) {
    for (const double y : {-1.0, 1.0}) {
      for (const double x : {-1.0, 1.0}) v.emplace_back(x, y, z);
    }
  }
  return v;
}

TEST(ContactFeature, AFaceIsItsCornersPolygonWithTheMeanDistanceAsSpinRadius) {
  const std::vector<Vec3> v = cube_corners();
  ContactFeature f;
  reserve_feature(f, v.size());
  const std::vector<int> bottom = {0, 1, 2, 3};
  make_feature(v, bottom, kUp, f);  // the plane's normal into the body: +z from the bottom face
  ASSERT_EQ(f.size(), 4);
  EXPECT_EQ(f.normal_point_count, 3);
  EXPECT_LT((f.reference_B - Vec3(0, 0, -1)).norm(), 1e-15);
  // Mean distance from the centre of a square of half-side 1: (sqrt 2 + asinh 1) / 3.
  EXPECT_NEAR(f.spin_radius, (std::sqrt(2.0) + std::asinh(1.0)) / 3.0, 1e-15);
  // Counter-clockwise about the normal: every inward normal points at the centre.
  for (int j = 0; j < 4; ++j) {
    const Vec3& a = v[static_cast<std::size_t>(f.polygon[static_cast<std::size_t>(j)])];
    EXPECT_GT(f.inward_B[static_cast<std::size_t>(j)].dot(f.reference_B - a), 0.0);
  }
}

TEST(ContactFeature, CollinearPointsAreAnEdgeAndOnePointAVertex) {
  std::vector<Vec3> v = {{-1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {1, 0, 1e-13}};
  ContactFeature f;
  reserve_feature(f, v.size());
  const std::vector<int> line = {0, 1, 2, 3};
  make_feature(v, line, kUp, f);
  ASSERT_EQ(f.size(), 2);
  EXPECT_NEAR(f.spin_radius, 0.5, 1e-15);  // L / 4 for L = 2
  const std::vector<int> one = {1};
  make_feature(v, one, kUp, f);
  ASSERT_EQ(f.size(), 1);
  EXPECT_EQ(f.spin_radius, 0.0);
}

TEST(ContactFeature, TheSupportMarginIsNTimesTheCentreOfPressuresDistanceInside) {
  const std::vector<Vec3> v = cube_corners();
  ContactFeature f;
  reserve_feature(f, v.size());
  const std::vector<int> bottom = {0, 1, 2, 3};
  make_feature(v, bottom, kUp, f);
  // N = 10 at (0.25, 0, -1): the moment about the centre is r x F = (0.25, 0, 0) x (0, 0, 10).
  const double N = 10.0;
  const Vec3 M = Vec3(0.25, 0, 0).cross(Vec3(0, 0, N));
  int side = -1;
  EXPECT_NEAR(support_margin(f, v, kUp, N, M, side), N * 0.75, 1e-14);  // nearest side: x = 1
  const Vec3& a = v[static_cast<std::size_t>(f.polygon[static_cast<std::size_t>(side)])];
  EXPECT_EQ(a.x(), 1.0);
  // Past the side x = 1 it is negative, and tipping there leaves that side's edge.
  const Vec3 M_out = Vec3(1.5, 0, 0).cross(Vec3(0, 0, N));
  EXPECT_NEAR(support_margin(f, v, kUp, N, M_out, side), -N * 0.5, 1e-14);
  tip_onto_side(v, side, kUp, f);
  ASSERT_EQ(f.size(), 2);
  for (const int i : f.polygon) EXPECT_EQ(v[static_cast<std::size_t>(i)].x(), 1.0);
}

}  // namespace
}  // namespace tumble
