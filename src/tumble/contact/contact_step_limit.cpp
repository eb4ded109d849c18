// The longest step the contacts allow (docs/design.md, "Contact"): while a contact is apart, its
// touchdown event sees the heights of the surface's points only at the ends of steps, so no step
// may be long enough for a point to reach the landing height below the plane and come back.
#include <algorithm>
#include <limits>

#include "tumble/contact/contact_system.hpp"
#include "tumble/contact/landing_bound.hpp"
#include "tumble/contact/plane_contact.hpp"

namespace tumble {

namespace {

// The bound on how fast a point's normal velocity turns towards the plane is taken at the start
// of the step. Its rotational part (alpha x r + omega x (omega x r)) turns with the body within
// a step the bound allows; this factor covers that. The COM's acceleration into the plane is
// gravity's, exact, plus loads that change little over such a step: taken as it is, so that a
// falling body's step ends near its landing rather than well short of it.
constexpr double kTurningMargin = 2.0;

}  // namespace

double ContactSystem::step_limit(double t, const VecX& y) const {
  double limit = std::numeric_limits<double>::infinity();
  d_.rescreened = false;
  const bool any_apart =
      std::any_of(s_.contacts.begin(), s_.contacts.end(),
                  [](const ContactStatus& s) { return s.mode == ContactMode::Apart; });
  if (!any_apart) return limit;
  d_.time_now = t;
  calc_accelerations(y);  // for how fast the points' normal velocities turn
  // The broad phase: which of a group's pairs this step watches, and how long it may be for the
  // others to stay apart through it.
  limit = std::min(limit, screen_pairs());
  for (const std::size_t c : watched()) {
    if (s_.contacts[c].mode != ContactMode::Apart) continue;
    const PlaneContact& contact = contacts_[c];
    if (contact.touches_a_body()) {
      limit = std::min(limit, pair_time_to_depth(c));
      continue;
    }
    const BodyMotion w = dynamics_.motion(contact.body);
    const Vec3& n = contact.normal_W;
    const SurfaceMotion motion{w.r_G_W, w.R_WB, w.R_WB * w.velocity.tail<3>(),
                               w.R_WB * w.velocity.head<3>()};
    const Vec3 a_G_W = moving_point_acceleration_W(w, Vec3::Zero(), Vec3::Zero());
    // A point r from the COM: n . (a_G + alpha x r + omega x (omega x r)) >= -turning; a
    // sphere's lowest point does not move with its turning.
    const double reach = pairs_[c]->turning_reach(contact.surface);
    const double turning =
        std::max(0.0, -n.dot(a_G_W)) +
        kTurningMargin * (w.acceleration.head<3>().norm() + motion.omega_W.squaredNorm()) * reach;
    limit = std::min(limit,
                     time_to_reach_depth(contact, motion, turning, s_.contacts[c].landing_height));
  }
  return limit;
}

}  // namespace tumble
