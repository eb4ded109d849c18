// Contacts with planes: their forces in each mode and the projection onto their constraints
// (docs/design.md, "Contact"). The modes, events and impacts are in contact_modes.cpp.
//
// In each mode a touching contact's force is the one that keeps its constraints' accelerations at
// zero. A constraint row is linear . (velocity of the body's material point at a point P) +
// angular . omega; with psi its time derivative (P itself may move over the body as it rolls, so
// psi is not the material point's acceleration; see solve_with_contacts), the forces are found
// from
//     rows . (psi_0 + A x) = 0,
// psi_0 from the accelerations without contact forces and A from the articulated-body
// algorithm's linear response to unit wrenches at the contacts (its impulsive form: no velocity
// terms, no gravity). Per mode:
//  - sliding: the normal motion (one row per normal point: the contact point, an edge's ends,
//    three corners of a face), each normal force carrying Coulomb's friction mu N against the
//    slip at the reference point O;
//  - rolling or sticking: all the motion the feature allows none of: a point's velocity (3 rows),
//    an edge's (5: it may still turn about the edge), a face's (6: the body is held).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "tumble/contact/contact_system.hpp"

#include "tumble/math/constraint_solve.hpp"

namespace tumble {

namespace {

// Responses below this fraction of the heaviest touching body's 1/m are round-off.
constexpr double kRoundOffResponse = 1e-6;
// Where redundant rows leave the forces open, a normal row's force counts 1e-6 of a friction
// row's of the same size (solve_contact_system): the friction taken is the least, to ~1e-6 of
// the push, and to ~1e-12 once extrapolated from a second solve at half the scale. (A larger
// scale leaves the friction rows' pivots at the solve's round-off threshold against the normal
// rows': at 1e6 the forces came out with noise of 1e-5.)
constexpr double kNormalRowScale = 1e3;

}  // namespace

ContactSystem::ContactSystem(std::span<const PlaneContact> contacts,
                             std::span<const RigidBody> bodies, const Vec3& gravity_W,
                             const ContactDynamics& dynamics, ContactState& state,
                             Eigen::Index dimension, double fixed_step)
    : contacts_(contacts),
      bodies_(bodies),
      fixed_step_(fixed_step),
      gravity_W_(gravity_W),
      dynamics_(dynamics),
      data_(std::make_unique<ContactData>(contacts, bodies.size(), dimension)),
      d_(*data_),
      s_(state) {
  // Room for every feature now, so that finding one during a step allocates nothing.
  s_.contacts.resize(contacts_.size());
  double heaviest = 0.0;
  for (std::size_t c = 0; c < contacts_.size(); ++c) {
    const PlaneContact& contact = contacts_[c];
    reserve_feature(s_.contacts[c].feature, contact.surface.vertices.size());
    const bool pair = contact.touches_a_body();
    // Two bodies touch at one point, whatever their shapes, as a sphere touches a plane: a
    // capsule against a capsule takes the sphere's part (none to settle, tip or stick on).
    pairs_.push_back(&contact_pair(pair ? ContactSurface::Kind::Sphere : contact.surface.kind));
    const bool held = !dynamics_.moves_freely(contact.body);
    // A polyhedron's points are held one by one on a held body; two bodies' spheres touch at one
    // point (sphere_pairs.cpp), which either may hold.
    held_polyhedron_.push_back(!pair && held && pairs_.back()->held_point_by_point());
    any_held_ = any_held_ || held || (pair && !dynamics_.moves_freely(contact.other_body));
    heaviest = std::max(heaviest, bodies_[contact.body].mass);
    if (pair) heaviest = std::max(heaviest, bodies_[contact.other_body].mass);
  }
  // A free body's response to a unit force is at least 1/m: a floor far below every real one.
  if (heaviest > 0.0) least_response_ = kRoundOffResponse / heaviest;
}

void ContactSystem::calc_accelerations(const VecX& y) const {
  dynamics_.calc_motion(y, true);
  dynamics_.gather_loads(y);
  solve_forces();
}

void ContactSystem::calc_rates(double t, const VecX& y, VecX& dydt) const {
  set_time(t);
  dynamics_.calc_motion(y, true);
  dynamics_.gather_loads(y, dydt);
  solve_forces();
  dynamics_.write_rates(y, dydt);
  write_powers(dydt, dynamics_.ledger_start());
}

PairView ContactSystem::view(std::size_t c) const {
  return {contacts_[c], dynamics_.motion(contacts_[c].body), s_.contacts[c], d_.now[c],
          d_.touching};
}

void ContactSystem::calc_contact_points() const {
  for (const std::size_t c : watched()) {
    const PlaneContact& contact = contacts_[c];
    if (contact.touches_a_body()) {
      calc_pair_point(c);
      continue;
    }
    const ContactStatus& status = s_.contacts[c];
    const BodyMotion w = dynamics_.motion(contact.body);
    const Vec3& n = contact.normal_W;
    ContactNow& now = d_.now[c];
    now.n_B = w.R_WB.transpose() * n;
    const Vec3 omega_B = w.velocity.head<3>();
    const Vec3 v_G_B = w.velocity.tail<3>();
    now.normal_point_rates_B.fill(Vec3::Zero());
    now.spin_radius = status.feature.spin_radius;
    PairView v = view(c);
    if (!pairs_[c]->calc_part_points(v, omega_B)) {
      // A sphere, or any surface apart: its support point is the contact point.
      now.support = support_point(contact, w.r_G_W, w.R_WB);
      now.reference_B = now.support.p_GC_B;
      now.reference_rate_B = support_rate_B(contact, now.n_B, omega_B);
      now.normal_points_B[0] = now.reference_B;
      now.normal_point_rates_B[0] = now.reference_rate_B;
      now.normal_point_count = 1;
    }
    now.support_normal_speed = normal_speed(c, now.support.p_GC_B);
    now.velocity_W = w.R_WB * (v_G_B + omega_B.cross(now.reference_B));
    const double spin = (w.R_WB * omega_B).dot(n);
    now.slip_W = now.velocity_W - n * n.dot(now.velocity_W) + now.spin_radius * spin * n;
    if (two_point(c)) {
      for (std::size_t k = 0; k < 2; ++k) {
        const Vec3 v_W = w.R_WB * (v_G_B + omega_B.cross(now.normal_points_B[k]));
        now.end_slip_W[k] = v_W - n * n.dot(v_W);
      }
    }
    now.wrench_B.setZero();
    now.force_W.setZero();
    now.friction_W.setZero();
    now.moment_about_O_B.setZero();
    now.normal_force = 0.0;
  }
}

Vec3 ContactSystem::slide_direction(std::size_t c, bool* follows_slip) const {
  const ContactStatus& status = s_.contacts[c];
  const Vec3& slip_W = d_.now[c].slip_W;
  const double slip = slip_W.norm();
  // The slip is followed while it is above slip_zero, or has grown and keeps to the way it went
  // at the start of the step (down to slip_floor); past that (it stopped within the step)
  // friction stays as it was, so that the right-hand side runs on smoothly through the stop that
  // the slip-stop event locates. So it does for a slip above slip_zero that has gone back, more
  // than 135 degrees round from that way: a stage of a long step that lands past the stop. Were
  // it followed there, friction would flip within the step, and the step would be rejected, and
  // again, until it were too short to reach the stop (a ball sliding to rolling took 20 rejected
  // steps, down to 2e-8 s, before its slip stopped). A slip that turns (a spinning body's) turns
  // far less within a step.
  const double along = slip_W.dot(status.slide_direction_W);
  const bool went_back = along < -std::sqrt(0.5) * slip;
  const bool followed = (slip > status.slip_zero && !went_back) ||
                        (status.slip_grown && slip > status.slip_floor && along > 0.0);
  if (follows_slip != nullptr) *follows_slip = followed;
  if (followed) return slip_W / slip;
  if (status.slide_turn_W.isZero(0.0)) return status.slide_direction_W;
  const double since = d_.time_now - status.slide_start_t;
  return (status.slide_direction_W + since * status.slide_turn_W).normalized();
}

bool ContactSystem::two_point(std::size_t c) const {
  return d_.now[c].normal_point_count == 2 && !held_polyhedron_[c];
}

Vec3 ContactSystem::end_slide_direction(std::size_t c, int end, const Vec3& slide_W,
                                        bool* follows_slip) const {
  const ContactStatus& status = s_.contacts[c];
  const ContactNow& now = d_.now[c];
  const auto k = static_cast<std::size_t>(end);
  const Vec3& slip_W = now.end_slip_W[k];
  const Vec3& last_W = status.end_slide_direction_W[k];
  const double slip = slip_W.norm();
  // As the whole part's slip (slide_direction): followed while it is above slip_zero, or has
  // grown and keeps to the way it went.
  const bool followed =
      slip > status.slip_zero ||
      (status.end_slip_grown[k] && slip > status.slip_floor && slip_W.dot(last_W) > 0.0);
  if (follows_slip != nullptr) *follows_slip = followed;
  if (followed) return slip_W / slip;
  if (!last_W.isZero(0.0)) return last_W;
  return rigid_slide_at(c, now.normal_points_B[k], slide_W);
}

Vec3 ContactSystem::rigid_slide_at(std::size_t c, const Vec3& p_B, const Vec3& slide_W) const {
  // Neither grown nor pushed on its own: the part's slide direction in slip space (its
  // tangential part, and rho times the spin about the normal) is a rigid motion of the part, and
  // this point moves with it. (Where the part slides so, the ends' own slips are exactly this.)
  const ContactNow& now = d_.now[c];
  const Vec3& n = contacts_[c].normal_W;
  const Mat3& R = dynamics_.motion(contacts_[c].body).R_WB;
  Vec3 u_W = slide_W - n * n.dot(slide_W);
  if (now.spin_radius > 0.0) {
    u_W += (n.dot(slide_W) / now.spin_radius) * n.cross(R * (p_B - now.reference_B));
  }
  const double size = u_W.norm();
  return size > 0.0 ? Vec3(u_W / size) : Vec3(slide_W - n * n.dot(slide_W));
}

void ContactSystem::calc_holds(double t, const VecX& y, std::span<ContactHold> holds) const {
  set_time(t);
  dynamics_.calc_motion(y, true);
  calc_contact_points();
  for (std::size_t c = 0; c < contacts_.size(); ++c) {
    const ContactStatus& status = s_.contacts[c];
    const ContactNow& now = d_.now[c];
    ContactHold& hold = holds[c];
    hold = ContactHold{};
    if (d_.screen.far(c)) continue;  // apart, its points not found
    // Two bodies touching are held at their one point as a plane's is (modes/modal_pair.hpp).
    const bool pair = contacts_[c].touches_a_body();
    if (status.mode == ContactMode::Apart) continue;
    if (!pair && (now.normal_point_count != 1 || now.spin_radius != 0.0)) {
      calc_points_hold(c, hold);
      continue;
    }
    if (status.mode == ContactMode::Rolling) {
      hold.kind = ContactHold::Kind::Point;
      continue;
    }
    hold.kind = ContactHold::Kind::Normal;
    hold.friction = contacts_[c].friction;
    const Vec3& n = normal_of(c);
    const Vec3 slide_W = slide_direction(c, &hold.follows_slip);
    hold.slide_W = slide_W - n * n.dot(slide_W);
  }
}

void ContactSystem::calc_points_hold(std::size_t c, ContactHold& hold) const {
  const ContactStatus& status = s_.contacts[c];
  const ContactNow& now = d_.now[c];
  const Vec3& n = contacts_[c].normal_W;
  const BodyMotion& w = dynamics_.motion(contacts_[c].body);
  hold.kind = ContactHold::Kind::Points;
  hold.point_count = now.normal_point_count;
  const bool slides = status.mode == ContactMode::Sliding;
  bool part_follows = false;
  const Vec3 slide_W = slides ? slide_direction(c, &part_follows) : Vec3::Zero();
  for (int k = 0; k < now.normal_point_count; ++k) {
    ContactHold::BodyPoint& point = hold.points[static_cast<std::size_t>(k)];
    point.p_B = now.normal_points_B[static_cast<std::size_t>(k)];
    if (!slides || status.pinned_end == k) {
      point.kind = ContactHold::Kind::Point;  // rolling, sticking, or a pivot's pinned end
      continue;
    }
    point.kind = ContactHold::Kind::Normal;
    point.friction = contacts_[c].friction;
    Vec3 along_W = Vec3::Zero();
    if (two_point(c)) {
      along_W = end_slide_direction(c, k, slide_W, &point.follows_slip);
    } else {
      // A face's corner: against its own slip while the part's is followed and the corner's is
      // not at rest (a face turning about it), else as the part's slide moves it.
      const Vec3 v_W = w.R_WB * (w.velocity.tail<3>() + w.velocity.head<3>().cross(point.p_B));
      const Vec3 slip_W = v_W - n * n.dot(v_W);
      point.follows_slip = part_follows && slip_W.norm() > status.slip_zero;
      along_W =
          point.follows_slip ? Vec3(slip_W.normalized()) : rigid_slide_at(c, point.p_B, slide_W);
    }
    point.slide_W = along_W - n * n.dot(along_W);
  }
}

Vec3 ContactSystem::moving_point_acceleration_W(const BodyMotion& w, const Vec3& p_B,
                                                const Vec3& rate_B) const {
  // d/dt R (v_G + omega x p), with p moving over the body at p'_B:
  //   R (a_G + alpha x p + omega x (v_G + omega x p) + omega x p'_B),
  // from the spatial acceleration (alpha; a_O), whose classical value at the COM is
  // a_O + omega x v_G. The passes give ground the acceleration -g (gravity as a fictitious
  // lift), so every acceleration they give is short of the true one by g: it is added back.
  const Vec3 omega_B = w.velocity.head<3>();
  const Vec3 v_P_B = w.velocity.tail<3>() + omega_B.cross(p_B);
  const Vec3 psi_B = w.acceleration.tail<3>() + w.acceleration.head<3>().cross(p_B) +
                     omega_B.cross(v_P_B) + omega_B.cross(rate_B);
  return w.R_WB * psi_B + gravity_W_;
}

Eigen::Index ContactSystem::append_contact_unknowns(std::size_t c, ContactMode mode,
                                                    ContactRows rows, const Vec3& slide_W,
                                                    Eigen::Index count) const {
  // A group's pairs have room for as many as may touch at once in a close packing
  // (contact_data.cpp); more touching grows it, the one allocation a step may make.
  if (mode != ContactMode::Apart &&
      static_cast<std::size_t>(count) + kMostRowsPerContact > d_.row_room()) {
    d_.reserve_rows(2 * d_.row_room() + kMostRowsPerContact);
  }
  if (contacts_[c].touches_a_body()) return append_pair_unknowns(c, mode, rows, slide_W, count);
  const PlaneContact& contact = contacts_[c];
  const ContactNow& now = d_.now[c];
  const Mat3& R = dynamics_.motion(contact.body).R_WB;
  const Vec3& n = contact.normal_W;
  const Vec3 zero = Vec3::Zero();
  const bool held_at_anchor = anchored(c);
  const bool two_points = two_point(c);
  const auto add = [&](const Vec3& p_B, const Vec3& rate_B, const Vec3& linear_W,
                       const Vec3& angular_W, bool normal, const Vec6& wrench_B, int anchor,
                       int end = -1) {
    d_.unknowns[static_cast<std::size_t>(count++)] = {
        c, p_B, rate_B, linear_W, angular_W, normal, held_at_anchor ? anchor : -1, end, wrench_B};
  };
  const bool points_only =
      mode == ContactMode::Sliding || (rows == ContactRows::Position && !held_at_anchor);
  if (mode == ContactMode::Apart) return count;
  const double mu = rows == ContactRows::Motion ? contact.friction : 0.0;
  const int pinned = s_.contacts[c].pinned_end;
  if (two_points && mode == ContactMode::Sliding && rows != ContactRows::Position && pinned >= 0) {
    // Pivoting: the pinned end's velocity is held (three rows); the other end slides, its
    // normal force carrying Coulomb's friction against its own slip.
    Vec3 t1, t2;
    plane_basis(n, t1, t2);
    const Vec3* lin[3] = {&n, &t1, &t2};
    const auto k = static_cast<std::size_t>(pinned);
    const std::size_t o = 1 - k;
    const Vec3& P = now.normal_points_B[k];
    for (int a = 0; a < 3; ++a) {
      add(P, now.normal_point_rates_B[k], *lin[a], zero, a == 0, wrench_at(R, P, *lin[a], zero), -1,
          pinned);
    }
    const Vec3& Q = now.normal_points_B[o];
    const Vec3 slide_o = end_slide_direction(c, static_cast<int>(o), slide_W);
    add(Q, now.normal_point_rates_B[o], n, zero, true, wrench_at(R, Q, n - mu * slide_o, zero), -1,
        static_cast<int>(o));
    return count;
  }
  if (two_points && points_only) {
    // Sliding on two points: each normal force carries Coulomb's friction against its own end's
    // slip (the part's spin about the normal makes the ends slip differently).
    for (int k = 0; k < 2; ++k) {
      const auto e = static_cast<std::size_t>(k);
      const Vec3& p = now.normal_points_B[e];
      const Vec3 slide_k = mu > 0.0 && mode == ContactMode::Sliding
                               ? end_slide_direction(c, k, slide_W)
                               : Vec3::Zero();
      add(p, now.normal_point_rates_B[e], n, zero, true, wrench_at(R, p, n - mu * slide_k, zero),
          -1, k);
    }
    return count;
  }
  if (points_only) {
    // Coulomb: each normal force N carries -mu N along the slip's tangential part at O and, for
    // a face (or an edge on a body a joint holds), a moment -mu N rho along its spin part (an
    // ellipsoidal limit surface: exact for sliding without spin).
    const double mu_slide = mode == ContactMode::Sliding ? mu : 0.0;
    const Vec3 slide_tangential_W = slide_W - n * n.dot(slide_W);
    const Vec3 spin_moment_W = -mu_slide * now.spin_radius * n.dot(slide_W) * n;
    for (int k = 0; k < now.normal_point_count; ++k) {
      const Vec3& p = now.normal_points_B[static_cast<std::size_t>(k)];
      const Vec3& rate = now.normal_point_rates_B[static_cast<std::size_t>(k)];
      // One point (a curved surface, a vertex) is its own reference point: one wrench.
      const Vec6 wrench =
          now.normal_point_count == 1
              ? wrench_at(R, p, n - mu_slide * slide_tangential_W, spin_moment_W)
              : Vec6(wrench_at(R, p, n, zero) +
                     wrench_at(R, now.reference_B, -mu_slide * slide_tangential_W, spin_moment_W));
      add(p, rate, n, zero, true, wrench, -1);
    }
    return count;
  }
  Vec3 t1, t2;
  plane_basis(n, t1, t2);
  if (held_polyhedron_[c]) {
    // On a body a joint holds, the joint and the plane share the load in a way no choice of the
    // resultant's rows can split: each of the feature's points is held still (along n, t1, t2),
    // and the solve keeps the rows the joint leaves free and gives the others no force. Each kept
    // normal row's force is what the plane pushes with at that point; all must push
    // (least_point_force >= 0). A Cubli's frame lying on its face, hinged at one edge: the
    // points on the hinge's axis respond with nothing, and the far edge carries the plane's load.
    for (int k = 0; k < now.normal_point_count; ++k) {
      const Vec3& p = now.normal_points_B[static_cast<std::size_t>(k)];
      const Vec3& rate = now.normal_point_rates_B[static_cast<std::size_t>(k)];
      const Vec3* held_along[3] = {&n, &t1, &t2};
      for (int a = 0; a < 3; ++a) {
        add(p, rate, *held_along[a], zero, a == 0, wrench_at(R, p, *held_along[a], zero), -1);
      }
    }
    return count;
  }
  // Rolling or sticking: the reference point's velocity (for a vertex or a curved surface that
  // is all); an edge's other end may not move across the edge or off the plane; a face may not
  // turn at all.
  const Vec3& O = now.reference_B;
  const Vec3* lin[3] = {&n, &t1, &t2};
  if (now.normal_point_count == 2) {
    const Vec3& A = now.normal_points_B[0];
    const Vec3& B = now.normal_points_B[1];
    const Vec3& A_rate = now.normal_point_rates_B[0];
    const Vec3& B_rate = now.normal_point_rates_B[1];
    for (int a = 0; a < 3; ++a) {
      add(A, A_rate, *lin[a], zero, a == 0, wrench_at(R, A, *lin[a], zero), 0, 0);
    }
    const Vec3 across_W = n.cross(R * (B - A)).normalized();
    add(B, B_rate, n, zero, true, wrench_at(R, B, n, zero), 1, 1);
    add(B, B_rate, across_W, zero, false, wrench_at(R, B, across_W, zero), 1, 1);
    return count;
  }
  for (int a = 0; a < 3; ++a) {
    add(O, now.reference_rate_B, *lin[a], zero, a == 0, wrench_at(R, O, *lin[a], zero), 0);
  }
  if (now.normal_point_count == 3) {
    for (int a = 0; a < 3; ++a) {
      add(O, zero, zero, *lin[a], a != 0, wrench_at(R, O, zero, *lin[a]), 0);
    }
  }
  return count;
}

Eigen::Index ContactSystem::gather_contact_unknowns(ContactRows rows) const {
  Eigen::Index count = 0;
  for (const std::size_t c : watched()) {
    const ContactMode mode = s_.contacts[c].mode;
    const Vec3 slide = mode == ContactMode::Sliding && rows == ContactRows::Motion
                           ? slide_direction(c)
                           : Vec3::Zero();
    count = append_contact_unknowns(c, mode, rows, slide, count);
  }
  return count;
}

namespace {

// A row's value on a body's velocity (w.velocity) or its response to a unit wrench
// (w.acceleration, the impulsive passes': no velocity terms), at the row's point p_B.
double row_on_velocity(const ContactUnknown& row, const BodyMotion& w, const Vec3& p_B) {
  const Vec3 omega_B = w.velocity.head<3>();
  return row.linear_W.dot(w.R_WB * (w.velocity.tail<3>() + omega_B.cross(p_B))) +
         row.angular_W.dot(w.R_WB * omega_B);
}
double row_on_response(const ContactUnknown& row, const BodyMotion& w, const Vec3& p_B) {
  const Vec3 alpha_B = w.acceleration.head<3>();
  return row.linear_W.dot(w.R_WB * (w.acceleration.tail<3>() + alpha_B.cross(p_B))) +
         row.angular_W.dot(w.R_WB * alpha_B);
}

}  // namespace

double ContactSystem::row_velocity(const ContactUnknown& row) const {
  const PlaneContact& contact = contacts_[row.contact];
  double velocity = row_on_velocity(row, dynamics_.motion(contact.body), row.point_B);
  if (contact.touches_a_body()) {
    velocity -= row_on_velocity(row, dynamics_.motion(contact.other_body), row.other_point_B);
  }
  return velocity;
}

void ContactSystem::add_contact_response(Eigen::Index j, std::size_t body, const Vec6& wrench_B,
                                         std::span<const Eigen::Index> rows) const {
  // Only the bodies that move with this one (hung through joints from the same ground joint)
  // respond: the others' rows respond with nothing, and their passes are skipped (three bodies
  // racing down a ramp: a third of the work).
  dynamics_.respond_to_unit_wrench({body, wrench_B});
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ContactUnknown& row = d_.unknowns[static_cast<std::size_t>(rows[i])];
    const PlaneContact& contact = contacts_[row.contact];
    const auto r = static_cast<Eigen::Index>(i);
    // The linear response of the row: its body's point's, less the other body's point's.
    if (dynamics_.moves_with(contact.body, body)) {
      d_.matrix(r, j) += row_on_response(row, dynamics_.motion(contact.body), row.point_B);
    }
    if (contact.touches_a_body() && dynamics_.moves_with(contact.other_body, body)) {
      d_.matrix(r, j) -=
          row_on_response(row, dynamics_.motion(contact.other_body), row.other_point_B);
    }
  }
}

void ContactSystem::calc_contact_matrix(std::span<const Eigen::Index> rows) const {
  const auto count = static_cast<Eigen::Index>(rows.size());
  for (Eigen::Index j = 0; j < count; ++j) {
    const ContactUnknown& u =
        d_.unknowns[static_cast<std::size_t>(rows[static_cast<std::size_t>(j)])];
    const PlaneContact& contact = contacts_[u.contact];
    d_.matrix.col(j).head(count).setZero();
    add_contact_response(j, contact.body, u.wrench_B, rows);
    // Between two bodies, the unknown pushes the other body too (the opposite force).
    if (contact.touches_a_body())
      add_contact_response(j, contact.other_body, u.other_wrench_B, rows);
  }
}

void ContactSystem::solve_forces() const {
  calc_contact_points();
  dynamics_.solve_under_loads();
  const Eigen::Index count = gather_contact_unknowns(ContactRows::Motion);
  if (count == 0) return;

  // psi_0 for each row: the acceleration of its point, which turns with the body and may also
  // move over it (moving_point_acceleration_W); an angular row's is alpha (its direction is fixed
  // in the world).
  // Between two bodies, it is the body's point's less the other body's point's, and the normal's
  // turning adds its own term.
  for (Eigen::Index i = 0; i < count; ++i) {
    const ContactUnknown& row = d_.unknowns[static_cast<std::size_t>(i)];
    const PlaneContact& contact = contacts_[row.contact];
    const BodyMotion w = dynamics_.motion(contact.body);
    d_.rhs(i) = -row.linear_W.dot(moving_point_acceleration_W(w, row.point_B, row.point_rate_B)) -
                row.angular_W.dot(w.R_WB * w.acceleration.head<3>()) - row.turning_acceleration;
    if (contact.touches_a_body()) {
      const BodyMotion o = dynamics_.motion(contact.other_body);
      d_.rhs(i) += row.linear_W.dot(
                       moving_point_acceleration_W(o, row.other_point_B, row.other_point_rate_B)) +
                   row.angular_W.dot(o.R_WB * o.acceleration.head<3>());
    }
  }
  solve_contact_rows(count, d_.rhs, RowQuantity::Acceleration);
  set_contact_resultants(count, d_.rhs);
  std::size_t wrench_count = 0;
  for (const std::size_t c : watched()) {
    d_.wrenches[wrench_count++] = {contacts_[c].body, d_.now[c].wrench_B};
    if (contacts_[c].touches_a_body()) {
      d_.wrenches[wrench_count++] = {contacts_[c].other_body, d_.now[c].other_wrench_B};
    }
  }
  dynamics_.solve_under_loads_and(std::span<const BodyWrench>(d_.wrenches.data(), wrench_count));
}

void ContactSystem::solve_contact_system(std::span<const Eigen::Index> rows, VecX& x,
                                         double zero) const {
  const auto count = static_cast<Eigen::Index>(rows.size());
  const auto unknown = [&](Eigen::Index i) -> const ContactUnknown& {
    return d_.unknowns[static_cast<std::size_t>(rows[static_cast<std::size_t>(i)])];
  };
  if (any_held_) {
    // A row that no force moves (a point on a hinge's axis: the joint holds that motion
    // entirely) carries no force. Its entries are round-off, and where every row is such, A's
    // own scale is round-off too and the solve could not tell them from real ones: each is set
    // aside here, against the floor of a real response.
    for (Eigen::Index i = 0; i < count; ++i) {
      if (d_.matrix.row(i).head(count).cwiseAbs().maxCoeff() > least_response_) continue;
      d_.matrix.row(i).head(count).setZero();
      d_.matrix.col(i).head(count).setZero();
      d_.matrix(i, i) = 1.0;
      x(i) = 0.0;
    }
  }
  // Where a joint (or another contact) makes rows redundant, it can carry part of a contact's
  // force, and the forces are not unique: a bob that a ball joint holds on a floor can be held by
  // the floor's push alone, or by a push and a friction that the rod balances. Of them, the one
  // with the least friction: friction the motion does not need would leave the cone where the
  // push alone holds (and the bob would slide off and land again for ever). The normal rows are
  // scaled to carry the load first (kNormalRowScale); among rows alike it is shared evenly.
  // That least weighted norm, of eps^2 |x_normal|^2 + |x_friction|^2 with eps = 1/scale, is the
  // least friction (and then the least push) plus a term in eps^2 and higher powers: an edge
  // mill's millstone, rolling on the ground at the end of an axle that a ball joint holds, took
  // 5.9e-5 N of friction along the axle where it needs none, and its N came out 2.5e-7 low. So
  // where the rows are redundant a second solve at eps doubled gives Richardson's extrapolation
  // (4 x(eps) - x(2 eps)) / 3, which leaves the eps^4 term: 1e-12 of the push.
  for (Eigen::Index i = 0; i < count; ++i) {
    d_.row_scales(i) = unknown(i).normal ? kNormalRowScale : 1.0;
  }
  d_.saved_matrix.topLeftCorner(count, count) = d_.matrix.topLeftCorner(count, count);
  d_.saved_rhs.head(count) = x.head(count);
  if (!solve_constraints_in_place(d_.matrix, x, count, d_.solve_scratch, zero, &d_.row_scales)) {
    return;
  }
  for (Eigen::Index i = 0; i < count; ++i) {
    if (unknown(i).normal) d_.row_scales(i) = 0.5 * kNormalRowScale;
  }
  d_.matrix.topLeftCorner(count, count) = d_.saved_matrix.topLeftCorner(count, count);
  solve_constraints_in_place(d_.matrix, d_.saved_rhs, count, d_.solve_scratch, zero,
                             &d_.row_scales);
  x.head(count) = (4.0 * x.head(count) - d_.saved_rhs.head(count)) / 3.0;
}

void ContactSystem::set_contact_resultants(Eigen::Index count, const VecX& x) const {
  // A far pair's were zeroed when it was last watched (apart).
  for (const std::size_t c : watched()) {
    ContactNow& now = d_.now[c];
    now.wrench_B.setZero();
    now.other_wrench_B.setZero();
    now.end_normal_force = {0.0, 0.0};
    now.end_friction_W = {Vec3::Zero(), Vec3::Zero()};
  }
  for (Eigen::Index j = 0; j < count; ++j) {
    const ContactUnknown& u = d_.unknowns[static_cast<std::size_t>(j)];
    ContactNow& now = d_.now[u.contact];
    now.wrench_B += x(j) * u.wrench_B;
    now.other_wrench_B += x(j) * u.other_wrench_B;
    if (u.end >= 0) {
      const auto k = static_cast<std::size_t>(u.end);
      const Vec3& n = contacts_[u.contact].normal_W;
      const Vec3 F_W = dynamics_.motion(contacts_[u.contact].body).R_WB * u.wrench_B.tail<3>();
      now.end_normal_force[k] += x(j) * n.dot(F_W);
      now.end_friction_W[k] += x(j) * (F_W - n * n.dot(F_W));
    }
  }
  for (const std::size_t c : watched()) {
    ContactNow& now = d_.now[c];
    const Vec3& n = normal_of(c);
    const Mat3& R = dynamics_.motion(contacts_[c].body).R_WB;
    const Vec3 F_B = now.wrench_B.tail<3>();
    now.force_W = R * F_B;
    now.normal_force = now.force_W.dot(n);
    now.friction_W = now.force_W - now.normal_force * n;
    now.moment_about_O_B = now.wrench_B.head<3>() - now.reference_B.cross(F_B);
    now.least_point_force = std::numeric_limits<double>::infinity();
  }
  // A held polyhedron's least push among the points whose rows were kept (a row the solve left
  // out has exactly no force); with none kept, the plane does not push at all.
  for (Eigen::Index j = 0; j < count; ++j) {
    const ContactUnknown& u = d_.unknowns[static_cast<std::size_t>(j)];
    ContactNow& now = d_.now[u.contact];
    if (!u.normal || !held_polyhedron_[u.contact] || x(j) == 0.0) continue;
    if (x(j) < now.least_point_force) {
      now.least_point_force = x(j);
      now.least_point_B = u.point_B;
    }
  }
  for (const std::size_t c : watched()) {
    ContactNow& now = d_.now[c];
    if (now.least_point_force == std::numeric_limits<double>::infinity()) {
      now.least_point_force = now.normal_force;
    }
  }
}

void ContactSystem::respond_to_contact_impulses(Eigen::Index count, const VecX& impulses) const {
  std::size_t wrench_count = 0;
  for (Eigen::Index j = 0; j < count; ++j) {
    const ContactUnknown& u = d_.unknowns[static_cast<std::size_t>(j)];
    const PlaneContact& contact = contacts_[u.contact];
    d_.wrenches[wrench_count++] = {contact.body, impulses(j) * u.wrench_B};
    if (contact.touches_a_body()) {
      d_.wrenches[wrench_count++] = {contact.other_body, impulses(j) * u.other_wrench_B};
    }
  }
  dynamics_.respond_to_impulses(std::span<const BodyWrench>(d_.wrenches.data(), wrench_count));
}

void ContactSystem::apply_contact_impulses(Eigen::Index count, const VecX& impulses,
                                           VecX& y) const {
  respond_to_contact_impulses(count, impulses);
  dynamics_.apply_speed_jumps(y);
}

void ContactSystem::write_powers(VecX& rates, Eigen::Index offset) const {
  // A far pair does no work (its ledger entry holds), and pooled pairs share an entry: every
  // entry zero, then the watched ones' added.
  const Eigen::Index entries = dynamics_.contact_ledger_size();
  const bool summed =
      watched().size() < contacts_.size() || entries < static_cast<Eigen::Index>(contacts_.size());
  if (summed) {
    rates.segment(offset + dynamics_.work_entry(0), entries).setZero();
  }
  for (const std::size_t c : watched()) {
    const BodyMotion w = dynamics_.motion(contacts_[c].body);
    double power = d_.now[c].wrench_B.dot(w.velocity);
    if (contacts_[c].touches_a_body()) {
      power += d_.now[c].other_wrench_B.dot(dynamics_.motion(contacts_[c].other_body).velocity);
    }
    if (summed) {
      rates(offset + dynamics_.work_entry(c)) += power;
    } else {
      rates(offset + dynamics_.work_entry(c)) = power;
    }
  }
}

void ContactSystem::add_work(std::size_t c, double work, VecX& y) const {
  y(dynamics_.ledger_start() + dynamics_.work_entry(c)) += work;
}

void ContactSystem::project_feature_positions(VecX& y) const {
  // The smallest move in the mass metric (the response to impulses along the rows) that puts the
  // normal points back on their planes, to first order (a face or an edge turns back flat as well
  // as moving), and a sticking polyhedron (a cone on its apex, a round body on a face) back on
  // its anchor. A curved surface's single point moves the least too.
  const Eigen::Index count = gather_contact_unknowns(ContactRows::Position);
  for (Eigen::Index i = 0; i < count; ++i) {
    const ContactUnknown& row = d_.unknowns[static_cast<std::size_t>(i)];
    const PlaneContact& contact = contacts_[row.contact];
    const ContactStatus& status = s_.contacts[row.contact];
    const BodyMotion w = dynamics_.motion(contact.body);
    const Vec3 x_P = w.r_G_W + w.R_WB * row.point_B;
    if (contact.touches_a_body()) {
      d_.x(i) = -d_.now[row.contact].support.height;  // the gap: a pair's one position row
    } else if (row.anchor < 0) {
      d_.x(i) = -(x_P - contact.point_W).dot(contact.normal_W);
    } else {
      // Off the anchor: the point's offset, and the small turn R_WB R_anchor^T as a vector.
      const Eigen::AngleAxisd turn(w.R_WB * status.anchor_R_WB.transpose());
      d_.x(i) = -row.linear_W.dot(x_P - status.anchor_W[static_cast<std::size_t>(row.anchor)]) -
                row.angular_W.dot(turn.angle() * turn.axis());
    }
  }
  solve_contact_rows(count, d_.x, RowQuantity::Position);
  respond_to_contact_impulses(count, d_.x);
  dynamics_.apply_displacement(y);
}

void ContactSystem::project(double t, VecX& y) const {
  dynamics_.normalise(t, y);
  if (!any_touching()) return;
  // A sphere's point, or a disk's, ring's or cylinder's rim point, is its support point: moving
  // a free body along the normal puts it back. A polyhedron, a cone, a side or a face has more,
  // and a body a joint holds moves only as its joints let it: the least move in the mass metric.
  bool features = false;
  for (const std::size_t c : watched()) {
    if (s_.contacts[c].mode == ContactMode::Apart) continue;
    features |= contacts_[c].touches_a_body() || !pairs_[c]->projects_along_normal(view(c)) ||
                !dynamics_.moves_freely(contacts_[c].body);
  }
  if (features) {
    dynamics_.calc_motion(y, true);
    calc_contact_points();
    project_feature_positions(y);
  } else {
    // Positions: each touching body back onto its plane along the normal (its COM): one point's
    // height is all a curved surface's contact constrains.
    dynamics_.calc_motion(y, false);
    for (const std::size_t c : watched()) {
      if (s_.contacts[c].mode == ContactMode::Apart) continue;
      const PlaneContact& contact = contacts_[c];
      const double height = pairs_[c]->point_height(view(c));
      dynamics_.translate(contact.body, -height * contact.normal_W, y);
    }
  }
  // Velocities: the least kinetic-energy change (impulses at the contacts) that zeroes the
  // velocity along each mode's constraints. Those impulses do work, which goes into each
  // contact's ledger entry like an impact's: after a step it is the drift's, ~rtol; after an
  // event it can be a point that the mode now holds coming down onto the plane (a cone landing
  // on its apex, whose rim then comes down too: held on the side, the rim's approach is stopped).
  dynamics_.calc_motion(y, true);
  calc_contact_points();
  const Eigen::Index count = gather_contact_unknowns(ContactRows::Projection);
  for (Eigen::Index i = 0; i < count; ++i) {
    d_.x(i) = -row_velocity(d_.unknowns[static_cast<std::size_t>(i)]);
  }
  d_.rhs.head(count) = d_.x.head(count);  // minus each row's velocity before
  solve_contact_rows(count, d_.x, RowQuantity::Velocity);
  apply_contact_impulses(count, d_.x, y);
  // An impulse P on a row whose velocity goes from v to 0 does P v / 2 of work.
  for (Eigen::Index i = 0; i < count; ++i) {
    const std::size_t c = d_.unknowns[static_cast<std::size_t>(i)].contact;
    add_work(c, -0.5 * d_.x(i) * d_.rhs(i), y);
  }
}

}  // namespace tumble
