// A body's sphere touching another body's sphere, capsule or box, or a body's capsule touching
// another's capsule (docs/scenario.md, "Bodies that touch each other"): a contact between two
// bodies, free or held by joints, in one tree or not. The pair is apart, its gap watched by the
// touchdown event, meets in an impact, or presses, slides and rolls on itself in the modes a
// plane's contact has (contact_modes.cpp), with the same events.
//
// The other surface is a core swept by a radius (pair_core.hpp): the gap is the sphere's
// centre's distance from the core less the radii, and the normal n runs from the core's nearest
// point p towards the centre. The gap's rate is n . (the centre's velocity less the other body's
// point at p); the reference point O is the midpoint of the two surfaces' nearest points, which
// is the contact point when they touch. Two capsules are the same with the body's core its axis's
// segment: its point nearest the other's axis slides over the body too (axes_closest.hpp), and
// stands where the sphere's centre stood.
//
// Touching, the rows are a plane's, relative: the normal row holds the gap's rate, measured at
// the centre and at p (p sliding over the other body), and its rate gains n's turning, n' . v
// (|v_t|^2 / d for two spheres); rolling or sticking, two more hold the tangential velocity of
// the body's point at O less the other's, O moving over each body as n turns. Each unknown
// pushes the body at O and the other body at O the opposite way.
//
// Impacts: Newton's restitution on the normal motion and Coulomb's friction on the impulse, as a
// plane's (contact_modes.cpp, impact): the impulse that leaves no slip if it lies in the cone,
// else one along n - mu s against the slip s before it (exact for two spheres on free bodies,
// whose slip keeps its direction through the impact); should the impulse add energy, it is taken
// plastic, then plastic and frictionless. Where it would drive a body resting on a plane into
// the plane, the plane holds that body in the same solve. A pair that comes together slower than
// a plane's settling touchdown settles (e = 0), and if the two are then pushed into each other
// the contact holds them (enter_pressed_pairs). Simultaneous impacts (balls touching in a row,
// one struck) go one pair at a time: the touching pair that approaches fastest first (the first
// in the file among equals), until no touching pair approaches.
#include <fmt/format.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "tumble/contact/axes_closest.hpp"
#include "tumble/contact/contact_scales.hpp"
#include "tumble/contact/contact_system.hpp"
#include "tumble/contact/landing_bound.hpp"
#include "tumble/contact/pair_core.hpp"
#include "tumble/contact/sphere_pair_line.hpp"
#include "tumble/math/constraint_solve.hpp"

namespace tumble {

namespace {

// Impulses at one instant between touching pairs, at most: a row of balls with e < 1 converges
// geometrically (each round takes energy out), and e = 1 passes a strike down a row of n balls in
// n - 1.
constexpr int kPairImpactRounds = 100000;
// As the plane's step limit (contact_step_limit.cpp): the relative acceleration of the spheres'
// centres changes within a step the bound allows (as the bodies turn, a pendulum swings); this
// factor covers that.
constexpr double kGapTurningMargin = 2.0;
// Rounds of letting go the planes that would pull, and holding those driven in, in one impact:
// each changes the set of held planes, of which a body has a few.
constexpr int kHoldingRounds = 20;

Vec3 sphere_centre_W(const BodyMotion& w, const ContactSurface& sphere) {
  return w.r_G_W + w.R_WB * sphere.centre_B;
}

// The velocity of the body's point p_B (body axes, from the COM), world axes.
Vec3 point_velocity_W(const BodyMotion& w, const Vec3& p_B) {
  return w.R_WB * (w.velocity.tail<3>() + w.velocity.head<3>().cross(p_B));
}

// The same point's response to a unit wrench (the impulsive passes' acceleration): its velocity's
// jump per unit impulse.
Vec3 point_response_W(const BodyMotion& w, const Vec3& p_B) {
  return w.R_WB * (w.acceleration.tail<3>() + w.acceleration.head<3>().cross(p_B));
}

// Where a pair's sphere (on the body, motion a) is against the other body's core (motion b;
// pair_core.hpp): the normal n (world) from the core's nearest point p to the sphere's centre,
// and how fast it turns; the centre's distance from the core; p (the other body's axes, from its
// COM) and how fast it slides over that body; and the velocity of the sphere's centre less the
// other body's point at p. n turns with the centre's motion relative to the other body that p
// does not follow, over the distance, and with that body's turning.
struct PairLine {
  // The body's core's point (body axes, from its COM: a sphere's centre; a capsule's axis's point
  // nearest the other's) and how fast it slides over the body.
  Vec3 core_B = Vec3::Zero();
  Vec3 core_rate_B = Vec3::Zero();
  Vec3 n_W = Vec3::UnitZ();
  Vec3 n_rate_W = Vec3::Zero();
  double distance = 0.0;
  Vec3 p_B = Vec3::Zero();
  Vec3 p_rate_B = Vec3::Zero();
  Vec3 relative_velocity_W = Vec3::Zero();
  // n_rate_W . relative_velocity_W: what n's turning adds to the gap's second derivative.
  double turning = 0.0;
};
// Two capsules (axes_closest.hpp, as `tumble modes` takes them): each one's point nearest the
// other's axis, sliding along its axis while inside its segment.
PairLine capsules_pair_line(const PlaneContact& contact, const BodyMotion& a, const BodyMotion& b) {
  const auto state = [](const BodyMotion& w) {
    return BodyState{w.r_G_W, w.R_WB, w.R_WB * w.velocity.tail<3>(), w.R_WB * w.velocity.head<3>()};
  };
  const CapsulesLineOf<double> capsules =
      capsules_line<double>(contact.surface, state(a), contact.other_surface, state(b));
  const Vec3 u_a_B = contact.surface.axes_B.col(2), u_b_B = contact.other_surface.axes_B.col(2);
  PairLine line;
  line.core_B = contact.surface.centre_B + capsules.closest.s * u_a_B;
  line.core_rate_B = capsules.rates.s * u_a_B;
  line.p_B = contact.other_surface.centre_B + capsules.closest.t * u_b_B;
  line.p_rate_B = capsules.rates.t * u_b_B;
  line.n_W = capsules.n_W;
  line.n_rate_W = capsules.n_rate_W;
  line.distance = capsules.distance;
  line.relative_velocity_W = capsules.relative_velocity_W;
  line.turning = line.n_rate_W.dot(line.relative_velocity_W);
  return line;
}

PairLine pair_line(const PlaneContact& contact, const BodyMotion& a, const BodyMotion& b) {
  if (contact.surface.kind == ContactSurface::Kind::Capsule) {
    return capsules_pair_line(contact, a, b);
  }
  PairLine line;
  line.core_B = contact.surface.centre_B;
  const Vec3 centre_W = sphere_centre_W(a, contact.surface);
  if (contact.other_surface.kind == ContactSurface::Kind::Sphere) {
    // Two spheres: the line of their centres, in world axes (inside a shell, n and the distance
    // along it turned round: pair_core.hpp), as `tumble modes` takes it (sphere_pair_line.hpp).
    line.p_B = contact.other_surface.centre_B;
    line.relative_velocity_W =
        point_velocity_W(a, contact.surface.centre_B) - point_velocity_W(b, line.p_B);
    const SpherePairLineOf<double> centres =
        sphere_pair_line<double>(Vec3(centre_W - sphere_centre_W(b, contact.other_surface)),
                                 line.relative_velocity_W, contact.other_surface.touched_inside);
    line.n_W = centres.n_W;
    line.n_rate_W = centres.n_rate_W;
    line.distance = centres.distance;
    line.turning = centres.turning;
    return line;
  }
  // A capsule, a box, a cylinder, a tube, a disk, a ring, a torus or a cone: in its body's axes,
  // where the nearest point slides along the feature's free directions (round the axis, at rho_p /
  // rho of the centre's motion), and the normal turns with what is left of the centre's relative
  // motion.
  const Vec3 x_B = b.R_WB.transpose() * (centre_W - b.r_G_W);
  const Vec3 centre_velocity_W = point_velocity_W(a, contact.surface.centre_B);
  const Vec3 u_B = b.R_WB.transpose() * (centre_velocity_W - point_velocity_W(b, x_B));
  const CoreLineOf<double> core = core_line<double>(contact.other_surface, x_B, u_B);
  line.distance = core.closest.distance;
  line.n_W = b.R_WB * core.closest.n_B;
  line.p_B = core.closest.p_B;
  line.p_rate_B = core.p_rate_B;
  // n turns over the other body at n_rate_B, and with it.
  line.n_rate_W = (b.R_WB * b.velocity.head<3>()).cross(line.n_W) + b.R_WB * core.n_rate_B;
  line.relative_velocity_W = centre_velocity_W - point_velocity_W(b, line.p_B);
  line.turning = line.n_rate_W.dot(line.relative_velocity_W);
  return line;
}

}  // namespace

ContactScales pair_contact_scales(const PlaneContact& contact, const Vec3& gravity_W,
                                  const BodyState& a, const BodyState& b) {
  const double size = std::max(pair_size(contact), 1e-300);
  ContactScales scales;
  scales.size = size;
  scales.speed =
      std::max({std::sqrt(gravity_W.norm() * size), a.v_G.norm() + a.omega_W.norm() * size,
                b.v_G.norm() + b.omega_W.norm() * size, 1e-300});
  scales.slip_zero = kSlipZero * scales.speed;
  const double g = gravity_W.norm();
  scales.settle_speed =
      g > 0.0 ? std::sqrt(2.0 * g * kSettleHeight * size) : kSettleHeight * scales.speed;
  scales.touching_height = kTouchingHeightPerSize * size;
  scales.landing_height = kSettleHeight * size;
  return scales;
}

void ContactSystem::calc_pair_point(std::size_t c) const {
  const PlaneContact& contact = contacts_[c];
  const BodyMotion a = dynamics_.motion(contact.body);
  const BodyMotion b = dynamics_.motion(contact.other_body);
  // Concentric spheres have no normal (they overlap, which the start refuses): any will do.
  const PairLine line = pair_line(contact, a, b);
  ContactNow& now = d_.now[c];
  now.pair_normal_W = line.n_W;
  const Vec3& n = now.pair_normal_W;
  const double other_radius = core_radius(contact.other_surface);
  const double gap = line.distance - contact.surface.radius - other_radius;
  const Vec3 O_W = b.r_G_W + b.R_WB * line.p_B + (other_radius + 0.5 * gap) * n;
  now.reference_B = a.R_WB.transpose() * (O_W - a.r_G_W);
  now.other_reference_B = b.R_WB.transpose() * (O_W - b.r_G_W);
  // How fast O moves over each body: n turns at n_rate_W, and over a body turning at omega at
  // that less omega x n; on the other body O moves with p as well.
  const Vec3 omega_a_W = a.R_WB * a.velocity.head<3>(), omega_b_W = b.R_WB * b.velocity.head<3>();
  now.reference_rate_B = line.core_rate_B - (contact.surface.radius + 0.5 * gap) *
                                                a.R_WB.transpose() *
                                                (line.n_rate_W - omega_a_W.cross(n));
  now.other_reference_rate_B = line.p_rate_B + (other_radius + 0.5 * gap) * b.R_WB.transpose() *
                                                   (line.n_rate_W - omega_b_W.cross(n));
  now.core_B = line.core_B;
  now.core_rate_B = line.core_rate_B;
  now.other_core_B = line.p_B;
  now.other_core_rate_B = line.p_rate_B;
  now.pair_turning = line.turning;
  now.n_B = a.R_WB.transpose() * n;
  now.support = {now.reference_B, gap};
  now.normal_points_B[0] = now.reference_B;
  now.normal_point_rates_B.fill(Vec3::Zero());
  now.normal_point_count = 1;
  now.spin_radius = 0.0;
  now.velocity_W =
      point_velocity_W(a, now.reference_B) - point_velocity_W(b, now.other_reference_B);
  now.support_normal_speed = n.dot(now.velocity_W);
  now.slip_W = now.velocity_W - n * now.support_normal_speed;
  now.wrench_B.setZero();
  now.other_wrench_B.setZero();
  now.force_W.setZero();
  now.friction_W.setZero();
  now.moment_about_O_B.setZero();
  now.normal_force = 0.0;
}

const Vec3& ContactSystem::normal_of(std::size_t c) const {
  return contacts_[c].touches_a_body() ? d_.now[c].pair_normal_W : contacts_[c].normal_W;
}

std::optional<ContactSystem::StartProblem> ContactSystem::pair_start_problem(std::size_t c) const {
  const PlaneContact& contact = contacts_[c];
  const ContactScales scales = pair_contact_scales(
      contact, gravity_W_, dynamics_.state(contact.body), dynamics_.state(contact.other_body));
  const ContactNow& now = d_.now[c];
  const std::string& a = bodies_[contact.body].name;
  const std::string& b = bodies_[contact.other_body].name;
  const double gap = now.support.height;
  if (gap < -scales.touching_height) {
    const double radii = contact.surface.radius + core_radius(contact.other_surface);
    std::string how;
    // (Two capsules: the body's surface is the first's, not a sphere.)
    const bool capsules = contact.surface.kind == ContactSurface::Kind::Capsule;
    switch (capsules ? ContactSurface::Kind::Capsule : contact.other_surface.kind) {
      case ContactSurface::Kind::Sphere:
        if (contact.other_surface.touched_inside) {
          how = fmt::format(
              "the sphere is inside the shell, its centre {:.6g} m from the shell's; its radius "
              "{:.6g} m, the shell's {:.6g} m",
              -(gap + radii), contact.surface.radius, contact.other_surface.radius);
          break;
        }
        how = fmt::format("their spheres' centres are {:.6g} m apart, their radii add to {:.6g} m",
                          radii + gap, radii);
        break;
      case ContactSurface::Kind::Capsule:
        if (capsules) {
          how = fmt::format(
              "their axes between their caps' centres are {:.6g} m apart, their radii add to "
              "{:.6g} m",
              radii + gap, radii);
          break;
        }
        how = fmt::format(
            "the sphere's centre is {:.6g} m from the capsule's axis between its caps' centres, "
            "their radii add to {:.6g} m",
            radii + gap, radii);
        break;
      default:
        how = fmt::format(
            "the sphere's centre is {:.6g} m from the {}, below 0 inside it, its radius {:.6g} m",
            radii + gap,
            contact.other_surface.kind == ContactSurface::Kind::Cylinder
                ? (contact.other_surface.face_inner_radius > 0.0 ? "tube" : "cylinder")
            : contact.other_surface.kind == ContactSurface::Kind::Cone               ? "cone"
            : contact.other_surface.kind != ContactSurface::Kind::Circle             ? "box"
            : contact.other_surface.face_inner_radius < contact.other_surface.radius ? "disk"
            : contact.other_surface.tube_radius > 0.0 ? "torus's centre circle"
                                                      : "ring",
            radii);
        break;
    }
    return StartProblem{c, fmt::format("bodies '{}' and '{}' start overlapping by {:.6g} m ({}); "
                                       "place them apart or just touching",
                                       a, b, -gap, how)};
  }
  const double vn = now.support_normal_speed;
  if (gap <= scales.touching_height && vn < -scales.slip_zero) {
    return StartProblem{
        c, fmt::format("bodies '{}' and '{}' start touching and moving into each other at {:.6g} "
                       "m/s; start them apart, or without that speed",
                       a, b, -vn)};
  }
  return std::nullopt;
}

Vec3 ContactSystem::core_relative_acceleration_W(std::size_t c) const {
  const PlaneContact& contact = contacts_[c];
  const ContactNow& now = d_.now[c];
  return moving_point_acceleration_W(dynamics_.motion(contact.body), now.core_B, now.core_rate_B) -
         moving_point_acceleration_W(dynamics_.motion(contact.other_body), now.other_core_B,
                                     now.other_core_rate_B);
}

double ContactSystem::pair_time_to_depth(std::size_t c) const {
  // The gap's second derivative is n . (the sphere's centre's acceleration less the other body's
  // at the core's nearest point p, which slides), plus n's turning, n' . (their relative
  // velocity): never negative but where the other body turns. Their sizes bound how fast the
  // gap's rate can turn down.
  const ContactNow& now = d_.now[c];
  // (Two spheres' turning is never negative, but inside a shell: its round-off is left out.)
  const ContactSurface& other = contacts_[c].other_surface;
  const bool spheres = other.kind == ContactSurface::Kind::Sphere && !other.touched_inside;
  const double bound =
      core_relative_acceleration_W(c).norm() + (spheres ? 0.0 : std::max(0.0, -now.pair_turning));
  return first_root(now.support.height + s_.contacts[c].landing_height, now.support_normal_speed,
                    kGapTurningMargin * bound);
}

double ContactSystem::pair_gap_acceleration(std::size_t c) const {
  // The gap's rate is n . (v_centre - v_p): d'' = n . (a_centre - a_p) + n' . (v_centre - v_p).
  const ContactNow& now = d_.now[c];
  return now.pair_normal_W.dot(core_relative_acceleration_W(c)) + now.pair_turning;
}

Eigen::Index ContactSystem::append_pair_unknowns(std::size_t c, ContactMode mode, ContactRows rows,
                                                 const Vec3& slide_W, Eigen::Index count) const {
  if (mode == ContactMode::Apart) return count;
  const PlaneContact& contact = contacts_[c];
  const ContactNow& now = d_.now[c];
  const Mat3& R_a = dynamics_.motion(contact.body).R_WB;
  const Mat3& R_b = dynamics_.motion(contact.other_body).R_WB;
  const Vec3& n = now.pair_normal_W;
  const Vec3 zero = Vec3::Zero();
  const auto add = [&](const Vec3& p_B, const Vec3& rate_B, const Vec3& other_p_B,
                       const Vec3& other_rate_B, const Vec3& linear_W, bool normal,
                       const Vec3& force_W, double turning) {
    ContactUnknown& u = d_.unknowns[static_cast<std::size_t>(count++)];
    u = ContactUnknown{};
    u.contact = c;
    u.point_B = p_B;
    u.point_rate_B = rate_B;
    u.linear_W = linear_W;
    u.normal = normal;
    u.wrench_B = wrench_at(R_a, now.reference_B, force_W, zero);
    u.other_point_B = other_p_B;
    u.other_point_rate_B = other_rate_B;
    u.other_wrench_B = wrench_at(R_b, now.other_reference_B, -force_W, zero);
    u.turning_acceleration = turning;
  };
  // The normal row: the gap's rate, at the sphere's centre and the core's nearest point (the same
  // as at O: n is along the radii).
  // Sliding, its force carries Coulomb's friction mu N against the slip at O.
  const bool slides = mode == ContactMode::Sliding && rows == ContactRows::Motion;
  const double mu = slides ? contact.friction : 0.0;
  const Vec3 along_W = slide_W - n * n.dot(slide_W);
  const double turning = rows == ContactRows::Motion ? now.pair_turning : 0.0;
  add(now.core_B, now.core_rate_B, now.other_core_B, now.other_core_rate_B, n, true,
      n - mu * along_W, turning);
  if (mode == ContactMode::Sliding || rows == ContactRows::Position) return count;
  // Rolling or sticking: O's tangential velocity on the body less that on the other, as O moves
  // over both. (The tangents turn with n too, which adds t' . v_O: zero while the rows hold.)
  Vec3 t1, t2;
  plane_basis(n, t1, t2);
  for (const Vec3* t : {&t1, &t2}) {
    add(now.reference_B, now.reference_rate_B, now.other_reference_B, now.other_reference_rate_B,
        *t, false, *t, 0.0);
  }
  return count;
}

Vec3 ContactSystem::pair_slip_acceleration(std::size_t c) const {
  // The slip's rate: O's relative acceleration, its part across n (the slip being ~0 where this
  // is asked, n's turning adds nothing to it).
  const PlaneContact& contact = contacts_[c];
  const ContactNow& now = d_.now[c];
  const Vec3 a_W = moving_point_acceleration_W(dynamics_.motion(contact.body), now.reference_B,
                                               now.reference_rate_B) -
                   moving_point_acceleration_W(dynamics_.motion(contact.other_body),
                                               now.other_reference_B, now.other_reference_rate_B);
  const Vec3& n = now.pair_normal_W;
  return a_W - n * n.dot(a_W);
}

void ContactSystem::enter_pressed_pairs(double t, VecX& y) {
  const auto is_pair = [](const PlaneContact& contact) { return contact.touches_a_body(); };
  if (std::none_of(contacts_.begin(), contacts_.end(), is_pair)) return;
  // One solve for them all, and another after each pair that enters (its force moves the rest).
  calc_accelerations(y);
  for (const std::size_t c : watched()) {
    const ContactStatus& status = s_.contacts[c];
    if (!contacts_[c].touches_a_body() || status.mode != ContactMode::Apart) continue;
    const ContactNow& now = d_.now[c];
    if (now.support.height > status.touching_height ||
        std::abs(now.support_normal_speed) > status.slip_zero) {
      continue;
    }
    // Touching with nothing between them: pushed into each other (the gap's acceleration with
    // no force there below zero), the contact holds them from here; otherwise they stay apart.
    if (-pair_gap_acceleration(c) > status.slip_zero / status.time_scale) {
      classify_contact(c, t, y, true);
      calc_accelerations(y);
    }
  }
}

double ContactSystem::pair_impacts(std::size_t first, double t, VecX& y) {
  dynamics_.calc_motion(y, true);
  calc_contact_points();
  // A gap that closed as they turned away (or that something slowly pushes shut) needs no impact.
  const double approach = -d_.now[first].support_normal_speed;
  const bool strikes = approach > s_.contacts[first].slip_zero;
  for (int round = 0; strikes; ++round) {
    // The touching pair that approaches fastest (the first in the file among equals).
    std::size_t fastest = contacts_.size();
    double fastest_approach = 0.0;
    for (const std::size_t c : watched()) {
      if (!contacts_[c].touches_a_body()) continue;
      const ContactNow& now = d_.now[c];
      const ContactStatus& s = s_.contacts[c];
      const double speed = -now.support_normal_speed;
      if (now.support.height <= s.landing_height && speed > s.slip_zero &&
          speed > fastest_approach) {
        fastest = c;
        fastest_approach = speed;
      }
    }
    if (fastest == contacts_.size()) break;
    if (round == kPairImpactRounds) {
      const PlaneContact& still = contacts_[fastest];
      throw std::runtime_error(fmt::format(
          "contact '{}': {} impacts between touching bodies at t = {:.9g} s, and '{}' and '{}' "
          "still approach each other at {:.3g} m/s",
          still.name, kPairImpactRounds, t, bodies_[still.body].name,
          bodies_[still.other_body].name, fastest_approach));
    }
    pair_impulse(fastest, t, y);
    dynamics_.calc_motion(y, true);
    calc_contact_points();
  }
  return approach;
}

void ContactSystem::mark_tied_groups(std::size_t c) {
  // The impulse moves the pair's bodies, and those that the held contacts tie to them: their
  // motion groups are marked (once a pass, not once a candidate: a bin's settling pass looks at
  // hundreds of pairs).
  std::fill(d_.tied_group.begin(), d_.tied_group.end(), 0);
  const auto mark = [&](std::size_t k) {
    const PlaneContact& contact = contacts_[k];
    if (dynamics_.can_move(contact.body)) d_.tied_group[dynamics_.motion_group(contact.body)] = 1;
    if (contact.touches_a_body() && dynamics_.can_move(contact.other_body)) {
      d_.tied_group[dynamics_.motion_group(contact.other_body)] = 1;
    }
  };
  mark(c);
  for (const std::size_t k : watched()) {
    if (d_.held_in_impact[k] != 0) mark(k);
  }
}

bool ContactSystem::moved_by_impulse(std::size_t k) const {
  const PlaneContact& contact = contacts_[k];
  const auto marked = [&](std::size_t body) {
    return dynamics_.can_move(body) && d_.tied_group[dynamics_.motion_group(body)] != 0;
  };
  return marked(contact.body) || (contact.touches_a_body() && marked(contact.other_body));
}

bool ContactSystem::hold_driven_in(std::size_t c, bool settling) {
  // At d_.impact_y: the touching plane contacts of the bodies that move with either of the
  // pair's whose points go into their planes; settling, the touching pairs too that come together
  // no faster than a settling touchdown.
  const PlaneContact& pair = contacts_[c];
  dynamics_.calc_motion(d_.impact_y, true);
  calc_contact_points();
  if (settling) mark_tied_groups(c);
  bool more = false;
  for (const std::size_t k : watched()) {
    const ContactStatus& status = s_.contacts[k];
    const PlaneContact& contact = contacts_[k];
    if (d_.held_in_impact[k] != 0 || k == c) continue;
    const ContactNow& now = d_.now[k];
    if (contact.touches_a_body()) {
      const double approach = -now.support_normal_speed;
      if (settling && now.support.height <= status.landing_height && approach > status.slip_zero &&
          approach <= status.settle_speed && moved_by_impulse(k)) {
        d_.held_in_impact[k] = 1;
        more = true;
      }
      continue;
    }
    if (status.mode == ContactMode::Apart) continue;
    if (!dynamics_.moves_with(contact.body, pair.body) &&
        !dynamics_.moves_with(contact.body, pair.other_body)) {
      continue;
    }
    for (int i = 0; i < now.normal_point_count; ++i) {
      if (normal_speed(k, now.normal_points_B[static_cast<std::size_t>(i)]) < -status.slip_zero) {
        d_.held_in_impact[k] = 1;
        more = true;
      }
    }
  }
  return more;
}

Vec3 ContactSystem::pair_impulse_holding(std::size_t c, double e, bool friction, bool settling,
                                         const VecX& y) {
  const PlaneContact& contact = contacts_[c];
  // The impulses that give the pair's normal motion -e of what it had (its slip stopped, if that
  // fits in the cone; else mu of the normal impulse against the slip) and stop the held planes'
  // normal motion, frictionless (their friction is theirs to take after, as they are classified
  // again). A plane (or pair) that would pull is let go, one driven in by the result is held,
  // until neither changes.
  Vec3 impulse_W = Vec3::Zero();
  for (int round = 0; round < kHoldingRounds; ++round) {
    dynamics_.calc_motion(y, true);
    calc_contact_points();
    const auto solve = [&](ContactMode mode, ContactRows rows, const Vec3& slide_W) {
      Eigen::Index count = append_contact_unknowns(c, mode, rows, slide_W, 0);
      for (const std::size_t k : watched()) {
        if (d_.held_in_impact[k] == 0) continue;
        count = append_contact_unknowns(k, ContactMode::Sliding, ContactRows::Projection,
                                        Vec3::Zero(), count);
      }
      for (Eigen::Index i = 0; i < count; ++i) {
        const ContactUnknown& row = d_.unknowns[static_cast<std::size_t>(i)];
        d_.x(i) = -(row.normal && row.contact == c ? 1.0 + e : 1.0) * row_velocity(row);
      }
      solve_contact_rows(count, d_.x, RowQuantity::Velocity);
      set_contact_resultants(count, d_.x);
      return count;
    };
    Eigen::Index count = 0;
    bool sticks = friction && contact.friction > 0.0;
    if (sticks) {
      try {
        count = solve(ContactMode::Rolling, ContactRows::Projection, Vec3::Zero());
        sticks = stick_margin(c, 1.0) >= 0.0;
      } catch (const InconsistentConstraints&) {
        sticks = false;
      }
    }
    if (!sticks) {
      const Vec3 slip_W = d_.now[c].slip_W;
      const bool slides = friction && contact.friction > 0.0 && std::isfinite(contact.friction);
      const Vec3 slide_W = slip_W.norm() > 0.0 ? Vec3(slip_W.normalized()) : pushed_direction(c);
      count = slides ? solve(ContactMode::Sliding, ContactRows::Motion, slide_W)
                     : solve(ContactMode::Sliding, ContactRows::Projection, Vec3::Zero());
    }
    impulse_W = d_.now[c].force_W;  // the impulse, as a force would be
    bool changed = false;
    for (const std::size_t k : watched()) {
      if (d_.held_in_impact[k] != 0 && d_.now[k].normal_force < 0.0) {
        d_.held_in_impact[k] = 0;  // it would pull: the body leaves that plane
        changed = true;
      }
    }
    d_.impact_y = y;
    apply_contact_impulses(count, d_.x, d_.impact_y);
    // A plane (or pair) not held that the result drives in is held too.
    if (!changed && !hold_driven_in(c, settling)) break;
  }
  return impulse_W;
}

void ContactSystem::pair_impulse(std::size_t c, double t, VecX& y) {
  const PlaneContact& contact = contacts_[c];
  const std::size_t a = contact.body, b = contact.other_body;
  // At y (pair_impacts' calc_contact_points).
  const ContactNow& now = d_.now[c];
  const Vec3 n = now.pair_normal_W;
  const Vec3 p_a_B = now.reference_B, p_b_B = now.other_reference_B;
  const Vec3 velocity_W = now.velocity_W, slip_W = now.slip_W;
  const double vn = now.support_normal_speed;
  const Mat3 R_a = dynamics_.motion(a).R_WB, R_b = dynamics_.motion(b).R_WB;
  const double energy_before = dynamics_.kinetic_energy();
  // As a plane's touchdown: one whose bounce would rise less than a millionth of the size
  // settles (the cascade of ever smaller bounces ends).
  const bool settles = -vn <= s_.contacts[c].settle_speed;

  // W: the jump of the relative velocity at O per unit impulse (on the body at O, and its
  // opposite on the other body), column by column; a body that does not move with the one
  // pushed has no response to it.
  Mat3 W;
  const Vec3 zero = Vec3::Zero();
  for (int j = 0; j < 3; ++j) {
    const Vec3 e = Vec3::Unit(j);
    Vec3 column = Vec3::Zero();
    dynamics_.respond_to_unit_wrench({a, wrench_at(R_a, p_a_B, e, zero)});
    column += point_response_W(dynamics_.motion(a), p_a_B);
    if (dynamics_.moves_with(b, a)) column -= point_response_W(dynamics_.motion(b), p_b_B);
    dynamics_.respond_to_unit_wrench({b, wrench_at(R_b, p_b_B, -e, zero)});
    column -= point_response_W(dynamics_.motion(b), p_b_B);
    if (dynamics_.moves_with(a, b)) column += point_response_W(dynamics_.motion(a), p_a_B);
    W.col(j) = column;
  }
  const Eigen::FullPivLU<Mat3> sticking(W);

  struct ImpactLaw {
    double e;
    bool friction;
  };
  const ImpactLaw laws[] = {{settles ? 0.0 : contact.restitution, true}, {0.0, true}, {0.0, false}};
  Vec3 impulse_W = Vec3::Zero();  // on the body, at O
  double work = 0.0;
  for (const ImpactLaw& law : laws) {
    const double vn_after = -law.e * vn;
    bool found = false;
    Vec3 sticking_friction_W = Vec3::Zero();
    if (law.friction && sticking.isInvertible()) {
      impulse_W = sticking.solve(vn_after * n - velocity_W);
      const double p_n = n.dot(impulse_W);
      sticking_friction_W = impulse_W - p_n * n;
      found = std::isinf(contact.friction) || sticking_friction_W.norm() <= contact.friction * p_n;
    }
    if (!found) {
      // Sliding: mu of the normal impulse against the slip (or, with none, against the friction
      // sticking would need); frictionless, along the normal alone.
      Vec3 along_W = n;
      if (law.friction && contact.friction > 0.0 && std::isfinite(contact.friction)) {
        const double slip = slip_W.norm();
        const double needed = sticking_friction_W.norm();
        if (slip > 0.0) {
          along_W -= contact.friction * slip_W / slip;
        } else if (needed > 0.0) {
          along_W += contact.friction * sticking_friction_W / needed;
        }
      }
      const double response = n.dot(W * along_W);
      // Neither body can move along the normal: nothing to stop, and no impulse.
      impulse_W = response > 0.0 ? Vec3(((vn_after - vn) / response) * along_W) : Vec3(zero);
    }
    d_.wrenches[0] = {a, wrench_at(R_a, p_a_B, impulse_W, zero)};
    d_.wrenches[1] = {b, wrench_at(R_b, p_b_B, -impulse_W, zero)};
    dynamics_.respond_to_impulses(std::span<const BodyWrench>(d_.wrenches.data(), 2));
    d_.impact_y = y;
    dynamics_.apply_speed_jumps(d_.impact_y);
    // A body resting on a plane that this impulse would drive into it (a ball struck from above,
    // on the floor): the plane takes its part of the blow in the same instant. A settling
    // impulse holds the touching pairs it drives together too: a cluster of touching balls
    // settles at once, where one pair at a time would hand the push back and forth, each round
    // a fraction of the last, down to round-off.
    std::fill(d_.held_in_impact.begin(), d_.held_in_impact.end(), 0);
    if (hold_driven_in(c, settles)) {
      impulse_W = pair_impulse_holding(c, law.e, law.friction, settles, y);
    }
    dynamics_.calc_motion(d_.impact_y, true);
    work = dynamics_.kinetic_energy() - energy_before;
    if (work <= kWorkRoundOff * energy_before) break;
  }
  y = d_.impact_y;
  add_work(c, work, y);
  dynamics_.calc_motion(y, true);
  calc_contact_points();
  const double vn_after = d_.now[c].support_normal_speed;
  const Vec3 O_W = dynamics_.motion(a).r_G_W + R_a * p_a_B;
  const std::string where =
      fmt::format("'{}' and '{}' at ({:.4g}, {:.4g}, {:.4g}) m, normal ({:.4g}, {:.4g}, {:.4g})",
                  bodies_[a].name, bodies_[b].name, O_W.x(), O_W.y(), O_W.z(), n.x(), n.y(), n.z());
  const ContactImpactNumbers numbers{energy_before, energy_before + work, -vn, vn_after, impulse_W};
  if (settles) {
    note_contact(t, c,
                 fmt::format("touchdown of {} at normal speed {:.3g} m/s: settles", where, -vn),
                 numbers);
    return;
  }
  note_contact(t, c,
               fmt::format("impact of {}: normal speed {:.4g} -> {:.4g} m/s, {:.4g} J lost", where,
                           -vn, vn_after, work == 0.0 ? 0.0 : -work),
               numbers);
}

}  // namespace tumble
