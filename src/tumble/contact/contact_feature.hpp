#pragma once
// The part of a polyhedron (a box, a plate, a mesh's convex hull) that touches a plane: one
// vertex, an edge or a face, found from the vertices at the plane. A rigid body pressed onto a
// plane along a feature feels a resultant whose centre of pressure (CoP) must lie in the
// feature: in the face's polygon, on the edge's segment, at the vertex. When the CoP reaches the
// boundary the body tips onto the smaller feature there (a face onto an edge, an edge onto a
// vertex), so the feature keeps, per side of its boundary, a linear function of the resultant
// that is >= 0 while the CoP is inside (support_margin).
//
// Everything is in body axes, from the COM: the feature is fixed in the body while it lasts.
#include <array>
#include <span>
#include <vector>

#include "tumble/math/types.hpp"

namespace tumble {

struct ContactFeature {
  // Vertex indices of the boundary, counter-clockwise about the plane's normal: 1 vertex, the 2
  // ends of an edge, or a face's convex polygon (>= 3).
  std::vector<int> polygon;
  // Per side j of the boundary: the inward normal (in the plane) at the side's first vertex
  // polygon[j]. An edge has two sides, one at each end, pointing along the edge.
  std::vector<Vec3> inward_B;
  // Where the constraints on the normal motion are taken: the vertex; the edge's ends; three
  // vertices of the face spanning it (the widest triangle).
  std::array<int, 3> normal_points{};
  int normal_point_count = 0;
  Vec3 reference_B = Vec3::Zero();  // the feature's centroid: friction acts and slip is taken here
  // Torsional friction radius: the largest friction moment about the normal is mu N times this
  // (the mean distance from the centroid under uniform pressure; 0 for a vertex).
  double spin_radius = 0.0;

  int size() const { return static_cast<int>(polygon.size()); }
  bool contains(int vertex) const;
};

// Two unit vectors in the plane of unit normal n, with u x v = n.
void plane_basis(const Vec3& n, Vec3& u, Vec3& v);

// Room for a feature of up to `vertex_count` vertices, so that building one later allocates
// nothing.
void reserve_feature(ContactFeature& feature, std::size_t vertex_count);

// The feature spanned by the `touching` vertices (indices into vertices_B) on a plane of normal
// n_B (body axes, unit): their convex hull in the plane. `touching` must not be empty.
void make_feature(std::span<const Vec3> vertices_B, std::span<const int> touching, const Vec3& n_B,
                  ContactFeature& feature);

// The feature the body tips onto when side `side` of the boundary carries the CoP: a face's edge
// polygon[side]..polygon[side + 1]; an edge's end polygon[side]. Needs size() >= 2.
void tip_onto_side(std::span<const Vec3> vertices_B, int side, const Vec3& n_B,
                   ContactFeature& feature);

// For a contact resultant of normal component N and moment M_O_B about reference_B (the
// normal's direction n_B): N times the CoP's distance inside side j, least over the sides (the
// side index in `side`). >= 0 while the CoP is in the feature; for a vertex, N itself.
double support_margin(const ContactFeature& feature, std::span<const Vec3> vertices_B,
                      const Vec3& n_B, double N, const Vec3& M_O_B, int& side);

}  // namespace tumble
