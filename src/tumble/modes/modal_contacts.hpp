#pragma once
// The contacts a linearisation holds (`tumble modes`): those touching their planes at t0, each at
// one point, and two bodies' spheres touching (a ball on a dome, in a bowl, on another ball). With
// friction the body's point there does not move (rolling or sticking: three constraints, as in a
// run's rolling mode); without, it only stays on the plane (one). The plane's force is whatever
// holds them, so the equations stay smooth and can be differentiated. A body resting on an edge, a
// face or a line of its side is refused: a small tilt moves its force to one edge or the other, and
// the motion has no linearisation there. What touches is decided by the run's touching height
// (contact/plane_contact.hpp) and where the point is by the contact's geometry
// (contact/contact_point.hpp). The run's Jacobian (state_jacobian.hpp) holds a run's contacts
// instead, in their modes, a sliding one with its friction.
#include <span>
#include <string>
#include <vector>

#include "tumble/contact/contact_hold.hpp"
#include "tumble/contact/contact_point.hpp"
#include "tumble/dynamics/model.hpp"

namespace tumble {

struct ModalContact {
  std::size_t contact = 0;  // in the model's contacts
  ContactPoint point;       // where it touches a plane
  // Two bodies touching (a sphere against a sphere or inside a shell): their points at the
  // contact point held together (modal_pair.hpp), rather than `point` against a plane.
  bool pair = false;
  Vec3 normal_W = Vec3::UnitZ();  // the plane's, or at t0 the pair's, towards the contact's body
  // Rolling or sticking (with friction): the point's whole motion held (three rows); otherwise
  // only its normal motion (one row), frictionless or, in a run's sliding mode, with Coulomb's
  // friction mu N along the slip (ContactHold's friction, follows_slip and slide_W).
  bool rolls = true;
  ContactHold sliding;
  int rows() const { return rolls ? 3 : 1; }
};

// The contacts touching their planes with the bodies at r_G_W, R_WB (per body), and the pairs of
// bodies touching. Throws NotSteady for one resting on an edge, a face or a line, and for a pair
// that touches along a line (two capsules lying along each other) or a circle (a sphere on a
// ring's axis), or whose sphere is over a seam of the other's surface (pair_core.hpp).
std::vector<ModalContact> touching_contacts(const Model& model, const std::vector<Vec3>& r_G_W,
                                            const std::vector<Mat3>& R_WB);
// The contacts as a run's modes hold them (`holds`, one per contact: contact_hold.hpp), with the
// bodies at r_G_W, R_WB: a hold on several points (Points) is one entry per point, each a point
// of the body.
std::vector<ModalContact> held_contacts(const Model& model, std::span<const ContactHold> holds,
                                        const std::vector<Vec3>& r_G_W,
                                        const std::vector<Mat3>& R_WB);

}  // namespace tumble
