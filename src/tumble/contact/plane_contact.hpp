#pragma once
// A body touching a fixed plane (the ground, a ramp): the plane, the Coulomb and restitution
// coefficients, and the part of the body's surface that can touch it. The surfaces are those
// whose lowest point is one point that moves smoothly over the body as it turns:
//  - a sphere or a shell (its centre at the COM);
//  - a circle in the body's x-y plane about the z axis: the rim of a disk or a ring, a cylinder
//    on one of its end rims;
//  - a cylinder lying on its side touches along a line; the resultant of an even pressure on it
//    acts at the line's middle, the lowest point of the circle z = 0.
// For each the contact point is the lowest point of the surface (its support point in -n), and
// it moves over the body at a rate that the rolling constraint needs (see support_rate_B).
#include <string>
#include <vector>

#include "tumble/math/types.hpp"

namespace tumble {

// A polyhedron (a box, a plate, a mesh) touches a plane at its vertices: at one, along an edge
// between two, or on a face (contact_feature.hpp); its support point is its lowest vertex.
// A cone touches at its apex, at a point of its base's rim, along a line of its side or on its
// base (cone_contact.hpp); its support point is the lower of its apex and its rim's lowest point.
struct ContactSurface {
  enum class Kind { Sphere, Circle, Cylinder, Polyhedron, Cone } kind = Kind::Sphere;
  double radius = 0.0;               // m; a cone's base
  double half_length = 0.0;          // m, cylinder: the end rims are at z = +-half_length
  std::vector<Vec3> vertices;        // m, polyhedron: from the COM, body axes; a cone: its apex
  Vec3 rim_centre_B = Vec3::Zero();  // m, a cone's base centre (its rim about the z axis)
};

struct PlaneContact {
  std::string name;
  std::size_t body = 0;
  ContactSurface surface;
  Vec3 point_W = Vec3::Zero();    // a point of the plane, m
  Vec3 normal_W = Vec3::UnitZ();  // unit, out of the plane towards the body
  double friction = 0.0;          // Coulomb mu, >= 0
  double restitution = 0.0;       // Newton's e in [0, 1]
};

// The lowest point of a surface over the plane, and its height above it.
struct SupportPoint {
  Vec3 p_GC_B = Vec3::Zero();  // contact point from the COM, body axes, m
  double height = 0.0;         // of the contact point above the plane, m (< 0: inside)
};

// The support point for a body at (r_G, R_WB) over the plane.
SupportPoint support_point(const PlaneContact& contact, const Vec3& r_G_W, const Mat3& R_WB);

// How fast the support point moves over the body (body axes, m/s) when the body turns at
// omega_B: the plane's normal turns in body axes at n_B' = n_B x omega_B, and the support point
// follows it.
Vec3 support_rate_B(const PlaneContact& contact, const Vec3& n_B, const Vec3& omega_B);

// The vertex of a polyhedron lowest along -n_B (the first of equals).
int lowest_vertex(const ContactSurface& surface, const Vec3& n_B);

// The unit vector in the body's x-y plane most opposed to n_B: where a circle about the z axis
// is lowest. Its projection on that plane's length goes to `projected_length`; a circle lying
// flat (projection zero) has no lowest point, and x is returned.
Vec3 lowest_in_plane(const Vec3& n_B, double& projected_length);

// A disk's, ring's or cylinder's rim (Circle, Cylinder): how far its highest point rises above its
// lowest along the plane's normal, 2 r sin(tilt); zero where it lies flat on a face, which these
// surface models do not resolve (its contact point would run round the rim ever faster).
double rim_rise(const ContactSurface& surface, const Vec3& n_B);

// Whether the surface is a rim that can lie flat on a face (rim_rise applies).
bool lies_flat_on_faces(const ContactSurface& surface);

// A length that sets the scale of the contact's tolerances: the surface's radius, or a
// polyhedron's (a cone's) farthest vertex (or rim point) from the COM.
double contact_size(const ContactSurface& surface);

}  // namespace tumble
