#pragma once
// The shapes of the scenario contract, each with its frame at the COM and its axis of symmetry z
// (a rod lies along x; a plate in the x-y plane; a cone has its base at z = -h/4 and its apex at
// z = 3h/4; a torus's centre circle lies in the x-y plane; a capsule is a cylinder of the given
// length along z capped by two hemispheres of its radius). Closed forms of the chapter's table in
// section 6.7.2.
#include <optional>
#include <string>
#include <string_view>

#include "tumble/inertia/mass_properties.hpp"

namespace tumble {

enum class ShapeKind {
  Point,
  Rod,
  Ring,
  Disk,
  Cylinder,
  Tube,
  Sphere,
  Shell,
  Box,
  Cone,
  Plate,
  Mesh,
  Torus,
  Capsule
};

struct Shape {
  ShapeKind kind = ShapeKind::Point;
  double length =
      0.0;  // m: rod, cylinder, tube; a capsule's straight part (its caps' centres apart)
  double radius = 0.0;  // m: ring, disk, cylinder, sphere, shell, cone, capsule; a torus's centre
                        // circle
  double tube_radius = 0.0;   // m: torus, its tube (less than its radius)
  double inner_radius = 0.0;  // m: tube
  double outer_radius = 0.0;  // m: tube
  double height = 0.0;        // m: cone
  Vec3 size = Vec3::Zero();   // m: box [a, b, c]; plate [a, b, 0]
  std::string mesh_file;      // mesh: path of a closed .obj or .stl
};

std::string_view shape_name(ShapeKind kind);
std::optional<ShapeKind> shape_kind_from_name(std::string_view name);

// The measure that a density multiplies to give the mass: volume (m^3) of the solids (cylinder,
// tube, sphere, box, cone, mesh, torus), area (m^2) of the surfaces (disk, plate, shell), length
// (m) of the curves (rod, ring). A point has none (0): it needs a mass.
double shape_measure(const Shape& shape);

// Mass properties of a uniform shape of the given mass, in the shape's frame: com = 0 and the
// closed-form inertia about it. A mesh is loaded, checked (closed, consistently oriented) and
// integrated exactly; its frame is the file's axes moved to its COM (where that COM lies in the
// file's frame: mesh_mass_properties(load_mesh(file), density).com). Throws InertiaError (or
// MeshError) for an impossible shape, naming the dimension and its value.
MassProperties shape_mass_properties(const Shape& shape, double mass);

}  // namespace tumble
