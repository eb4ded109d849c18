#pragma once
// What differs from one pair of touching surfaces to the next, behind one interface
// (docs/design.md, "Where a new kind of contact goes"): which of a body's points may land, which
// part of it touches, the parts it settles and tips onto, and the points and names of the part
// that touches. ContactSystem keeps what is the same for every pair (the modes, the forces and
// their rows, the impact law, the events, the projection) and asks the pair for the rest; it
// never tests a surface's kind. Each pair is one class in one file:
//  - sphere_on_plane.cpp: a sphere or shell, touching at its lowest point, which moves over it;
//  - round_on_plane.cpp: a disk, ring, cylinder, tube or cone, on a rim point, its side or a face;
//  - polyhedron_on_plane.cpp: a box, plate or mesh, on a vertex, an edge or a face.
// contact_pair() (contact_pairs.cpp) is the one table that picks a contact's pair from the kinds
// of the two surfaces; contact between two bodies' surfaces adds its column there.
#include <span>
#include <string>
#include <vector>

#include "tumble/contact/contact_data.hpp"
#include "tumble/contact/contact_dynamics.hpp"
#include "tumble/contact/contact_point.hpp"
#include "tumble/contact/contact_status.hpp"
#include "tumble/contact/landing_bound.hpp"
#include "tumble/contact/plane_contact.hpp"
#include "tumble/math/function_ref.hpp"
#include "tumble/math/types.hpp"

namespace tumble {

// The height above the contact's plane of the body's point p_B (body axes, from the COM), and
// its material velocity along the plane's normal, for the body's motion w.
inline double height_above_plane(const PlaneContact& contact, const BodyMotion& w,
                                 const Vec3& p_B) {
  return (w.r_G_W + w.R_WB * p_B - contact.point_W).dot(contact.normal_W);
}
inline double normal_speed(const PlaneContact& contact, const BodyMotion& w, const Vec3& p_B) {
  const Vec3 v_P_B = w.velocity.tail<3>() + w.velocity.head<3>().cross(p_B);
  return contact.normal_W.dot(w.R_WB * v_P_B);
}

// A point of the body's surface, moving over the body at rate_B: a round body's lowest rim point
// stays lowest as the body spins about its axis, so it does not have the spin's centripetal
// acceleration that the material point there has (80 m/s^2 up, on a 5 cm rim at 40 rad/s: a
// rim that comes down would look as if it lifted).
struct SurfacePoint {
  Vec3 p_B = Vec3::Zero();
  Vec3 rate_B = Vec3::Zero();  // m/s, over the body
};

// One contact as its pair sees it: the plane and the surface, the body's motion at the state
// last evaluated (it follows later evaluations), the contact's status (its mode, its part, its
// scales), what was found for it at that state, and the contact subsystem's scratch list of
// touching vertices.
struct PairView {
  const PlaneContact& contact;
  BodyMotion motion;
  ContactStatus& status;
  ContactNow& now;
  std::vector<int>& touching;

  const ContactSurface& surface() const { return contact.surface; }
  // The plane's normal in body axes.
  Vec3 n_B() const { return motion.R_WB.transpose() * contact.normal_W; }
  double height(const Vec3& p_B) const { return height_above_plane(contact, motion, p_B); }
  double normal_speed(const Vec3& p_B) const { return tumble::normal_speed(contact, motion, p_B); }
  // Whether a point at this height (within the landing height) moving at this normal speed lands
  // with the one that touches down: not moving away from the plane; or at it (a landing located
  // to round-off), unless it leaves faster than a settling touchdown lands: that point has just
  // bounced off, and an impulse or a contact that held it there would take its bounce.
  bool lands_with(double height, double normal_speed) const {
    return normal_speed <= status.slip_zero ||
           (height <= status.touching_height && normal_speed <= status.settle_speed);
  }
};

class ContactPair {
 public:
  virtual ~ContactPair() = default;

  // The surface's point lowest along -n_B (body axes, from the COM: its support point over the
  // plane), and how fast that point moves over the body as the body turns at omega_B (the
  // plane's normal turns in body axes at n_B x omega_B, and the point follows it).
  virtual Vec3 lowest_point_B(const ContactSurface& surface, const Vec3& n_B) const = 0;
  virtual Vec3 lowest_point_rate_B(const ContactSurface& surface, const Vec3& n_B,
                                   const Vec3& omega_B) const = 0;
  // A length that sets the scale of the contact's tolerances (plane_contact.hpp's contact_size).
  virtual double size(const ContactSurface& surface) const = 0;
  // The first time a point of the surface could be `depth` below the plane (landing_bound.hpp).
  virtual double time_to_reach_depth(const PlaneContact& contact, const SurfaceMotion& motion,
                                     double turning, double depth) const = 0;

  // For `tumble modes`: the one point at which the surface rests on the plane (into `point`), or
  // why it rests on more than a point (an edge, a face, a line of its side: a small tilt moves
  // the plane's force, and the motion has no linearisation), as a sentence to follow "contact
  // NAME: "; empty where it rests on one. `lowest` is its support point (height within
  // `within`: touching), `height_of` a body point's height over the plane.
  virtual std::string resting_point(const ContactSurface& surface, const Vec3& n_B,
                                    const SupportPoint& lowest, double within,
                                    FunctionRef<double(const Vec3&)> height_of,
                                    ContactPoint& point) const = 0;

  // Whether, on a body a joint holds, its part's points are held one by one (a polyhedron's: the
  // joint takes what the plane does not).
  virtual bool held_point_by_point() const { return false; }
  // How far from the COM a point whose normal velocity the body's turning changes may be, for
  // the step limit: the surface's size; 0 for a sphere, whose lowest point turning never moves.
  virtual double turning_reach(const ContactSurface& surface) const {
    return contact_size(surface);
  }

  // The points of the part that touches, into v.now (after the body's motion, with the plane's
  // normal n_B in v.now and its rates zeroed); false where no part is held, and the contact
  // point is the surface's support point (a sphere; any surface apart).
  virtual bool calc_part_points(PairView& v, const Vec3& omega_B) const = 0;
  // Each point that may land first while the contact is apart (a sphere's lowest point; a
  // polyhedron's vertices, as the lowest may be leaving while another comes down; a round body's
  // ends' lowest rim points).
  virtual void for_each_landing_point(const PairView& v,
                                      FunctionRef<void(const Vec3&)> watch) const = 0;
  // Whether, touching, another of its points may still land (the touchdown event watches the
  // support point in v.now): not a sphere's.
  virtual bool lands_while_touching() const { return true; }
  // N times the centre of pressure's least distance inside the part (N itself at a point), and
  // the side where it is least (-1: none), from v.now's resultant.
  virtual double support_margin(const PairView& v, int& side) const = 0;
  // The part's name for the events ("a face", "its rim"), or nullptr where none is held.
  virtual const char* part_name(const PairView& v) const = 0;

  // A two-point part's end (0: its first point, 1: its second) for the events ("its apex").
  virtual const char* end_name(const PairView& v, int end) const {
    (void)v;
    return end == 0 ? "the edge's first end" : "the edge's second end";
  }

  // The part that touches (into v.status): points within `within` of the plane that land with
  // the touchdown (PairView::lands_with; with `resting`, only those not moving away from it).
  // Without `resting` something always touches (a landing located to round-off is at the
  // plane: at least its lowest part); with it, false where nothing does.
  virtual bool find_touching_part(PairView& v, double within, bool resting) const = 0;
  // After a landing that settles: the part, what landed with it (its points within the height
  // it takes as landing together).
  virtual void find_settled_part(PairView& v) const = 0;
  // After an impact that bounces: the part's points that did not bounce off stay on the plane
  // (into v.status); false where none does (it is apart).
  virtual bool keep_unbounced_part(PairView& v) const = 0;

  // Settling a touching contact on its part or the parts it may tip onto: `settle` is tried on
  // each candidate in order with the points the candidate leaves out (that must not go into the
  // plane) until one holds; true if one does. After the body's pose and velocity.
  using SettleTry = FunctionRef<bool(std::span<const SurfacePoint> left_out)>;
  virtual bool settle_on_candidates(PairView& v, SettleTry settle) const = 0;
  // Whether the part can tip (a face or an edge, a round body's part) at an impact whose
  // impulse's centre left it; and tipping there onto `side` (false: it cannot, and lands as it
  // is).
  virtual bool can_tip(const PairView& v) const = 0;
  virtual bool tip_at_impact(PairView& v, int side) const = 0;
  // After tip_at_impact: a part that has lost the point p_B that landed becomes that point alone
  // (a polyhedron's vertex), so that the impulse stops its approach.
  virtual void keep_landing_point(PairView& v, const Vec3& p_B) const {
    (void)v;
    (void)p_B;
  }
  // At the support event (the margin reached zero on `side`, with N and whether the plane still
  // presses by the subsystem's tolerance): tips onto the smaller part there, true; false if it
  // lifts off instead.
  virtual bool tip_on_support(PairView& v, int side, bool still_presses) const = 0;
  // On a held body (held_point_by_point), the point p_B whose push reached zero leaves the part
  // (into v.status); false where no point is left.
  virtual bool drop_point(PairView& v, const Vec3& p_B) const {
    (void)v;
    (void)p_B;
    return false;
  }
  // Whether, sticking, the part is held at an anchor fixed in the body (a polyhedron's feature, a
  // cone's apex, a round body's face); a rolling part moves over the body and is not.
  virtual bool anchored(const PairView& v) const = 0;
  // On one end's rim point: the other end's lowest rim point and its rate over the body (into
  // other), which must not go into the plane if it is at it; false where there is none.
  virtual bool other_end_B(const PairView& v, SurfacePoint& other) const {
    (void)v;
    (void)other;
    return false;
  }
  // Whether the part's points are its support point and nothing more (a sphere's lowest point, a
  // disk's or cylinder's rim point), so that moving a free body along the normal projects it;
  // and the height of that point (after the body's pose).
  virtual bool projects_along_normal(const PairView& v) const = 0;
  virtual double point_height(const PairView& v) const;
  // Whether the part keeps up with a direction that only steps see (a rim point near flat,
  // round_contact.hpp), and keeping up with it after a step.
  virtual bool follows_direction(const PairView& v) const {
    (void)v;
    return false;
  }
  virtual void follow_direction(PairView& v) const { (void)v; }
};

// What a body's surface touches: a fixed plane (a body's surface against another body's goes
// here).
enum class TouchedSurface { Plane };

// The one table of pairs: a body's surface of this kind touching `touched`.
const ContactPair& contact_pair(ContactSurface::Kind surface,
                                TouchedSurface touched = TouchedSurface::Plane);

}  // namespace tumble
