// Two bodies touching at their spheres (docs/scenario.md, "Bodies that touch each other"): a
// contact between two bodies, free or held by joints, in one tree or not. For now the pair is
// apart, its gap watched by the touchdown event, or meets in an impact; contact that lasts
// (pressing, sliding, rolling on each other) ends the run where it would begin.
//
// The gap is the distance between the spheres' centres less their radii, and the normal n runs
// from the other body's sphere towards the body's. Both spheres' points on the line of centres
// move along it as the centres do, so the gap's rate is n . (the bodies' relative velocity at
// any point of that line); the reference point O is the midpoint of the spheres' nearest points,
// which is the contact point when they touch.
//
// Impacts: Newton's restitution on the normal motion and Coulomb's friction on the impulse, as a
// plane's (contact_modes.cpp, impact): the impulse that leaves no slip if it lies in the cone,
// else one along n - mu s against the slip s before it (exact for two spheres on free bodies,
// whose slip keeps its direction through the impact); should the impulse add energy, it is taken
// plastic, then plastic and frictionless. A pair that comes together slower than a plane's
// settling touchdown settles (e = 0); if the two are then pushed into each other, the run ends
// there. Simultaneous impacts (balls touching in a row, one struck) go one pair at a time: the
// touching pair that approaches fastest first (the first in the file among equals), until no
// touching pair approaches.
#include <fmt/format.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "tumble/contact/contact_scales.hpp"
#include "tumble/contact/contact_system.hpp"
#include "tumble/contact/landing_bound.hpp"

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

double smaller_radius(const PlaneContact& contact) {
  return std::min(contact.surface.radius, contact.other_surface.radius);
}

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

}  // namespace

ContactScales pair_contact_scales(const PlaneContact& contact, const Vec3& gravity_W,
                                  const BodyState& a, const BodyState& b) {
  const double size = std::max(smaller_radius(contact), 1e-300);
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
  const Vec3 centre_a_W = sphere_centre_W(a, contact.surface);
  const Vec3 centre_b_W = sphere_centre_W(b, contact.other_surface);
  const Vec3 apart_W = centre_a_W - centre_b_W;
  const double distance = apart_W.norm();
  ContactNow& now = d_.now[c];
  // Concentric spheres have no normal (they overlap, which the start refuses): any will do.
  now.pair_normal_W = distance > 0.0 ? Vec3(apart_W / distance) : Vec3::UnitZ();
  const Vec3& n = now.pair_normal_W;
  const double gap = distance - contact.surface.radius - contact.other_surface.radius;
  const Vec3 O_W = centre_b_W + (contact.other_surface.radius + 0.5 * gap) * n;
  now.reference_B = a.R_WB.transpose() * (O_W - a.r_G_W);
  now.other_reference_B = b.R_WB.transpose() * (O_W - b.r_G_W);
  now.reference_rate_B.setZero();
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
    const double radii = contact.surface.radius + contact.other_surface.radius;
    return StartProblem{
        c, fmt::format("bodies '{}' and '{}' start overlapping by {:.6g} m (their spheres' centres "
                       "are {:.6g} m apart, their radii add to {:.6g} m); place them apart or just "
                       "touching",
                       a, b, -gap, radii + gap, radii)};
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

Vec3 ContactSystem::centres_relative_acceleration_W(const PlaneContact& contact,
                                                    const BodyMotion& a,
                                                    const BodyMotion& b) const {
  return moving_point_acceleration_W(a, contact.surface.centre_B, Vec3::Zero()) -
         moving_point_acceleration_W(b, contact.other_surface.centre_B, Vec3::Zero());
}

double ContactSystem::pair_time_to_depth(std::size_t c) const {
  const PlaneContact& contact = contacts_[c];
  const BodyMotion a = dynamics_.motion(contact.body);
  const BodyMotion b = dynamics_.motion(contact.other_body);
  // The gap's second derivative is n . (a_A - a_B), the centres' relative acceleration, plus the
  // square of their relative velocity across n over their distance, which is never negative: the
  // size of that relative acceleration bounds how fast the gap's rate can turn down.
  const Vec3 relative_acceleration_W = centres_relative_acceleration_W(contact, a, b);
  const ContactNow& now = d_.now[c];
  return first_root(now.support.height + s_.contacts[c].landing_height, now.support_normal_speed,
                    kGapTurningMargin * relative_acceleration_W.norm());
}

double ContactSystem::pair_gap_acceleration(std::size_t c) const {
  const PlaneContact& contact = contacts_[c];
  const BodyMotion a = dynamics_.motion(contact.body);
  const BodyMotion b = dynamics_.motion(contact.other_body);
  // The distance d between the centres: d'' = n . (a_A - a_B) + |v_A - v_B|^2 less its part
  // along n, over d (the line of centres turning).
  const Vec3 apart_W =
      sphere_centre_W(a, contact.surface) - sphere_centre_W(b, contact.other_surface);
  const Vec3 n = apart_W.normalized();
  const Vec3 relative_velocity_W = point_velocity_W(a, contact.surface.centre_B) -
                                   point_velocity_W(b, contact.other_surface.centre_B);
  const Vec3 relative_acceleration_W = centres_relative_acceleration_W(contact, a, b);
  const double along = n.dot(relative_velocity_W);
  return n.dot(relative_acceleration_W) +
         (relative_velocity_W.squaredNorm() - along * along) / apart_W.norm();
}

void ContactSystem::pair_impacts(std::size_t first, double t, VecX& y) {
  dynamics_.calc_motion(y, true);
  calc_contact_points();
  const PlaneContact& contact = contacts_[first];
  const ContactStatus& status = s_.contacts[first];
  const double approach = -d_.now[first].support_normal_speed;
  if (!(approach > status.slip_zero)) return;  // the gap closed as they turned away: no impact
  for (int round = 0;; ++round) {
    // The touching pair that approaches fastest (the first in the file among equals).
    std::size_t fastest = contacts_.size();
    double fastest_approach = 0.0;
    for (std::size_t c = 0; c < contacts_.size(); ++c) {
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
  // A settling touchdown leaves the pair together with no speed between them. Where something
  // pushes them into each other (a ball resting on another; a plastic strike, whose bodies then
  // turn into each other), only contact that lasts would hold them, and the run ends here rather
  // than go on by a chatter of ever smaller impacts.
  if (approach > status.settle_speed) return;
  calc_accelerations(y);
  const double pressing = -pair_gap_acceleration(first);
  if (pressing > status.slip_zero / status.time_scale) {
    throw std::runtime_error(fmt::format(
        "contact '{}': bodies '{}' and '{}' settle against each other at t = {:.9g} s and are "
        "pushed on at {:.3g} m/s^2: contact that lasts between two bodies (one resting, "
        "sliding or rolling on the other) is not built yet, only their impacts",
        contact.name, bodies_[contact.body].name, bodies_[contact.other_body].name, t, pressing));
  }
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
      found = sticking_friction_W.norm() <= contact.friction * p_n;
    }
    if (!found) {
      // Sliding: mu of the normal impulse against the slip (or, with none, against the friction
      // sticking would need); frictionless, along the normal alone.
      Vec3 along_W = n;
      if (law.friction && contact.friction > 0.0) {
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
