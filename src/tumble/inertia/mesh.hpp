#pragma once
// Closed triangle meshes and their exact mass properties by the polyhedral volume integrals
// (divergence theorem over each triangle; Mirtich 1996, Eberly "Polyhedral Mass Properties").
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "tumble/inertia/mass_properties.hpp"
#include "tumble/inertia/shapes.hpp"

namespace tumble {

class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct TriangleMesh {
  std::vector<Vec3> vertices;                 // m, in the file's frame
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from outside
};

// Reads Wavefront .obj (v and f records; polygons are fanned into triangles) or STL (ASCII or
// binary; coincident vertices are merged). Throws MeshError naming the file and what is wrong.
TriangleMesh load_mesh(const std::string& path);

// Throws MeshError if the mesh is open (an edge used by one face: says which and how many such
// edges), inconsistently oriented (an edge traversed twice the same way), or encloses a
// non-positive volume (inside out).
void validate_closed_mesh(const TriangleMesh& mesh);

// Exact volume, COM and inertia about the COM (file axes) of the solid the mesh bounds, for a
// uniform density (kg/m^3).
MassProperties mesh_mass_properties(const TriangleMesh& mesh, double density);
double mesh_volume(const TriangleMesh& mesh);

// A closed tessellation of a solid shape (cylinder, tube, sphere, box, cone) with about
// `resolution` segments around, in the shape's frame: for checking the closed forms against the
// mesh integrator. Every vertex lies on the true surface (inscribed); a box is exact and ignores
// `resolution`. Throws MeshError for other kinds or resolution < 3.
TriangleMesh tessellate(const Shape& shape, int resolution);

}  // namespace tumble
