#include "tumble/inertia/mesh.hpp"
#include "tumble/inertia/message_format.hpp"

#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace tumble {
namespace {

using inertia_detail::format_number;

// "1 edge belongs" / "4 edges belong"
std::string edges_belong(int count) {
  return std::to_string(count) + (count == 1 ? " edge belongs" : " edges belong");
}

std::string edge_text(const std::pair<int, int>& edge) {
  return "vertices " + std::to_string(edge.first) + "-" + std::to_string(edge.second);
}

// ---- Volume integrals --------------------------------------------------------------------------
// By the divergence theorem the solid is the signed sum of the tetrahedra (p0, a, b, c) that join
// a reference point p0 to each outward-wound triangle (a, b, c). With the corners taken relative
// to p0 (so the apex is the origin), one tetrahedron has
//   V   = a . (b x c) / 6,
//   int r dV     = V (a + b + c) / 4,
//   int r r^T dV = V / 20 [a a^T + b b^T + c c^T + (a + b + c)(a + b + c)^T]
// (the exact moments of a tetrahedron with one vertex at the origin; Tonon 2004, "Explicit exact
// formulas for the 3-D tetrahedron inertia tensor"). The inertia about p0 is then
//   I = rho (tr(C) 1 - C),  C = int r r^T dV.
struct VolumeMoments {
  double volume = 0.0;
  Vec3 first = Vec3::Zero();   // int (r - p0) dV
  Mat3 second = Mat3::Zero();  // int (r - p0)(r - p0)^T dV
};

VolumeMoments volume_moments(const TriangleMesh& mesh, const Vec3& p0) {
  VolumeMoments m;
  for (const auto& triangle : mesh.triangles) {
    const Vec3 a = mesh.vertices[triangle[0]] - p0;
    const Vec3 b = mesh.vertices[triangle[1]] - p0;
    const Vec3 c = mesh.vertices[triangle[2]] - p0;
    const double volume = a.dot(b.cross(c)) / 6.0;
    const Vec3 sum = a + b + c;
    m.volume += volume;
    m.first += volume * sum / 4.0;
    m.second += volume / 20.0 *
                (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose());
  }
  return m;
}

Vec3 vertex_centroid(const TriangleMesh& mesh) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& v : mesh.vertices) sum += v;
  return sum / static_cast<double>(mesh.vertices.size());
}

void check_indices(const TriangleMesh& mesh) {
  const int count = static_cast<int>(mesh.vertices.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (const int index : mesh.triangles[t]) {
      if (index < 0 || index >= count) {
        throw MeshError("triangle " + std::to_string(t) + " refers to vertex " +
                        std::to_string(index) + " but the mesh has " + std::to_string(count) +
                        " vertices");
      }
    }
  }
}

// ---- Tessellation helpers ----------------------------------------------------------------------
// A ring of n vertices of radius r at height z, counter-clockwise seen from +z; returns the index
// of its first vertex.
int add_ring(TriangleMesh& mesh, int n, double r, double z) {
  const int first = static_cast<int>(mesh.vertices.size());
  for (int k = 0; k < n; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / n;
    mesh.vertices.emplace_back(r * std::cos(angle), r * std::sin(angle), z);
  }
  return first;
}

int add_vertex(TriangleMesh& mesh, const Vec3& p) {
  mesh.vertices.push_back(p);
  return static_cast<int>(mesh.vertices.size()) - 1;
}

// The band between a lower and an upper ring (same n), facing away from the axis when outward is
// true, towards it otherwise (the bore of a tube).
void add_band(TriangleMesh& mesh, int n, int lower, int upper, bool outward) {
  for (int k = 0; k < n; ++k) {
    const int b0 = lower + k, b1 = lower + (k + 1) % n;
    const int t0 = upper + k, t1 = upper + (k + 1) % n;
    if (outward) {
      mesh.triangles.push_back({b0, b1, t1});
      mesh.triangles.push_back({b0, t1, t0});
    } else {
      mesh.triangles.push_back({b0, t1, b1});
      mesh.triangles.push_back({b0, t0, t1});
    }
  }
}

// A fan from a centre vertex to a ring, facing +z when up is true, -z otherwise.
void add_fan(TriangleMesh& mesh, int n, int centre, int ring, bool up) {
  for (int k = 0; k < n; ++k) {
    const int r0 = ring + k, r1 = ring + (k + 1) % n;
    if (up) {
      mesh.triangles.push_back({centre, r0, r1});
    } else {
      mesh.triangles.push_back({centre, r1, r0});
    }
  }
}

// The annulus between an inner and an outer ring in one plane, facing +z when up is true.
void add_annulus(TriangleMesh& mesh, int n, int inner, int outer, bool up) {
  for (int k = 0; k < n; ++k) {
    const int i0 = inner + k, i1 = inner + (k + 1) % n;
    const int o0 = outer + k, o1 = outer + (k + 1) % n;
    if (up) {
      mesh.triangles.push_back({i0, o0, o1});
      mesh.triangles.push_back({i0, o1, i1});
    } else {
      mesh.triangles.push_back({i0, o1, o0});
      mesh.triangles.push_back({i0, i1, o1});
    }
  }
}

TriangleMesh tessellate_box(const Vec3& size) {
  TriangleMesh mesh;
  const Vec3 h = size / 2.0;
  // Vertex k has coordinate signs from its bits: bit 0 -> x, bit 1 -> y, bit 2 -> z.
  for (int k = 0; k < 8; ++k) {
    mesh.vertices.emplace_back((k & 1) ? h.x() : -h.x(), (k & 2) ? h.y() : -h.y(),
                               (k & 4) ? h.z() : -h.z());
  }
  // Each face as a quad wound counter-clockwise seen from outside.
  const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5},   // -x, +x
                           {0, 1, 5, 4}, {2, 6, 7, 3},   // -y, +y
                           {0, 2, 3, 1}, {4, 5, 7, 6}};  // -z, +z
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  return mesh;
}

TriangleMesh tessellate_cylinder(double radius, double length, int n) {
  TriangleMesh mesh;
  const int bottom = add_ring(mesh, n, radius, -length / 2.0);
  const int top = add_ring(mesh, n, radius, length / 2.0);
  const int bottom_centre = add_vertex(mesh, Vec3(0.0, 0.0, -length / 2.0));
  const int top_centre = add_vertex(mesh, Vec3(0.0, 0.0, length / 2.0));
  add_band(mesh, n, bottom, top, true);
  add_fan(mesh, n, bottom_centre, bottom, false);
  add_fan(mesh, n, top_centre, top, true);
  return mesh;
}

TriangleMesh tessellate_tube(double inner_radius, double outer_radius, double length, int n) {
  TriangleMesh mesh;
  const int outer_bottom = add_ring(mesh, n, outer_radius, -length / 2.0);
  const int outer_top = add_ring(mesh, n, outer_radius, length / 2.0);
  const int inner_bottom = add_ring(mesh, n, inner_radius, -length / 2.0);
  const int inner_top = add_ring(mesh, n, inner_radius, length / 2.0);
  add_band(mesh, n, outer_bottom, outer_top, true);
  add_band(mesh, n, inner_bottom, inner_top, false);
  add_annulus(mesh, n, inner_bottom, outer_bottom, false);
  add_annulus(mesh, n, inner_top, outer_top, true);
  return mesh;
}

// UV sphere: n segments around and n/2 (at least 2) from pole to pole, all corners on the sphere.
TriangleMesh tessellate_sphere(double radius, int n) {
  TriangleMesh mesh;
  const int stacks = std::max(2, n / 2);
  const int north = add_vertex(mesh, Vec3(0.0, 0.0, radius));
  std::vector<int> rings;
  for (int j = 1; j < stacks; ++j) {
    const double polar = std::numbers::pi * j / stacks;
    rings.push_back(add_ring(mesh, n, radius * std::sin(polar), radius * std::cos(polar)));
  }
  const int south = add_vertex(mesh, Vec3(0.0, 0.0, -radius));
  add_fan(mesh, n, north, rings.front(), true);
  for (std::size_t j = 0; j + 1 < rings.size(); ++j)
    add_band(mesh, n, rings[j + 1], rings[j], true);
  add_fan(mesh, n, south, rings.back(), false);
  return mesh;
}

// Cone with its base at z = -h/4 and apex at z = 3h/4, so that its COM is at the origin.
TriangleMesh tessellate_cone(double radius, double height, int n) {
  TriangleMesh mesh;
  const int base = add_ring(mesh, n, radius, -height / 4.0);
  const int base_centre = add_vertex(mesh, Vec3(0.0, 0.0, -height / 4.0));
  const int apex = add_vertex(mesh, Vec3(0.0, 0.0, 3.0 * height / 4.0));
  add_fan(mesh, n, base_centre, base, false);
  add_fan(mesh, n, apex, base, true);
  return mesh;
}

}  // namespace

// A closed, consistently oriented (2-manifold) surface uses every undirected edge in exactly two
// triangles, once in each direction; it then bounds a solid whose volume is positive when the
// triangles wind counter-clockwise seen from outside.
void validate_closed_mesh(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) throw MeshError("mesh has no triangles");
  check_indices(mesh);

  // For each undirected edge (low, high): how many triangles run low->high and high->low.
  std::map<std::pair<int, int>, std::pair<int, int>> edge_uses;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) {
      throw MeshError("triangle " + std::to_string(t) + " is degenerate: it uses vertices " +
                      std::to_string(tri[0]) + ", " + std::to_string(tri[1]) + ", " +
                      std::to_string(tri[2]));
    }
    for (int k = 0; k < 3; ++k) {
      const int from = tri[k], to = tri[(k + 1) % 3];
      auto& uses = edge_uses[{std::min(from, to), std::max(from, to)}];
      (from < to ? uses.first : uses.second) += 1;
    }
  }

  int open = 0, non_manifold = 0, same_direction = 0;
  std::pair<int, int> open_example, non_manifold_example, same_direction_example;
  for (const auto& [edge, uses] : edge_uses) {
    const int total = uses.first + uses.second;
    if (total == 1) {
      if (open++ == 0) open_example = edge;
    } else if (total > 2) {
      if (non_manifold++ == 0) non_manifold_example = edge;
    } else if (uses.first != 1) {
      if (same_direction++ == 0) same_direction_example = edge;
    }
  }
  if (open > 0) {
    throw MeshError("mesh is open: " + edges_belong(open) + " to only one triangle, e.g. " +
                    edge_text(open_example) + " (a missing face or unmerged vertices)");
  }
  if (non_manifold > 0) {
    throw MeshError("mesh is not a closed surface: " + edges_belong(non_manifold) +
                    " to more than two triangles, e.g. " + edge_text(non_manifold_example));
  }
  if (same_direction > 0) {
    throw MeshError("mesh is inconsistently oriented: " + std::to_string(same_direction) +
                    (same_direction == 1 ? " edge is" : " edges are") +
                    " traversed twice in the same direction, e.g. " +
                    edge_text(same_direction_example) + " (a flipped triangle)");
  }
  const double volume = mesh_volume(mesh);
  if (!(volume > 0.0)) {
    throw MeshError("mesh encloses a non-positive volume " + format_number(volume) +
                    " m^3: it is inside out (triangles wound clockwise seen from outside); "
                    "reverse every triangle");
  }
}

double mesh_volume(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) return 0.0;
  check_indices(mesh);
  return volume_moments(mesh, vertex_centroid(mesh)).volume;
}

MassProperties mesh_mass_properties(const TriangleMesh& mesh, double density) {
  if (!(density > 0.0) || !std::isfinite(density)) {
    throw InertiaError("mesh density must be > 0 (kg/m^3), got " + format_number(density));
  }
  if (mesh.triangles.empty()) throw MeshError("mesh has no triangles");
  check_indices(mesh);

  // Two passes keep the second moments free of cancellation: the first, about the vertex
  // centroid, finds the COM; the second integrates about the COM itself.
  const Vec3 centroid = vertex_centroid(mesh);
  const VolumeMoments about_centroid = volume_moments(mesh, centroid);
  if (!(about_centroid.volume > 0.0)) {
    throw MeshError("mesh encloses a non-positive volume " + format_number(about_centroid.volume) +
                    " m^3: it is open or inside out (run validate_closed_mesh)");
  }
  const Vec3 com = centroid + about_centroid.first / about_centroid.volume;
  const VolumeMoments about_com = volume_moments(mesh, com);

  MassProperties mp;
  mp.mass = density * about_com.volume;
  // The residual first moment about the computed COM is round-off; remove its parallel-axis term
  // anyway: C_G = C - V d d^T with d = first / V.
  const Vec3 residual = about_com.first / about_com.volume;
  mp.com = com + residual;
  const Mat3 second_about_com =
      about_com.second - about_com.volume * residual * residual.transpose();
  const Mat3 inertia = density * (second_about_com.trace() * Mat3::Identity() - second_about_com);
  mp.inertia_about_com = 0.5 * (inertia + inertia.transpose());
  return mp;
}

TriangleMesh tessellate(const Shape& shape, int resolution) {
  shape_measure(shape);  // throws InertiaError naming a non-positive or inconsistent dimension
  if (shape.kind == ShapeKind::Box) return tessellate_box(shape.size);
  if (resolution < 3) {
    throw MeshError("tessellation resolution must be >= 3 segments around, got " +
                    std::to_string(resolution));
  }
  switch (shape.kind) {
    case ShapeKind::Cylinder:
      return tessellate_cylinder(shape.radius, shape.length, resolution);
    case ShapeKind::Tube:
      return tessellate_tube(shape.inner_radius, shape.outer_radius, shape.length, resolution);
    case ShapeKind::Sphere:
      return tessellate_sphere(shape.radius, resolution);
    case ShapeKind::Cone:
      return tessellate_cone(shape.radius, shape.height, resolution);
    default:
      throw MeshError("cannot tessellate a " + std::string(shape_name(shape.kind)) +
                      ": only the solids cylinder, tube, sphere, box and cone");
  }
}

}  // namespace tumble
