// Triangle meshes: the exact polyhedral integrals, the tessellations of the solid shapes against
// the chapter's closed forms, the closed-surface checks and the .obj / .stl loaders.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "expect_throw.hpp"
#include "test_constants.hpp"
#include "test_math.hpp"
#include "tumble/inertia/mass_properties.hpp"
#include "tumble/inertia/mesh.hpp"
#include "tumble/inertia/shapes.hpp"
#include "tumble/math/rotation.hpp"

namespace tumble {
namespace {

using test::kPi;

using test::max_abs;

std::string mesh_path(const std::string& name) {
  return std::string(TUMBLE_TEST_DATA_DIR) + "/meshes/" + name;
}

using test::expect_throw_containing;

Shape solid(ShapeKind kind, double radius, double length_or_height = 0.0) {
  Shape s;
  s.kind = kind;
  s.radius = radius;
  s.length = length_or_height;
  s.height = length_or_height;
  return s;
}
Shape tube_shape(double inner, double outer, double length) {
  Shape s;
  s.kind = ShapeKind::Tube;
  s.inner_radius = inner;
  s.outer_radius = outer;
  s.length = length;
  return s;
}
Shape box_shape(const Vec3& size) {
  Shape s;
  s.kind = ShapeKind::Box;
  s.size = size;
  return s;
}

// Mass properties of the tessellated shape carrying the same mass as the closed form.
MassProperties tessellated(const Shape& shape, int resolution, double mass) {
  const TriangleMesh mesh = tessellate(shape, resolution);
  return mesh_mass_properties(mesh, mass / mesh_volume(mesh));
}

// Largest error of the tessellation's inertia per unit mass, relative to the largest moment.
double relative_inertia_error(const Shape& shape, int resolution) {
  const Mat3 exact = shape_mass_properties(shape, 1.0).inertia_about_com;
  return max_abs(tessellated(shape, resolution, 1.0).inertia_about_com - exact) / max_abs(exact);
}

std::string write_temp_file(const std::string& name, const std::string& contents) {
  const std::string path = ::testing::TempDir() + "tumble_mesh_test_" + name;
  std::ofstream(path, std::ios::binary) << contents;
  return path;
}

// ---- The polyhedral integrals ------------------------------------------------------------------

// A box is a polyhedron, so the integrals are exact: I = M/12 diag(b^2 + c^2, a^2 + c^2,
// a^2 + b^2) to round-off (1e-12 relative, per the brief; the sums have 12 terms).
TEST(MeshIntegrator, BoxIsExact) {
  for (const Vec3& size : {Vec3(1, 1, 1), Vec3(4, 1, 2), Vec3(0.01, 3, 0.5)}) {
    for (const double M : {1.0, 12.0}) {
      const MassProperties mesh = tessellated(box_shape(size), 0, M);
      const MassProperties exact = shape_mass_properties(box_shape(size), M);
      EXPECT_NEAR(mesh.mass, M, 1e-12 * M);
      EXPECT_LE(mesh.com.norm(), 1e-12 * size.maxCoeff());
      EXPECT_LE(max_abs(mesh.inertia_about_com - exact.inertia_about_com),
                1e-12 * max_abs(exact.inertia_about_com))
          << mesh.inertia_about_com;
      EXPECT_NEAR(mesh_volume(tessellate(box_shape(size), 0)), size.prod(), 1e-12 * size.prod());
    }
  }
}

// Tetrahedron x/a + y/b + z/c <= 1 (x, y, z >= 0), integrated by slices: V = abc/6,
// r_G = (a, b, c)/4, int x^2 dV = a^3 b c / 60, int x y dV = a^2 b^2 c / 120 (and permutations).
// Then I about the corner, moved to the COM by the parallel axis theorem. Round-off: 1e-13.
Mat3 tetrahedron_inertia_about_com(double a, double b, double c, double density) {
  const Vec3 L(a, b, c);
  const double V = a * b * c / 6;
  Mat3 second;  // int r r^T dV about the right-angled corner
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      second(i, j) = i == j ? V * L(i) * L(i) / 10 : V * L(i) * L(j) / 20;
    }
  }
  const double M = density * V;
  const Vec3 r_OG = L / 4;  // COM from the corner
  const Mat3 I_corner = density * (second.trace() * Mat3::Identity() - second);
  // Parallel axis theorem backwards: I_G = I_O - M (|c|^2 1 - c c^T).
  return I_corner - M * (r_OG.squaredNorm() * Mat3::Identity() - r_OG * r_OG.transpose());
}

TriangleMesh corner_tetrahedron(double a, double b, double c, const Vec3& corner) {
  TriangleMesh mesh;
  mesh.vertices = {corner, corner + Vec3(a, 0, 0), corner + Vec3(0, b, 0), corner + Vec3(0, 0, c)};
  mesh.triangles = {{0, 2, 1}, {0, 3, 2}, {0, 1, 3}, {1, 2, 3}};
  return mesh;
}

TEST(MeshIntegrator, TetrahedronMatchesIntegrationBySlices) {
  for (const Vec3& legs : {Vec3(1, 1, 1), Vec3(2, 3, 1.5), Vec3(0.1, 5, 0.7)}) {
    const double density = 7.0;
    const Vec3 corner(-1, 0.5, 2);
    const TriangleMesh mesh = corner_tetrahedron(legs.x(), legs.y(), legs.z(), corner);
    EXPECT_NO_THROW(validate_closed_mesh(mesh));
    const MassProperties mp = mesh_mass_properties(mesh, density);
    const double V = legs.prod() / 6;
    EXPECT_NEAR(mp.mass, density * V, 1e-13 * density * V);
    EXPECT_LE((mp.com - (corner + legs / 4)).norm(), 1e-13 * legs.maxCoeff());
    const Mat3 expected = tetrahedron_inertia_about_com(legs.x(), legs.y(), legs.z(), density);
    EXPECT_LE(max_abs(mp.inertia_about_com - expected), 1e-13 * max_abs(expected))
        << mp.inertia_about_com << "\nvs\n"
        << expected;
  }
}

// Moving the mesh rigidly (x -> R x + p) moves the COM to R c + p and turns the inertia into
// R I R^T. Far from the origin (|p| = 1e4 for a body of size ~1) the integrals about the COM keep
// their accuracy: the vertices themselves are rounded to ulp(1e4) ~ 2e-12, which bounds the error
// at ~1e-11 relative; a naive sum about the origin would lose (|p| / size)^2 eps ~ 1e-8.
TEST(MeshIntegrator, RigidMotionMovesTheCOMAndRotatesTheInertiaEvenFarFromTheOrigin) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Shape shape = solid(ShapeKind::Cone, 0.5, 1.2);
  const TriangleMesh local = tessellate(shape, 24);
  const MassProperties at_origin = mesh_mass_properties(local, 3.0);
  for (const double distance : {1.0, 1e4}) {
    for (int trial = 0; trial < 5; ++trial) {
      const Mat3 R = exp_so3(kPi * Vec3(u(rng), u(rng), u(rng)));
      const Vec3 p = distance * Vec3(u(rng), u(rng), u(rng));
      TriangleMesh moved = local;
      for (Vec3& v : moved.vertices) v = R * v + p;
      const MassProperties mp = mesh_mass_properties(moved, 3.0);
      const double scale = max_abs(at_origin.inertia_about_com);
      EXPECT_NEAR(mp.mass, at_origin.mass, 1e-10 * at_origin.mass);
      EXPECT_LE((mp.com - (R * at_origin.com + p)).norm(), 1e-11 * distance + 1e-14);
      EXPECT_LE(max_abs(mp.inertia_about_com - R * at_origin.inertia_about_com * R.transpose()),
                1e-10 * scale)
          << "distance " << distance;
    }
  }
}

// The same rotated body two ways: express_in_parent of the box closed form, and the exact mesh
// integral of the rotated box's vertices. Exact polyhedron, so round-off only: 1e-12.
TEST(MeshIntegrator, RotatedBoxAgreesWithExpressInParent) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Shape prism = box_shape(Vec3(4, 1, 2));
  const MassProperties body = shape_mass_properties(prism, 12.0);
  for (int trial = 0; trial < 10; ++trial) {
    const Mat3 R = exp_so3(kPi * Vec3(u(rng), u(rng), u(rng)));
    const Vec3 p(u(rng), u(rng), u(rng));
    TriangleMesh mesh = tessellate(prism, 0);
    for (Vec3& v : mesh.vertices) v = R * v + p;
    const MassProperties integrated = mesh_mass_properties(mesh, 12.0 / 8.0);
    const MassProperties expressed = express_in_parent(body, R, p);
    EXPECT_LE((integrated.com - expressed.com).norm(), 1e-13);
    EXPECT_LE(max_abs(integrated.inertia_about_com - expressed.inertia_about_com), 1e-12 * 20);
  }
}

TEST(MeshIntegrator, NonPositiveDensityIsRefused) {
  expect_throw_containing<InertiaError>(
      [] { mesh_mass_properties(tessellate(box_shape(Vec3(1, 1, 1)), 0), -2.0); },
      "mesh density must be > 0 (kg/m^3), got -2");
}

// ---- Tessellations against the closed forms ----------------------------------------------------

TEST(Tessellation, EverySolidIsClosedOutwardAndCentredAtItsCOM) {
  const std::vector<Shape> shapes = {box_shape(Vec3(1, 2, 3)), solid(ShapeKind::Cylinder, 0.5, 2.0),
                                     tube_shape(0.3, 0.5, 1.0), solid(ShapeKind::Sphere, 0.7),
                                     solid(ShapeKind::Cone, 0.4, 1.0)};
  for (const Shape& s : shapes) {
    for (const int n : {3, 8, 64}) {
      const TriangleMesh mesh = tessellate(s, n);
      EXPECT_NO_THROW(validate_closed_mesh(mesh)) << shape_name(s.kind) << " n = " << n;
      EXPECT_GT(mesh_volume(mesh), 0.0);
      // COM at the origin by symmetry (cone: a pyramid's COM is h/4 above any base polygon).
      EXPECT_LE(mesh_mass_properties(mesh, 1.0).com.norm(), 1e-14) << shape_name(s.kind);
      // Inscribed: every vertex lies inside the closed-form solid, on its surface.
      EXPECT_LE(mesh_volume(mesh), shape_measure(s) * (1 + 1e-15)) << shape_name(s.kind);
    }
  }
}

// An inscribed regular n-gon of circumradius R is n triangles of apex angle d = 2 pi / n, each
// with area R^2 sin(d) / 2 and polar moment about the centre (|p1|^2 + |p2|^2 + p1.p2) A / 6, so
// its polar moment per unit area is f R^2 / 2 with f = (2 + cos d) / 3, and (regular, n >= 3) it
// is isotropic in its plane. So the prism, the polygonal annulus and the pyramid have exactly the
// closed forms of the cylinder, tube and cone with every R^2 replaced by f R^2, and volumes
// scaled by n sin(d) / (2 pi). Checked to round-off (1e-12) at several n.
TEST(Tessellation, InscribedPolygonsGiveExactlyTheClosedFormsWithRSquaredScaled) {
  for (const int n : {3, 5, 16, 100}) {
    const double d = 2 * kPi / n;
    const double f = (2 + std::cos(d)) / 3;
    const double area_ratio = n * std::sin(d) / (2 * kPi);
    const double M = 2.0;
    const double sqrt_f = std::sqrt(f);

    const Shape cyl = solid(ShapeKind::Cylinder, 0.6, 1.7);
    const Shape cyl_scaled = solid(ShapeKind::Cylinder, 0.6 * sqrt_f, 1.7);
    const Shape pipe = tube_shape(0.35, 0.6, 0.9);
    const Shape pipe_scaled = tube_shape(0.35 * sqrt_f, 0.6 * sqrt_f, 0.9);
    const Shape cone = solid(ShapeKind::Cone, 0.6, 1.4);
    const Shape cone_scaled = solid(ShapeKind::Cone, 0.6 * sqrt_f, 1.4);
    for (const auto& [shape, scaled] :
         {std::pair{cyl, cyl_scaled}, std::pair{pipe, pipe_scaled}, std::pair{cone, cone_scaled}}) {
      EXPECT_NEAR(mesh_volume(tessellate(shape, n)), area_ratio * shape_measure(shape),
                  1e-12 * shape_measure(shape))
          << shape_name(shape.kind) << " n = " << n;
      const Mat3 expected = shape_mass_properties(scaled, M).inertia_about_com;
      EXPECT_LE(max_abs(tessellated(shape, n, M).inertia_about_com - expected),
                1e-12 * max_abs(expected))
          << shape_name(shape.kind) << " n = " << n;
    }
  }
}

// Convergence of every solid's tessellation to its closed form. Inscribed facets of angular step
// d = 2 pi / n lie inside the surface by O(R d^2), so the error per unit mass is O(d^2): it must
// fall ~4x when n doubles (ratio in [3.5, 4.5], well clear of first order's 2 and of the 8-16 of
// higher orders). At the finest n it must also stay under a bound:
//  - cylinder, tube, cone (curved one way): d^2 / 6, since the error is exactly the factor
//    1 - f = (1 - cos d) / 3 <= d^2 / 6 on R^2 (previous test);
//  - UV sphere (curved both ways, steps d around and d pole to pole): a flat facet lies at most
//    R (1 - cos(d / sqrt 2)) <= R d^2 / 4 inside the sphere (its corners span at most d x d), and
//    removing a surface layer of depth h changes I / M = (2/5) R^2 by the relative amount 2 h / R
//    (mass 3 h / R, with second moment (2/3) R^2 per unit mass); so the error is under d^2 / 2.
TEST(Tessellation, ErrorAgainstTheClosedFormsFallsAtSecondOrder) {
  struct Case {
    Shape shape;
    double bound_per_d2;  // bound on the relative error at the finest n, over d^2
  };
  const std::vector<Case> cases = {{solid(ShapeKind::Cylinder, 0.5, 2.0), 1.0 / 6},
                                   {tube_shape(0.3, 0.5, 1.0), 1.0 / 6},
                                   {solid(ShapeKind::Cone, 0.4, 1.0), 1.0 / 6},
                                   {solid(ShapeKind::Sphere, 0.7), 1.0 / 2}};
  const std::vector<int> resolutions = {16, 32, 64, 128};
  for (const Case& c : cases) {
    std::vector<double> errors;
    for (const int n : resolutions) errors.push_back(relative_inertia_error(c.shape, n));
    for (std::size_t k = 0; k + 1 < errors.size(); ++k) {
      const double ratio = errors[k] / errors[k + 1];
      EXPECT_GT(ratio, 3.5) << shape_name(c.shape.kind) << " n = " << resolutions[k];
      EXPECT_LT(ratio, 4.5) << shape_name(c.shape.kind) << " n = " << resolutions[k];
    }
    const double d = 2 * kPi / resolutions.back();
    EXPECT_LT(errors.back(), c.bound_per_d2 * d * d) << shape_name(c.shape.kind);
  }
}

TEST(Tessellation, OnlySolidsAtAUsableResolution) {
  expect_throw_containing<MeshError>([] { tessellate(solid(ShapeKind::Ring, 1.0), 16); },
                                     "cannot tessellate a ring");
  expect_throw_containing<MeshError>([] { tessellate(solid(ShapeKind::Cylinder, 1.0, 1.0), 2); },
                                     "tessellation resolution must be >= 3 segments around, got 2");
  expect_throw_containing<InertiaError>([] { tessellate(tube_shape(0.5, 0.4, 1.0), 16); },
                                        "tube inner_radius 0.5 must be less than outer_radius 0.4");
}

// ---- Closed-surface checks ---------------------------------------------------------------------

TEST(ValidateClosedMesh, OpenFlippedAndInsideOutMeshesAreRefusedWithTheirReason) {
  expect_throw_containing<MeshError>(
      [] { validate_closed_mesh(load_mesh(mesh_path("open_box.obj"))); },
      "mesh is open: 4 edges belong to only one triangle, e.g. vertices 4-5");
  expect_throw_containing<MeshError>(
      [] { validate_closed_mesh(load_mesh(mesh_path("cube_flipped_face.obj"))); },
      "mesh is inconsistently oriented: 4 edges are traversed twice in the same direction");
  expect_throw_containing<MeshError>(
      [] { validate_closed_mesh(load_mesh(mesh_path("cube_inside_out.obj"))); },
      "mesh encloses a non-positive volume -1 m^3: it is inside out");
}

TEST(ValidateClosedMesh, NonManifoldDegenerateAndOutOfRangeTrianglesAreRefused) {
  // Two closed tetrahedra sharing only the edge 0-1 (a "bow tie"): that edge has four triangles,
  // every other edge two.
  TriangleMesh bowtie = corner_tetrahedron(1, 1, 1, Vec3::Zero());
  bowtie.vertices.push_back(Vec3(0.5, -1, 0));  // 4
  bowtie.vertices.push_back(Vec3(0.5, 0, -1));  // 5
  TriangleMesh second;
  second.vertices = bowtie.vertices;
  second.triangles = {{0, 1, 4}, {0, 5, 1}, {0, 4, 5}, {1, 5, 4}};
  if (mesh_volume(second) < 0) {
    for (auto& t : second.triangles) std::swap(t[1], t[2]);  // wind it outward
  }
  ASSERT_NO_THROW(validate_closed_mesh(second));
  for (const auto& t : second.triangles) bowtie.triangles.push_back(t);
  expect_throw_containing<MeshError>(
      [&] { validate_closed_mesh(bowtie); },
      "mesh is not a closed surface: 1 edge belongs to more than two triangles, e.g. vertices 0-1");

  TriangleMesh degenerate = corner_tetrahedron(1, 1, 1, Vec3::Zero());
  degenerate.triangles.push_back({2, 2, 3});
  expect_throw_containing<MeshError>([&] { validate_closed_mesh(degenerate); },
                                     "triangle 4 is degenerate: it uses vertices 2, 2, 3");

  TriangleMesh out_of_range = corner_tetrahedron(1, 1, 1, Vec3::Zero());
  out_of_range.triangles[1][2] = 9;
  expect_throw_containing<MeshError>([&] { validate_closed_mesh(out_of_range); },
                                     "triangle 1 refers to vertex 9 but the mesh has 4 vertices");
  expect_throw_containing<MeshError>([] { validate_closed_mesh(TriangleMesh{}); },
                                     "mesh has no triangles");
}

// ---- Loaders -----------------------------------------------------------------------------------

// Every OBJ face form (v, v/vt, v/vt/vn, v//vn, negative indices, quads and triangles) reads the
// same unit cube: 8 vertices, 12 triangles, volume 1, COM at its centre, I = rho/6 diag(1, 1, 1)
// exactly (a polyhedron; round-off 1e-15).
TEST(MeshLoaders, ObjFaceFormsAllReadTheUnitCube) {
  const TriangleMesh cube = load_mesh(mesh_path("unit_cube.obj"));
  EXPECT_EQ(cube.vertices.size(), 8u);
  EXPECT_EQ(cube.triangles.size(), 12u);
  EXPECT_NO_THROW(validate_closed_mesh(cube));
  const MassProperties mp = mesh_mass_properties(cube, 2.0);
  EXPECT_NEAR(mp.mass, 2.0, 1e-15);
  EXPECT_LE((mp.com - Vec3::Constant(0.5)).norm(), 1e-15);
  EXPECT_LE(max_abs(mp.inertia_about_com - Mat3::Identity() * 2.0 / 6.0), 1e-15);
}

// One tetrahedron written as .obj, ASCII .stl and binary .stl (whose header starts with "solid",
// as some exporters write it). STL stores each triangle's corners separately: merging them must
// give back the 4 shared vertices, so the surface is closed. The coordinates are exact in float32,
// so all three give bit-identical properties, which also match integration by slices (1e-13).
TEST(MeshLoaders, ObjAndBothStlKindsGiveTheSameTetrahedron) {
  const std::vector<std::string> files = {"tetrahedron.obj", "tetrahedron_ascii.stl",
                                          "tetrahedron_binary.stl"};
  const MassProperties reference = mesh_mass_properties(load_mesh(mesh_path(files[0])), 5.0);
  for (const std::string& file : files) {
    const TriangleMesh mesh = load_mesh(mesh_path(file));
    EXPECT_EQ(mesh.vertices.size(), 4u) << file;
    EXPECT_EQ(mesh.triangles.size(), 4u) << file;
    EXPECT_NO_THROW(validate_closed_mesh(mesh)) << file;
    const MassProperties mp = mesh_mass_properties(mesh, 5.0);
    EXPECT_EQ(mp.mass, reference.mass) << file;
    EXPECT_EQ(mp.com, reference.com) << file;
    EXPECT_EQ(mp.inertia_about_com, reference.inertia_about_com) << file;
  }
  EXPECT_LE((reference.com - (Vec3(1, 2, 3) + Vec3(2, 3, 1.5) / 4)).norm(), 1e-13);
  const Mat3 expected = tetrahedron_inertia_about_com(2, 3, 1.5, 5.0);
  EXPECT_LE(max_abs(reference.inertia_about_com - expected), 1e-13 * max_abs(expected));
}

TEST(MeshLoaders, UnreadableOrMalformedFilesNameThePathAndTheFault) {
  const std::string missing = mesh_path("no_such_mesh.obj");
  expect_throw_containing<MeshError>([&] { load_mesh(missing); },
                                     "mesh file '" + missing + "': cannot be read: no such file");
  expect_throw_containing<MeshError>([] { load_mesh("part.ply"); },
                                     "mesh file 'part.ply': unknown extension '.ply'");

  const std::string bad_index =
      write_temp_file("bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 5\n");
  expect_throw_containing<MeshError>(
      [&] { load_mesh(bad_index); },
      "line 4: face refers to vertex 5 but only 3 vertices are defined before it");
  const std::string bad_vertex = write_temp_file("bad_vertex.obj", "v 0 0 zero\n");
  expect_throw_containing<MeshError>([&] { load_mesh(bad_vertex); },
                                     "line 1: a vertex needs three finite coordinates");
  const std::string two_corners = write_temp_file("two_corners.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n");
  expect_throw_containing<MeshError>([&] { load_mesh(two_corners); },
                                     "line 3: a face needs at least 3 vertices");
  const std::string no_faces = write_temp_file("no_faces.obj", "# nothing\nv 0 0 0\n");
  expect_throw_containing<MeshError>([&] { load_mesh(no_faces); }, "contains no faces");

  const std::string quad_facet = write_temp_file(
      "quad.stl",
      "solid q\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n"
      "vertex 0 1 0\nendloop\nendfacet\nendsolid q\n");
  expect_throw_containing<MeshError>([&] { load_mesh(quad_facet); },
                                     "facet 0 has 4 vertices; STL facets are triangles");
  const std::string garbage = write_temp_file("garbage.stl", "this is not a mesh");
  expect_throw_containing<MeshError>([&] { load_mesh(garbage); }, "neither an ASCII STL");

  // A binary STL cut short by one byte no longer matches its announced size.
  std::ifstream in(mesh_path("tetrahedron_binary.stl"), std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  bytes.pop_back();
  const std::string truncated = write_temp_file("truncated.stl", bytes);
  expect_throw_containing<MeshError>(
      [&] { load_mesh(truncated); },
      "or a binary STL whose size, 283 bytes, is not the 84 + 50 x 4 its header announces");
}

// ---- Mesh as a shape ---------------------------------------------------------------------------

// The unit cube file, used as a shape of mass 3: frame moved to its COM, I = M/6 diag(1, 1, 1)
// exactly as the box closed form (the polyhedral integrals are exact for a polyhedron; round-off
// 1e-15 relative).
TEST(MeshShape, UnitCubeFileMatchesTheBoxClosedForm) {
  Shape cube;
  cube.kind = ShapeKind::Mesh;
  cube.mesh_file = mesh_path("unit_cube.obj");
  EXPECT_NEAR(shape_measure(cube), 1.0, 1e-15);
  const MassProperties mp = shape_mass_properties(cube, 3.0);
  EXPECT_EQ(mp.mass, 3.0);
  EXPECT_EQ(mp.com, Vec3::Zero());
  EXPECT_LE(max_abs(mp.inertia_about_com -
                    shape_mass_properties(box_shape(Vec3(1, 1, 1)), 3.0).inertia_about_com),
            1e-15 * 0.5);
}

TEST(MeshShape, AnOpenMeshFileIsRefusedNamingTheFile) {
  Shape open;
  open.kind = ShapeKind::Mesh;
  open.mesh_file = mesh_path("open_box.obj");
  expect_throw_containing<MeshError>([&] { shape_mass_properties(open, 1.0); },
                                     "open_box.obj: mesh is open");
}

}  // namespace
}  // namespace tumble
