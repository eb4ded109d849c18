#pragma once
// The parts of a cone that touch a plane. A cone (apex A on its z axis, base of radius r about
// the z axis, its centre C) touches at its apex, at one point of its base's rim, along a line of
// its side (from the apex to a rim point: it lies on its side), or on its base (a disk face). As
// for a polyhedron's feature (contact_feature.hpp), the plane's resultant must have its centre
// of pressure (CoP) in the part: on the line's segment, in the base's disk; when the CoP reaches
// the boundary the cone tips onto the apex or the rim point there.
//
// Unlike a polyhedron's vertices, the rim point moves over the body as the cone turns: rolling
// on its rim or its side, the point of contact runs round the rim. Everything is in body axes,
// from the COM.
#include <array>

#include "tumble/contact/plane_contact.hpp"
#include "tumble/math/types.hpp"

namespace tumble {

enum class ConePart { None, Apex, Rim, Side, Base };  // None: apart

// Where a cone part's contact constraints are taken, and how those points move over the body.
struct ConePartPoints {
  // The points whose normal motion the part constrains: the apex; the rim point; the apex and
  // the rim point (side); three points of the rim at 120 degrees (base).
  // (Eigen's vectors are not zeroed by `{}`: every entry is set here.)
  std::array<Vec3, 3> points_B = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  std::array<Vec3, 3> rates_B = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};  // over the body, m/s
  int count = 0;
  // Where slip is taken and friction acts: the point; the line's middle; the base's centre.
  Vec3 reference_B = Vec3::Zero();
  Vec3 reference_rate_B = Vec3::Zero();
  // Torsional friction radius (mean distance from the reference point under even pressure):
  // 0 at a point, L/4 on the side's line of length L, 2r/3 on the base.
  double spin_radius = 0.0;
};

// The direction (body x-y plane, unit) of the rim point lowest along -n_B, and its motion over
// the body when the body turns at omega_B. Near flat the lowest point is ill-defined (a cone
// just tipped off its base, or about to land on it), so the direction leans towards `previous`
// (the last one known) by a weight of 1e-12 against the tilt: exact to ~1e-12 relative once
// the cone leans, continuous through flat.
Vec3 rim_direction(const Vec3& n_B, const Vec3& previous_B);
Vec3 rim_direction_rate(const Vec3& n_B, const Vec3& omega_B, const Vec3& previous_B);

// The points of `part` for a cone on a plane of normal n_B (unit, body axes), the body turning
// at omega_B; `rim_direction_B` is the rim point's direction where the part holds one.
ConePartPoints cone_part_points(const ContactSurface& cone, ConePart part, const Vec3& n_B,
                                const Vec3& omega_B, const Vec3& rim_direction_B);

// For a contact resultant of normal component N and moment M_O_B about the part's reference
// point O: N times the CoP's distance inside the part (the side, from the apex to rim_point_B:
// from each end, `side` 0 at the apex, 1 at the rim; the base: from the rim), N itself for a
// point. >= 0 while the CoP is in.
double cone_support_margin(const ContactSurface& cone, ConePart part, const Vec3& rim_point_B,
                           const Vec3& O_B, const Vec3& n_B, double N, const Vec3& M_O_B,
                           int& side);

// Where the CoP of a resultant on the base leaves it: the rim direction (body axes, unit) it
// points to from the centre, `otherwise_B` if it is at the centre.
Vec3 base_tip_direction(const Vec3& n_B, const Vec3& M_O_B, const Vec3& otherwise_B);

const char* cone_part_name(ConePart part);  // "its apex", "its rim", "its side", "its base"

}  // namespace tumble
