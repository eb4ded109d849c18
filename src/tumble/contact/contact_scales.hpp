#pragma once
// The scales a contact's tolerances are taken from, fixed at the run's start (ContactStatus):
// what counts as no slip, as touching, as a landing that settles. A plane's contact takes them
// from its body's surface and speed; a pair of bodies from both bodies' (sphere_pairs.cpp).
#include "tumble/body/rigid_body.hpp"
#include "tumble/contact/plane_contact.hpp"
#include "tumble/math/types.hpp"

namespace tumble {

// Slip slower than this fraction of the contact's speed scale counts as none: events locate the
// slip's zero to a few ulps of t, leaving ~1e-15 of the scale.
inline constexpr double kSlipZero = 1e-9;
// Touchdowns whose bounce would rise less than this fraction of the contact's size settle
// (restitution 0): the cascade of ever smaller bounces ends after finitely many.
inline constexpr double kSettleHeight = 1e-6;
// An impact's work counts as none (not a gain) within this fraction of the kinetic energy: an
// elastic impact's is zero up to round-off.
inline constexpr double kWorkRoundOff = 1e-12;

struct ContactScales {
  double size = 1.0;   // m: the length the heights are fractions of
  double speed = 1.0;  // m/s
  double slip_zero = 0.0, settle_speed = 0.0, touching_height = 0.0, landing_height = 0.0;
};

// A body's contact with a plane, from its surface's size and the body's state s.
ContactScales contact_scales(const PlaneContact& contact, const Vec3& gravity_W,
                             const BodyState& s);
// A contact between two bodies' spheres, from the smaller sphere and both bodies' states.
ContactScales pair_contact_scales(const PlaneContact& contact, const Vec3& gravity_W,
                                  const BodyState& a, const BodyState& b);

}  // namespace tumble
