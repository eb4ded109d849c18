#pragma once
// The other surface of a contact between two bodies as a core swept by a radius: a sphere is its
// centre swept by its radius, a capsule its axis's segment between its caps' centres swept by
// its radius, a box its own solid (radius 0). The body's sphere touches it where
// the sphere's centre comes within the two radii of the core, so the gap is the centre's
// distance from the core less the radii, and the normal runs from the core's closest point to
// the centre. As the centre moves, that closest point slides over the core along the directions
// its feature leaves free (a box's face: both of the face's; an edge or a capsule's segment: its
// direction; a vertex, a segment's end or a sphere's centre: none), and the normal turns with what
// is left of the centre's motion across it (sphere_pairs.cpp). A cylinder or a disk is its own
// solid too (radius 0): its nearest point is on a flat face, on its round side (sliding along the
// axis and round it) or on a rim (round it); round a circle p_B moves at R / rho of the centre's
// motion round the axis, rho the centre's distance from the axis. A ring is its rim, a circle
// (radius 0), and a torus the same circle swept by its tube's radius.
//
// A shell touched from inside (a bowl) is its centre swept by minus its radius: the distance is
// measured along the normal, which runs from the centre towards the shell's wall (away from the
// sphere's centre, at minus the centres' distance), so that the gap, the distance less the radii,
// is R - d - r there, and every formula in the normal, its turning and the contact point holds
// with these signs.
#include <array>

#include "tumble/contact/plane_contact.hpp"
#include "tumble/math/types.hpp"

namespace tumble {

// Written over the scalar: a run's pairs take it in double (sphere_pairs.cpp), `tumble modes` in
// Dual, which differentiates it (modes/modal_pair.hpp), so that both hold the same geometry. Its
// branches (which feature is nearest) are the value's; the derivatives are those of the feature
// the value is on.
template <typename S>
struct CoreClosestOf {
  // The core's point nearest the centre (body axes, from the COM), and the unit normal from it
  // towards the centre (any, where they coincide).
  Vec3Of<S> p_B = Vec3Of<S>::Zero();
  Vec3Of<S> n_B = Vec3Of<S>::UnitZ();
  // m, of the centre from the core along n (< 0: inside a box, by that much; inside a shell,
  // minus the centres' distance)
  S distance = S(0.0);
  int slide_count = 0;  // how many directions p_B slides along: 2 a face, 1 an edge or segment
  std::array<Vec3Of<S>, 2> slide_B = {Vec3Of<S>::Zero(), Vec3Of<S>::Zero()};  // unit, body axes
  // How fast p_B moves along each direction per unit of the centre's motion along it: 1 over a
  // flat feature; round a circle of radius R (a cylinder's side or rim) whose axis the centre is
  // rho from, R / rho.
  std::array<S, 2> slide_scale = {S(1.0), S(1.0)};
  // Whether the nearest point is on a circle (a ring's, a torus's, a rim, a bore) whose axis the
  // centre is within a billionth of its radius of: every point of that circle is then as near,
  // or nearly, and the two touch along the circle. On a ring's or a torus's circle, or a bore's
  // rim, the contact is then held as the circle's resultant: p_B the circle's centre, n_B its
  // axis (pair_core.cpp, touching_all_round).
  bool on_circle_axis = false;
  // Whether the centre is within a billionth of the core's size of a seam, where the nearest
  // point passes from one feature to the next (a box's face to its edge, a cylinder's side or
  // face to its rim, a cone's side to its apex, a capsule's side to its cap): the normal turns on
  // one side of the seam and not (or otherwise) on the other, and the contact has no
  // linearisation there.
  bool on_feature_seam = false;
};
using CoreClosest = CoreClosestOf<double>;

// The core's point nearest x_B (body axes, from the COM), of a sphere, capsule, box, cylinder,
// tube, disk, ring, torus or cone surface.
template <typename S>
CoreClosestOf<S> core_closest(const ContactSurface& surface, const Vec3Of<S>& x_B);
extern template CoreClosestOf<double> core_closest(const ContactSurface&, const Vec3&);
extern template CoreClosestOf<Dual> core_closest(const ContactSurface&, const Vec3Of<Dual>&);

// The nearest point as the centre moves at u_B relative to the other body's material point at
// x_B (both in that body's axes): how fast p_B slides over the body (along each free direction,
// at its scale of the centre's motion along it), and how fast n turns over the body (with what
// is left of that motion across n, over the distance: none where the centre is on the core).
template <typename S>
struct CoreLineOf {
  CoreClosestOf<S> closest;
  Vec3Of<S> p_rate_B = Vec3Of<S>::Zero();
  Vec3Of<S> n_rate_B = Vec3Of<S>::Zero();
};
template <typename S>
CoreLineOf<S> core_line(const ContactSurface& surface, const Vec3Of<S>& x_B, const Vec3Of<S>& u_B);
extern template CoreLineOf<double> core_line(const ContactSurface&, const Vec3&, const Vec3&);
extern template CoreLineOf<Dual> core_line(const ContactSurface&, const Vec3Of<Dual>&,
                                           const Vec3Of<Dual>&);

// The radius that sweeps the core: a sphere's or capsule's, a torus's tube's; a box's,
// cylinder's, disk's or ring's 0; a shell's touched from inside, minus its radius.
double core_radius(const ContactSurface& surface);
// The length that sets a pair's tolerances: the smaller radius (a box's core has none).
double pair_size(const PlaneContact& contact);

}  // namespace tumble
