#pragma once
// Where a touching pair of bodies touch, for `tumble modes`: a body's sphere against the other
// body's sphere, or inside its shell (a ball on a dome, in a bowl, on another ball), written over
// the scalar so that the linearisation differentiates it. The centres' line is the run's
// (contact/sphere_pair_line.hpp); the contact point O is where the run puts it, midway between
// the two surfaces' nearest points along n (the point of contact, where they touch), and moves
// with the other's centre, n's turning and the gap's rate:
//     O = p + (r_p + gap / 2) n,    O' = v_p + (r_p + gap / 2) n' + (gap' / 2) n,
// p the other's centre and r_p its radius (minus a shell's). The rows hold the two bodies' points
// at O together (rolling or sticking: three) or only their motion along n (frictionless: one),
// as a plane's hold its body's point. Two capsules are the same with p the other's axis's point
// nearest the first's and the normal along the line between the axes' nearest points
// (contact/axes_closest.hpp), p sliding along its axis at t':
//     O' = v_p + t' u_b + (r_p + gap / 2) n' + (gap' / 2) n.
// A sphere against any other core (a capsule, a box, a cylinder, a tube, a disk, a ring, a torus,
// a cone: contact/pair_core.hpp) is the same with p the core's point nearest the sphere's centre,
// sliding over the other body at p_rate along the feature's free directions, and n turning over
// that body at n_rate_B as the run's pair has it (core_line):
//     O' = v_p + R_b p_rate + (r_p + gap / 2) n' + (gap' / 2) n,   n' = w_b x n + R_b n_rate_B.
#include "tumble/body/rigid_body.hpp"
#include "tumble/contact/axes_closest.hpp"
#include "tumble/contact/pair_core.hpp"
#include "tumble/contact/plane_contact.hpp"
#include "tumble/contact/sphere_pair_line.hpp"

namespace tumble {

template <typename S>
struct ModalPairPointOf {
  Vec3Of<S> n_W, n_rate_W;  // from the other body towards the sphere, world
  Vec3Of<S> O_W, O_rate_W;  // the contact point and its rate, world
  S gap = S(0.0);           // m: the centres' distance less the radii
};

// The gap along n between the first's surface (radius `radius` about its core's point) and the
// other's (other_radius about p_W), and O midway between them along n, with its rate: n and n'
// set in `at` already; v_p_W the other body's material point's velocity at p, p_slide_W how fast
// p slides over that body (world), w the first's core point's velocity less that material
// point's (p slides square to n, so the gap's rate is n . w).
template <typename S>
void place_contact_point(ModalPairPointOf<S>& at, const S& distance, double radius,
                         double other_radius, const Vec3Of<S>& p_W, const Vec3Of<S>& v_p_W,
                         const Vec3Of<S>& p_slide_W, const Vec3Of<S>& w) {
  at.gap = distance - radius - other_radius;
  const S gap_rate = at.n_W.dot(w);
  const S reach = other_radius + 0.5 * at.gap;
  at.O_W = p_W + reach * at.n_W;
  at.O_rate_W = v_p_W + p_slide_W + reach * at.n_rate_W + (0.5 * gap_rate) * at.n_W;
}

// Two capsules (contact/axes_closest.hpp), as the run's pair takes them (sphere_pairs.cpp): p
// slides along the second's axis at t'.
template <typename S>
ModalPairPointOf<S> modal_capsules_point(const PlaneContact& contact, const BodyStateOf<S>& a,
                                         const BodyStateOf<S>& b) {
  const CapsulesLineOf<S> line = capsules_line<S>(contact.surface, a, contact.other_surface, b);
  ModalPairPointOf<S> at;
  at.n_W = line.n_W;
  at.n_rate_W = line.n_rate_W;
  const Vec3Of<S> v_p_b = b.v_G + b.omega_W.cross(Vec3Of<S>(line.p_b_W - b.r_G));
  place_contact_point<S>(at, line.distance, contact.surface.radius, contact.other_surface.radius,
                         line.p_b_W, v_p_b,
                         line.rates.t * (b.R_WB * contact.other_surface.axes_B.col(2).cast<S>()),
                         line.relative_velocity_W);
  return at;
}

// A sphere against the other body's core, as the run's pair takes it (sphere_pairs.cpp).
template <typename S>
ModalPairPointOf<S> modal_sphere_core_point(const PlaneContact& contact, const BodyStateOf<S>& a,
                                            const BodyStateOf<S>& b) {
  using V3 = Vec3Of<S>;
  const V3 centre_offset_W = a.R_WB * contact.surface.centre_B.cast<S>();
  const V3 centre_W = a.r_G + centre_offset_W;
  const V3 v_centre_W = a.v_G + a.omega_W.cross(centre_offset_W);
  // The centre and its velocity less the other body's material point's there, in its axes.
  const V3 x_B = b.R_WB.transpose() * V3(centre_W - b.r_G);
  const V3 u_B =
      b.R_WB.transpose() * V3(v_centre_W - (b.v_G + b.omega_W.cross(V3(centre_W - b.r_G))));
  const CoreLineOf<S> core = core_line<S>(contact.other_surface, x_B, u_B);
  ModalPairPointOf<S> at;
  at.n_W = b.R_WB * core.closest.n_B;
  at.n_rate_W = b.omega_W.cross(at.n_W) + b.R_WB * core.n_rate_B;
  const V3 p_offset_W = b.R_WB * core.closest.p_B;
  const V3 v_p_W = b.v_G + b.omega_W.cross(p_offset_W);  // the other body's material point at p
  place_contact_point<S>(at, core.closest.distance, contact.surface.radius,
                         core_radius(contact.other_surface), V3(b.r_G + p_offset_W), v_p_W,
                         V3(b.R_WB * core.p_rate_B), V3(v_centre_W - v_p_W));
  return at;
}

// Contact `contact` (a pair: a sphere against the other's sphere, shell or other core, or two
// capsules), its body in state a and the other in state b.
template <typename S>
ModalPairPointOf<S> modal_pair_point(const PlaneContact& contact, const BodyStateOf<S>& a,
                                     const BodyStateOf<S>& b) {
  if (contact.surface.kind == ContactSurface::Kind::Capsule) {
    return modal_capsules_point<S>(contact, a, b);
  }
  if (contact.other_surface.kind != ContactSurface::Kind::Sphere) {
    return modal_sphere_core_point<S>(contact, a, b);
  }
  using V3 = Vec3Of<S>;
  const V3 centre_offset_W = a.R_WB * contact.surface.centre_B.cast<S>();
  const V3 other_offset_W = b.R_WB * contact.other_surface.centre_B.cast<S>();
  const V3 v_centre_W = a.v_G + a.omega_W.cross(centre_offset_W);
  const V3 v_other_W = b.v_G + b.omega_W.cross(other_offset_W);
  const V3 other_W = b.r_G + other_offset_W;
  const V3 relative_velocity_W = v_centre_W - v_other_W;
  const SpherePairLineOf<S> line =
      sphere_pair_line<S>(V3(a.r_G + centre_offset_W - other_W), relative_velocity_W,
                          contact.other_surface.touched_inside);
  ModalPairPointOf<S> at;
  at.n_W = line.n_W;
  at.n_rate_W = line.n_rate_W;
  // The other's centre does not slide over its body.
  place_contact_point<S>(at, line.distance, contact.surface.radius,
                         core_radius(contact.other_surface), other_W, v_other_W, V3(V3::Zero()),
                         relative_velocity_W);
  return at;
}

}  // namespace tumble
