// Mass properties of the chapter's section 6.7.2: the closed-form table, the parallel axis
// theorem, rotated parts, principal axes, the physical-validity checks and the planar forms.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "expect_throw.hpp"
#include "test_constants.hpp"
#include "test_math.hpp"
#include "tumble/inertia/mass_properties.hpp"
#include "tumble/inertia/planar.hpp"
#include "tumble/inertia/shapes.hpp"
#include "tumble/math/rotation.hpp"

namespace tumble {
namespace {

using test::kPi;

Shape make_shape(ShapeKind kind) {
  Shape s;
  s.kind = kind;
  return s;
}
Shape rod(double length) {
  Shape s = make_shape(ShapeKind::Rod);
  s.length = length;
  return s;
}
Shape with_radius(ShapeKind kind, double radius) {
  Shape s = make_shape(kind);
  s.radius = radius;
  return s;
}
Shape cylinder(double radius, double length) {
  Shape s = with_radius(ShapeKind::Cylinder, radius);
  s.length = length;
  return s;
}
Shape tube(double inner, double outer, double length) {
  Shape s = make_shape(ShapeKind::Tube);
  s.inner_radius = inner;
  s.outer_radius = outer;
  s.length = length;
  return s;
}
Shape box(double a, double b, double c) {
  Shape s = make_shape(ShapeKind::Box);
  s.size = Vec3(a, b, c);
  return s;
}
Shape cone(double radius, double height) {
  Shape s = with_radius(ShapeKind::Cone, radius);
  s.height = height;
  return s;
}
Shape plate(double a, double b) {
  Shape s = make_shape(ShapeKind::Plate);
  s.size = Vec3(a, b, 0.0);
  return s;
}

using test::max_abs;

using test::expect_throw_containing;

Vec3 random_vector(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return Vec3(u(rng), u(rng), u(rng));
}

// ---- Names and measures ------------------------------------------------------------------------

TEST(ShapeNames, EveryKindRoundTripsAndUnknownNamesAreRefused) {
  const std::array<const char*, 12> names = {"point",  "rod",   "ring", "disk", "cylinder", "tube",
                                             "sphere", "shell", "box",  "cone", "plate",    "mesh"};
  for (const char* name : names) {
    const auto kind = shape_kind_from_name(name);
    ASSERT_TRUE(kind.has_value()) << name;
    EXPECT_EQ(shape_name(*kind), name);
  }
  EXPECT_FALSE(shape_kind_from_name("cube").has_value());
  EXPECT_FALSE(shape_kind_from_name("Box").has_value());  // names are lower case, as in YAML
  EXPECT_FALSE(shape_kind_from_name("").has_value());
}

// The measures follow from each other by geometry, not only from their formulas: a tube is the
// difference of two cylinders, a cone a third of its cylinder, a shell's area the derivative of
// the sphere's volume and a ring's length the derivative of the disk's area. Round-off only:
// 1e-15 relative.
TEST(ShapeMeasure, VolumesAreasAndLengthsAgreeWithGeometry) {
  for (const double R : {0.1, 0.75, 3.0}) {
    for (const double L : {0.2, 1.0, 5.5}) {
      const double cylinder_volume = shape_measure(cylinder(R, L));
      EXPECT_NEAR(cylinder_volume, kPi * R * R * L, 1e-15 * cylinder_volume);
      EXPECT_NEAR(shape_measure(tube(R / 3, R, L)),
                  cylinder_volume - shape_measure(cylinder(R / 3, L)), 1e-15 * cylinder_volume);
      EXPECT_NEAR(shape_measure(cone(R, L)), cylinder_volume / 3, 1e-15 * cylinder_volume);
      EXPECT_NEAR(shape_measure(rod(L)), L, 0.0);
    }
    const double sphere_volume = shape_measure(with_radius(ShapeKind::Sphere, R));
    EXPECT_NEAR(sphere_volume, 4.0 / 3.0 * kPi * R * R * R, 1e-15 * sphere_volume);
    // dV/dR = 4 pi R^2 (shell area), dA/dR = 2 pi R (ring length).
    EXPECT_NEAR(shape_measure(with_radius(ShapeKind::Shell, R)), 3 * sphere_volume / R,
                1e-15 * sphere_volume / R);
    const double disk_area = shape_measure(with_radius(ShapeKind::Disk, R));
    EXPECT_NEAR(disk_area, kPi * R * R, 1e-15 * disk_area);
    EXPECT_NEAR(shape_measure(with_radius(ShapeKind::Ring, R)), 2 * disk_area / R,
                1e-15 * disk_area / R);
  }
  EXPECT_EQ(shape_measure(box(4, 1, 2)), 8.0);
  EXPECT_EQ(shape_measure(plate(4, 0.5)), 2.0);
  EXPECT_EQ(shape_measure(make_shape(ShapeKind::Point)), 0.0);
}

// ---- Closed forms ------------------------------------------------------------------------------

// The table of section 6.7.2, transcribed independently of the implementation. Each case is
// checked at several masses and dimensions (not one tuned case). The closed forms are a few
// flops each: 1e-15 relative to the largest moment is round-off.
TEST(ClosedForms, EveryShapeMatchesTheChaptersTable) {
  struct Case {
    Shape shape;
    Vec3 moments_per_mass;  // (I_xx, I_yy, I_zz) / M
  };
  std::vector<Case> cases;
  for (const double R : {0.05, 0.4, 2.0}) {
    for (const double L : {0.1, 1.3, 7.0}) {
      cases.push_back({rod(L), Vec3(0, L * L / 12, L * L / 12)});
      cases.push_back(
          {cylinder(R, L), Vec3((3 * R * R + L * L) / 12, (3 * R * R + L * L) / 12, R * R / 2)});
      const double a = 0.6 * R;
      const double transverse = (3 * (a * a + R * R) + L * L) / 12;
      cases.push_back({tube(a, R, L), Vec3(transverse, transverse, (a * a + R * R) / 2)});
      const double cone_transverse = 3 * R * R / 20 + 3 * L * L / 80;
      cases.push_back({cone(R, L), Vec3(cone_transverse, cone_transverse, 3 * R * R / 10)});
      cases.push_back(
          {box(R, L, 0.3), Vec3((L * L + 0.09) / 12, (R * R + 0.09) / 12, (R * R + L * L) / 12)});
      cases.push_back({plate(R, L), Vec3(L * L / 12, R * R / 12, (R * R + L * L) / 12)});
    }
    cases.push_back({with_radius(ShapeKind::Ring, R), Vec3(R * R / 2, R * R / 2, R * R)});
    cases.push_back({with_radius(ShapeKind::Disk, R), Vec3(R * R / 4, R * R / 4, R * R / 2)});
    cases.push_back({with_radius(ShapeKind::Sphere, R), Vec3::Constant(2 * R * R / 5)});
    cases.push_back({with_radius(ShapeKind::Shell, R), Vec3::Constant(2 * R * R / 3)});
  }
  cases.push_back({make_shape(ShapeKind::Point), Vec3::Zero()});

  for (const double M : {0.5, 1.0, 12.0}) {
    for (const Case& c : cases) {
      const MassProperties mp = shape_mass_properties(c.shape, M);
      const Mat3 expected = (M * c.moments_per_mass).asDiagonal();
      EXPECT_EQ(mp.mass, M);
      EXPECT_EQ(mp.com, Vec3::Zero()) << "the shape's frame is at its COM";
      EXPECT_LE(max_abs(mp.inertia_about_com - expected), 1e-15 * max_abs(expected))
          << shape_name(c.shape.kind) << " M = " << M << "\n"
          << mp.inertia_about_com;
    }
  }
}

// The chapter's own example numbers: the prism a x b x c = 4 x 1 x 2 with M = 12 has
// I_0 = diag(5, 20, 17).
TEST(ClosedForms, ChaptersPrismIsDiag5_20_17) {
  const MassProperties prism = shape_mass_properties(box(4, 1, 2), 12.0);
  EXPECT_LE(max_abs(prism.inertia_about_com - Vec3(5, 20, 17).asDiagonal().toDenseMatrix()), 1e-14);
}

TEST(ClosedForms, ImpossibleDimensionsAndMassesAreNamed) {
  expect_throw_containing<InertiaError>([] { shape_mass_properties(tube(0.3, 0.2, 1.0), 1.0); },
                                        "tube inner_radius 0.3 must be less than outer_radius 0.2");
  expect_throw_containing<InertiaError>([] { shape_mass_properties(tube(0.2, 0.2, 1.0), 1.0); },
                                        "tube inner_radius 0.2 must be less than outer_radius 0.2");
  expect_throw_containing<InertiaError>([] { shape_mass_properties(box(1, 1, 1), -1.0); },
                                        "mass must be > 0, got -1");
  expect_throw_containing<InertiaError>([] { shape_mass_properties(box(1, 1, 1), 0.0); },
                                        "mass must be > 0, got 0");
  expect_throw_containing<InertiaError>([] { shape_mass_properties(cylinder(-1, 2), 1.0); },
                                        "cylinder radius must be > 0, got -1");
  expect_throw_containing<InertiaError>([] { shape_mass_properties(cylinder(1, 0), 1.0); },
                                        "cylinder length must be > 0, got 0");
  expect_throw_containing<InertiaError>([] { shape_mass_properties(box(1, 0, 1), 1.0); },
                                        "box size[1] (b, along y) must be > 0, got 0");
  expect_throw_containing<InertiaError>([] { shape_mass_properties(cone(1, std::nan("")), 1.0); },
                                        "cone height must be > 0, got nan");
  expect_throw_containing<InertiaError>([] { shape_mass_properties(rod(-0.5), 1.0); },
                                        "rod length must be > 0, got -0.5");
  expect_throw_containing<InertiaError>(
      [] { shape_mass_properties(with_radius(ShapeKind::Shell, 0), 1.0); },
      "shell radius must be > 0, got 0");
  expect_throw_containing<InertiaError>(
      [] {
        Shape slab = plate(1, 2);
        slab.size.z() = 0.1;
        shape_mass_properties(slab, 1.0);
      },
      "plate size[2] must be 0");
  expect_throw_containing<InertiaError>(
      [] { shape_mass_properties(make_shape(ShapeKind::Mesh), 1.0); }, "mesh needs a file");
  // The measure checks the same dimensions.
  expect_throw_containing<InertiaError>([] { shape_measure(with_radius(ShapeKind::Sphere, -2)); },
                                        "sphere radius must be > 0, got -2");
}

// ---- Thin limits -------------------------------------------------------------------------------

// A tube of mean radius R and wall t (a = R - t/2, b = R + t/2) has a^2 + b^2 = 2 R^2 + t^2 / 2,
// so it differs from the thin-walled tube (I_zz = M R^2, I_xx = M (6 R^2 + L^2) / 12) by exactly
// M t^2 / 4 and M t^2 / 8: the error vanishes quadratically with the wall. Round-off: 1e-15 of
// the moments.
TEST(ThinLimits, TubeApproachesTheThinWalledTubeAsTheWallThins) {
  const double M = 3.0, R = 0.5, L = 2.0;
  for (const double t : {0.1, 0.01, 0.001}) {
    const Mat3 I = shape_mass_properties(tube(R - t / 2, R + t / 2, L), M).inertia_about_com;
    EXPECT_NEAR(I(2, 2) - M * R * R, M * t * t / 4, 1e-15 * M * R * R) << "t = " << t;
    EXPECT_NEAR(I(0, 0) - M * (6 * R * R + L * L) / 12, M * t * t / 8,
                1e-15 * M * (6 * R * R + L * L) / 12)
        << "t = " << t;
  }
}

// A cylinder is a stack of disks: same I_zz at any length, and I_xx / M -> R^2 / 4 (the thin
// disk) with the difference L^2 / 12 per unit mass. Likewise a box with c -> 0 tends to the
// plate, differing by M c^2 / 12 about x and y.
TEST(ThinLimits, ShortCylinderTendsToTheDiskAndThinBoxToThePlate) {
  const double M = 2.0, R = 0.8;
  const Mat3 disk = shape_mass_properties(with_radius(ShapeKind::Disk, R), M).inertia_about_com;
  for (const double L : {0.1, 1e-3, 1e-6}) {
    const Mat3 cyl = shape_mass_properties(cylinder(R, L), M).inertia_about_com;
    EXPECT_NEAR(cyl(2, 2), disk(2, 2), 1e-15 * disk(2, 2));
    EXPECT_NEAR(cyl(0, 0) / M - disk(0, 0) / M, L * L / 12, 1e-15 * R * R);
    EXPECT_NEAR(cyl(1, 1) / M - disk(1, 1) / M, L * L / 12, 1e-15 * R * R);
  }
  const Mat3 lamina = shape_mass_properties(plate(0.7, 1.9), M).inertia_about_com;
  for (const double c : {0.1, 1e-3, 1e-6}) {
    const Mat3 slab = shape_mass_properties(box(0.7, 1.9, c), M).inertia_about_com;
    EXPECT_NEAR(slab(0, 0) - lamina(0, 0), M * c * c / 12, 1e-15 * lamina(2, 2));
    EXPECT_NEAR(slab(1, 1) - lamina(1, 1), M * c * c / 12, 1e-15 * lamina(2, 2));
    EXPECT_NEAR(slab(2, 2), lamina(2, 2), 1e-15 * lamina(2, 2));
  }
}

// ---- Composites: the parallel axis theorem -----------------------------------------------------

// Chapter example 6 (Cubli): four rods of mass M/4 and length L on the sides of a square. Rods
// along x sit at y = +-L/2; rods along y are rods along x turned 90 degrees about z and sit at
// x = +-L/2. About the centre: I_zz = M L^2 / 3 and, by symmetry and the planar identity
// I_zz = I_xx + I_yy, I_xx = I_yy = M L^2 / 6. About the corner pivot O, L / sqrt(2) away,
// I_O = M L^2 / 3 + M L^2 / 2. Tolerance: the 90 degree turn has cos = 6e-17, so entries carry
// ~1e-16 M L^2 of round-off; 1e-14 M L^2 is generous.
TEST(Composite, SquareFrameOfFourRodsIsML2Over3AboutTheCentre) {
  for (const double M : {1.0, 2.5}) {
    for (const double L : {0.2, 1.0, 3.0}) {
      const MassProperties one_rod = shape_mass_properties(rod(L), M / 4);
      const Mat3 turned = rotation_from_axis_angle(Vec3::UnitZ(), kPi / 2);
      const std::vector<MassProperties> sides = {
          express_in_parent(one_rod, Mat3::Identity(), Vec3(0, L / 2, 0)),
          express_in_parent(one_rod, Mat3::Identity(), Vec3(0, -L / 2, 0)),
          express_in_parent(one_rod, turned, Vec3(L / 2, 0, 0)),
          express_in_parent(one_rod, turned, Vec3(-L / 2, 0, 0)),
      };
      const MassProperties frame = combine(sides);
      const double tol = 1e-14 * M * L * L;
      EXPECT_NEAR(frame.mass, M, 1e-15 * M);
      EXPECT_LE(frame.com.norm(), 1e-15 * L);
      const Mat3 expected = Vec3(M * L * L / 6, M * L * L / 6, M * L * L / 3).asDiagonal();
      EXPECT_LE(max_abs(frame.inertia_about_com - expected), tol) << frame.inertia_about_com;
      EXPECT_NEAR(planar::square_frame_about_center(M, L), frame.inertia_about_com(2, 2), tol);

      const Mat3 about_corner = inertia_about_point(frame, Vec3(-L / 2, -L / 2, 0));
      EXPECT_NEAR(about_corner(2, 2), M * L * L / 3 + M * L * L / 2, tol);
      // A planar lamina sits exactly on the triangle-inequality boundary: accepted.
      EXPECT_NO_THROW(validate_inertia(frame.inertia_about_com));
    }
  }
}

// Two point masses m1, m2 a distance d apart: the COM divides d in the ratio m2 : m1 and the
// inertia about it is that of the reduced mass mu = m1 m2 / (m1 + m2) at distance d,
// I = mu (|d|^2 1 - d d^T). Round-off of a few flops on |d|^2 ~ 10: 1e-14 of mu |d|^2.
TEST(Composite, TwoPointMassesGiveTheReducedMassInertia) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 20; ++trial) {
    const double m1 = 0.5 + trial * 0.1, m2 = 3.0 - trial * 0.05;
    const Vec3 p1 = random_vector(rng, 2.0), p2 = random_vector(rng, 2.0);
    MassProperties a, b;
    a.mass = m1;
    a.com = p1;
    b.mass = m2;
    b.com = p2;
    const std::vector<MassProperties> parts = {a, b};
    const MassProperties both = combine(parts);
    const Vec3 d = p2 - p1;
    const double mu = m1 * m2 / (m1 + m2);
    EXPECT_LE((both.com - (p1 + m2 / (m1 + m2) * d)).norm(), 1e-15 * 4);
    const Mat3 expected = mu * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
    EXPECT_LE(max_abs(both.inertia_about_com - expected), 1e-14 * mu * d.squaredNorm());
  }
}

// Direct integration over a discrete body: I_O = sum m_i (|r_i - O|^2 1 - (r_i - O)(r_i - O)^T)
// must equal combine() followed by inertia_about_point(O). Sums of 50 terms of size ~ 10: 1e-13
// of the total.
TEST(Composite, ParallelAxisAboutAnyPointMatchesTheDirectSum) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> mass(0.1, 2.0);
  std::vector<MassProperties> points(50);
  for (MassProperties& p : points) {
    p.mass = mass(rng);
    p.com = random_vector(rng, 1.5);
  }
  const MassProperties body = combine(points);
  for (int trial = 0; trial < 10; ++trial) {
    const Vec3 O = random_vector(rng, 3.0);
    Mat3 direct = Mat3::Zero();
    for (const MassProperties& p : points) {
      const Vec3 r = p.com - O;
      direct += p.mass * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
    }
    EXPECT_LE(max_abs(inertia_about_point(body, O) - direct), 1e-13 * max_abs(direct));
  }
  // About its own COM the parallel-axis term vanishes.
  EXPECT_LE(max_abs(inertia_about_point(body, body.com) - body.inertia_about_com), 0.0);
}

// Cutting a box into its 8 octant boxes (a/2 x b/2 x c/2, mass M/8, centres at +-a/4, +-b/4,
// +-c/4) and putting it back by the parallel axis theorem gives the whole box: I_xx =
// 8 [M/8 (b^2 + c^2)/48 + M/8 (b^2 + c^2)/16] = M (b^2 + c^2)/12. Placed off the origin to
// exercise the offsets; round-off of 8-term sums: 1e-14 relative.
TEST(Composite, EightOctantBoxesMakeTheWholeBox) {
  for (const Vec3& size : {Vec3(1, 1, 1), Vec3(4, 1, 2), Vec3(0.3, 2.2, 0.05)}) {
    const double M = 12.0;
    const Vec3 centre(3.0, -2.0, 5.0);
    const MassProperties octant =
        shape_mass_properties(box(size.x() / 2, size.y() / 2, size.z() / 2), M / 8);
    std::vector<MassProperties> octants;
    for (int k = 0; k < 8; ++k) {
      const Vec3 sign((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1);
      octants.push_back(
          express_in_parent(octant, Mat3::Identity(), centre + sign.cwiseProduct(size / 4)));
    }
    const MassProperties whole = combine(octants);
    const Mat3 expected =
        shape_mass_properties(box(size.x(), size.y(), size.z()), M).inertia_about_com;
    EXPECT_NEAR(whole.mass, M, 1e-15 * M);
    EXPECT_LE((whole.com - centre).norm(), 1e-15 * 10);
    EXPECT_LE(max_abs(whole.inertia_about_com - expected), 1e-14 * max_abs(expected));
  }
}

TEST(Composite, EmptyOrMasslessPartsAreRefused) {
  expect_throw_containing<InertiaError>([] { combine(std::vector<MassProperties>{}); },
                                        "cannot combine an empty list of parts");
  expect_throw_containing<InertiaError>([] { combine(std::vector<MassProperties>(2)); },
                                        "total mass of the parts must be > 0, got 0");
  MassProperties negative;
  negative.mass = -1.0;
  expect_throw_containing<InertiaError>([&] { combine(std::vector<MassProperties>{negative}); },
                                        "part mass must be >= 0, got -1");
}

// ---- Rotated parts -----------------------------------------------------------------------------

// Turning the chapter's prism (4 x 1 x 2, diag(5, 20, 17)) a quarter turn about z puts its long
// side along y: I_xx and I_yy swap. About x it swaps I_yy and I_zz. Round-off from cos(pi/2):
// 1e-14 of the largest moment.
TEST(RotatedPart, QuarterTurnsSwapTheMoments) {
  const MassProperties prism = shape_mass_properties(box(4, 1, 2), 12.0);
  const Vec3 p(1, 2, 3);
  const MassProperties about_z =
      express_in_parent(prism, rotation_from_axis_angle(Vec3::UnitZ(), kPi / 2), p);
  EXPECT_LE(max_abs(about_z.inertia_about_com - Vec3(20, 5, 17).asDiagonal().toDenseMatrix()),
            1e-14 * 20);
  EXPECT_EQ(about_z.com, p);
  const MassProperties about_x =
      express_in_parent(prism, rotation_from_axis_angle(Vec3::UnitX(), kPi / 2), p);
  EXPECT_LE(max_abs(about_x.inertia_about_com - Vec3(5, 17, 20).asDiagonal().toDenseMatrix()),
            1e-14 * 20);
}

// Random rotations and offsets: the tensor becomes R I R^T (symmetric, same trace and principal
// moments: rotation changes axes, not the body), and an off-centre COM moves as a point,
// p + R c. Round-off of 3x3 products: 1e-14 relative.
TEST(RotatedPart, ExpressInParentRotatesTheTensorAndMovesTheCOM) {
  std::mt19937 rng(5);
  MassProperties part = shape_mass_properties(cone(0.4, 1.5), 2.0);
  part.com = Vec3(0.1, -0.2, 0.3);  // a part frame whose origin is not at the COM
  for (int trial = 0; trial < 50; ++trial) {
    const Mat3 R = exp_so3(random_vector(rng, kPi));
    const Vec3 p = random_vector(rng, 5.0);
    const MassProperties moved = express_in_parent(part, R, p);
    const double scale = max_abs(part.inertia_about_com);
    EXPECT_EQ(moved.mass, part.mass);
    EXPECT_LE((moved.com - (p + R * part.com)).norm(), 1e-14 * 5);
    EXPECT_LE(max_abs(moved.inertia_about_com - R * part.inertia_about_com * R.transpose()),
              1e-14 * scale);
    EXPECT_LE(max_abs(moved.inertia_about_com - moved.inertia_about_com.transpose()),
              1e-14 * scale);
    EXPECT_NEAR(moved.inertia_about_com.trace(), part.inertia_about_com.trace(), 1e-14 * scale);
    EXPECT_LE((principal_axes(moved.inertia_about_com).moments -
               principal_axes(part.inertia_about_com).moments)
                  .cwiseAbs()
                  .maxCoeff(),
              1e-14 * scale);
  }
}

// ---- Principal axes ----------------------------------------------------------------------------

// I = R diag(m) R^T for random moments (a valid body: triangle inequality holds) and random R.
// principal_axes must return m ascending, a proper rotation, and axes along R's columns (up to
// sign). Draws whose moments are closer than 1e-2 are rejected: there the axes are ill-defined
// (the eigenvector error is ~ eps |I| / gap). Tolerances: moments to 1e-13 of |I|; axes to
// eps |I| / gap ~ 1e-16 * 5 / 1e-2 = 5e-14, checked at 1e-11.
TEST(PrincipalAxes, RecoverTheMomentsAndAProperRotationFromRandomTensors) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> moment(0.5, 5.0);
  int accepted = 0;
  while (accepted < 200) {
    std::array<double, 3> m = {moment(rng), moment(rng), moment(rng)};
    std::sort(m.begin(), m.end());
    if (m[1] - m[0] < 1e-2 || m[2] - m[1] < 1e-2 || m[2] > m[0] + m[1]) continue;
    ++accepted;
    const Mat3 R = exp_so3(random_vector(rng, kPi));
    const Vec3 moments(m[0], m[1], m[2]);
    const Mat3 I = R * moments.asDiagonal() * R.transpose();

    const PrincipalAxes pa = principal_axes(I);
    EXPECT_LE((pa.moments - moments).cwiseAbs().maxCoeff(), 1e-13 * m[2]);
    EXPECT_NEAR(pa.axes.determinant(), 1.0, 1e-14);
    EXPECT_LE(max_abs(pa.axes.transpose() * pa.axes - Mat3::Identity()), 1e-14);
    EXPECT_LE(max_abs(pa.axes * pa.moments.asDiagonal() * pa.axes.transpose() - I), 1e-13 * m[2]);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(std::abs(pa.axes.col(k).dot(R.col(k))), 1.0, 1e-11);
    }
  }
}

// Equal moments (sphere: all three; cylinder: two) leave the axes free, but they must still form
// a proper rotation that reproduces the tensor.
TEST(PrincipalAxes, RepeatedMomentsStillGiveAProperRotation) {
  std::mt19937 rng(9);
  for (const Shape& s : {with_radius(ShapeKind::Sphere, 1.0), cylinder(0.5, 3.0)}) {
    const Mat3 R = exp_so3(random_vector(rng, kPi));
    const Mat3 I = R * shape_mass_properties(s, 2.0).inertia_about_com * R.transpose();
    const PrincipalAxes pa = principal_axes(I);
    EXPECT_NEAR(pa.axes.determinant(), 1.0, 1e-14);
    EXPECT_LE(max_abs(pa.axes * pa.moments.asDiagonal() * pa.axes.transpose() - I),
              1e-14 * max_abs(I));
    EXPECT_LE(pa.moments(0), pa.moments(1));
    EXPECT_LE(pa.moments(1), pa.moments(2));
  }
}

// ---- Validity of an inertia tensor -------------------------------------------------------------

TEST(ValidateInertia, EachFailureSaysWhatAndByHowMuch) {
  Mat3 not_symmetric = Vec3(4, 4, 4).asDiagonal();
  not_symmetric(0, 1) = 1.0;
  not_symmetric(1, 0) = 0.5;
  expect_throw_containing<InertiaError>(
      [&] { validate_inertia(not_symmetric); },
      "inertia is not symmetric: I_xy = 1 but I_yx = 0.5 (differ by 0.5)");

  expect_throw_containing<InertiaError>(
      [] { validate_inertia(Vec3(-2, 3, 4).asDiagonal().toDenseMatrix()); },
      "inertia is not positive definite: smallest principal moment is -2");
  expect_throw_containing<InertiaError>([] { validate_inertia(Mat3::Zero()); },
                                        "smallest principal moment is 0");

  expect_throw_containing<InertiaError>(
      [] { validate_inertia(Vec3(1, 1, 3).asDiagonal().toDenseMatrix()); },
      "principal moments 1, 1, 3 break the triangle inequality: 3 > 1 + 1 by 1");
  // The same failure seen through rotated axes is still found (it is about principal moments).
  const Mat3 R = rotation_from_axis_angle(Vec3(1, 2, 3), 0.7);
  expect_throw_containing<InertiaError>(
      [&] { validate_inertia(R * Vec3(1, 1, 3).asDiagonal() * R.transpose()); },
      "break the triangle inequality");

  Mat3 not_finite = Mat3::Identity();
  not_finite(1, 2) = std::nan("");
  expect_throw_containing<InertiaError>([&] { validate_inertia(not_finite); },
                                        "inertia has a non-finite entry: I_yz = nan");

  // A slender rod alone has a zero moment about its axis: not a valid body inertia.
  expect_throw_containing<InertiaError>(
      [] { validate_inertia(shape_mass_properties(rod(1.0), 1.0).inertia_about_com); },
      "smallest principal moment is 0");
}

// Laminae and curves in a plane satisfy I_zz = I_xx + I_yy exactly: they lie on the boundary of
// the triangle inequality and must pass, also after an arbitrary rotation (which adds ~1e-16
// relative round-off, far inside the 1e-9 tolerance). Every solid passes with margin.
TEST(ValidateInertia, BoundaryShapesAndAllSolidsAreAccepted) {
  std::mt19937 rng(17);
  const std::vector<Shape> shapes = {plate(0.3, 2.0),
                                     with_radius(ShapeKind::Disk, 0.7),
                                     with_radius(ShapeKind::Ring, 1.3),
                                     cylinder(0.01, 100.0),
                                     cylinder(10.0, 0.001),
                                     tube(0.99, 1.0, 0.01),
                                     with_radius(ShapeKind::Sphere, 0.2),
                                     with_radius(ShapeKind::Shell, 0.2),
                                     box(4, 1, 2),
                                     box(1e-3, 1, 1),
                                     cone(0.5, 3.0)};
  for (const Shape& s : shapes) {
    const Mat3 I = shape_mass_properties(s, 1.7).inertia_about_com;
    EXPECT_NO_THROW(validate_inertia(I)) << shape_name(s.kind);
    const Mat3 R = exp_so3(random_vector(rng, kPi));
    EXPECT_NO_THROW(validate_inertia(R * I * R.transpose())) << shape_name(s.kind) << " rotated";
  }
}

// The tolerance is relative to the largest moment: 1e-12 past the boundary is round-off and
// passes; 1e-6 past it is a real error and fails.
TEST(ValidateInertia, ToleranceIsRelativeToTheLargestMoment) {
  for (const double scale : {1e-6, 1.0, 1e6}) {
    EXPECT_NO_THROW(
        validate_inertia(scale * Vec3(1, 1, 2 * (1 + 1e-12)).asDiagonal().toDenseMatrix()));
    EXPECT_THROW(validate_inertia(scale * Vec3(1, 1, 2 * (1 + 1e-6)).asDiagonal().toDenseMatrix()),
                 InertiaError);
  }
  // A caller may widen the tolerance, e.g. for measured data: 5e-4 past the boundary passes at
  // 1e-3 and fails at the default.
  const Mat3 measured = Vec3(1, 1, 2 * (1 + 5e-4)).asDiagonal();
  EXPECT_NO_THROW(validate_inertia(measured, 1e-3));
  EXPECT_THROW(validate_inertia(measured), InertiaError);
}

// ---- Planar forms ------------------------------------------------------------------------------

// The planar moments are the I_zz of the 3D shapes lying in the x-y plane (rod along x, ring,
// disk, plate), and the planar parallel axis theorem is the zz entry of the 3D one for an
// in-plane offset. Round-off: 1e-15 relative.
TEST(Planar, MomentsAreTheZzOfThe3DShapesAndParallelAxisAgrees) {
  for (const double M : {0.3, 4.0}) {
    for (const double R : {0.25, 1.5}) {
      const auto zz = [M](const Shape& s) {
        return shape_mass_properties(s, M).inertia_about_com(2, 2);
      };
      EXPECT_NEAR(planar::rod_about_center(M, R), zz(rod(R)), 1e-15 * zz(rod(R)));
      EXPECT_NEAR(planar::ring_about_center(M, R), zz(with_radius(ShapeKind::Ring, R)),
                  1e-15 * M * R * R);
      EXPECT_NEAR(planar::disk_about_center(M, R), zz(with_radius(ShapeKind::Disk, R)),
                  1e-15 * M * R * R);
      EXPECT_NEAR(planar::plate_about_center(M, R, 2 * R), zz(plate(R, 2 * R)), 1e-15 * M * R * R);

      const MassProperties disk = shape_mass_properties(with_radius(ShapeKind::Disk, R), M);
      const Vec3 O(0.3, -1.1, 0.0);
      EXPECT_NEAR(planar::parallel_axis(disk.inertia_about_com(2, 2), M, O.norm()),
                  inertia_about_point(disk, O)(2, 2), 1e-15 * M * 4);
    }
  }
  // Chapter example 5 (bat, pivot at the knob): I_O = I_G + M L^2.
  EXPECT_DOUBLE_EQ(planar::parallel_axis(0.05, 0.9, 0.6), 0.05 + 0.9 * 0.36);
  expect_throw_containing<InertiaError>([] { planar::disk_about_center(-1.0, 1.0); },
                                        "disk mass must be > 0, got -1");
  expect_throw_containing<InertiaError>([] { planar::square_frame_about_center(1.0, 0.0); },
                                        "frame side must be > 0, got 0");
}

}  // namespace
}  // namespace tumble
