#pragma once
// The parts of a round body that touch a plane: a cone, a disk or ring, a cylinder or tube, a
// torus, a capsule. Each is bounded by two circles about its z axis, its ends A and B (body axes,
// from the COM):
//  - a cone: A its apex (a circle of radius 0), B its base's rim;
//  - a cylinder or tube: A the rim at z = -L/2, B the rim at z = +L/2;
//  - a disk or ring: its one rim, both ends at once;
//  - a torus: a ring's rim swept by its tube; a capsule: its caps' centres (z = -+L/2, circles of
//    radius 0) swept by its radius, as a tube: what touches is the point of the swept sphere
//    below a rim point (a cap's lowest point), which turns over the body as a sphere's does.
// It touches at a point of an end's rim (the apex), along the line of its side between the two
// ends' rim points below the axis, or on an end's face (a disk; a ring's or tube's face holds
// only its rim, but its pressure's centre may be anywhere in the circle). As for a polyhedron's
// feature (contact_feature.hpp), the plane's resultant must have its centre of pressure (CoP)
// in the part: on the side's segment, in the face's circle; when the CoP reaches the boundary
// the body tips onto the rim point there.
//
// Unlike a polyhedron's vertices, a rim point moves over the body as it turns: rolling on a rim
// or on the side, the point of contact runs round the rim.
#include <array>

#include "tumble/contact/plane_contact.hpp"
#include "tumble/math/types.hpp"

namespace tumble {

// What of a round body touches: None, apart; EndA / EndB, a point of that end's rim (the cone's
// apex for A); Side; FaceA / FaceB, lying on that end's face.
enum class RoundPart { None, EndA, EndB, Side, FaceA, FaceB };

// The two end circles of a round surface (ContactSurface::Kind Circle, Cylinder or Cone).
struct RoundEnds {
  std::array<Vec3, 2> centre_B = {Vec3::Zero(), Vec3::Zero()};  // m, from the COM
  std::array<double, 2> radius = {0.0, 0.0};                    // m
  double face_inner_radius = 0.0;  // m: a ring's or tube's faces are hollow within it
  bool one_rim = false;            // a disk or ring: A and B are the same circle
  // The ends' axes in the body's: their circles lie in the plane of the first two, about the
  // third. The body's own (`turned` false) but for a composite's part.
  Mat3 axes_B = Mat3::Identity();
  bool turned = false;
  double tube = 0.0;  // m: a torus's tube about its one rim (0: the rim itself)
};

RoundEnds round_ends(const ContactSurface& surface);

// v_B less its part along the ends' axis: its projection on the ends' plane (body axes).
Vec3 in_ends_plane(const RoundEnds& ends, const Vec3& v_B);
// The direction x e1 + y e2 of the ends' plane (body axes; e1, e2 the ends' first two axes).
Vec3 ends_plane_direction(const RoundEnds& ends, double x, double y);
// The unit vector of the ends' plane most opposed to n_B: where their circles are lowest. The
// length of n_B's projection on the plane (the sine of the ends' tilt from the plane) goes to
// `projected_length`; flat (projection zero), the ends' first axis is returned.
Vec3 lowest_rim_direction(const RoundEnds& ends, const Vec3& n_B, double& projected_length);
// The sine of the ends' tilt from a plane of normal n_B.
double tilt_sine(const RoundEnds& ends, const Vec3& n_B);

// 0 for the parts at end A, 1 at end B (its rim point or its face).
int end_of(RoundPart part);
bool is_face(RoundPart part);
// EndA or EndB: one end's rim point (a cone's apex).
bool is_end(RoundPart part);
// Whether the part holds a rim point (of radius > 0), which moves round its rim (not a face, not
// a cone's apex, not a capsule's cap).
bool holds_rim_point(const ContactSurface& surface, RoundPart part);

// Where a round part's contact constraints are taken, and how those points move over the body.
struct RoundPartPoints {
  // The points whose normal motion the part constrains: the rim point (the apex); the two ends'
  // rim points (side, end A first); three points of the face's rim at 120 degrees.
  // (Eigen's vectors are not zeroed by `{}`: every entry is set here.)
  std::array<Vec3, 3> points_B = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  std::array<Vec3, 3> rates_B = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};  // over the body, m/s
  int count = 0;
  // Where slip is taken and friction acts: the point; the line's middle; the face's centre.
  Vec3 reference_B = Vec3::Zero();
  Vec3 reference_rate_B = Vec3::Zero();
  // Torsional friction radius (mean distance from the reference point under even pressure):
  // 0 at a point, L/4 on the side's line of length L, 2r/3 on a full face, r on a ring's.
  double spin_radius = 0.0;
};

// The direction (in the ends' plane, unit) of the rim points lowest along -n_B, and their motion
// over the body when the body turns at omega_B. Near flat the lowest point is ill-defined (just
// tipped off a face, or about to land on it), so the direction leans towards `previous` (the
// last one known) by a weight of 1e-12 against the tilt: exact to ~1e-12 relative once the
// body leans, continuous through flat.
Vec3 rim_direction(const RoundEnds& ends, const Vec3& n_B, const Vec3& previous_B);
// The direction (into u_B) and its rate (into u_rate_B), from one normalisation.
void rim_direction_and_rate(const RoundEnds& ends, const Vec3& n_B, const Vec3& omega_B,
                            const Vec3& previous_B, Vec3& u_B, Vec3& u_rate_B);

// The rim point of end k (0: A, 1: B) in direction u_B (unit, in the ends' plane).
Vec3 rim_point(const RoundEnds& ends, int k, const Vec3& u_B);
// The surface's point lowest along -n_B over a point of a rim (or an end's centre): that point
// itself; a torus's, its tube's radius further along -n_B.
Vec3 on_surface(const RoundEnds& ends, const Vec3& circle_point_B, const Vec3& n_B);
// The surface's point over end k's rim point in direction u_B (on_surface of rim_point). And that
// point's motion over the body from the rim point's (rim_rate_B), the body turning at omega_B (the
// normal turns in body axes at n_B x omega_B).
Vec3 surface_point(const RoundEnds& ends, int k, const Vec3& u_B, const Vec3& n_B);
Vec3 surface_point_rate(const RoundEnds& ends, const Vec3& rim_rate_B, const Vec3& n_B,
                        const Vec3& omega_B);

// The points of `part` on a plane of normal n_B (unit, body axes), the body turning at omega_B;
// `rim_direction_B` is the rim points' direction where the part holds them.
RoundPartPoints round_part_points(const RoundEnds& ends, RoundPart part, const Vec3& n_B,
                                  const Vec3& omega_B, const Vec3& rim_direction_B);

// For a contact resultant of normal component N and moment M_O_B about the part's reference
// point O: N times the CoP's distance inside the part (the side, between its end points
// points_B[0] (A) and points_B[1] (B): from each end, `side` 0 at A, 1 at B; a face: from its
// rim, `side` 0), N itself for a point. >= 0 while the CoP is in.
double round_support_margin(const ContactSurface& surface, RoundPart part,
                            const std::array<Vec3, 3>& points_B, const Vec3& O_B, const Vec3& n_B,
                            double N, const Vec3& M_O_B, int& side);

// Where the CoP of a resultant on a face leaves it: the rim direction (body axes, unit) it
// points to from the centre, `otherwise_B` if it is at the centre.
Vec3 face_tip_direction(const RoundEnds& ends, const Vec3& n_B, const Vec3& M_O_B,
                        const Vec3& otherwise_B);

// "its apex", "its rim", "its side", "its base" (a cone); "its rim", "its face" (a disk or
// ring); "its -z rim", "its +z face", ... (a cylinder or tube, by the end's side of the COM);
// "its -z cap", "its +z cap", "its side" (a capsule).
const char* round_part_name(const ContactSurface& surface, RoundPart part);

}  // namespace tumble
