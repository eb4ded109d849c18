// The contacts' modes as a hybrid system (docs/design.md, "Contact"): each contact is apart,
// sliding, or rolling (sticking), and only located events change that. Three event functions per
// contact:
//  - touchdown: the height of the contact point (a polyhedron: of its lowest vertex not already
//    touching) while it approaches; an impact follows;
//  - support: the normal force (a polyhedron's face or edge: N times the centre of pressure's
//    distance inside the feature); at zero the body lifts off, or tips onto the feature's side;
//  - stick-slip: sliding, the slip along its direction (and a grown slip left within round-off
//    of zero stops a moment later); rolling, mu N less the friction needed. A slip that starts
//    is slip_onset.cpp's.
#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "tumble/contact/contact_system.hpp"

#include "tumble/contact/contact_scales.hpp"

#include "tumble/math/constraint_solve.hpp"

namespace tumble {

namespace {

// A slip that has grown is followed by its own direction down to this fraction of slip_zero
// (still ~1e6 above the round-off of the velocities it is the difference of) while it keeps to
// the way it went at the step's start (ContactSystem::slide_direction).
constexpr double kSlipFloor = 1e-3;
// A grown slip that a step leaves below slip_zero stops this fraction of the time scale later
// (the slip-stop event), unless it crosses zero first.
constexpr double kSlipStopWait = 1e-6;
// Where the slip's component along its direction vanishes (the slip-stop event), a slip left
// within this many slip_zero (1e-6 of the speed scale) has stopped: in 3D it passes near zero,
// not through it, turning faster than steps resolve, and would hover there, friction flipping.
constexpr double kSlipStoppedNear = 1e3;
// A slip that has been above that, and comes back within it to hover there (no smaller at the
// end of a step than at its start), stops this fraction of the time scale later.
constexpr double kHoverStopWait = 1e-9;
// Settled landings that go apart at once (or slip stops that slide on at once), each within this
// fraction of the time scale of the last, this many in a row: a cascade that would not end
// (docs/design.md, "Painleve").
constexpr double kCascadeGap = 1e-6;
constexpr int kCascadeEvents = 1000;
// Impacts at one instant on one contact, at most: each takes energy out (or none, elastic), and
// an impulse on one vertex drives another into the plane less each time.
constexpr int kImpactRounds = 100;

// Rolling or sticking holds while the friction it needs is within this fraction of mu N over
// the cone's edge: at the edge itself (a sphere on a ramp at exactly mu = (2/7) tan(theta)) the
// two agree only to round-off, and a slip that started there would grow slower than slip_zero
// over the time scale (start_sliding could not see it grow, and the contact would be left with
// no mode: apart, landing again at once).
constexpr double kFrictionEdge = 1e-9;

// A face's or an edge's support (N times the CoP's distance inside it) reaches zero where its
// centre of pressure reaches a side (the body tips onto that side), or where N itself reaches
// zero (it lifts off: a ladder's top leaving a frictionless wall). At the located zero of a
// lift-off N is round-off, and its sign says nothing: deciding by it tipped the ladder onto a
// vertex at N = +6e-13 N, and the vertex then pulled the ladder to the wall (N down to -197 N).
// The plane still presses where N is above kSlipZero of the body's weight (of its mass times
// 1 m/s^2 where gravity is weaker), the tolerance the contact's accelerations are held to.
bool still_presses(double N, double mass, const Vec3& gravity_W) {
  return N > kSlipZero * mass * std::max(gravity_W.norm(), 1.0);
}

}  // namespace

double ContactSystem::support_margin_of(std::size_t c, int& side) const {
  if (held_polyhedron_[c]) {
    // The plane pushes at each point it holds, or the point leaves (drop_point).
    side = -1;
    return d_.now[c].least_point_force;
  }
  return pairs_[c]->support_margin(view(c), side);
}

Vec3 ContactSystem::pushed_direction(std::size_t c) const {
  // Against the friction sticking needs, which then saturates at mu N.
  const Vec3 needed = friction_demand(c);
  const double size = needed.norm();
  return size > 0.0 ? Vec3(-needed / size) : s_.contacts[c].slide_direction_W;
}

Vec3 ContactSystem::friction_demand(std::size_t c) const {
  const ContactNow& now = d_.now[c];
  const double rho = now.spin_radius;
  const Vec3& n = contacts_[c].normal_W;
  if (!(rho > 0.0)) return now.friction_W;
  return now.friction_W + (now.moment_about_O_B.dot(now.n_B) / rho) * n;
}

ContactSystem::EndFrictions ContactSystem::end_frictions(std::size_t c, double edge) const {
  // Two points, each holding what its own cone holds: the friction across the part at each end
  // is what the rows found there, and the friction along it (all at the first end's rows) may
  // be shared between the ends as they can take it.
  const ContactNow& now = d_.now[c];
  EndFrictions ends;
  ends.along_direction_W = part_direction_W(c);
  const Vec3& e = ends.along_direction_W;
  for (std::size_t k = 0; k < 2; ++k) {
    const Vec3& F_W = now.end_friction_W[k];
    ends.cap[k] = edge * contacts_[c].friction * now.end_normal_force[k];
    ends.across_W[k] = F_W - e * e.dot(F_W);
    ends.along += e.dot(F_W);
    const double across = ends.across_W[k].norm();
    ends.room[k] = std::sqrt(std::max(0.0, ends.cap[k] * ends.cap[k] - across * across));
  }
  return ends;
}

double ContactSystem::stick_margin(std::size_t c, double edge) const {
  // Friction without a limit (`friction: inf`, between two bodies): it never slips.
  if (std::isinf(contacts_[c].friction)) return 1.0;
  if (!two_point(c)) {
    return edge * contacts_[c].friction * d_.now[c].normal_force - friction_demand(c).norm();
  }
  const EndFrictions ends = end_frictions(c, edge);
  double margin = ends.room[0] + ends.room[1] - std::abs(ends.along);
  for (std::size_t k = 0; k < 2; ++k)
    margin = std::min(margin, ends.cap[k] - ends.across_W[k].norm());
  return margin;
}

Vec3 ContactSystem::part_direction_W(std::size_t c) const {
  const ContactNow& now = d_.now[c];
  const Vec3& n = contacts_[c].normal_W;
  const Vec3 d_W =
      dynamics_.motion(contacts_[c].body).R_WB * (now.normal_points_B[1] - now.normal_points_B[0]);
  return (d_W - n * n.dot(d_W)).normalized();
}

double ContactSystem::watched_height(std::size_t c, double height, double normal_speed) const {
  // The height, but kept positive while the point is at the plane (within the landing height)
  // and not moving into it: a bounce may rise and land again within one step (its flight is a
  // parabola, which a high-order method steps over), and the height alone would not change sign
  // between the impact (h = 0) and the landing (h < 0); a polyhedron's vertices that just left
  // the plane start at h = 0. Right after an event, whatever it left at the plane counts as not
  // yet landed, however it moves (a contact that lifts off, with round-off of normal speed, may
  // turn straight back): the event function must start above zero to see it cross. A point
  // deeper than the landing height has crossed the plane, even if it now rises (a tumbling
  // body's end that dipped through it and is turning back at the end of a step; step_limit keeps
  // a whole dip from fitting inside one).
  const ContactStatus& status = s_.contacts[c];
  const bool at_plane = height >= -status.landing_height;
  const bool after_event = d_.time_now == s_.last_event_t;
  return at_plane && (normal_speed > -status.slip_zero || after_event)
             ? std::max(height, status.touching_height)
             : height;
}

double ContactSystem::landing_watch(std::size_t c, Vec3& landing_B) const {
  // Every point that may land first: a polyhedron's vertices (the lowest may be leaving the plane
  // while another comes down through it), a round body's ends' lowest rim points, a sphere's
  // lowest point.
  double least = std::numeric_limits<double>::infinity();
  const auto watch = [&](const Vec3& p_B) {
    const double g = watched_height(c, height_above_plane(c, p_B), normal_speed(c, p_B));
    if (g < least) {
      least = g;
      landing_B = p_B;
    }
  };
  pairs_[c]->for_each_landing_point(view(c), watch);
  return least;
}

void ContactSystem::event_functions(double t, const VecX& y, VecX& g) const {
  d_.time_now = t;
  if (any_touching()) {
    calc_accelerations(y);
  } else {
    dynamics_.calc_motion(y, true);
    calc_contact_points();
  }
  // A far pair's (broad_phase.hpp) hold at 1: it cannot touch within the step.
  if (watched().size() < contacts_.size()) g.setOnes();
  for (const std::size_t c : watched()) {
    const auto base = static_cast<Eigen::Index>(3 * c);
    const ContactNow& now = d_.now[c];
    const ContactStatus& status = s_.contacts[c];
    const PlaneContact& contact = contacts_[c];
    g(base) = g(base + 1) = g(base + 2) = 1.0;
    // Apart, the point nearest to landing (two bodies: their spheres' gap); touching, a
    // polyhedron or a round body watches the part that may land next.
    Vec3 landing_B = Vec3::Zero();
    if (contact.touches_a_body()) {
      if (status.mode == ContactMode::Apart) {
        g(base) = watched_height(c, now.support.height, now.support_normal_speed);
      }
    } else if (status.mode == ContactMode::Apart) {
      g(base) = landing_watch(c, landing_B);
    } else if (pairs_[c]->lands_while_touching()) {
      g(base) = watched_height(c, now.support.height, now.support_normal_speed);
    }
    if (status.mode == ContactMode::Apart) continue;
    int side = -1;
    g(base + 1) = support_margin_of(c, side);
    if (status.mode == ContactMode::Sliding) {
      double end_value = 0.0;
      const bool ends_watched = two_point(c) && stopping_end(c, end_value) >= 0;
      if (contact.friction > 0.0 && two_point(c) && status.pinned_end >= 0) {
        // Pivoting: the pinned end's friction reaches the cone's edge, or the other end's slip
        // stops.
        g(base + 2) = pinned_friction_margin(c);
        if (ends_watched) g(base + 2) = std::min(g(base + 2), end_value);
      } else if (contact.friction > 0.0 && ends_watched) {
        // A two-point part whose ends slide on their own: either end's slip stops.
        g(base + 2) = end_value;
      } else if (contact.friction > 0.0) {
        // The slip stops where its component along the direction it had at the start of the
        // step vanishes; a grown slip that a step leaves below slip_zero (where it may turn, or
        // hover, instead of crossing zero along any one direction) has stopped, an instant on.
        g(base + 2) = now.slip_W.dot(status.slide_direction_W);
        if (status.slip_stop_armed) g(base + 2) = std::min(g(base + 2), status.slip_stop_by - t);
      }
    } else {
      // The cone's edge as classification takes it (kFrictionEdge): at exactly the critical
      // friction the demand hovers at mu N to round-off, and must not leave it.
      g(base + 2) = stick_margin(c, 1.0 + kFrictionEdge);
    }
  }
}

int ContactSystem::stopping_end(std::size_t c, double& value) const {
  const ContactStatus& status = s_.contacts[c];
  const ContactNow& now = d_.now[c];
  int stopping = -1;
  for (int k = 0; k < 2; ++k) {
    const auto e = static_cast<std::size_t>(k);
    if (k == status.pinned_end || status.end_slide_direction_W[e].isZero(0.0)) continue;
    const double along = now.end_slip_W[e].dot(status.end_slide_direction_W[e]);
    if (stopping < 0 || along < value) {
      stopping = k;
      value = along;
    }
  }
  return stopping;
}

double ContactSystem::pinned_friction_margin(std::size_t c) const {
  const auto k = static_cast<std::size_t>(s_.contacts[c].pinned_end);
  const ContactNow& now = d_.now[c];
  return (1.0 + kFrictionEdge) * contacts_[c].friction * now.end_normal_force[k] -
         now.end_friction_W[k].norm();
}

void ContactSystem::pin_or_push_end(std::size_t c, int end, const VecX& y) {
  ContactStatus& status = s_.contacts[c];
  const auto k = static_cast<std::size_t>(end);
  status.pinned_end = end;
  status.end_slide_direction_W[k].setZero();
  status.end_slip_grown[k] = false;
  calc_accelerations(y);
  if (d_.now[c].end_normal_force[k] > 0.0 && pinned_friction_margin(c) >= 0.0) return;
  // It cannot hold: it slides from rest against the friction it would need.
  const Vec3 needed_W = d_.now[c].end_friction_W[k];
  status.pinned_end = -1;
  if (needed_W.norm() > 0.0) status.end_slide_direction_W[k] = -needed_W.normalized();
  calc_accelerations(y);
}

bool ContactSystem::refresh_event_functions(double t, const VecX& y) {
  d_.time_now = t;
  bool refresh = false;
  for (const std::size_t c : watched()) {
    const ContactStatus& s = s_.contacts[c];
    refresh |= s.mode == ContactMode::Sliding || pairs_[c]->follows_direction(view(c));
  }
  if (!refresh) return false;
  // The slip-stop event watches the slip's component along the direction it had at the start of
  // the step: in 3D the slip may turn, and it stops where that component first vanishes. A round
  // body's rim point leans towards where it was (round_contact.hpp): that is kept up with it.
  dynamics_.calc_motion(y, true);
  calc_contact_points();
  for (const std::size_t c : watched()) {
    ContactStatus& status = s_.contacts[c];
    const double slip = d_.now[c].slip_W.norm();
    if (status.mode == ContactMode::Sliding &&
        (slip > status.slip_zero || (status.slip_grown && slip > status.slip_floor))) {
      status.slide_direction_W = d_.now[c].slip_W / slip;
      status.slide_turn_W.setZero();  // the slip itself says where it goes
      status.slip_grown = true;
    }
    const bool sliding = status.mode == ContactMode::Sliding;
    const double near = kSlipStoppedNear * status.slip_zero;
    if (sliding && slip > near) status.slip_left_near = true;
    const bool in_band = sliding && status.slip_grown && slip <= status.slip_zero;
    // Back near zero and no smaller than a step ago: it hovers (friction flips it this way and
    // that in steps ever shorter) instead of running straight into zero as a stop does.
    const bool hovers = sliding && status.slip_left_near && slip <= near &&
                        slip >= status.slip_last_step && !in_band;
    if (hovers && !status.slip_stop_armed) {
      status.slip_stop_by = t + kHoverStopWait * status.time_scale;
    } else if (in_band && !status.slip_stop_armed) {
      status.slip_stop_by = t + kSlipStopWait * status.time_scale;
    }
    status.slip_stop_armed =
        in_band || hovers ||
        (status.slip_stop_armed && sliding && status.slip_left_near && slip <= near);
    status.slip_last_step = sliding ? slip : 0.0;
    if (sliding && two_point(c)) {
      // Each end's slip, followed once it has grown (its stop is watched from then on).
      for (int k = 0; k < 2; ++k) {
        const auto e = static_cast<std::size_t>(k);
        const double end_slip = d_.now[c].end_slip_W[e].norm();
        if (k == status.pinned_end || !(end_slip > status.slip_zero)) continue;
        status.end_slide_direction_W[e] = d_.now[c].end_slip_W[e] / end_slip;
        status.end_slip_grown[e] = true;
      }
    }
    PairView v = view(c);
    if (pairs_[c]->follows_direction(v)) pairs_[c]->follow_direction(v);
  }
  return true;
}

void ContactSystem::note_contact(double t, std::size_t contact, std::string what,
                                 std::optional<ContactImpactNumbers> impact) {
  s_.events.push_back({t, contact, std::move(what), impact});
}

void ContactSystem::note_event_numbers(std::size_t first, const VecX& y) {
  if (first >= s_.events.size()) return;
  dynamics_.calc_motion(y, true);
  calc_contact_points();
  const double kinetic_energy = dynamics_.kinetic_energy();
  for (std::size_t i = first; i < s_.events.size(); ++i) {
    ContactEventRecord& e = s_.events[i];
    const ContactNow& now = d_.now[e.contact];
    // An impact's energies are its own; a change of modes gives no impulse, so the energy is
    // the same on both sides of it (a stopping slip's last trace, below slip_zero, aside).
    e.kinetic_energy_before = e.impact ? e.impact->kinetic_energy_before : kinetic_energy;
    e.kinetic_energy_after = e.impact ? e.impact->kinetic_energy_after : kinetic_energy;
    const Vec3& n = normal_of(e.contact);
    e.normal_speed = now.velocity_W.dot(n);
    e.slip_speed = (now.slip_W - n * n.dot(now.slip_W)).norm();
    const BodyMotion w = dynamics_.motion(contacts_[e.contact].body);
    e.point_W = w.r_G_W + w.R_WB * now.reference_B;
    e.normal_W = n;
  }
}

double ContactSystem::height_above_plane(std::size_t c, const Vec3& p_B) const {
  const PlaneContact& contact = contacts_[c];
  return tumble::height_above_plane(contact, dynamics_.motion(contact.body), p_B);
}

double ContactSystem::normal_speed(std::size_t c, const Vec3& p_B) const {
  const PlaneContact& contact = contacts_[c];
  return tumble::normal_speed(contact, dynamics_.motion(contact.body), p_B);
}

double ContactSystem::normal_acceleration(std::size_t c, const Vec3& p_B,
                                          const Vec3& rate_B) const {
  const PlaneContact& contact = contacts_[c];
  const BodyMotion w = dynamics_.motion(contact.body);
  return contact.normal_W.dot(moving_point_acceleration_W(w, p_B, rate_B));
}

bool ContactSystem::settle_on_feature(std::size_t c, double t, VecX& y,
                                      std::span<const SurfacePoint> left_out) {
  ContactStatus& status = s_.contacts[c];
  const PlaneContact& contact = contacts_[c];
  const ContactNow& now = d_.now[c];
  // Consistent: the plane pushes (N > 0) with its CoP in the feature, and the touching vertices
  // (points) left out of the feature do not go into the plane.
  const auto consistent = [&] {
    int side = -1;
    if (!(now.normal_force > 0.0) || support_margin_of(c, side) < 0.0) return false;
    const double tolerance = kSlipZero * std::max(gravity_W_.norm(), 1.0);
    for (const int i : d_.touching) {
      if (status.feature.contains(i)) continue;
      const Vec3& p = contact.surface.vertices[static_cast<std::size_t>(i)];
      if (normal_acceleration(c, p) < -tolerance) return false;
    }
    for (const SurfacePoint& p : left_out) {
      if (normal_acceleration(c, p.p_B, p.rate_B) < -tolerance) return false;
    }
    return true;
  };
  status.mode = ContactMode::Rolling;
  status.clear_end_slips();  // a two-point part's ends: from their slips now
  // Where joints tie the contact's motions together, rolling may ask for accelerations no force
  // gives together: then it cannot roll or stick, and slides the way it is pushed.
  bool can_roll = true;
  try {
    calc_accelerations(y);
  } catch (const InconsistentConstraints&) {
    can_roll = false;
  }
  const double slip = now.slip_W.norm();
  const bool end_moves[2] = {now.end_slip_W[0].norm() > status.slip_zero,
                             now.end_slip_W[1].norm() > status.slip_zero};
  if (can_roll && contact.friction > 0.0 && two_point(c) && (end_moves[0] || end_moves[1])) {
    // A two-point part with an end that slips: each end slides against its own slip, or, with
    // one end at rest, it pivots there if the friction that needs fits in the cone.
    status.mode = ContactMode::Sliding;
    status.slide_direction_W = slip > 0.0 ? Vec3(now.slip_W / slip) : status.slide_direction_W;
    status.slide_turn_W.setZero();
    status.slip_grown = slip > status.slip_zero;
    status.slip_left_near = false;
    status.slip_stop_armed = false;
    for (std::size_t k = 0; k < 2; ++k) {  // (the ends were cleared above)
      if (!end_moves[k]) continue;
      status.end_slide_direction_W[k] = now.end_slip_W[k].normalized();
      status.end_slip_grown[k] = true;
    }
    if (end_moves[0] != end_moves[1]) {
      pin_or_push_end(c, end_moves[0] ? 1 : 0, y);
    } else {
      calc_accelerations(y);
    }
    if (!consistent()) return false;
    // Pinned: what is left of its slip (below slip_zero) goes.
    if (status.pinned_end >= 0) project(t, y);
    return true;
  }
  if (!can_roll) {
    if (!start_sliding(c, t, y)) return false;
  } else if (slip > status.slip_zero) {
    status.mode = ContactMode::Sliding;
    status.slide_direction_W = now.slip_W / slip;
    status.slide_turn_W.setZero();
    status.slip_grown = true;
    status.slip_left_near = false;
    status.slip_stop_armed = false;
    calc_accelerations(y);
  } else if (contact.friction > 0.0 && now.normal_force > 0.0 &&
             stick_margin(c, 1.0 + kFrictionEdge) >= 0.0) {
    if (!consistent()) return false;
    anchor_contact(c);
    project(t, y);  // no slip at all from here
    return true;
  } else if (!start_sliding(c, t, y)) {
    return false;
  }
  return consistent();
}

bool ContactSystem::end_stop_watched(std::size_t c) const {
  double value = 0.0;
  return stopping_end(c, value) >= 0;
}

void ContactSystem::on_end_slip_event(std::size_t c, double t, VecX& y) {
  ContactStatus& status = s_.contacts[c];
  calc_accelerations(y);
  double end_value = std::numeric_limits<double>::infinity();
  const int stopping = stopping_end(c, end_value);
  const PairView v = view(c);
  if (status.pinned_end >= 0 && !(pinned_friction_margin(c) > end_value)) {
    // The pinned end's friction reached the cone's edge first: it slides from rest, against the
    // friction it needed.
    const int k = status.pinned_end;
    const char* end = pairs_[c]->end_name(v, k);
    pin_or_push_end(c, k, y);
    // (Still pinned: the friction fits after all, the event having been round-off.)
    if (status.pinned_end < 0) {
      note_contact(t, c,
                   fmt::format("{} slides: the friction sticking needs leaves the cone", end));
    }
    return;
  }
  const auto e = static_cast<std::size_t>(stopping);
  const double slip = d_.now[c].end_slip_W[e].norm();
  if (slip > kSlipStoppedNear * status.slip_zero) {
    // The end's slip turned away from the direction it had; it did not stop.
    status.end_slide_direction_W[e] = d_.now[c].end_slip_W[e] / slip;
    status.end_slip_grown[e] = true;
    return;
  }
  note_contact(t, c, fmt::format("slip stops at {}", pairs_[c]->end_name(v, stopping)));
  // What is left of its slip goes (the least kinetic-energy change that holds that end), so that
  // the end counts as at rest: left at up to kSlipStoppedNear slip_zero, it would count as
  // sliding, and stop again at once. The other end, sliding with a slip as near zero, has stopped
  // with it (a cone's side coming to roll, its two ends stopping within round-off of each other):
  // what is left of its slip goes too, else it would stop again an instant on, or not, as
  // round-off fell.
  const auto other = static_cast<std::size_t>(1 - stopping);
  const bool both = status.pinned_end < 0 &&
                    d_.now[c].end_slip_W[other].norm() <= kSlipStoppedNear * status.slip_zero;
  const int pinned = status.pinned_end;
  status.pinned_end = stopping;
  project(t, y);
  if (both) {
    status.pinned_end = static_cast<int>(other);
    project(t, y);
  }
  status.pinned_end = pinned;
  classify_contact(c, t, y);
}

void ContactSystem::classify_contact(std::size_t c, double t, VecX& y, bool always_note) {
  ContactStatus& status = s_.contacts[c];
  const ContactMode before = status.mode;
  const int size_before = status.feature.size();
  const RoundPart part_before = status.round_part;
  const int pinned_before = status.pinned_end;
  const bool held = settle_on_candidates(c, t, y);
  if (!held) set_apart(c);
  const int size = status.feature.size();
  const bool same = status.mode == before && size == size_before &&
                    status.round_part == part_before && status.pinned_end == pinned_before;
  if (same && !always_note) return;
  std::string what = status.mode == ContactMode::Apart     ? "apart"
                     : status.mode == ContactMode::Sliding ? "slides"
                     : anchored(c) || held_polyhedron_[c]  ? "sticks"
                                                           : "rolls";
  const PairView v = view(c);
  if (const char* part = pairs_[c]->part_name(v)) what += fmt::format(" on {}", part);
  if (status.mode == ContactMode::Sliding && status.pinned_end >= 0) {
    what +=
        fmt::format(", turning about {}, which sticks", pairs_[c]->end_name(v, status.pinned_end));
  }
  note_contact(t, c, std::move(what));
}

bool ContactSystem::settle_on_candidates(std::size_t c, double t, VecX& y) {
  dynamics_.calc_motion(y, false);
  PairView v = view(c);
  return pairs_[c]->settle_on_candidates(v, [&](std::span<const SurfacePoint> left_out) {
    return settle_on_feature(c, t, y, left_out);
  });
}

void ContactSystem::set_apart(std::size_t c) {
  ContactStatus& status = s_.contacts[c];
  status.mode = ContactMode::Apart;
  status.slide_turn_W.setZero();
  status.slip_stop_armed = false;
  status.clear_end_slips();
  status.feature.polygon.clear();  // keeps its reserved room
  status.feature.inward_B.clear();
  status.feature.spin_radius = 0.0;
  status.round_part = RoundPart::None;
}

bool ContactSystem::anchored(std::size_t c) const {
  // A held polyhedron's points are held one by one, and the joint holds the rest.
  if (held_polyhedron_[c]) return false;
  return pairs_[c]->anchored(view(c));
}

void ContactSystem::anchor_contact(std::size_t c) {
  const PlaneContact& contact = contacts_[c];
  if (!anchored(c)) return;  // it rolls: no anchor
  const ContactNow& now = d_.now[c];
  ContactStatus& status = s_.contacts[c];
  const BodyMotion w = dynamics_.motion(contact.body);
  const Vec3& n = contact.normal_W;
  const auto on_plane = [&](const Vec3& p_B) {
    const Vec3 x = w.r_G_W + w.R_WB * p_B;
    return Vec3(x - n * n.dot(x - contact.point_W));
  };
  const bool edge = now.normal_point_count == 2;
  status.anchor_W[0] = on_plane(edge ? now.normal_points_B[0] : now.reference_B);
  status.anchor_W[1] = on_plane(edge ? now.normal_points_B[1] : now.reference_B);
  status.anchor_R_WB = w.R_WB;
}

void ContactSystem::impact(std::size_t c, double t, VecX& y) {
  const PlaneContact& contact = contacts_[c];
  ContactStatus& status = s_.contacts[c];
  const ContactPair& pair = *pairs_[c];
  PairView v = view(c);
  dynamics_.calc_motion(y, true);
  calc_contact_points();
  // The point that landed: apart, the one the event watched (not always the lowest).
  Vec3 landing_B = d_.now[c].support.p_GC_B;
  if (status.mode == ContactMode::Apart) landing_watch(c, landing_B);
  const double vn_before = normal_speed(c, landing_B);
  const bool settles = -vn_before <= status.settle_speed || contact.restitution == 0.0;
  const double energy_before = dynamics_.kinetic_energy();
  // Points about to land with it (within the settling height) land together: a box falling
  // flat would otherwise rattle between its corners in ever shorter bounces. Each law starts
  // from that landing part (an attempt may tip it).
  pair.find_touching_part(v, status.landing_height, false);
  d_.landing = status;
  d_.landing.clear_end_slips();  // a sliding impulse's ends slide as the slip before it maps

  // Newton's restitution on the normal motion, Coulomb on the tangential impulse: the impulse
  // that leaves no slip if it lies in the cone, else a sliding impulse (normal impulses, each
  // with mu of it against the slip). A polyhedron lands on every vertex at the plane; if the
  // impulse's centre would leave that feature, it lands on the smaller feature there. Should the
  // impulse add energy (it can, where rotation couples normal and tangential motion), the impact
  // is taken as plastic (e = 0). Should a plastic sliding impulse still add energy (its friction,
  // held along the slip before it, can drive the slip the other way: a box landing on an edge
  // while it tumbles), it is taken plastic and frictionless, which never does (the normal rows'
  // velocities go to zero: -v.W^-1 v / 2 of kinetic energy) and lies in the cone.
  struct ImpactLaw {
    double e;
    bool friction;
  };
  const ImpactLaw laws[] = {{settles ? 0.0 : contact.restitution, true}, {0.0, true}, {0.0, false}};
  double work = 0.0;
  Eigen::Index count = 0;
  for (const ImpactLaw& law : laws) {
    status = d_.landing;
    for (int attempt = 0; attempt < 3; ++attempt) {
      dynamics_.calc_motion(y, true);
      calc_contact_points();
      const ContactNow& now = d_.now[c];
      const auto solve_for_restitution = [&] {
        for (Eigen::Index i = 0; i < count; ++i) {
          const ContactUnknown& row = d_.unknowns[static_cast<std::size_t>(i)];
          d_.x(i) = -(row.normal ? 1.0 + law.e : 1.0) * row_velocity(row);
        }
        solve_contact_rows(count, d_.x, RowQuantity::Velocity);
        set_contact_resultants(count, d_.x);  // the impulse, as a force would be
      };
      if (law.friction) {
        count = append_contact_unknowns(c, ContactMode::Rolling, ContactRows::Projection,
                                        Vec3::Zero(), 0);
        // No impulse may both bounce the contact and stop its slip where a joint ties the two
        // together (a pendulum's bob on a wall): then it slides.
        bool sticks = true;
        try {
          solve_for_restitution();
        } catch (const InconsistentConstraints&) {
          sticks = false;
        }
        if (!sticks || !(stick_margin(c, 1.0) >= 0.0)) {
          const double slip = now.slip_W.norm();
          const Vec3 slide = slip > 0.0 ? Vec3(now.slip_W / slip) : pushed_direction(c);
          count = append_contact_unknowns(c, ContactMode::Sliding, ContactRows::Motion, slide, 0);
          solve_for_restitution();
        }
      } else {
        // Sliding's rows for projection: the normal ones, with no friction on them.
        count = append_contact_unknowns(c, ContactMode::Sliding, ContactRows::Projection,
                                        Vec3::Zero(), 0);
        solve_for_restitution();
      }
      int side = -1;
      if (pair.can_tip(v) && support_margin_of(c, side) < 0.0) {
        if (held_polyhedron_[c]) {
          drop_point(c, now.least_point_B);
        } else if (!pair.tip_at_impact(v, side)) {
          break;
        } else {
          // An impulse that stops nothing of the point that landed is no impact: tipped onto a
          // side without it (a box sticking on an edge whose face lands), it lands on that point.
          pair.keep_landing_point(v, landing_B);
        }
        continue;
      }
      break;
    }
    d_.impact_y = y;
    apply_contact_impulses(count, d_.x, d_.impact_y);
    dynamics_.calc_motion(d_.impact_y, true);
    work = dynamics_.kinetic_energy() - energy_before;
    if (work <= kWorkRoundOff * energy_before) break;
  }
  // The impulse the last law applied (the solve left it as a force would be).
  const Vec3 impulse_W = d_.now[c].force_W;
  y = d_.impact_y;
  add_work(c, work, y);
  dynamics_.calc_motion(y, true);
  const double vn_after = normal_speed(c, landing_B);
  const ContactImpactNumbers numbers{energy_before, energy_before + work, -vn_before, vn_after,
                                     impulse_W};
  const char* part = pair.part_name(v);
  const std::string on = part ? fmt::format(" on {}", part) : std::string();
  const std::string impact_note =
      settles ? fmt::format("touchdown{} at normal speed {:.3g} m/s: settles", on, -vn_before)
              : fmt::format("impact{}: normal speed {:.4g} -> {:.4g} m/s, {:.4g} J lost", on,
                            -vn_before, vn_after, -work);
  note_contact(t, c, impact_note, numbers);
  release_contacts_sent_away(c, t, y);
  if (settles) {
    pair.find_settled_part(v);
    classify_contact(c, t, y, true);  // the impact set the part: say what holds it
    check_landing_cascade(c, t, -vn_before);
    return;
  }
  if (!pair.keep_unbounced_part(v)) {
    set_apart(c);  // it bounces (a sphere: it was apart)
    return;
  }
  classify_contact(c, t, y);
}

void ContactSystem::release_contacts_sent_away(std::size_t landed, double t, VecX& y) {
  for (const std::size_t c : watched()) {
    if (c == landed || s_.contacts[c].mode == ContactMode::Apart) continue;
    if (still_touches_after_jump(c, y)) continue;
    set_apart(c);
    note_contact(t, c,
                 fmt::format("lifts off: the impact at {} sends it away", contacts_[landed].name));
  }
}

bool ContactSystem::cascade_goes_on(std::size_t c, double t, bool undone) {
  ContactStatus& status = s_.contacts[c];
  // An event that the same instant undoes (a settled landing that nothing holds; a slip stop
  // that slides on at once) and that follows the last one within kCascadeGap of the time scale
  // continues a cascade; anything else ends it. Past kCascadeEvents in a row it would not end.
  const bool follows = t - status.cascade_last_t <= kCascadeGap * status.time_scale;
  if (undone && !follows) status.cascade_first_t = t;
  status.cascade_events = undone ? (follows ? status.cascade_events + 1 : 1) : 0;
  status.cascade_last_t = t;
  return status.cascade_events >= kCascadeEvents;
}

void ContactSystem::check_landing_cascade(std::size_t c, double t, double speed) {
  const ContactStatus& status = s_.contacts[c];
  if (!cascade_goes_on(c, t, status.mode == ContactMode::Apart)) return;
  // Painleve's inconsistent case: friction presses it on while it slides, yet with no force it
  // goes into the plane; the literature resolves it by an impulse (a jam), not built. Friction
  // without a limit: rolling on would pull the two together (N < 0), and free, the friction that
  // rolling took is gone, which presses them on; with a finite mu they would slide before they
  // part.
  const double mu = contacts_[c].friction;
  const std::string why = std::isinf(mu)
                              ? std::string(
                                    "rolling on would pull the bodies together, and without its "
                                    "friction they are pressed on (friction: inf never lets them "
                                    "slip); give the contact a finite friction")
                              : fmt::format(
                                    "no mode is consistent here (Painleve's paradox: friction {} "
                                    "presses the body on as it slides); lower the friction",
                                    mu);
  throw std::runtime_error(fmt::format(
      "contact '{}': {} landings from t = {:.9g} to {:.9g} s (the last at {:.3g} m/s) that no "
      "contact mode holds: {}",
      contacts_[c].name, status.cascade_events, status.cascade_first_t, t, speed, why));
}

void ContactSystem::check_slip_stop_cascade(std::size_t c, double t) {
  const ContactStatus& status = s_.contacts[c];
  if (!cascade_goes_on(c, t, status.mode == ContactMode::Sliding)) return;
  // A body wedged as it slides (a ball between a wall, the floor and another ball): each slip
  // that stops starts again at once, no mode holding it; as Painleve's case, a jam (an impulse)
  // would resolve it, not built.
  throw std::runtime_error(fmt::format(
      "contact '{}': {} slip stops from t = {:.9g} to {:.9g} s, each sliding on at once: no "
      "contact mode holds its friction here (the body is wedged as it slides, its contacts' "
      "friction {} pressing it on); lower the friction",
      contacts_[c].name, status.cascade_events, status.cascade_first_t, t, contacts_[c].friction));
}

void ContactSystem::on_event(std::size_t event_index, double t, VecX& y) {
  const std::size_t first_new = s_.events.size();
  d_.time_now = t;
  s_.last_event_t = -std::numeric_limits<double>::infinity();  // until it is handled
  const std::size_t c = event_index / 3;
  ContactStatus& status = s_.contacts[c];
  switch (event_index % 3) {
    case 0:  // touchdown
      if (contacts_[c].touches_a_body()) {
        const double approach = pair_impacts(c, t, y);
        // The bodies' contacts with planes, in the speeds the impulses left (a ball rolling on a
        // table, struck, slides; a ball rolling into a step leaves the floor).
        classify_touching(t, y, true, "lifts off: an impact between bodies sends it away");
        // A settling touchdown or a plastic strike leaves a pair together with no speed between
        // them. Where something pushes them into each other (a ball resting on another; a ball
        // struck into a pendulum's bob, which then swings away from its straight path), the
        // contact holds them from here, rather than a chatter of ever smaller impacts.
        enter_pressed_pairs(t, y);
        // A touchdown that settles and that nothing then holds, again and again at once, is a
        // plane's cascade of landings: no mode is consistent (a log rolling off a rail with
        // `friction: inf`, which would pull to keep rolling, is pressed on once free).
        if (approach <= status.settle_speed) check_landing_cascade(c, t, approach);
        break;
      }
      impact(c, t, y);
      // Left apart with a point at the plane moving into it (the impulse on one vertex of an
      // edge can drive the other down), it lands again at once, rather than a step later.
      for (int round = 1; round < kImpactRounds && status.mode == ContactMode::Apart; ++round) {
        dynamics_.calc_motion(y, true);
        calc_contact_points();
        Vec3 p_B = Vec3::Zero();
        if (landing_watch(c, p_B) > 0.0 || !(normal_speed(c, p_B) < -status.slip_zero)) break;
        impact(c, t, y);
      }
      break;
    case 1:  // support: lift-off, or the CoP at the feature's side
      on_support_event(c, t, y);
      break;
    default:
      if (status.mode == ContactMode::Sliding && contacts_[c].friction > 0.0 && two_point(c) &&
          (status.pinned_end >= 0 || end_stop_watched(c))) {
        on_end_slip_event(c, t, y);
      } else if (status.mode == ContactMode::Sliding) {
        dynamics_.calc_motion(y, true);
        calc_contact_points();
        const double slip = d_.now[c].slip_W.norm();
        if (slip > kSlipStoppedNear * status.slip_zero) {
          // The slip turned away from the direction it had (3D); it did not stop.
          status.slide_direction_W = d_.now[c].slip_W / slip;
          status.slide_turn_W.setZero();
          status.slip_grown = true;
          status.slip_stop_armed = false;
          break;
        }
        note_contact(t, c, "slip stops");
        if (slip > status.slip_zero) {
          // What is left of it goes: the least kinetic-energy change that leaves no slip.
          status.mode = ContactMode::Rolling;
          anchor_contact(c);  // held where it is now, not where it last stuck
          project(t, y);
          status.mode = ContactMode::Sliding;
        }
        classify_contact(c, t, y);
        check_slip_stop_cascade(c, t);
      } else {
        calc_accelerations(y);
        if (pulling(c)) {
          // Its push jumped below zero with the friction it needs (a sphere rolling over a box's
          // face onto its edge, where the normal starts to turn with the centre's motion at
          // once: v^2 / r of it): the support event has happened at this instant too, and is
          // the one it takes.
          on_support_event(c, t, y);
          break;
        }
        if (start_sliding(c, t, y)) {
          const std::string what = "slides: the friction sticking needs leaves the cone";
          const int pinned = status.pinned_end;
          const PairView v = view(c);
          note_contact(t, c,
                       pinned < 0
                           ? what
                           : fmt::format("slides on {}, turning about {}, which sticks: the "
                                         "friction sticking needs leaves the cone at {}",
                                         pairs_[c]->part_name(v), pairs_[c]->end_name(v, pinned),
                                         pairs_[c]->end_name(v, 1 - pinned)));
          break;
        }
        lift_off_or_hold_slide(c, t, y);
      }
      break;
  }
  release_pulling_contacts(c, t, y);
  s_.last_event_t = t;
  note_event_numbers(first_new, y);
}

void ContactSystem::on_support_event(std::size_t c, double t, VecX& y) {
  ContactStatus& status = s_.contacts[c];
  calc_accelerations(y);
  int side = -1;
  support_margin_of(c, side);
  const ContactPair& pair = *pairs_[c];
  PairView v = view(c);
  if (held_polyhedron_[c] && pair.can_tip(v) && d_.now[c].normal_force > 0.0) {
    drop_point(c, d_.now[c].least_point_B);
    if (status.mode == ContactMode::Apart) {
      note_contact(t, c, "lifts off");
      return;
    }
    note_contact(t, c, fmt::format("tips onto {}", pair.part_name(v)));
    classify_contact(c, t, y);
    return;
  }
  const bool presses =
      still_presses(d_.now[c].normal_force, bodies_[contacts_[c].body].mass, gravity_W_);
  if (pair.tip_on_support(v, side, presses)) {
    note_contact(t, c, fmt::format("tips onto {}", pair.part_name(v)));
    classify_contact(c, t, y);
    return;
  }
  set_apart(c);
  note_contact(t, c, "lifts off");
}

void ContactSystem::release_pulling_contacts(std::size_t handled, double t, VecX& y) {
  if (contacts_.size() < 2) return;
  // Each round releases one contact (or tips it onto a part that may need the next round).
  for (std::size_t round = 0; round < contacts_.size(); ++round) {
    calc_accelerations(y);
    std::size_t pulls = contacts_.size();
    for (const std::size_t c : watched()) {
      if (c == handled || s_.contacts[c].mode == ContactMode::Apart) continue;
      if (pulling(c)) {
        pulls = c;
        break;
      }
    }
    if (pulls == contacts_.size()) return;
    on_support_event(pulls, t, y);
  }
}

bool ContactSystem::pulling(std::size_t c) const {
  const double N = held_polyhedron_[c] ? d_.now[c].least_point_force : d_.now[c].normal_force;
  return -N > kSlipZero * bodies_[contacts_[c].body].mass * std::max(gravity_W_.norm(), 1.0);
}

ContactScales contact_scales(const PlaneContact& contact, const Vec3& gravity_W,
                             const BodyState& s) {
  const double size = std::max(contact_size(contact.surface), 1e-300);
  ContactScales scales;
  scales.size = size;
  scales.speed = std::max(
      {std::sqrt(gravity_W.norm() * size), s.v_G.norm() + s.omega_W.norm() * size, 1e-300});
  scales.slip_zero = kSlipZero * scales.speed;
  const double g_n = std::abs(gravity_W.dot(contact.normal_W));
  scales.settle_speed =
      g_n > 0.0 ? std::sqrt(2.0 * g_n * kSettleHeight * size) : kSettleHeight * scales.speed;
  scales.touching_height = touching_height(contact.surface);
  scales.landing_height = kSettleHeight * size;
  return scales;
}

std::optional<ContactSystem::StartProblem> ContactSystem::start_problem(const VecX& y0) const {
  d_.screen.watch_all();  // every pair checked
  dynamics_.calc_motion(y0, true);
  calc_contact_points();
  for (std::size_t c = 0; c < contacts_.size(); ++c) {
    const PlaneContact& contact = contacts_[c];
    if (contact.touches_a_body()) {
      if (std::optional<StartProblem> problem = pair_start_problem(c)) return problem;
      continue;
    }
    const ContactScales scales = contact_scales(contact, gravity_W_, dynamics_.state(contact.body));
    const ContactNow& now = d_.now[c];
    if (now.support.height < -scales.touching_height) {
      return StartProblem{
          c, fmt::format("body '{}' starts {:.6g} m inside the plane; place it on or above it",
                         bodies_[contact.body].name, -now.support.height)};
    }
    const double vn = now.support_normal_speed;
    if (now.support.height <= scales.touching_height && vn < -scales.slip_zero) {
      return StartProblem{
          c, fmt::format("body '{}' starts touching the plane and moving into it at {:.6g} m/s; "
                         "start it above the plane, or without that speed",
                         bodies_[contact.body].name, -vn)};
    }
  }
  return std::nullopt;
}

void ContactSystem::begin(double t0, const VecX& y) {
  s_.events.clear();
  s_.last_event_t = -std::numeric_limits<double>::infinity();
  if (contacts_.empty()) return;
  d_.screen.watch_all();  // a run's start sees every pair, whatever the run before it screened
  dynamics_.calc_motion(y, true);  // the bodies' states set the scales
  VecX y_start = y;                // classifying may project it; the run starts from y itself
  d_.impact_y.resize(y.size());
  d_.onset_y.resize(y.size());
  d_.onset_dydt.resize(y.size());
  for (std::size_t c = 0; c < contacts_.size(); ++c) {
    const PlaneContact& contact = contacts_[c];
    const ContactScales scales =
        contact.touches_a_body()
            ? pair_contact_scales(contact, gravity_W_, dynamics_.state(contact.body),
                                  dynamics_.state(contact.other_body))
            : contact_scales(contact, gravity_W_, dynamics_.state(contact.body));
    ContactStatus& status = s_.contacts[c];
    set_apart(c);
    status.rim_direction_B = Vec3::UnitX();
    status.slide_direction_W = Vec3::UnitX();
    status.slip_grown = false;
    status.slip_left_near = false;
    status.cascade_events = 0;
    status.cascade_last_t = -std::numeric_limits<double>::infinity();
    status.slip_zero = scales.slip_zero;
    status.slip_floor = kSlipFloor * scales.slip_zero;
    status.settle_speed = scales.settle_speed;
    status.touching_height = scales.touching_height;
    status.landing_height = scales.landing_height;
    status.time_scale = scales.size / scales.speed;
  }
  for (std::size_t c = 0; c < contacts_.size(); ++c) {
    if (contacts_[c].touches_a_body()) continue;  // a pair touching at the start is apart
    dynamics_.calc_motion(y_start, true);
    calc_contact_points();
    const ContactNow& now = d_.now[c];
    const ContactStatus& status = s_.contacts[c];
    if (now.support.height > status.touching_height ||
        now.support_normal_speed > status.slip_zero) {
      continue;
    }
    PairView v = view(c);
    pairs_[c]->find_touching_part(v, status.touching_height, false);
    classify_contact(c, t0, y_start);
  }
  // Two bodies touching at the start press on each other if they are pushed together.
  enter_pressed_pairs(t0, y_start);
  note_event_numbers(0, y_start);
}

void ContactSystem::reclassify(double t, VecX& y, bool speeds_jumped) {
  const std::size_t first_new = s_.events.size();
  classify_touching(t, y, speeds_jumped, "lifts off: the jump sends it away from the plane");
  note_event_numbers(first_new, y);
}

void ContactSystem::classify_touching(double t, VecX& y, bool speeds_jumped,
                                      const char* lifts_off) {
  // After a jump, the contacts that it sends away are let go, and those it left slipping are
  // classified (they slide), before the others: one classified to roll projects every touching
  // contact's velocities onto its mode's constraints, and would take away the bounce or the slip
  // of a contact whose mode is still the one from before the jump (a ball struck off the floor
  // would stay on it; a ball that rolled into a wall, stopped there and still spinning, would
  // roll again, into the wall).
  std::vector<char>& slipping = d_.slipping_after_jump;
  std::fill(slipping.begin(), slipping.end(), 0);
  if (speeds_jumped) {
    for (const std::size_t c : watched()) {
      if (s_.contacts[c].mode == ContactMode::Apart || still_touches_after_jump(c, y)) continue;
      set_apart(c);
      note_contact(t, c, lifts_off);
    }
    dynamics_.calc_motion(y, true);
    calc_contact_points();
    for (const std::size_t c : watched()) {
      const ContactStatus& status = s_.contacts[c];
      if (status.mode == ContactMode::Rolling && d_.now[c].slip_W.norm() > status.slip_zero) {
        slipping[c] = 1;
      }
    }
  }
  for (const int pass : {1, 0}) {
    for (const std::size_t c : watched()) {
      if (s_.contacts[c].mode != ContactMode::Apart && slipping[c] == pass) {
        classify_contact(c, t, y);
      }
    }
  }
}

bool ContactSystem::still_touches_after_jump(std::size_t c, const VecX& y) {
  ContactStatus& status = s_.contacts[c];
  dynamics_.calc_motion(y, true);
  calc_contact_points();
  const ContactNow& now = d_.now[c];
  if (contacts_[c].touches_a_body()) return !(now.support_normal_speed > status.slip_zero);
  int leaving = 0;
  for (int k = 0; k < now.normal_point_count; ++k) {
    if (normal_speed(c, now.normal_points_B[static_cast<std::size_t>(k)]) > status.slip_zero) {
      ++leaving;
    }
  }
  if (leaving == 0) return true;
  if (leaving == now.normal_point_count) return false;
  // Some of its points leave, some stay: it touches with those that stay (a frame hinged at one
  // edge of its face, thrown up: the hinge's edge stays).
  PairView v = view(c);
  return pairs_[c]->find_touching_part(v, status.touching_height, true);
}

void ContactSystem::drop_point(std::size_t c, const Vec3& p_B) {
  PairView v = view(c);
  if (!pairs_[c]->drop_point(v, p_B)) set_apart(c);
}

}  // namespace tumble
