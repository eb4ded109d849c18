#pragma once
// A body touching a fixed plane (the ground, a ramp): the plane, the Coulomb and restitution
// coefficients, and the part of the body's surface that can touch it:
//  - a sphere or a shell (its centre at the COM, or, a composite's part, anywhere in the body),
//    whose lowest point moves smoothly over it as it turns;
//  - a round body: a disk or ring, a cylinder or tube, a cone, a torus, a capsule
//    (round_contact.hpp), which touches at a rim point (a capsule's cap), along its side or on a
//    face;
//  - a polyhedron: a box, a plate, a mesh (contact_feature.hpp), which touches at a vertex,
//    along an edge or on a face.
// Apart, the contact point watched for touchdown is the surface's lowest point (its support
// point in -n).
#include <string>
#include <vector>

#include "tumble/math/types.hpp"

namespace tumble {

// A polyhedron's support point is its lowest vertex; a round body's, the lower of its two ends'
// lowest rim points (round_contact.hpp).
struct ContactSurface {
  // A capsule touches a plane as a round body (round_contact.hpp) and another body's sphere.
  enum class Kind { Sphere, Circle, Cylinder, Polyhedron, Cone, Capsule } kind = Kind::Sphere;
  double radius = 0.0;  // m; a cone's base
  // m, cylinder: the end rims are at z = +-half_length; capsule: its caps' centres
  double half_length = 0.0;
  std::vector<Vec3> vertices;        // m, polyhedron: from the COM, body axes; a cone: its apex
  Vec3 rim_centre_B = Vec3::Zero();  // m, a cone's base centre (its rim about the z axis)
  // m: a ring's or tube's end faces are annuli from this radius out (0: full disks)
  double face_inner_radius = 0.0;
  Vec3 centre_B = Vec3::Zero();  // m, a sphere's, box's or capsule's centre from the COM (a part's)
  // m, a box's half-sizes along its axes (axes_B: the body's own, or a composite's box part's):
  // what touches another body's sphere (pair_core.hpp); zero for every other shape.
  Vec3 half_size = Vec3::Zero();
  // A composite's round part (a disk or ring, a cylinder or tube, a cone) or capsule: its own
  // axes in the body's (its axis of symmetry the third), and centre_B its centre (a cylinder's
  // middle, a disk's centre; a cone's apex and base centre are in `vertices` and rim_centre_B,
  // placed already).
  // Otherwise the body's own axes and COM (`turned` false).
  Mat3 axes_B = Mat3::Identity();
  bool turned = false;
  // m, a torus (kind Circle): its surface is the points within this of its centre circle, so
  // what touches is the circle's point that a ring would touch, this much further down.
  double tube_radius = 0.0;
  // A shell that another body's sphere touches from inside (a bowl, a spherical cavity): the
  // sphere started within it (pair_core.hpp).
  bool touched_inside = false;
};

// A contact between two bodies' surfaces (`type: bodies`) is one of these too, so that every
// contact has its place in the model's list, its columns, events and ledger entry: `body`'s
// surface (a sphere) touches `other_body`'s other_surface (a sphere, a box, a capsule, ...:
// pair_core.hpp), or a capsule touches a capsule (axes_closest.hpp), and point_W and normal_W
// are unused (sphere_pairs.cpp).
struct PlaneContact {
  static constexpr std::size_t kNoOtherBody = static_cast<std::size_t>(-1);

  std::string name;
  std::size_t body = 0;
  ContactSurface surface;
  std::size_t other_body = kNoOtherBody;
  ContactSurface other_surface;
  bool touches_a_body() const { return other_body != kNoOtherBody; }
  // A pair of a group, which the broad phase watches only while its two bodies come near
  // (broad_phase.hpp); a pair named on its own is always watched.
  bool screened = false;
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

// A length that sets the scale of the contact's tolerances: a sphere's radius, or a polyhedron's
// (a round body's) farthest vertex (or rim point) from the COM.
double contact_size(const ContactSurface& surface);

// How near the plane a surface's point counts as touching it: this fraction of its size. A run's
// contact modes and `tumble modes` decide what touches by it alike.
inline constexpr double kTouchingHeightPerSize = 1e-9;
double touching_height(const ContactSurface& surface);

}  // namespace tumble
