// A slip that starts from rolling or sticking (docs/design.md, "Contact"). It starts where the
// friction rolling needs, F, reaches the edge of the cone, |F| = mu N. There sliding along the
// way the contact is pushed, d0 = -F / |F|, carries the same friction as rolling: the slip starts
// with zero acceleration, and its jerk decides where it goes. Held along d0, the slip's
// acceleration grows as -W (F' + mu N' d0) t (W: the slip's response to friction, N held on the
// plane), and where W is not isotropic (a coin on its rim) that need not point along
// d0: the slip would turn back at once, stop, start again, and chatter. The consistent start
// turns the friction as it goes: d = d0 + d' t with d' normal to d0 and the jerk along d0,
//     j(d') = j_held + (d a_slip / d d) d' = J d0,   J > 0,
// which has one solution for W positive definite (its component along d0 is -d0.(F' + mu N' d0)
// over d0.W^-1 d0, positive where the needed friction leaves the cone). Its terms come from the
// solves themselves: j_held by a central difference in time along the motion, the slip
// acceleration's response to turning d by central differences in d. Once the slip is above
// slip_zero, its own direction takes over. J <= 0 is Painleve's case (friction high enough that,
// sliding, it presses the contact on): the slip cannot start, and the contact lifts off if with
// no force it would leave the plane (lift_off_or_hold_slide).
#include <Eigen/Dense>
#include <array>
#include <cmath>

#include "tumble/contact/contact_system.hpp"

namespace tumble {

namespace {

// Steps of the central differences: in time, a fraction of the contact's time scale (the slip
// it leaves, ~1e-12 of the speed scale, stays below slip_zero, so d0 holds); in direction, radians.
// Both leave ~1e-10 of round-off in what they measure, and truncation below that.
constexpr double kOnsetTimeStep = 1e-6;
constexpr double kOnsetTurnStep = 1e-5;

}  // namespace

bool ContactSystem::start_sliding(std::size_t c, double t, const VecX& y) {
  if (two_point(c) && contacts_[c].friction > 0.0 && start_sliding_on_two_points(c, t, y)) {
    return true;
  }
  // (A two-point part none of whose ends can start so: as one slip, which maps onto its ends.)
  ContactStatus& status = s_.contacts[c];
  const Vec3 d0 = pushed_direction(c);  // from the rolling forces in d_.now
  status.mode = ContactMode::Sliding;
  status.slide_direction_W = d0;
  status.slide_turn_W.setZero();
  status.slide_start_t = t;
  status.slip_grown = false;
  status.slip_left_near = false;
  status.slip_stop_armed = false;
  status.clear_end_slips();  // a two-point part's ends slide as the part's direction maps onto them
  const Vec3 a = slip_acceleration_at(c, y, d0);
  // Sliding that would pull the surfaces together is no mode (its friction would drive the slip
  // on, not resist it): lift_off_or_hold_slide decides.
  if (pulling(c)) {
    calc_accelerations(y);
    return false;
  }
  if (contacts_[c].friction == 0.0) return true;  // nothing can drive it back
  // Accelerations below this are round-off of zero (slip_zero over the time scale).
  const double zero = status.slip_zero / status.time_scale;
  bool grows = a.dot(d0) > zero;
  if (!grows && a.norm() <= zero) {
    // At the cone's edge: the jerk decides, and the direction turns as it needs.
    grows = turn_starting_slip(c, t, y);
  }
  calc_accelerations(y);
  return grows;
}

bool ContactSystem::turn_starting_slip(std::size_t c, double t, const VecX& y) {
  ContactStatus& status = s_.contacts[c];
  const Vec3 d0 = status.slide_direction_W;
  const Vec3 n = normal_of(c);  // (a pair's turns with the states tried below)

  // The jerk with the direction held, along the motion the derivative gives.
  const double dt = kOnsetTimeStep * status.time_scale;
  calc_rates(t, y, d_.onset_dydt);
  d_.onset_y = y + dt * d_.onset_dydt;
  const Vec3 after = slip_acceleration_at(c, d_.onset_y, d0);
  d_.onset_y = y - dt * d_.onset_dydt;
  const Vec3 before = slip_acceleration_at(c, d_.onset_y, d0);
  const Vec3 jerk_held = (after - before) / (2.0 * dt);

  // Slip space: the plane's tangents, and the normal too where the contact has a spin radius
  // (slip_W's spin component). Its basis: d0, then the directions d may turn in.
  std::array<Vec3, 3> basis = {d0, Vec3::Zero(), Vec3::Zero()};
  const bool with_spin = d_.now[c].spin_radius > 0.0;
  int turns = 1;
  if (with_spin) {
    plane_basis(d0, basis[1], basis[2]);
    turns = 2;
  } else {
    basis[1] = n.cross(d0).normalized();
  }
  const int size = turns + 1;
  // Unknowns: the turn rate along each of basis[1..turns], then J.
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Vec3 rhs = Vec3::Zero();
  for (int k = 0; k < size; ++k) rhs(k) = -basis[static_cast<std::size_t>(k)].dot(jerk_held);
  for (int i = 0; i < turns; ++i) {
    const Vec3& e = basis[static_cast<std::size_t>(i + 1)];
    const Vec3 plus = slip_acceleration_at(c, y, (d0 + kOnsetTurnStep * e).normalized());
    const Vec3 minus = slip_acceleration_at(c, y, (d0 - kOnsetTurnStep * e).normalized());
    const Vec3 response = (plus - minus) / (2.0 * kOnsetTurnStep);
    for (int k = 0; k < size; ++k) A(k, i) = basis[static_cast<std::size_t>(k)].dot(response);
  }
  A(0, turns) = -1.0;  // -J d0, in the basis
  status.slide_direction_W = d0;
  Vec3 z = Vec3::Zero();
  z.head(size) = A.topLeftCorner(size, size).fullPivLu().solve(rhs.head(size));
  const double J = z(turns);
  if (!(J > 0.0) || !z.allFinite()) return false;  // the slip cannot start
  for (int i = 0; i < turns; ++i) {
    status.slide_turn_W += z(i) * basis[static_cast<std::size_t>(i + 1)];
  }
  return true;
}

bool ContactSystem::start_sliding_on_two_points(std::size_t c, double t, const VecX& y) {
  ContactStatus& status = s_.contacts[c];
  const ContactNow& now = d_.now[c];
  // From the sticking forces (d_.now): the friction along the part shared between the ends as
  // they can take it (as stick_margin shares it), and each end pushed against its share.
  const EndFrictions ends = end_frictions(c, 1.0);
  const double room = ends.room[0] + ends.room[1];
  std::array<Vec3, 2> push_W;
  for (std::size_t k = 0; k < 2; ++k) {
    const double share = room > 0.0 ? ends.room[k] / room : 0.5;
    const Vec3 F_W = ends.across_W[k] + share * ends.along * ends.along_direction_W;
    push_W[k] = F_W.norm() > 0.0 ? Vec3(-F_W.normalized()) : Vec3::Zero();
  }
  status.mode = ContactMode::Sliding;
  status.slide_direction_W = pushed_direction(c);
  status.slide_turn_W.setZero();
  status.slide_start_t = t;
  status.slip_grown = false;
  status.slip_left_near = false;
  status.slip_stop_armed = false;
  // Accelerations below this are round-off of zero (slip_zero over the time scale).
  const double zero = status.slip_zero / status.time_scale;
  const BodyMotion w = dynamics_.motion(contacts_[c].body);
  const Vec3& n = contacts_[c].normal_W;
  // It pivots about one end, the other sliding, or both slide: the first whose pinned end's
  // friction fits in its cone and whose sliding ends' slips are not driven back.
  for (const int pinned : {0, 1, -1}) {
    status.clear_end_slips();
    status.pinned_end = pinned;
    bool pushed = true;
    for (int k = 0; k < 2; ++k) {
      if (k == pinned) continue;
      status.end_slide_direction_W[static_cast<std::size_t>(k)] =
          push_W[static_cast<std::size_t>(k)];
      pushed = pushed && !push_W[static_cast<std::size_t>(k)].isZero(0.0);
    }
    if (!pushed) continue;
    calc_accelerations(y);
    if (pinned >= 0 && !(pinned_friction_margin(c) >= 0.0)) continue;
    bool grows = true;
    for (int k = 0; k < 2; ++k) {
      if (k == pinned) continue;
      const auto e = static_cast<std::size_t>(k);
      const Vec3 a_W = moving_point_acceleration_W(w, now.normal_points_B[e], Vec3::Zero());
      grows = grows && (a_W - n * n.dot(a_W)).dot(push_W[e]) >= -zero;
    }
    if (grows) return true;
  }
  status.clear_end_slips();
  calc_accelerations(y);
  return false;
}

void ContactSystem::lift_off_or_hold_slide(std::size_t c, double t, const VecX& y) {
  ContactStatus& status = s_.contacts[c];
  const ContactStatus sliding = status;
  const ContactNow& now = d_.now[c];
  const bool pair = contacts_[c].touches_a_body();
  // The part's points, as the body's points there, and the other end's lowest rim point, which
  // moves over the body as it turns. (Two bodies: their gap.)
  std::array<SurfacePoint, 4> points;
  std::size_t count = 0;
  for (int k = 0; k < now.normal_point_count && !pair; ++k) {
    points[count++] = {now.normal_points_B[static_cast<std::size_t>(k)], Vec3::Zero()};
  }
  SurfacePoint other;
  if (!pair && pairs_[c]->other_end_B(view(c), other) &&
      height_above_plane(c, other.p_B) <= status.touching_height) {
    points[count++] = other;
  }
  set_apart(c);
  calc_accelerations(y);
  // A zero of what the normal acceleration is measured against (gravity's scale).
  const double tolerance = status.slip_zero / status.time_scale;
  bool leaves = !pair || pair_gap_acceleration(c) >= -tolerance;
  for (std::size_t k = 0; k < count; ++k) {
    leaves = leaves && normal_acceleration(c, points[k].p_B, points[k].rate_B) >= -tolerance;
  }
  if (leaves) {
    note_contact(t, c, "lifts off: sliding would need friction pressing it on");
    return;
  }
  // No mode is consistent (Painleve's inconsistent case; the literature resolves it with a
  // tangential impulse, not built): it slides along the pushed direction, held.
  status = sliding;
  status.slide_turn_W.setZero();
  calc_accelerations(y);
  note_contact(t, c, "slides: the friction sticking needs leaves the cone (inconsistent)");
}

Vec3 ContactSystem::slip_acceleration_at(std::size_t c, const VecX& y, const Vec3& slide_W) {
  s_.contacts[c].slide_direction_W = slide_W;
  calc_accelerations(y);
  return slip_acceleration(c);
}

Vec3 ContactSystem::slip_acceleration(std::size_t c) const {
  // slip_W = the tangential part of O's velocity + rho (omega . n) n, with O moving over the
  // body at its rate and n fixed in the world.
  if (contacts_[c].touches_a_body()) return pair_slip_acceleration(c);
  const ContactNow& now = d_.now[c];
  const BodyMotion w = dynamics_.motion(contacts_[c].body);
  const Vec3& n = contacts_[c].normal_W;
  const Vec3 a_O_W = moving_point_acceleration_W(w, now.reference_B, now.reference_rate_B);
  const double spin_rate = n.dot(w.R_WB * w.acceleration.head<3>());
  return a_O_W - n * n.dot(a_O_W) + now.spin_radius * spin_rate * n;
}

}  // namespace tumble
