#include "tumble/inertia/shapes.hpp"
#include "tumble/inertia/message_format.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#include "tumble/inertia/mesh.hpp"

namespace tumble {
namespace {

constexpr std::array<std::pair<ShapeKind, std::string_view>, 14> kShapeNames = {{
    {ShapeKind::Point, "point"},
    {ShapeKind::Rod, "rod"},
    {ShapeKind::Ring, "ring"},
    {ShapeKind::Disk, "disk"},
    {ShapeKind::Cylinder, "cylinder"},
    {ShapeKind::Tube, "tube"},
    {ShapeKind::Sphere, "sphere"},
    {ShapeKind::Shell, "shell"},
    {ShapeKind::Box, "box"},
    {ShapeKind::Cone, "cone"},
    {ShapeKind::Plate, "plate"},
    {ShapeKind::Mesh, "mesh"},
    {ShapeKind::Torus, "torus"},
    {ShapeKind::Capsule, "capsule"},
}};

using inertia_detail::format_number;

// "cylinder radius must be > 0, got -1"
void require_positive(const Shape& shape, std::string_view dimension, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InertiaError(std::string(shape_name(shape.kind)) + " " + std::string(dimension) +
                       " must be > 0, got " + format_number(value));
  }
}

// Every dimension the shape uses must be positive and finite, and a tube's bore smaller than its
// outside; the dimensions a shape does not use are ignored.
void check_dimensions(const Shape& shape) {
  switch (shape.kind) {
    case ShapeKind::Point:
      return;
    case ShapeKind::Rod:
      require_positive(shape, "length", shape.length);
      return;
    case ShapeKind::Ring:
    case ShapeKind::Disk:
    case ShapeKind::Sphere:
    case ShapeKind::Shell:
      require_positive(shape, "radius", shape.radius);
      return;
    case ShapeKind::Cylinder:
    case ShapeKind::Capsule:
      require_positive(shape, "radius", shape.radius);
      require_positive(shape, "length", shape.length);
      return;
    case ShapeKind::Tube:
      require_positive(shape, "inner_radius", shape.inner_radius);
      require_positive(shape, "outer_radius", shape.outer_radius);
      require_positive(shape, "length", shape.length);
      if (!(shape.inner_radius < shape.outer_radius)) {
        throw InertiaError("tube inner_radius " + format_number(shape.inner_radius) +
                           " must be less than outer_radius " + format_number(shape.outer_radius));
      }
      return;
    case ShapeKind::Box:
      require_positive(shape, "size[0] (a, along x)", shape.size.x());
      require_positive(shape, "size[1] (b, along y)", shape.size.y());
      require_positive(shape, "size[2] (c, along z)", shape.size.z());
      return;
    case ShapeKind::Cone:
      require_positive(shape, "radius", shape.radius);
      require_positive(shape, "height", shape.height);
      return;
    case ShapeKind::Plate:
      require_positive(shape, "size[0] (a, along x)", shape.size.x());
      require_positive(shape, "size[1] (b, along y)", shape.size.y());
      if (shape.size.z() != 0.0) {
        throw InertiaError("plate size[2] must be 0 (a plate is thin; use a box for a slab), got " +
                           format_number(shape.size.z()));
      }
      return;
    case ShapeKind::Mesh:
      if (shape.mesh_file.empty()) throw InertiaError("mesh needs a file (.obj or .stl)");
      return;
    case ShapeKind::Torus:
      require_positive(shape, "radius", shape.radius);
      require_positive(shape, "tube_radius", shape.tube_radius);
      if (!(shape.tube_radius < shape.radius)) {
        throw InertiaError("torus tube_radius " + format_number(shape.tube_radius) +
                           " must be less than its radius " + format_number(shape.radius));
      }
      return;
  }
}

void check_mass(double mass) {
  if (!(mass > 0.0) || !std::isfinite(mass)) {
    throw InertiaError("mass must be > 0, got " + format_number(mass));
  }
}

TriangleMesh load_closed_mesh(const Shape& shape) {
  TriangleMesh mesh = load_mesh(shape.mesh_file);
  try {
    validate_closed_mesh(mesh);
  } catch (const MeshError& error) {
    throw MeshError(shape.mesh_file + ": " + error.what());
  }
  return mesh;
}

// Inertia diag(I_xx, I_yy, I_zz) about the COM, on the shape's axes.
Mat3 diagonal(double xx, double yy, double zz) {
  return Vec3(xx, yy, zz).asDiagonal();
}

}  // namespace

std::string_view shape_name(ShapeKind kind) {
  for (const auto& [k, name] : kShapeNames) {
    if (k == kind) return name;
  }
  return "unknown";
}

std::optional<ShapeKind> shape_kind_from_name(std::string_view name) {
  for (const auto& [kind, n] : kShapeNames) {
    if (n == name) return kind;
  }
  return std::nullopt;
}

double shape_measure(const Shape& shape) {
  check_dimensions(shape);
  const double R = shape.radius;
  switch (shape.kind) {
    case ShapeKind::Point:
      return 0.0;
    case ShapeKind::Rod:
      return shape.length;
    case ShapeKind::Ring:
      return 2.0 * std::numbers::pi * R;
    case ShapeKind::Disk:
      return std::numbers::pi * R * R;
    case ShapeKind::Cylinder:
      return std::numbers::pi * R * R * shape.length;
    case ShapeKind::Tube: {
      const double a = shape.inner_radius, b = shape.outer_radius;
      return std::numbers::pi * (b * b - a * a) * shape.length;
    }
    case ShapeKind::Sphere:
      return 4.0 / 3.0 * std::numbers::pi * R * R * R;
    case ShapeKind::Shell:
      return 4.0 * std::numbers::pi * R * R;
    case ShapeKind::Box:
      return shape.size.prod();
    case ShapeKind::Cone:
      return std::numbers::pi * R * R * shape.height / 3.0;
    case ShapeKind::Plate:
      return shape.size.x() * shape.size.y();
    case ShapeKind::Mesh:
      return mesh_volume(load_closed_mesh(shape));
    case ShapeKind::Capsule:  // the cylinder and the two caps, a sphere between them
      return std::numbers::pi * R * R * (shape.length + 4.0 * R / 3.0);
    case ShapeKind::Torus:  // Pappus: the tube's section times the path of its centre
      return std::numbers::pi * shape.tube_radius * shape.tube_radius * 2.0 * std::numbers::pi * R;
  }
  return 0.0;
}

// The closed forms of the chapter's table (section 6.7.2), about the COM, symmetry axis z.
MassProperties shape_mass_properties(const Shape& shape, double mass) {
  check_mass(mass);
  check_dimensions(shape);
  const double M = mass;
  const double R = shape.radius;
  const double L = shape.length;
  MassProperties mp;
  mp.mass = M;
  switch (shape.kind) {
    case ShapeKind::Point:
      // All the mass at the COM: no inertia about it.
      break;
    case ShapeKind::Rod:
      // Slender rod along x: I_yy = I_zz = M L^2 / 12, I_xx = 0 (singular; see validate_inertia).
      mp.inertia_about_com = diagonal(0.0, M * L * L / 12.0, M * L * L / 12.0);
      break;
    case ShapeKind::Ring:
      mp.inertia_about_com = diagonal(M * R * R / 2.0, M * R * R / 2.0, M * R * R);
      break;
    case ShapeKind::Disk:
      mp.inertia_about_com = diagonal(M * R * R / 4.0, M * R * R / 4.0, M * R * R / 2.0);
      break;
    case ShapeKind::Cylinder: {
      const double transverse = M * (3.0 * R * R + L * L) / 12.0;
      mp.inertia_about_com = diagonal(transverse, transverse, M * R * R / 2.0);
      break;
    }
    case ShapeKind::Tube: {
      const double a = shape.inner_radius, b = shape.outer_radius;
      const double transverse = M * (3.0 * (a * a + b * b) + L * L) / 12.0;
      mp.inertia_about_com = diagonal(transverse, transverse, M * (a * a + b * b) / 2.0);
      break;
    }
    case ShapeKind::Sphere: {
      const double moment = 2.0 * M * R * R / 5.0;
      mp.inertia_about_com = diagonal(moment, moment, moment);
      break;
    }
    case ShapeKind::Shell: {
      const double moment = 2.0 * M * R * R / 3.0;
      mp.inertia_about_com = diagonal(moment, moment, moment);
      break;
    }
    case ShapeKind::Box: {
      const double a = shape.size.x(), b = shape.size.y(), c = shape.size.z();
      mp.inertia_about_com = diagonal(M * (b * b + c * c) / 12.0, M * (a * a + c * c) / 12.0,
                                      M * (a * a + b * b) / 12.0);
      break;
    }
    case ShapeKind::Cone: {
      // About the COM, h/4 above the base.
      const double h = shape.height;
      const double transverse = 3.0 * M * R * R / 20.0 + 3.0 * M * h * h / 80.0;
      mp.inertia_about_com = diagonal(transverse, transverse, 3.0 * M * R * R / 10.0);
      break;
    }
    case ShapeKind::Plate: {
      const double a = shape.size.x(), b = shape.size.y();
      mp.inertia_about_com =
          diagonal(M * b * b / 12.0, M * a * a / 12.0, M * (a * a + b * b) / 12.0);
      break;
    }
    case ShapeKind::Mesh: {
      // Uniform density rho = M / V; the frame is the file's axes moved to the COM.
      const TriangleMesh mesh = load_closed_mesh(shape);
      const double density = M / mesh_volume(mesh);
      mp = mesh_mass_properties(mesh, density);
      mp.mass = M;  // exactly the given mass, not rho V with its round-off
      mp.com = Vec3::Zero();
      break;
    }
    case ShapeKind::Torus: {
      // A solid torus: about its axis M (R^2 + 3 r^2 / 4), about a diameter M (R^2 / 2 +
      // 5 r^2 / 8) (the tube's disks of radius r, each at R from the axis).
      const double r = shape.tube_radius;
      const double transverse = M * (R * R / 2.0 + 5.0 * r * r / 8.0);
      mp.inertia_about_com = diagonal(transverse, transverse, M * (R * R + 3.0 * r * r / 4.0));
      break;
    }
    case ShapeKind::Capsule: {
      // The mass shared by volume: the cylinder's m_c (length L), the two caps' m_s (a sphere's
      // worth). About the axis: m_c R^2 / 2 + 2 m_s R^2 / 5. About a diameter through the COM:
      // the cylinder's m_c (3 R^2 + L^2) / 12, and each cap's 2 (m_s / 2) R^2 / 5 about its flat
      // face's centre, moved to its own COM (3R/8 out) and then to the capsule's (L/2 + 3R/8
      // from it): m_s (2 R^2 / 5 + L^2 / 4 + 3 L R / 8) for the two.
      const double cylinder = L / (L + 4.0 * R / 3.0), caps = 1.0 - cylinder;
      const double m_c = M * cylinder, m_s = M * caps;
      const double transverse = m_c * (3.0 * R * R + L * L) / 12.0 +
                                m_s * (2.0 * R * R / 5.0 + L * L / 4.0 + 3.0 * L * R / 8.0);
      mp.inertia_about_com =
          diagonal(transverse, transverse, m_c * R * R / 2.0 + 2.0 * m_s * R * R / 5.0);
      break;
    }
  }
  return mp;
}

}  // namespace tumble
