// Contacts with planes in the articulated formulation: a hybrid system whose modes change only at
// located events (docs/design.md, "Contact").
//
// In each mode a touching contact's force is the one that keeps its constraints' accelerations at
// zero. With psi = d/dt of the velocity of the body's material point at the contact (the point
// itself moves over the body as it rolls, so psi is not the material point's acceleration; see
// constraint_acceleration_W), the force is found from
//     rows . (psi_0 + A x) = 0,
// psi_0 from the accelerations without contact forces and A from the articulated-body
// algorithm's linear response to unit forces at the contacts (its impulsive form: no velocity
// terms, no gravity). Sliding: one row, the normal, and the force N (n - mu s) with s the slip
// direction (Coulomb). Rolling: three rows, the whole contact-point acceleration, and a free
// force whose tangential part the stick-slip event keeps inside the cone.
#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tumble/multibody/articulated_formulation.hpp"

namespace tumble {

namespace {

// Solves the leading n x n block of A x = b by Gaussian elimination with partial pivoting, in
// place (b becomes x): A is preallocated for every contact, so nothing is allocated here.
void solve_in_place(MatX& A, VecX& b, Eigen::Index n) {
  for (Eigen::Index col = 0; col < n; ++col) {
    Eigen::Index pivot = col;
    for (Eigen::Index r = col + 1; r < n; ++r) {
      if (std::abs(A(r, col)) > std::abs(A(pivot, col))) pivot = r;
    }
    if (!(std::abs(A(pivot, col)) > 0.0)) {
      throw std::runtime_error(
          "the contacts' constraints are redundant (two contacts hold the same freedom)");
    }
    if (pivot != col) {
      for (Eigen::Index c = col; c < n; ++c) std::swap(A(pivot, c), A(col, c));
      std::swap(b(pivot), b(col));
    }
    for (Eigen::Index r = col + 1; r < n; ++r) {
      const double factor = A(r, col) / A(col, col);
      for (Eigen::Index c = col; c < n; ++c) A(r, c) -= factor * A(col, c);
      b(r) -= factor * b(col);
    }
  }
  for (Eigen::Index r = n; r-- > 0;) {
    double sum = b(r);
    for (Eigen::Index c = r + 1; c < n; ++c) sum -= A(r, c) * b(c);
    b(r) = sum / A(r, r);
  }
}

// Touching contacts are at the plane within this fraction of their size.
constexpr double kTouchingHeight = 1e-9;
// Slip slower than this fraction of the contact's speed scale counts as none: events locate the
// slip's zero to a few ulps of t, leaving ~1e-15 of the scale.
constexpr double kSlipZero = 1e-9;
// Touchdowns whose bounce would rise less than this fraction of the contact's size settle
// (restitution 0): the cascade of ever smaller bounces ends after finitely many.
constexpr double kSettleHeight = 1e-6;

// Where a contact slides when the friction rolling needs does not fit in the cone: the way it is
// pushed, against that friction (which then saturates at mu N).
Vec3 pushed_direction(const Vec3& friction_needed_W, const Vec3& otherwise_W) {
  const double size = friction_needed_W.norm();
  return size > 0.0 ? Vec3(-friction_needed_W / size) : otherwise_W;
}

}  // namespace

void ArticulatedFormulation::set_up_contacts() {
  const std::size_t count = model_.contacts.size();
  for (const PlaneContact& contact : model_.contacts) {
    if (tree_[slot_of_body_[contact.body]].type != TreeJoint::Type::Free) {
      throw std::invalid_argument("contact '" + contact.name + "': body '" +
                                  model_.bodies[contact.body].name +
                                  "' is held by a joint; a body in contact must be free");
    }
    event_specs_.push_back({contact.name + " touchdown", EventDirection::Falling});
    event_specs_.push_back({contact.name + " lift-off", EventDirection::Falling});
    event_specs_.push_back({contact.name + " stick-slip", EventDirection::Falling});
  }
  contact_status_.resize(count);
  contact_now_.resize(count);
  unknowns_.resize(3 * count);
  const auto rows = static_cast<Eigen::Index>(3 * count);
  contact_matrix_.resize(rows, rows);
  contact_rhs_.resize(rows);
  contact_x_.resize(rows);
}

Eigen::Index ArticulatedFormulation::contact_entry(std::size_t contact) const {
  return first_motor_entry() +
         static_cast<Eigen::Index>(motor_joints_.size() + model_.impulses.size() +
                                   lock_joints_.size() + contact);
}

void ArticulatedFormulation::calc_contact_points() const {
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    const PlaneContact& contact = model_.contacts[c];
    const Workspace& w = work_[slot_of_body_[contact.body]];
    ContactNow& now = contact_now_[c];
    now.support = support_point(contact, w.r_G_W, w.R_WC);
    now.n_B = w.R_WC.transpose() * contact.normal_W;
    const Vec3 omega_B = w.velocity.head<3>();
    now.support_rate_B = support_rate_B(contact, now.n_B, omega_B);
    now.velocity_W = w.R_WC * (w.velocity.tail<3>() + omega_B.cross(now.support.p_GC_B));
    now.slip_W = now.velocity_W - contact.normal_W * contact.normal_W.dot(now.velocity_W);
    now.force_W.setZero();
    now.friction_W.setZero();
    now.normal_force = 0.0;
  }
}

Vec3 ArticulatedFormulation::slide_direction(std::size_t c) const {
  const double slip = contact_now_[c].slip_W.norm();
  if (slip > contact_status_[c].slip_zero) return contact_now_[c].slip_W / slip;
  return contact_status_[c].slide_direction_W;
}

Eigen::Index ArticulatedFormulation::gather_contact_unknowns(ContactRows rows) const {
  Eigen::Index count = 0;
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    const Vec3& n = model_.contacts[c].normal_W;
    switch (contact_status_[c].mode) {
      case ContactMode::Apart:
        break;
      case ContactMode::Sliding: {
        const Vec3 force = rows == ContactRows::Motion
                               ? Vec3(n - model_.contacts[c].friction * slide_direction(c))
                               : n;
        unknowns_[static_cast<std::size_t>(count++)] = {c, n, force};
        break;
      }
      case ContactMode::Rolling:
        for (int axis = 0; axis < 3; ++axis) {
          const Vec3 e = Vec3::Unit(axis);
          unknowns_[static_cast<std::size_t>(count++)] = {c, e, e};
        }
        break;
    }
  }
  return count;
}

namespace {

// A force at a contact point on its body's workspace entry: (moment about the COM; force), the
// body's axes.
template <typename Work>
void add_force_at(Work& w, const Vec3& p_GC_B, const Vec3& F_W) {
  const Vec3 F_B = w.R_WC.transpose() * F_W;
  w.external.template head<3>() += p_GC_B.cross(F_B);
  w.external.template tail<3>() += F_B;
}

}  // namespace

void ArticulatedFormulation::calc_contact_matrix(Eigen::Index count, double mode_time) const {
  for (Eigen::Index j = 0; j < count; ++j) {
    for (Workspace& w : work_) {
      w.external.setZero();
      w.qdd.setZero();
    }
    const ContactUnknown& u = unknowns_[static_cast<std::size_t>(j)];
    const PlaneContact& contact = model_.contacts[u.contact];
    add_force_at(work_[slot_of_body_[contact.body]], contact_now_[u.contact].support.p_GC_B,
                 u.force_W);
    solve(mode_time, true);
    for (Eigen::Index i = 0; i < count; ++i) {
      const ContactUnknown& row = unknowns_[static_cast<std::size_t>(i)];
      const Workspace& w = work_[slot_of_body_[model_.contacts[row.contact].body]];
      const Vec3& p = contact_now_[row.contact].support.p_GC_B;
      // The linear response of the contact point: no velocity terms in the impulsive passes.
      const Vec3 response_W =
          w.R_WC * (w.acceleration.tail<3>() + w.acceleration.head<3>().cross(p));
      contact_matrix_(i, j) = row.row_W.dot(response_W);
    }
  }
  for (Workspace& w : work_) w.external.setZero();
}

void ArticulatedFormulation::solve_with_contacts(double mode_time) const {
  if (model_.contacts.empty()) {
    solve(mode_time, false);
    return;
  }
  calc_contact_points();
  for (Workspace& w : work_) w.applied = w.external;
  solve(mode_time, false);
  const Eigen::Index count = gather_contact_unknowns(ContactRows::Motion);
  if (count == 0) return;

  // psi_0 for each row: d/dt (v_G + omega x p) with p the contact point's offset, which turns
  // with the body and also moves over it (p' = omega x p + R p'_B):
  //   psi = a_G + alpha x p + omega x (omega x p + R p'_B),
  // in the body's axes from the spatial acceleration (alpha; a_O), whose classical value at the
  // COM is a_O + omega x v_G, and the -g that ground's acceleration carries.
  for (Eigen::Index i = 0; i < count; ++i) {
    const ContactUnknown& row = unknowns_[static_cast<std::size_t>(i)];
    const ContactNow& now = contact_now_[row.contact];
    const Workspace& w = work_[slot_of_body_[model_.contacts[row.contact].body]];
    const Vec3 omega_B = w.velocity.head<3>();
    const Vec3& p = now.support.p_GC_B;
    const Vec3 v_P_B = w.velocity.tail<3>() + omega_B.cross(p);
    const Vec3 psi_B = w.acceleration.tail<3>() + w.acceleration.head<3>().cross(p) +
                       omega_B.cross(v_P_B) + omega_B.cross(now.support_rate_B);
    contact_rhs_(i) = -row.row_W.dot(w.R_WC * psi_B + model_.gravity_W);
  }
  calc_contact_matrix(count, mode_time);
  solve_in_place(contact_matrix_, contact_rhs_, count);

  for (Workspace& w : work_) w.external = w.applied;
  for (Eigen::Index j = 0; j < count; ++j) {
    const ContactUnknown& u = unknowns_[static_cast<std::size_t>(j)];
    const Vec3 F_W = contact_rhs_(j) * u.force_W;
    ContactNow& now = contact_now_[u.contact];
    add_force_at(work_[slot_of_body_[model_.contacts[u.contact].body]], now.support.p_GC_B, F_W);
    now.force_W += F_W;
  }
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    ContactNow& now = contact_now_[c];
    const Vec3& n = model_.contacts[c].normal_W;
    now.normal_force = now.force_W.dot(n);
    now.friction_W = now.force_W - now.normal_force * n;
  }
  solve(mode_time, false);
}

void ArticulatedFormulation::apply_contact_impulses(Eigen::Index count, const VecX& impulses,
                                                    double mode_time, VecX& y) const {
  for (Workspace& w : work_) {
    w.external.setZero();
    w.qdd.setZero();
  }
  for (Eigen::Index j = 0; j < count; ++j) {
    const ContactUnknown& u = unknowns_[static_cast<std::size_t>(j)];
    add_force_at(work_[slot_of_body_[model_.contacts[u.contact].body]],
                 contact_now_[u.contact].support.p_GC_B, impulses(j) * u.force_W);
  }
  solve(mode_time, true);
  for (std::size_t k = 0; k < tree_.size(); ++k) {
    const TreeJoint& joint = tree_[k];
    if (joint.nv > 0) y.segment(joint.v, joint.nv) += work_[k].qdd;
  }
}

void ArticulatedFormulation::write_contact_powers(VecX& rates, Eigen::Index offset) const {
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    rates(offset + contact_entry(c)) = contact_now_[c].force_W.dot(contact_now_[c].velocity_W);
  }
}

void ArticulatedFormulation::solve_contacts_at(const VecX& y) const {
  calc_kinematics(y, true);
  accumulate_element_loads(y, schedule_time_, rates_, 0, nullptr);
  solve_with_contacts(schedule_time_);
}

void ArticulatedFormulation::project(double t, VecX& y) const {
  OdeSystem::project(t, y);
  const bool touching =
      std::any_of(contact_status_.begin(), contact_status_.end(),
                  [](const ContactStatus& s) { return s.mode != ContactMode::Apart; });
  if (!touching) return;
  // Positions: each touching body back onto its plane along the normal (its free joint's COM).
  calc_kinematics(y, false);
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    if (contact_status_[c].mode == ContactMode::Apart) continue;
    const PlaneContact& contact = model_.contacts[c];
    const Workspace& w = work_[slot_of_body_[contact.body]];
    const double height = support_point(contact, w.r_G_W, w.R_WC).height;
    y.segment<3>(tree_[slot_of_body_[contact.body]].q) -= height * contact.normal_W;
  }
  // Velocities: the least kinetic-energy change (impulses at the contacts) that zeroes the
  // normal velocity of sliding contacts and the whole contact velocity of rolling ones.
  calc_kinematics(y, true);
  calc_contact_points();
  const Eigen::Index count = gather_contact_unknowns(ContactRows::Projection);
  for (Eigen::Index i = 0; i < count; ++i) {
    const ContactUnknown& row = unknowns_[static_cast<std::size_t>(i)];
    contact_x_(i) = -row.row_W.dot(contact_now_[row.contact].velocity_W);
  }
  calc_contact_matrix(count, schedule_time_);
  solve_in_place(contact_matrix_, contact_x_, count);
  apply_contact_impulses(count, contact_x_, schedule_time_, y);
}

void ArticulatedFormulation::event_functions(double /*t*/, const VecX& y, VecX& g) const {
  const bool touching =
      std::any_of(contact_status_.begin(), contact_status_.end(),
                  [](const ContactStatus& s) { return s.mode != ContactMode::Apart; });
  if (touching) {
    solve_contacts_at(y);
  } else {
    calc_kinematics(y, true);
    calc_contact_points();
  }
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    const auto base = static_cast<Eigen::Index>(3 * c);
    const ContactNow& now = contact_now_[c];
    const ContactStatus& status = contact_status_[c];
    const PlaneContact& contact = model_.contacts[c];
    g(base) = g(base + 1) = g(base + 2) = 1.0;
    switch (status.mode) {
      case ContactMode::Apart: {
        // Height, but kept positive while the contact point moves away from the plane: a bounce
        // may rise and land again within one step (its flight is a parabola, which a high-order
        // method steps over), and the height alone would not change sign between the impact
        // (h = 0) and the landing (h < 0).
        const double moving_away = now.velocity_W.dot(contact.normal_W);
        g(base) = moving_away > 0.0 ? std::max(now.support.height, status.touching_height)
                                    : now.support.height;
        break;
      }
      case ContactMode::Sliding:
        g(base + 1) = now.normal_force;
        if (contact.friction > 0.0) g(base + 2) = now.slip_W.dot(status.slide_direction_W);
        break;
      case ContactMode::Rolling:
        g(base + 1) = now.normal_force;
        g(base + 2) = contact.friction * now.normal_force - now.friction_W.norm();
        break;
    }
  }
}

bool ArticulatedFormulation::refresh_event_functions(double /*t*/, const VecX& y) {
  bool sliding = false;
  for (const ContactStatus& s : contact_status_) sliding |= s.mode == ContactMode::Sliding;
  if (!sliding) return false;
  // The slip-stop event watches the slip's component along the direction it had at the start of
  // the step: in 3D the slip may turn, and it stops where that component first vanishes.
  calc_kinematics(y, true);
  calc_contact_points();
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    ContactStatus& status = contact_status_[c];
    const double slip = contact_now_[c].slip_W.norm();
    if (status.mode == ContactMode::Sliding && slip > status.slip_zero) {
      status.slide_direction_W = contact_now_[c].slip_W / slip;
    }
  }
  return true;
}

void ArticulatedFormulation::note_contact(double t, std::size_t contact, std::string what) {
  contact_events_.push_back({t, contact, std::move(what)});
}

void ArticulatedFormulation::classify_contact(std::size_t c, double t, VecX& y) {
  ContactStatus& status = contact_status_[c];
  const PlaneContact& contact = model_.contacts[c];
  const ContactMode before = status.mode;
  status.mode = ContactMode::Rolling;
  solve_contacts_at(y);
  const ContactNow& now = contact_now_[c];
  const double slip = now.slip_W.norm();
  if (!(now.normal_force > 0.0)) {
    status.mode = ContactMode::Apart;
  } else if (slip > status.slip_zero) {
    status.mode = ContactMode::Sliding;
    status.slide_direction_W = now.slip_W / slip;
  } else if (contact.friction > 0.0 &&
             now.friction_W.norm() <= contact.friction * now.normal_force) {
    project(t, y);  // no slip at all from here
  } else {
    status.mode = ContactMode::Sliding;
    status.slide_direction_W = pushed_direction(now.friction_W, status.slide_direction_W);
  }
  if (status.mode != before) {
    note_contact(t, c,
                 status.mode == ContactMode::Apart     ? "apart"
                 : status.mode == ContactMode::Sliding ? "slides"
                                                       : "rolls");
  }
}

void ArticulatedFormulation::impact(std::size_t c, double t, VecX& y) {
  const PlaneContact& contact = model_.contacts[c];
  ContactStatus& status = contact_status_[c];
  const Vec3& n = contact.normal_W;
  calc_kinematics(y, true);
  calc_contact_points();
  // K: the contact point's velocity change per unit impulse there (3 x 3, world).
  for (int axis = 0; axis < 3; ++axis) {
    unknowns_[static_cast<std::size_t>(axis)] = {c, Vec3::Unit(axis), Vec3::Unit(axis)};
  }
  calc_contact_matrix(3, schedule_time_);
  const Mat3 K = contact_matrix_.topLeftCorner<3, 3>();
  const Vec3 v_before = contact_now_[c].velocity_W;
  const double vn_before = n.dot(v_before);
  const Vec3 slip_before = v_before - vn_before * n;
  const bool settles = -vn_before <= status.settle_speed || contact.restitution == 0.0;

  // Newton's restitution on the normal velocity, Coulomb on the tangential impulse: the impulse
  // that leaves no slip if it lies in the cone, else a sliding impulse P_n (n - mu s) against
  // the slip. Should that add energy (it can, where rotation couples the two), the impact is
  // taken as plastic (e = 0), which never does.
  Vec3 P = Vec3::Zero();
  double work = 0.0;
  for (const double e : {settles ? 0.0 : contact.restitution, 0.0}) {
    P = K.inverse() * (-e * vn_before * n - v_before);
    const double Pn = P.dot(n);
    const Vec3 Pt = P - Pn * n;
    if (Pt.norm() > contact.friction * Pn) {
      const double slip = slip_before.norm();
      const Vec3 s = slip > 0.0 ? Vec3(slip_before / slip)
                                : (Pt.norm() > 0.0 ? Vec3(-Pt / Pt.norm()) : Vec3::Zero());
      const Vec3 d = n - contact.friction * s;
      P = (-(1.0 + e) * vn_before / n.dot(K * d)) * d;
    }
    work = P.dot(v_before + 0.5 * (K * P));
    if (work <= 0.0) break;
  }
  for (int axis = 0; axis < 3; ++axis) contact_x_(axis) = P(axis);
  apply_contact_impulses(3, contact_x_, schedule_time_, y);
  y(ledger_ + contact_entry(c)) += work;
  const double vn_after = vn_before + n.dot(K * P);
  if (settles) {
    note_contact(t, c, fmt::format("touchdown at normal speed {:.3g} m/s: settles", -vn_before));
    classify_contact(c, t, y);
  } else {
    note_contact(t, c,
                 fmt::format("impact: normal speed {:.4g} -> {:.4g} m/s, {:.4g} J lost", -vn_before,
                             vn_after, -work));
  }
}

EventAction ArticulatedFormulation::on_event(std::size_t event_index, double t, VecX& y) {
  const std::size_t c = event_index / 3;
  ContactStatus& status = contact_status_[c];
  switch (event_index % 3) {
    case 0:  // touchdown
      impact(c, t, y);
      break;
    case 1:  // lift-off
      status.mode = ContactMode::Apart;
      note_contact(t, c, "lifts off");
      break;
    default:
      if (status.mode == ContactMode::Sliding) {
        calc_kinematics(y, true);
        calc_contact_points();
        const double slip = contact_now_[c].slip_W.norm();
        if (slip > status.slip_zero) {
          // The slip turned away from the direction it had (3D); it did not stop.
          status.slide_direction_W = contact_now_[c].slip_W / slip;
          break;
        }
        note_contact(t, c, "slip stops");
        classify_contact(c, t, y);
      } else {
        solve_contacts_at(y);
        status.mode = ContactMode::Sliding;
        status.slide_direction_W =
            pushed_direction(contact_now_[c].friction_W, status.slide_direction_W);
        note_contact(t, c, "slides: the friction rolling needs leaves the cone");
      }
      break;
  }
  return EventAction::Jump;
}

namespace {

struct ContactScales {
  double speed = 1.0, slip_zero = 0.0, settle_speed = 0.0, touching_height = 0.0;
};

ContactScales contact_scales(const PlaneContact& contact, const Vec3& gravity_W,
                             const BodyState& s) {
  const double size = std::max(contact_size(contact.surface), 1e-300);
  ContactScales scales;
  scales.speed = std::max(
      {std::sqrt(gravity_W.norm() * size), s.v_G.norm() + s.omega_W.norm() * size, 1e-300});
  scales.slip_zero = kSlipZero * scales.speed;
  const double g_n = std::abs(gravity_W.dot(contact.normal_W));
  scales.settle_speed =
      g_n > 0.0 ? std::sqrt(2.0 * g_n * kSettleHeight * size) : kSettleHeight * scales.speed;
  scales.touching_height = kTouchingHeight * size;
  return scales;
}

}  // namespace

std::optional<ArticulatedFormulation::ContactStartProblem>
ArticulatedFormulation::contact_start_problem(const VecX& y0) const {
  calc_kinematics(y0, true);
  calc_contact_points();
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    const PlaneContact& contact = model_.contacts[c];
    const ContactScales scales = contact_scales(contact, model_.gravity_W, states_[contact.body]);
    const ContactNow& now = contact_now_[c];
    if (now.support.height < -scales.touching_height) {
      return ContactStartProblem{
          c, fmt::format("body '{}' starts {:.6g} m inside the plane; place it on or above it",
                         model_.bodies[contact.body].name, -now.support.height)};
    }
    const double vn = now.velocity_W.dot(contact.normal_W);
    if (now.support.height <= scales.touching_height && vn < -scales.slip_zero) {
      return ContactStartProblem{
          c, fmt::format("body '{}' starts touching the plane and moving into it at {:.6g} m/s; "
                         "start it above the plane, or without that speed",
                         model_.bodies[contact.body].name, -vn)};
    }
  }
  return std::nullopt;
}

void ArticulatedFormulation::begin_contacts(double t0, const VecX& y) {
  contact_events_.clear();
  if (model_.contacts.empty()) return;
  calc_kinematics(y, true);  // the bodies' states set the scales
  VecX y_start = y;          // classifying may project it; the run starts from y itself
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    const PlaneContact& contact = model_.contacts[c];
    const ContactScales scales = contact_scales(contact, model_.gravity_W, states_[contact.body]);
    ContactStatus& status = contact_status_[c];
    status = ContactStatus{};
    status.slip_zero = scales.slip_zero;
    status.settle_speed = scales.settle_speed;
    status.touching_height = scales.touching_height;
  }
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    calc_kinematics(y_start, true);
    calc_contact_points();
    const ContactNow& now = contact_now_[c];
    const PlaneContact& contact = model_.contacts[c];
    if (now.support.height <= contact_status_[c].touching_height &&
        now.velocity_W.dot(contact.normal_W) <= contact_status_[c].slip_zero) {
      classify_contact(c, t0, y_start);
    }
  }
}

void ArticulatedFormulation::reclassify_contacts(double t, VecX& y) {
  for (std::size_t c = 0; c < model_.contacts.size(); ++c) {
    if (contact_status_[c].mode != ContactMode::Apart) classify_contact(c, t, y);
  }
}

}  // namespace tumble
